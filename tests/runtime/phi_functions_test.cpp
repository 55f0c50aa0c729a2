// The phi-functions of small matrices (runtime/integrate/phi_functions.h) against closed forms
// (scalars, a rotation generator, a Jordan block) and against Eigen's own matrix exponential
// (unsupported/Eigen/MatrixFunctions, Higham's Pade scaling and squaring) of the augmented
// block matrix whose exponential holds them; and the structured products phi_k(tau A) b of
// runtime/integrate/structured_jacobian.h against the same for the dense A = N + U V^T.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <array>
#include <cmath>
#include <random>
#include <span>
#include <unsupported/Eigen/MatrixFunctions>
#include <vector>

#include "runtime/integrate/phi_functions.h"
#include "runtime/integrate/structured_jacobian.h"

namespace sled::runtime {
namespace {

// phi_k(z) in long double: the series for |z| < 1, else the recurrence from e^z upwards, which
// loses no accuracy there.
long double ScalarPhi(int k, long double z) {
  if (std::fabs(static_cast<double>(z)) < 1.0) {
    long double sum = 0.0L, term = 1.0L;
    for (int j = 1; j <= k; ++j) term /= j;
    for (int j = 0; j < 60; ++j) {
      sum += term;
      term *= z / static_cast<long double>(j + k + 1);
    }
    return sum;
  }
  long double value = std::exp(z);
  long double factorial = 1.0L;
  for (int j = 0; j < k; ++j) {
    value = (value - 1.0L / factorial) / z;
    factorial *= static_cast<long double>(j + 1);
  }
  return value;
}

// phi_0..phi_p of z by Eigen's exponential of [[Z, I, 0...], [0, 0, I, ...], ..., 0]:
// its top block row is [e^Z, phi_1(Z), ..., phi_p(Z)]. In long double, so the reference's own
// rounding (which grows with the norm of a non-normal Z) stays far below the tolerances.
std::vector<Eigen::MatrixXd> ReferencePhi(const Eigen::MatrixXd& z, int p) {
  using Wide = Eigen::Matrix<long double, Eigen::Dynamic, Eigen::Dynamic>;
  const Eigen::Index m = z.rows();
  Wide big = Wide::Zero((p + 1) * m, (p + 1) * m);
  big.topLeftCorner(m, m) = z.cast<long double>();
  for (int k = 0; k < p; ++k) big.block(k * m, (k + 1) * m, m, m).setIdentity();
  const Wide e = big.exp();
  std::vector<Eigen::MatrixXd> out;
  for (int k = 0; k <= p; ++k) out.push_back(e.block(0, k * m, m, m).cast<double>());
  return out;
}

double RelativeDifference(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  return (a - b).norm() / std::max(b.norm(), 1e-300);
}

TEST(PhiFunctions, MatchesScalarClosedFormsFromDecayToGrowth) {
  PhiFunctions functions;
  std::vector<Eigen::MatrixXd> phi(6), half(6);
  for (const double z : {-1e4, -300.0, -20.0, -1.0, -1e-9, 0.0, 1e-6, 0.7, 3.0, 25.0}) {
    functions.Compute(Eigen::MatrixXd::Constant(1, 1, z), 5, phi, half);
    for (int k = 0; k <= 5; ++k) {
      const double exact = static_cast<double>(ScalarPhi(k, z));
      const double exact_half = static_cast<double>(ScalarPhi(k, z / 2));
      EXPECT_NEAR(phi[static_cast<std::size_t>(k)](0, 0), exact, 1e-13 * std::abs(exact))
          << "phi_" << k << "(" << z << ")";
      EXPECT_NEAR(half[static_cast<std::size_t>(k)](0, 0), exact_half, 1e-13 * std::abs(exact_half))
          << "phi_" << k << "(" << z / 2 << ")";
    }
  }
}

TEST(PhiFunctions, RotationGeneratorGivesTheRotation) {
  // Z = [[0, w], [-w, 0]]: e^Z is the rotation by w, and phi_1(Z) = Z^-1 (e^Z - I).
  PhiFunctions functions;
  std::vector<Eigen::MatrixXd> phi(3);
  for (const double w : {0.3, 5.0, 800.0}) {
    Eigen::Matrix2d z;
    z << 0, w, -w, 0;
    functions.Compute(z, 2, phi);
    Eigen::Matrix2d rotation;
    rotation << std::cos(w), std::sin(w), -std::sin(w), std::cos(w);
    EXPECT_LT((phi[0] - rotation).norm(), 1e-13 * std::max(1.0, w)) << w;
    const Eigen::Matrix2d phi1 = z.inverse() * (rotation - Eigen::Matrix2d::Identity());
    EXPECT_LT((phi[1] - phi1).norm(), 1e-13 * std::max(1.0, w)) << w;
    const Eigen::Matrix2d phi2 = z.inverse() * (phi1 - Eigen::Matrix2d::Identity());
    EXPECT_LT((phi[2] - phi2).norm(), 1e-13 * std::max(1.0, w)) << w;
  }
}

TEST(PhiFunctions, JordanBlockGivesTheDerivative) {
  // A defective matrix (a critically damped oscillator has one): phi_k of [[l, 1], [0, l]] is
  // [[phi_k(l), phi_k'(l)], [0, phi_k(l)]] with phi_k' = phi_k - k phi_{k+1}.
  PhiFunctions functions;
  std::vector<Eigen::MatrixXd> phi(5);
  for (const double l : {-200.0, -3.0, 0.5}) {
    Eigen::Matrix2d z;
    z << l, 1, 0, l;
    functions.Compute(z, 4, phi);
    for (int k = 0; k < 4; ++k) {
      const double value = static_cast<double>(ScalarPhi(k, l));
      const double derivative = static_cast<double>(ScalarPhi(k, l) - k * ScalarPhi(k + 1, l));
      const auto& f = phi[static_cast<std::size_t>(k)];
      EXPECT_NEAR(f(0, 0), value, 1e-13 * std::abs(value)) << k << " " << l;
      EXPECT_NEAR(f(1, 1), value, 1e-13 * std::abs(value)) << k << " " << l;
      EXPECT_NEAR(f(0, 1), derivative, 1e-12 * std::abs(derivative) + 1e-300) << k << " " << l;
      EXPECT_EQ(f(1, 0), 0.0);
    }
  }
}

TEST(PhiFunctions, DefectiveTwoByTwoMatchesTheJordanClosedForm) {
  // A critically damped oscillator x'' = -c x' - k x with c^2 = 4k, times a step h: Z = h
  // [[-c, -k], [1, 0]] has the double eigenvalue l = -h c/2 and one eigenvector: Z = S J S^-1
  // with J = [[l, 1], [0, l]], so phi_k(theta Z) = S [[phi_k(theta l), theta phi_k'(theta l)],
  // [0, phi_k(theta l)]] S^-1 with phi_k' = phi_k - k phi_{k+1}. From a rate of 1e-3 to 1e4
  // (`step_1000g`'s steps have h c/2 = 4 to 100), and at thetas of the dense output.
  PhiFunctions functions;
  std::vector<Eigen::MatrixXd> phi(6), half(6), scaled(6);
  for (const double rate : {1e-3, 0.7, 4.1, 100.6, 1e4}) {
    for (const double theta : {1.0, 0.5, 0.37}) {
      // Z = [[2l, -l^2], [1, 0]] (h = 1, c = -2l); S's columns are the Jordan chain (l, 1),
      // (1, 0): Z S = S J.
      const double l = -rate;
      Eigen::Matrix2d z;
      z << 2.0 * l, -l * l, 1.0, 0.0;
      Eigen::Matrix2d chain;
      chain << l, 1.0, 1.0, 0.0;
      functions.Compute(z, 5, phi, half);
      EXPECT_TRUE(functions.closed_form());
      functions.ComputeScaled(theta, 5, scaled);
      const double tl = theta * l;
      for (int k = 0; k <= 4; ++k) {
        // phi_k(theta Z) = chain [[phi_k(tl), theta phi_k'(tl)], [0, phi_k(tl)]] chain^-1.
        const auto value = static_cast<double>(ScalarPhi(k, tl));
        const auto derivative = static_cast<double>(ScalarPhi(k, tl) - k * ScalarPhi(k + 1, tl));
        Eigen::Matrix2d jordan;
        jordan << value, theta * derivative, 0.0, value;
        const Eigen::Matrix2d exact = chain * jordan * chain.inverse();
        const auto& f = scaled[static_cast<std::size_t>(k)];
        EXPECT_LE((f.topLeftCorner(2, 2) - exact).norm(), 1e-13 * exact.norm())
            << "rate " << rate << " theta " << theta << " k " << k;
      }
    }
  }
}

TEST(PhiFunctions, NearlyDefectiveTwoByTwoMatchesTheReference) {
  // Damping a hair off critical (the split of the double eigenvalue, sqrt(c^2/4 - k), from 1e-8
  // of the rate up, both sides), a stiff decay beside a slow mode, and a random 2 x 2: against
  // the long double exponential of the augmented matrix. (The decay takes 15 squarings, each
  // adding a rounding: 6e-13 there, below 1e-13 elsewhere.)
  PhiFunctions functions;
  std::vector<Eigen::MatrixXd> phi(6), half(6);
  std::vector<Eigen::Matrix2d> cases;
  for (const double split : {0.0, 1e-16, -1e-16, 1e-8, -1e-8, 1e-3, -1e-3, 0.3}) {
    const double c = 10.0;
    Eigen::Matrix2d z;
    z << -c, -(c * c / 4.0) * (1.0 - split), 1.0, 0.0;
    cases.push_back(z);
  }
  Eigen::Matrix2d decay;
  decay << -1e4, 0.0, 3.0, -1e-3;
  cases.push_back(decay);
  Eigen::Matrix2d random;
  random << 0.3, -2.0, 1.7, -5.0;
  cases.push_back(random);
  for (std::size_t c = 0; c < cases.size(); ++c) {
    functions.Compute(cases[c], 5, phi, half);
    const auto reference = ReferencePhi(cases[c], 5);
    const auto reference_half = ReferencePhi(0.5 * cases[c], 5);
    for (std::size_t k = 0; k <= 5; ++k) {
      EXPECT_LT(RelativeDifference(phi[k].topLeftCorner(2, 2), reference[k]), 1e-12)
          << "case " << c << " k " << k;
      EXPECT_LT(RelativeDifference(half[k].topLeftCorner(2, 2), reference_half[k]), 1e-12)
          << "case " << c << " k " << k << " (half)";
    }
  }
}

TEST(PhiFunctions, CoincidingPairsAreBlockedInTheDecomposition) {
  // Z = S diag(J, D, d) S^-1: J a critically damped oscillator's Jordan block (double eigenvalue
  // l, one eigenvector), D a double eigenvalue with two eigenvectors, d two lone decays. The
  // eigenvectors of J and D are (nearly) parallel or arbitrary; the decomposition keeps both as
  // 2 x 2 blocks and stays on the spectral path, to the reference's accuracy.
  std::mt19937 random(3);
  std::normal_distribution<double> normal;
  PhiFunctions functions;
  std::vector<Eigen::MatrixXd> phi(6), half(6), scaled(6);
  for (const double rate : {0.8, 4.0, 60.0}) {
    Eigen::MatrixXd d = Eigen::MatrixXd::Zero(6, 6);
    const double l = -rate;
    d.block(0, 0, 2, 2) << 2.0 * l, -l * l, 1.0, 0.0;
    d(2, 2) = d(3, 3) = 0.05 * rate;
    d(4, 4) = -0.3 * rate;
    d(5, 5) = -2.5 * rate;
    Eigen::MatrixXd s(6, 6);
    for (Eigen::Index i = 0; i < s.size(); ++i) s.data()[i] = normal(random);
    s.diagonal().array() += 4.0;  // well-conditioned
    const Eigen::MatrixXd z = s * d * s.inverse();
    functions.Compute(z, 5, phi, half);
    EXPECT_TRUE(functions.spectral()) << rate;
    EXPECT_EQ(functions.decomposition().blocks(), 2) << rate;
    const auto reference = ReferencePhi(z, 5);
    const auto reference_half = ReferencePhi(0.5 * z, 5);
    for (std::size_t k = 0; k <= 5; ++k) {
      EXPECT_LT(RelativeDifference(phi[k].topLeftCorner(6, 6), reference[k]), 1e-11)
          << "rate " << rate << " k " << k;
      EXPECT_LT(RelativeDifference(half[k].topLeftCorner(6, 6), reference_half[k]), 1e-11)
          << "rate " << rate << " k " << k << " (half)";
    }
    for (const double theta : {0.9, 0.37}) {
      functions.ComputeScaled(theta, 5, scaled);
      const auto reference_theta = ReferencePhi(theta * z, 5);
      for (std::size_t k = 0; k <= 5; ++k) {
        EXPECT_LT(RelativeDifference(scaled[k].topLeftCorner(6, 6), reference_theta[k]), 1e-11)
            << "rate " << rate << " theta " << theta << " k " << k;
      }
    }
  }
}

TEST(PhiFunctions, MatchesEigensExponentialOfTheAugmentedMatrix) {
  std::mt19937 random(7);
  std::normal_distribution<double> normal;
  PhiFunctions functions;
  std::vector<Eigen::MatrixXd> phi(6), half(6);
  for (const int m : {1, 3, 8}) {
    for (const double scale : {0.01, 1.0, 40.0}) {
      Eigen::MatrixXd z(m, m);
      for (Eigen::Index i = 0; i < z.size(); ++i) z.data()[i] = scale * normal(random);
      // Shift the spectrum into the left half plane, as a stiff Jacobian's.
      z.diagonal().array() -= scale;
      functions.Compute(z, 5, phi, half);
      const auto reference = ReferencePhi(z, 5);
      const auto reference_half = ReferencePhi(0.5 * z, 5);
      for (std::size_t k = 0; k <= 5; ++k) {
        EXPECT_LT(RelativeDifference(phi[k], reference[k]), 1e-11)
            << "m " << m << " scale " << scale << " k " << k;
        EXPECT_LT(RelativeDifference(half[k], reference_half[k]), 1e-11)
            << "m " << m << " scale " << scale << " k " << k << " (half)";
      }
    }
  }
}

TEST(PhiFunctions, ScaledFunctionsMatchTheReferenceOnBothPaths) {
  // ComputeScaled gives phi_k(theta Z) for the last Compute's Z: from its eigen-decomposition
  // when Z is diagonalizable (random matrices), by squaring theta Z when it is not (a 4 x 4
  // Jordan block: the spectral path must refuse it), and a 2 x 2 Z (a damped oscillator's H,
  // a Jordan block) by the closed form of phi_two_by_two.h.
  std::mt19937 random(11);
  std::normal_distribution<double> normal;
  std::vector<Eigen::MatrixXd> cases;
  // Whether the spectral path must be taken (1), refused (0), or may be either (-1: a wide
  // random spectrum, where it depends on the eigenvectors' condition); 2: the 2 x 2 closed form.
  std::vector<int> spectral;
  Eigen::Matrix2d oscillator;
  oscillator << -1e4, -2.5e3, 1.0, 0.0;  // c/m = 1e4 1/s, k/m = 2.5e3 1/s^2, times h = 0.15 s
  cases.push_back(0.15 * oscillator);
  spectral.push_back(2);
  for (const int m : {3, 8, 20}) {
    const double scale = m == 20 ? 30.0 : 3.0;
    Eigen::MatrixXd z(m, m);
    for (Eigen::Index i = 0; i < z.size(); ++i) z.data()[i] = scale * normal(random);
    z.diagonal().array() -= 2.0 * scale;
    cases.push_back(z);
    spectral.push_back(m == 20 ? -1 : 1);
  }
  Eigen::Matrix2d jordan;
  jordan << -40.0, 1.0, 0.0, -40.0;
  cases.push_back(jordan);
  spectral.push_back(2);
  Eigen::Matrix4d jordan4 = Eigen::Matrix4d::Zero();
  jordan4.diagonal().setConstant(-40.0);
  jordan4.diagonal(1).setOnes();
  cases.push_back(jordan4);
  spectral.push_back(0);
  PhiFunctions functions;
  std::vector<Eigen::MatrixXd> phi(6), scaled(6);
  for (std::size_t c = 0; c < cases.size(); ++c) {
    const Eigen::MatrixXd& z = cases[c];
    functions.Compute(z, 5, phi);
    if (spectral[c] >= 0) {
      EXPECT_EQ(functions.spectral(), spectral[c] == 1) << "case " << c;
      EXPECT_EQ(functions.closed_form(), spectral[c] == 2) << "case " << c;
    }
    for (const double theta : {1.0, 0.37, 1e-3}) {
      functions.ComputeScaled(theta, 5, scaled);
      const auto reference = ReferencePhi(theta * z, 5);
      for (std::size_t k = 0; k <= 5; ++k) {
        EXPECT_LT(RelativeDifference(scaled[k].topLeftCorner(z.rows(), z.rows()), reference[k]),
                  1e-11)
            << "case " << c << " theta " << theta << " k " << k;
      }
    }
  }
}

// A = N + U V^T with N^2 = 0: a chain of three masses on stiff springs, positions x and
// velocities v (N: x' = v), the springs and dampers as rank-one terms.
StructuredJacobian ThreeMasses(double stiffness, double damping) {
  StructuredJacobian a;
  a.Reserve(6, 4);
  for (std::size_t i = 0; i < 3; ++i) a.nilpotent.push_back({i, i + 3, 1.0});
  const double masses[3] = {1.0, 0.5, 2.0};
  // Springs: ground-1, 1-2, 2-3; direction d in position space.
  const int pairs[3][2] = {{-1, 0}, {0, 1}, {1, 2}};
  for (const auto& pair : pairs) {
    Eigen::VectorXd d = Eigen::VectorXd::Zero(3);
    if (pair[0] >= 0) d[pair[0]] = -1.0;
    d[pair[1]] = 1.0;
    Eigen::VectorXd u = Eigen::VectorXd::Zero(6);
    Eigen::VectorXd v = Eigen::VectorXd::Zero(6);
    for (int i = 0; i < 3; ++i) u[3 + i] = d[i] / masses[i];  // M^-1 d
    v.head(3) = -stiffness * d;
    v.tail(3) = -damping * d;
    a.AddColumns(u, v);
  }
  return a;
}

TEST(StructuredPhi, ProductsMatchTheDenseFunctions) {
  StructuredPhi products;
  products.Reserve(6, 4);
  std::mt19937 random(3);
  std::normal_distribution<double> normal;
  for (const double stiffness : {10.0, 1e6}) {
    for (const double damping : {0.0, 50.0}) {
      StructuredJacobian a = ThreeMasses(stiffness, damping);
      ASSERT_TRUE(a.NilpotentByPattern());
      const double h = 0.01;
      products.Prepare(a, h);
      const Eigen::MatrixXd dense = a.Dense();
      Eigen::VectorXd b(6);
      for (auto& value : b) value = normal(random);
      for (const double fraction : {1.0, 0.5, 0.3}) {
        const auto reference = ReferencePhi(fraction * h * dense, 3);
        const auto which = fraction == 1.0   ? StructuredPhi::Fraction::kWhole
                           : fraction == 0.5 ? StructuredPhi::Fraction::kHalf
                                             : StructuredPhi::Fraction::kOther;
        if (which == StructuredPhi::Fraction::kOther) products.PrepareOther(fraction * h);
        for (int k = 0; k <= 3; ++k) {
          Eigen::VectorXd out = Eigen::VectorXd::Constant(6, 1.0);
          products.Accumulate(k, which, std::span<const double>(b.data(), 6), 2.0,
                              std::span<double>(out.data(), 6));
          const Eigen::VectorXd expected =
              Eigen::VectorXd::Constant(6, 1.0) + 2.0 * reference[static_cast<std::size_t>(k)] * b;
          EXPECT_LT((out - expected).norm(), 1e-10 * expected.norm())
              << "k " << k << " stiffness " << stiffness << " damping " << damping << " fraction "
              << fraction;
        }
      }
    }
  }
}

// The dense output's sum y0 + sum_k s_k phi_k(tau A) b_k at several tau of one step, on a step
// whose h H is decomposed (stiff springs: the eigenbasis path) and one whose is not (soft ones:
// the functions of tau H), with the b_k changed between two calls as a new step changes them.
// One mass on a spring per axis, as `step_1000g`'s rider: critically damped along x (k, c =
// 2 sqrt(k)), and the same weak overdamped spring along y and z (double eigenvalues with two
// eigenvectors each): H's eigen-decomposition keeps three 2 x 2 blocks.
StructuredJacobian CriticalSpring(double stiffness) {
  StructuredJacobian a;
  a.Reserve(6, 4);
  for (std::size_t i = 0; i < 3; ++i) a.nilpotent.push_back({i, i + 3, 1.0});
  for (int axis = 0; axis < 3; ++axis) {
    const double k = axis == 0 ? stiffness : 0.01 * stiffness;
    const double c = axis == 0 ? 2.0 * std::sqrt(stiffness) : 0.5 * std::sqrt(stiffness);
    Eigen::VectorXd u = Eigen::VectorXd::Zero(6);
    Eigen::VectorXd v = Eigen::VectorXd::Zero(6);
    u[3 + axis] = 1.0;
    v[axis] = -k;
    v[3 + axis] = -c;
    a.AddColumns(u, v);
  }
  return a;
}

TEST(StructuredPhi, DenseOutputMatchesTheDenseFunctionsOnBothPaths) {
  StructuredPhi products;
  products.Reserve(6, 4);
  std::mt19937 random(5);
  std::normal_distribution<double> normal;
  for (const double stiffness : {10.0, 1e6, -1e5}) {
    // -1e5: CriticalSpring(1e5), not ThreeMasses.
    StructuredJacobian a = stiffness > 0.0 ? ThreeMasses(stiffness, 50.0) : CriticalSpring(1e5);
    const double h = 0.01;
    products.Prepare(a, h);
    const Eigen::MatrixXd dense = a.Dense();
    for (int step = 0; step < 2; ++step) {
      std::vector<Eigen::VectorXd> b(3, Eigen::VectorXd(6));
      for (auto& vector : b) {
        for (auto& value : vector) value = normal(random);
      }
      Eigen::VectorXd y0(6);
      for (auto& value : y0) value = normal(random);
      products.ForgetDense();
      for (const double theta : {0.1, 0.37, 0.9}) {
        const double tau = theta * h;
        const auto reference = ReferencePhi(tau * dense, 3);
        const std::array<double, 3> scale = {tau, h * theta * theta, h * theta * theta * theta};
        Eigen::VectorXd expected = y0;
        for (std::size_t k = 1; k <= 3; ++k) expected += scale[k - 1] * reference[k] * b[k - 1];
        Eigen::VectorXd out(6);
        products.Dense(
            tau, std::span<const double>(y0.data(), 6),
            {std::span<const double>(b[0].data(), 6), std::span<const double>(b[1].data(), 6),
             std::span<const double>(b[2].data(), 6)},
            scale, std::span<double>(out.data(), 6));
        EXPECT_LT((out - expected).norm(), 1e-12 * expected.norm())
            << "stiffness " << stiffness << " step " << step << " theta " << theta;
      }
    }
  }
}

TEST(StructuredPhi, DenseJacobianWithoutNilpotentPart) {
  // N = 0, U = J, V = I: the products are those of J itself.
  StructuredJacobian a;
  a.Reserve(3, 3);
  Eigen::Matrix3d j;
  j << -100, 2, 0, 1, -3, 40, 0, -40, -1;
  for (int c = 0; c < 3; ++c) a.AddColumns(j.col(c), Eigen::Vector3d::Unit(c));
  StructuredPhi products;
  products.Reserve(3, 3);
  products.Prepare(a, 0.2);
  const auto reference = ReferencePhi(0.2 * j, 3);
  const Eigen::Vector3d b(1, -2, 0.5);
  for (int k = 0; k <= 3; ++k) {
    Eigen::Vector3d out = Eigen::Vector3d::Zero();
    products.Accumulate(k, StructuredPhi::Fraction::kWhole, std::span<const double>(b.data(), 3),
                        1.0, std::span<double>(out.data(), 3));
    EXPECT_LT((out - reference[static_cast<std::size_t>(k)] * b).norm(), 1e-12 * out.norm()) << k;
  }
}

TEST(StructuredShiftedSolver, SolvesTheShiftedSystem) {
  StructuredJacobian a = ThreeMasses(1e6, 50.0);
  StructuredShiftedSolver solver;
  solver.Reserve(6, 4);
  for (const double alpha : {1e4, 3.0}) {
    ASSERT_TRUE(solver.Factor(a, alpha));
    const Eigen::MatrixXd shifted = alpha * Eigen::MatrixXd::Identity(6, 6) - a.Dense();
    Eigen::VectorXd r(6);
    r << 1, -2, 3, 0.5, 7, -1;
    Eigen::VectorXd x(6);
    solver.Solve(std::span<const double>(r.data(), 6), std::span<double>(x.data(), 6));
    const Eigen::VectorXd reference = shifted.fullPivLu().solve(r);
    EXPECT_LT((x - reference).norm(), 1e-12 * reference.norm()) << alpha;
  }
}

}  // namespace
}  // namespace sled::runtime
