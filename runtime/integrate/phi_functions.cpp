#include "runtime/integrate/phi_functions.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "runtime/integrate/phi_two_by_two.h"

namespace sled::runtime {
namespace {

// ||X||_1 at or below this after scaling: the Taylor degree stays near 14 and the recurrence for
// the lower functions contracts.
constexpr double kScaledNorm = 0.5;

// The Taylor series of phi_p(X) is truncated where the next term, ||X||^(d+1) / (d+1+p)!, is
// below this (relative to the leading I/p!, which is at most 1).
constexpr double kTruncation = 1e-17;

// The spectral path (phi_spectral.h) costs an eigen-decomposition (some 25 m^3 operations) and
// about 4 (p + 1) m^3 per set of functions; the squaring path (d + p + s (p + 1)) m^3 with
// s = log2(||Z|| / kScaledNorm) squarings. Compute decomposes Z beyond kSpectralNorm (where the
// squaring path squares at all), ComputeScaled uses the decomposition beyond
// kSpectralScaledNorm. The exponential method's dense output applies the decomposition to its
// three vectors (StructuredPhi::Dense) and forms the functions of tau H only without one: on
// the flagship at 1e-3 with the threshold at 8, auto's exponential stints spent 25 % of the
// run's instructions on the functions of tau H of undecomposed steps; at 0.5 the run takes 5 %
// fewer instructions (2.54e9 against 2.67e9, callgrind).
constexpr double kSpectralNorm = 0.5;
constexpr double kSpectralScaledNorm = 2.0;

// Below this size the products are coefficient loops (lazyProduct): Eigen's blocked product
// costs more than the arithmetic for the 2 x 2 to 16 x 16 matrices of a few stiff terms.
constexpr Eigen::Index kSmall = 4;

template <class Out, class A, class B>
void Multiply(Out&& out, const A& a, const B& b) {
  if (a.rows() <= kSmall) {
    out.noalias() = a.lazyProduct(b);
  } else {
    out.noalias() = a * b;
  }
}

double OneNorm(const Eigen::Ref<const Eigen::MatrixXd>& z) {
  double norm = 0.0;
  for (Eigen::Index j = 0; j < z.cols(); ++j) norm = std::max(norm, z.col(j).cwiseAbs().sum());
  return norm;
}

}  // namespace

void PhiFunctions::Reserve(Eigen::Index capacity, int p) {
  const auto count = static_cast<std::size_t>(p) + 1;
  if (next_.size() < count) next_.resize(count);
  for (std::size_t k = 0; k < count; ++k) {
    if (next_[k].rows() != capacity) next_[k].resize(capacity, capacity);
  }
  if (scaled_.rows() < capacity) {
    scaled_.resize(capacity, capacity);
    product_.resize(capacity, capacity);
  }
  if (base_.rows() < capacity) {
    base_.resize(capacity, capacity);
    theta_z_.resize(capacity, capacity);
  }
  spectral_.Reserve(capacity);
}

void PhiFunctions::SizeOutputs(Eigen::Index m, int p, std::span<Eigen::MatrixXd> phi,
                               std::span<Eigen::MatrixXd> half) {
  if (p < 0 || p > kMaxOrder || phi.size() <= static_cast<std::size_t>(p) ||
      (!half.empty() && half.size() <= static_cast<std::size_t>(p))) {
    throw std::invalid_argument(
        "PhiFunctions::Compute: needs a square Z, 0 <= p <= kMaxOrder "
        "and p + 1 outputs");
  }
  const auto order = static_cast<std::size_t>(p);
  if (phi[0].rows() < m || phi[0].cols() != phi[0].rows()) phi[0].resize(m, m);
  const Eigen::Index capacity = phi[0].rows();
  for (std::size_t k = 0; k <= order; ++k) {
    if (phi[k].rows() != capacity || phi[k].cols() != capacity) phi[k].resize(capacity, capacity);
    if (!half.empty() && (half[k].rows() < m || half[k].cols() < m)) half[k].resize(m, m);
  }
}

void PhiFunctions::Compute(const Eigen::Ref<const Eigen::MatrixXd>& z, int p,
                           std::span<Eigen::MatrixXd> phi, std::span<Eigen::MatrixXd> half) {
  if (z.rows() != z.cols()) {
    throw std::invalid_argument("PhiFunctions::Compute: needs a square Z");
  }
  const Eigen::Index m = z.rows();
  SizeOutputs(m, p, phi, half);
  if (base_.rows() < m) base_.resize(phi[0].rows(), phi[0].rows());
  base_.topLeftCorner(m, m) = z;
  base_size_ = m;
  squarings_ = 0;
  if (m == 0) return;
  base_norm_ = OneNorm(z);
  spectral_.Forget();
  if (m == 2) {
    TwoByTwoPhi(z, 1.0, p, phi);
    if (!half.empty()) TwoByTwoPhi(z, 0.5, p, half);
    return;
  }
  if (base_norm_ > kSpectralNorm && spectral_.Decompose(z)) {
    spectral_.Evaluate(1.0, p, phi);
    if (!half.empty()) spectral_.Evaluate(0.5, p, half);
    return;
  }
  ComputeBySquaring(z, p, phi, half);
}

void PhiFunctions::ComputeScaled(double theta, int p, std::span<Eigen::MatrixXd> phi) {
  const Eigen::Index m = base_size_;
  SizeOutputs(m, p, phi, {});
  if (m == 0) return;
  if (m == 2) {
    TwoByTwoPhi(base_.topLeftCorner(2, 2), theta, p, phi);
    return;
  }
  if (spectral_.valid() && theta * base_norm_ > kSpectralScaledNorm) {
    spectral_.Evaluate(theta, p, phi);
    return;
  }
  if (theta_z_.rows() < m) theta_z_.resize(base_.rows(), base_.rows());
  theta_z_.topLeftCorner(m, m) = theta * base_.topLeftCorner(m, m);
  ComputeBySquaring(theta_z_.topLeftCorner(m, m), p, phi, {});
}

void PhiFunctions::ComputeBySquaring(const Eigen::Ref<const Eigen::MatrixXd>& z, int p,
                                     std::span<Eigen::MatrixXd> phi,
                                     std::span<Eigen::MatrixXd> half) {
  const Eigen::Index m = z.rows();
  const auto order = static_cast<std::size_t>(p);
  const Eigen::Index capacity = phi[0].rows();
  Reserve(capacity, p);
  auto corner = [m](Eigen::MatrixXd& matrix) { return matrix.topLeftCorner(m, m); };

  // Scaling: the functions of Z/2 are the state before the last squaring, so ask for at least
  // one when they are wanted.
  const double norm = OneNorm(z);
  int s = 0;
  if (std::isfinite(norm) && norm > kScaledNorm) {
    s = static_cast<int>(std::ceil(std::log2(norm / kScaledNorm)));
  }
  if (!half.empty()) s = std::max(s, 1);
  squarings_ = s;
  auto x = corner(scaled_);
  x = std::ldexp(1.0, -s) * z;
  const double x_norm = std::ldexp(norm, -s);

  const int degree = PhiTaylorDegree(x_norm, p, 39 - p);

  // Horner for phi_p(X) = sum_{j=0..d} X^j / (j+p)!.
  auto top = corner(phi[order]);
  auto product = corner(product_);
  top.setIdentity();
  top *= InverseFactorial(degree + p);
  for (int j = degree - 1; j >= 0; --j) {
    Multiply(product, x, top);
    top = product;
    top.diagonal().array() += InverseFactorial(j + p);
  }
  // phi_k = X phi_{k+1} + I/k!, downwards.
  for (int k = p - 1; k >= 0; --k) {
    const auto i = static_cast<std::size_t>(k);
    auto lower = corner(phi[i]);
    Multiply(lower, x, corner(phi[i + 1]));
    lower.diagonal().array() += InverseFactorial(k);
  }

  // Modified squaring.
  for (int step = 0; step < s; ++step) {
    if (step == s - 1 && !half.empty()) {
      for (std::size_t k = 0; k <= order; ++k) corner(half[k]) = corner(phi[k]);
    }
    for (std::size_t k = 1; k <= order; ++k) {
      auto next = corner(next_[k]);
      Multiply(next, corner(phi[0]), corner(phi[k]));
      for (std::size_t j = 1; j <= k; ++j) {
        next += InverseFactorial(static_cast<int>(k - j)) * corner(phi[j]);
      }
      next *= std::ldexp(1.0, -static_cast<int>(k));
    }
    Multiply(corner(next_[0]), corner(phi[0]), corner(phi[0]));
    // Same-size matrices: swapping exchanges their storage, never allocates.
    for (std::size_t k = 0; k <= order; ++k) phi[k].swap(next_[k]);
  }
}

int PhiTaylorDegree(double x_norm, int p, int max_degree) {
  int degree = 0;
  double term = 1.0;  // x_norm^(d+1) / (d+1+p)! * p!, built up
  for (; degree < max_degree; ++degree) {
    term *= x_norm / static_cast<double>(degree + 1 + p);
    if (term < kTruncation) break;
  }
  return degree;
}

}  // namespace sled::runtime
