// The two Rosenbrock-W methods of the `rosenbrock` integrator (rosenbrock.h says which step takes
// which), in the W-free form its stages are computed in (Hairer & Wanner, Solving ODEs II,
// §IV.7, (7.4)-(7.6)): with W the Jacobian approximation and u = Gamma k,
//   (1/(h gamma) I - W) u_i = f(t + c_i h, y0 + sum_j a_ij u_j) + sum_j (C_ij / h) u_j
//                             + d_i h f_t,
//   y1 = y0 + sum_j m_j u_j,  error estimate = sum_j e_j u_j,
// where a = alpha Gamma^-1, C = -Gamma^-1 below the diagonal, m = b Gamma^-1,
// e = (b - bhat) Gamma^-1, c_i = sum_j alpha_ij and d_i = sum_j gamma_ij, for the method
//   (I - h gamma W) k_i = h f(t + c_i h, y0 + sum_j alpha_ij k_j) + h W sum_j gamma_ij k_j
//                         + d_i h^2 f_t,   y1 = y0 + sum_i b_i k_i.
// A W-method keeps its order with any W: the order conditions treat W as its own kind of vertex
// in the trees, and a tree with a W vertex must have weight zero.
#pragma once

#include <array>

namespace sled::runtime {

struct RosenbrockTableau {
  static constexpr int kMaxStages = 6;
  using Square = std::array<std::array<double, kMaxStages>, kMaxStages>;
  using Row = std::array<double, kMaxStages>;

