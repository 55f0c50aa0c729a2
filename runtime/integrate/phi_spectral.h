// The phi-functions of a small diagonalizable matrix from its eigen-decomposition Z = W L W^-1:
//
//   phi_k(theta Z) = Re(W diag(phi_k(theta lambda_i)) W^-1),
//
// the scalar functions of each eigenvalue by the recurrence from e^z when |z| is large, else by
// the series at z / 2^s and the modified squaring of phi_functions.h on the scalar. One
// decomposition serves every theta: the exponential method's dense output asks for the
// functions of tau H at every output row inside a step, and a step of 0.15 s over a decay of
// 1e4 1/s needed 12 squarings of products of the whole set of matrices per row (87 % of the
// instructions of `stiff_decay` went there).
//
// A matrix whose eigenvectors are ill-conditioned (a Jordan block: a critically damped
// oscillator, a rigid mode with no stiffness) is refused: Decompose returns false and the caller
// takes the squaring path, which needs no eigenvectors. The eigenvector matrix's reciprocal
// condition number rcond must exceed kMinReciprocalCondition, and ||Z||_1 / rcond stay below
// kMaxNormOverCondition: the eigenvalues are found to about eps ||Z|| / rcond, and a slow mode
// that neither decays nor grows over the step (|e^z| near 1) carries that error into the
// functions (a stiff mode of rate 2e5 over a step of 2 s beside one of rate 400 takes the
// squaring path).
//
// Storage is fixed at kMaxSize (twice the structured Jacobian's largest rank): no allocation.
#pragma once

#include <Eigen/Core>
#include <Eigen/Eigenvalues>
#include <complex>
#include <span>

namespace sled::runtime {

class SpectralPhi {
 public:
  static constexpr int kMaxSize = 48;
  static constexpr int kMaxOrder = 8;
  static constexpr double kMinReciprocalCondition = 1e-4;
  static constexpr double kMaxNormOverCondition = 2e5;

  // Decomposes Z (m x m, m <= kMaxSize, finite); false when it cannot be used (too large,
  // not diagonalizable to the condition above, not finite). The decomposition is kept for
  // Evaluate until the next call.
  bool Decompose(const Eigen::Ref<const Eigen::MatrixXd>& z);
  bool valid() const { return valid_; }
  void Forget() { valid_ = false; }

  // phi_0(theta Z) ... phi_p(theta Z) into the top-left m x m corners of phi[0..p] (sized by
  // the caller to at least m x m). Requires valid() and 0 <= p <= kMaxOrder.
  void Evaluate(double theta, int p, std::span<Eigen::MatrixXd> phi) const;

  // phi_0(z) ... phi_p(z) of a complex scalar into out[0..p].
  static void Scalar(std::complex<double> z, int p, std::complex<double>* out);

  // The functions applied to vectors rather than formed as matrices (the exponential method's
  // dense output: three products per output row, where Evaluate costs (p + 1) m^3): the
  // eigenvalues of Z, the coordinates W^-1 x of a vector (zero beyond x's size, which may be
  // below m), and Re(W c) of coordinates c. Require valid().
  using ComplexVector = Eigen::Matrix<std::complex<double>, Eigen::Dynamic, 1, 0, kMaxSize, 1>;
  Eigen::Index size() const { return size_; }
  const ComplexVector& eigenvalues() const { return values_; }
  void ToEigenbasis(const Eigen::Ref<const Eigen::VectorXd>& x, ComplexVector& coordinates) const;
  void FromEigenbasis(const ComplexVector& coordinates, Eigen::Ref<Eigen::VectorXd> x) const;

 private:
  using Real = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxSize, kMaxSize>;
  using Complex =
      Eigen::Matrix<std::complex<double>, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxSize, kMaxSize>;

  // inverse_ = vectors_^-1 by Gauss-Jordan elimination with partial pivoting, in plain loops on
  // the top-left m x m (Eigen's LU and inverse made four zeroed temporaries of full capacity,
  // 36 KB each, per decomposition: 90 % of Decompose's instructions). False when singular.
  bool InvertVectors();

  Eigen::EigenSolver<Real> solver_{kMaxSize};
  Real input_;
  Complex vectors_, inverse_;
  mutable Complex scaled_;  // W diag(phi_k); InvertVectors' elimination
  ComplexVector values_;
  mutable Eigen::Matrix<std::complex<double>, kMaxOrder + 1, kMaxSize> functions_;
  Eigen::Index size_ = 0;
  bool valid_ = false;
};

}  // namespace sled::runtime
