#include "runtime/integrate/phi_two_by_two.h"

#include <algorithm>
#include <cmath>

#include "runtime/integrate/phi_functions.h"

namespace sled::runtime {
namespace {

// As phi_functions.cpp: the series at a spectral radius of at most kScaledNorm, truncated where
// the next term falls below 1e-17 (PhiTaylorDegree); two more terms than the scalar series take,
// for b's factor j in (x^j)'s N part.
constexpr double kScaledNorm = 0.5;
constexpr int kMaxDegree = 30;

// a I + b N.
struct Element {
  double a = 0.0;
  double b = 0.0;
};

Element Multiply(const Element& x, const Element& y, double delta) {
  return {x.a * y.a + delta * x.b * y.b, x.a * y.b + x.b * y.a};
}

}  // namespace

void TwoByTwoPhi(const Eigen::Ref<const Eigen::MatrixXd>& z, double theta, int p,
                 std::span<Eigen::MatrixXd> phi) {
  Eigen::Matrix2d functions[PhiFunctions::kMaxOrder + 1];
  TwoByTwoPhi(Eigen::Matrix2d(z.topLeftCorner(2, 2)), theta, p, functions);
  for (int k = 0; k <= p; ++k) {
    phi[static_cast<std::size_t>(k)].topLeftCorner(2, 2) = functions[k];
  }
}

void TwoByTwoPhi(const Eigen::Matrix2d& z, double theta, int p, Eigen::Matrix2d* phi) {
  const double mu = 0.5 * (z(0, 0) + z(1, 1));
  const double half_difference = 0.5 * (z(0, 0) - z(1, 1));
  // N = Z - mu I = [[half_difference, z01], [z10, -half_difference]]: N^2 = delta I exactly.
  const double delta = half_difference * half_difference + z(0, 1) * z(1, 0);
  // The spectral radius of theta Z is at most |theta| (|mu| + sqrt|delta|).
  const double radius = std::abs(theta) * (std::abs(mu) + std::sqrt(std::abs(delta)));
  int s = 0;
  if (std::isfinite(radius) && radius > kScaledNorm) {
    s = static_cast<int>(std::ceil(std::log2(radius / kScaledNorm)));
  }
  const double scale = std::ldexp(theta, -s);
  const Element x{scale * mu, scale};  // theta Z / 2^s = scale mu I + scale N
  const double x_radius = std::ldexp(radius, -s);
  const int degree = std::min(PhiTaylorDegree(x_radius, p, kMaxDegree) + 2, kMaxDegree);

  Element out[PhiFunctions::kMaxOrder + 1];
  // phi_p(x) = sum_j x^j / (j + p)! by Horner, then phi_k = x phi_{k+1} + 1/k! downwards.
  Element top{InverseFactorial(degree + p), 0.0};
  for (int j = degree - 1; j >= 0; --j) {
    top = Multiply(x, top, delta);
    top.a += InverseFactorial(j + p);
  }
  out[p] = top;
  for (int k = p - 1; k >= 0; --k) {
    out[k] = Multiply(x, out[k + 1], delta);
    out[k].a += InverseFactorial(k);
  }
  // Modified squaring: phi_k(2x) = 2^-k [phi_0(x) phi_k(x) + sum_{j=1..k} phi_j(x) / (k-j)!].
  Element next[PhiFunctions::kMaxOrder + 1];
  for (int step = 0; step < s; ++step) {
    double half_power = 1.0;
    for (int k = 1; k <= p; ++k) {
      half_power *= 0.5;
      Element sum = Multiply(out[0], out[k], delta);
      for (int j = 1; j <= k; ++j) {
        sum.a += InverseFactorial(k - j) * out[j].a;
        sum.b += InverseFactorial(k - j) * out[j].b;
      }
      next[k] = {half_power * sum.a, half_power * sum.b};
    }
    next[0] = Multiply(out[0], out[0], delta);
    std::copy(next, next + p + 1, out);
  }
  for (int k = 0; k <= p; ++k) {
    Eigen::Matrix2d& f = phi[k];
    const Element& e = out[k];
    f(0, 0) = e.a + e.b * half_difference;
    f(0, 1) = e.b * z(0, 1);
    f(1, 0) = e.b * z(1, 0);
    f(1, 1) = e.a - e.b * half_difference;
  }
}

}  // namespace sled::runtime