  int stages = 0;
  int order = 0;
  double gamma = 0.0;
  Square a{};
  Square c{};
  Row m{};
  Row e{};
  Row alpha_sum{};
  Row gamma_sum{};
};

namespace rosenbrock_detail {

using Square = RosenbrockTableau::Square;
using Row = RosenbrockTableau::Row;

// The W-free form of a method given by alpha (strictly lower), Gamma (lower, gamma on the
// diagonal), b and bhat.
constexpr RosenbrockTableau FromStages(int stages, int order, const Square& alpha,
                                       const Square& gamma_matrix, const Row& b, const Row& bhat) {
  // Gamma^-1 by forward substitution (Gamma is lower triangular).
  Square inverse{};
  for (int col = 0; col < stages; ++col) {
    for (int row = 0; row < stages; ++row) {
      double value = row == col ? 1.0 : 0.0;
      for (int k = 0; k < row; ++k) value -= gamma_matrix[row][k] * inverse[k][col];
      inverse[row][col] = value / gamma_matrix[row][row];
    }
  }
  RosenbrockTableau t;
  t.stages = stages;
  t.order = order;
  t.gamma = gamma_matrix[0][0];
  for (int i = 0; i < stages; ++i) {
    for (int j = 0; j < stages; ++j) {
      double a = 0.0;
      for (int k = 0; k < stages; ++k) a += alpha[i][k] * inverse[k][j];
      t.a[i][j] = j < i ? a : 0.0;
      t.c[i][j] = j < i ? -inverse[i][j] : 0.0;
      t.alpha_sum[i] += alpha[i][j];
      t.gamma_sum[i] += gamma_matrix[i][j];
      t.m[j] += b[i] * inverse[i][j];
      t.e[j] += (b[i] - bhat[i]) * inverse[i][j];
    }
  }
  return t;
}

// ROS34PW2: Rang & Angermann, "New Rosenbrock W-methods of order 3 for partial differential
// algebraic equations of index 1", BIT Numer. Math. 45 (2005) 761-787 (as tabulated in PETSc's
// TSROSWRA34PW2). Four stages, order 3 with an embedded order-2 solution, L-stable (R(inf) = 0)
// and stiffly accurate.
constexpr double kGamma3 = 4.3586652150845900e-01;
constexpr RosenbrockTableau kRos34pw2 = FromStages(
    4, 3,
    {{{0.0, 0.0, 0.0, 0.0},
      {8.7173304301691801e-01, 0.0, 0.0, 0.0},
      {8.4457060015369423e-01, -1.1299064236484185e-01, 0.0, 0.0},
      {0.0, 0.0, 1.0, 0.0}}},
    {{{kGamma3, 0.0, 0.0, 0.0},
      {-8.7173304301691801e-01, kGamma3, 0.0, 0.0},
      {-9.0338057013044082e-01, 5.4180672388095326e-02, kGamma3, 0.0},
      {2.4212380706095346e-01, -1.2232505839045147e+00, 5.4526025533510214e-01, kGamma3}}},
    {2.4212380706095346e-01, -1.2232505839045147e+00, 1.5452602553351020e+00, kGamma3},
    {3.7810903145819369e-01, -9.6042292212423178e-02, 5.0e-01, 2.1793326075422950e-01});

}  // namespace rosenbrock_detail

using rosenbrock_detail::kRos34pw2;

// The six-stage W-method of order 4 of Rahunanthan & Stanescu, "High-order W-methods",
// J. Comput. Appl. Math. 233 (2010) 1798-1811, gamma = 1/4, R(inf) = 0: its a, C, m, c and d
// as published. The paper gives no error estimate (it is used with fixed steps). One exists on
// the same stages: the eight order-3 conditions of a W-method (sum b = 1; sum b alpha = 1/2,
// sum b gamma = 0; five of order 3) have rank 5 on them, so every bhat = b + s v, v their null
// vector (-7.1216, 12.9527, -5.3316, -3.0161, 1.5166, 1), is of W-order 3. We take s = 1/16,
// where bhat's R(inf) is 1 (the estimate neither vanishes nor grows on the stiff modes), and
// e = (b - bhat) Gamma^-1 = -v Gamma^-1 / 16. (Found by evaluating the B-series of the stages on
// random polynomial problems with a random W; tests/runtime/integrator_accuracy_test.cpp checks
// the orders.)
constexpr RosenbrockTableau kRahunanthanStanescu4 = {
    .stages = 6,
    .order = 4,
    .gamma = 0.25,
    .a = {{{0.0, 0.0, 0.0, 0.0, 0.0, 0.0},
           {5.812383407115008e-01, 0.0, 0.0, 0.0, 0.0, 0.0},
           {9.039624413714670e-01, 1.8615191555345010e+00, 0.0, 0.0, 0.0, 0.0},
           {2.0765797196750000e+00, 1.884255381414796e-01, 1.8701589674910320e+00, 0.0, 0.0, 0.0},
           {4.4355506384843120e+00, 5.4571817986101890e+00, 4.6163507880689300e+00,
            3.1181119524023610e+00, 0.0, 0.0},
           {1.0791701698483260e+01, -1.005691522584131e+01, 1.4995644854284190e+01,
            5.2743399543909430e+00, 1.4297308712611900e+00, 0.0}}},
    .c = {{{0.0, 0.0, 0.0, 0.0, 0.0, 0.0},
           {-2.661294105131369e+00, 0.0, 0.0, 0.0, 0.0, 0.0},
           {-3.128450202373838e+00, 0.0, 0.0, 0.0, 0.0, 0.0},
           {-6.920335474535658e+00, -1.202675288266817e+00, -9.733561811413620e+00, 0.0, 0.0, 0.0},
           {-2.809530629102695e+01, 2.0371262954793770e+01, -4.104375275302869e+01,
            -1.966373175620895e+01, 0.0, 0.0},
           {9.7998186780974000e+00, 1.1935792886603180e+01, 3.6738749290132010e+00,
            1.4807828541095500e+01, 8.318583998690680e-01, 0.0}}},
    .m = {6.4562170746532350e+00, -4.853141317768053e+00, 9.7653183340692600e+00,
          2.0810841772787230e+00, 6.603936866352417e-01, 6.000000000000000e-01},
    .e = {-7.7592238210560383e-02, -3.3456221259119978e-01, -4.9302229423790456e-01,
          -1.843347355371503e-01, -3.2715518608983285e-01, -2.5e-01},
    .alpha_sum = {0.0, 1.453095851778752e-01, 3.817422770256738e-01, 6.367813704374599e-01,
                  7.560744496323561e-01, 9.271047239875670e-01},
    .gamma_sum = {2.5e-01, 8.36691184292894e-02, 5.44718623516351e-02, -3.402289722355864e-01,
                  3.37651588339529e-02, -9.03074267618540e-02},
};

}  // namespace sled::runtime
