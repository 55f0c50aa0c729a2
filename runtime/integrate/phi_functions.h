// The phi-functions of exponential integrators, for small dense matrices:
//   phi_0(Z) = e^Z,   phi_k(Z) = sum_{j >= 0} Z^j / (j + k)!,   so Z phi_{k+1}(Z) = phi_k(Z) -
//   I/k!.
// (Hochbruck & Ostermann, "Exponential integrators", Acta Numerica 19 (2010) 209-286, §2.)
//
// Method: a Taylor polynomial of phi_p at X = Z / 2^s with ||X||_1 <= 1/2 (degree chosen from
// ||X|| so the truncation is below the unit roundoff), the lower functions by the recurrence
// phi_k(X) = X phi_{k+1}(X) + I/k! (stable at this norm), then s steps of the modified squaring
// of Skaflestad & Wright, "The scaling and modified squaring method for matrix functions related
// to the exponential", Appl. Numer. Math. 59 (2009) 783-799:
//   phi_0(2X) = phi_0(X)^2,   phi_k(2X) = 2^-k [phi_0(X) phi_k(X) + sum_{j=1..k} phi_j(X)/(k-j)!].
// The last squaring starts from the functions of Z/2, which the exponential integrator's half
// steps need, so they come free.
//
// The matrices are small (the stiff subspace of a structured Jacobian, structured_jacobian.h):
// the cost is (d + p + s (p + 1)) products of m x m matrices. A diagonalizable Z with
// well-conditioned eigenvectors takes a cheaper path instead (phi_spectral.h): the scalar
// functions of its eigenvalues, (p + 1) complex products of m x m matrices whatever ||Z||, and
// ComputeScaled gives the functions of theta Z for any theta from the same decomposition. A
// 2 x 2 Z (one stiff term with its rate) takes neither: its functions have a closed form in
// the two scalars of a I + b (Z - mu I), defective or not (phi_two_by_two.h).
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <span>
#include <stdexcept>
#include <vector>

#include "runtime/integrate/phi_spectral.h"

namespace sled::runtime {

class PhiFunctions {
 public:
  // The highest order this class computes (the exponential integrator needs up to 5).
  static constexpr int kMaxOrder = 8;

  // Writes phi_0(Z) ... phi_p(Z) into the top-left m x m corners of phi[0..p] (Z is m x m), and
  // phi_0(Z/2) ... phi_p(Z/2) into those of half[0..p] when `half` is not empty. An output
  // smaller than m x m is resized to m x m; larger ones keep their size, so a caller that sizes
  // its outputs for the largest Z once never allocates here (nor does the workspace, which grows
  // the same way). All outputs of one call must have the same size. Requires
  // 0 <= p <= kMaxOrder, phi.size() > p, and a finite Z (NaN or infinite entries give NaN).
  void Compute(const Eigen::Ref<const Eigen::MatrixXd>& z, int p, std::span<Eigen::MatrixXd> phi,
               std::span<Eigen::MatrixXd> half = {});

  // phi_0(theta Z) ... phi_p(theta Z) for the Z of the last Compute, into phi[0..p] as Compute
  // writes them (the exponential method's dense output: tau = theta h). From that Compute's
  // eigen-decomposition when it had one, else by scaling and squaring theta Z.
  void ComputeScaled(double theta, int p, std::span<Eigen::MatrixXd> phi);

  // Sizes the workspace for matrices up to `capacity` x `capacity` and orders up to p, so no
  // later Compute allocates (Compute also grows it when needed).
  void Reserve(Eigen::Index capacity, int p);

  // The number of squarings of the last Compute (for tests and statistics; 0 on the spectral
  // path).
  int squarings() const { return squarings_; }
  // Whether the last Compute took the 2 x 2 closed form (phi_two_by_two.h).
  bool closed_form() const { return base_size_ == 2; }
  // Whether the last Compute took the spectral path.
  bool spectral() const { return spectral_.valid(); }
  // That path's eigen-decomposition of Z (valid only when spectral()).
  const SpectralPhi& decomposition() const { return spectral_; }

 private:
  // The Taylor polynomial and modified squaring (the path for any Z).
  void ComputeBySquaring(const Eigen::Ref<const Eigen::MatrixXd>& z, int p,
                         std::span<Eigen::MatrixXd> phi, std::span<Eigen::MatrixXd> half);
  // Checks the arguments and sizes the outputs for an m x m Z.
  static void SizeOutputs(Eigen::Index m, int p, std::span<Eigen::MatrixXd> phi,
                          std::span<Eigen::MatrixXd> half);

  SpectralPhi spectral_;
  Eigen::MatrixXd base_;  // the Z of the last Compute (top-left base_size_ x base_size_)
  Eigen::Index base_size_ = 0;
  double base_norm_ = 0.0;             // its 1-norm
  Eigen::MatrixXd theta_z_;            // theta Z for ComputeScaled without a decomposition
  std::vector<Eigen::MatrixXd> next_;  // the functions of the doubled argument, per squaring
  Eigen::MatrixXd scaled_;             // X = Z / 2^s
  Eigen::MatrixXd product_;
  int squarings_ = 0;
};

namespace detail {
// 1/k! for k = 0..40, from long double products, so within a rounding of the exact value.
inline constexpr std::array<double, 41> kInverseFactorials = [] {
  std::array<double, 41> values{};
  long double inverse = 1.0L;
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (i > 0) inverse /= static_cast<long double>(i);
    values[i] = static_cast<double>(inverse);
  }
  return values;
}();
}  // namespace detail

// The degree d at which the Taylor series of phi_p, at a scaled norm or spectral radius x_norm,
// is truncated: the first d whose next term, x_norm^(d+1) / (d+1+p)!, is below 1e-17 of the
// leading 1/p!, and at most max_degree.
int PhiTaylorDegree(double x_norm, int p, int max_degree);

// 1/k! for k = 0..40. Inline: the scalar phi-functions of a dense output row call it in their
// inner loops.
inline double InverseFactorial(int k) {
  if (k < 0 || k > 40) throw std::out_of_range("InverseFactorial: k must be in [0, 40]");
  return detail::kInverseFactorials[static_cast<std::size_t>(k)];
}

}  // namespace sled::runtime
