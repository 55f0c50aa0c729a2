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
// Where the eigenvectors are ill-conditioned because two eigenvalues (nearly) coincide (a
// critically damped spring beside other modes: a 2 x 2 Jordan block), the decomposition keeps
// that pair as a 2 x 2 block B instead: its invariant subspace, the null space of
// (Z - l1 I)(Z - l2 I), is well-conditioned when the pair is apart from the other eigenvalues,
// and Z = W diag(l_i, B_j) W^-1 with phi_k(theta B_j) in closed form (phi_two_by_two.h). The
// closest pairs are blocked in turn until W is well-conditioned (a double eigenvalue with two
// eigenvectors, which the solver may give nearly parallel, is such a pair too: `step_1000g`'s
// spring has a critically damped axial pair and two equal transverse ones). A matrix whose
// eigenvectors are still ill-conditioned (a longer Jordan chain, a triple eigenvalue) is refused:
// Decompose returns false and the caller takes the squaring path, which needs no eigenvectors. The
// eigenvector matrix's reciprocal condition number rcond must exceed kMinReciprocalCondition, and
// ||Z||_1 / rcond stay below kMaxNormOverCondition: the eigenvalues are found to about eps ||Z|| /
// rcond, and a slow mode that neither decays nor grows over the step (|e^z| near 1) carries that
// error into the functions (a stiff mode of rate 2e5 over a step of 2 s beside one of rate 400
// takes the squaring path).
//
// Storage is fixed at kMaxSize (twice the structured Jacobian's largest rank): no allocation.
#pragma once

#include <Eigen/Core>
#include <Eigen/Eigenvalues>
#include <Eigen/QR>
#include <array>
#include <complex>
#include <span>

namespace sled::runtime {

class SpectralPhi {
 public:
  static constexpr int kMaxSize = 48;
  static constexpr int kMaxOrder = 8;
  static constexpr double kMinReciprocalCondition = 1e-4;
  static constexpr double kMaxNormOverCondition = 2e5;
  // A 2 x 2 block's subspace must be invariant to this, relative to ||Z||_1.
  static constexpr double kBlockResidual = 1e-12;

  // Decomposes Z (m x m, m <= kMaxSize, finite); false when it cannot be used (too large,
  // not diagonalizable to the condition above, not finite). The decomposition is kept for
  // Evaluate until the next call.
  bool Decompose(const Eigen::Ref<const Eigen::MatrixXd>& z);
  // Sizes the complex workspace for matrices up to capacity x capacity (Decompose grows it
  // when needed; after Reserve it never allocates).
  void Reserve(Eigen::Index capacity);
  bool valid() const { return valid_; }
  void Forget() { valid_ = false; }

  // phi_0(theta Z) ... phi_p(theta Z) into the top-left m x m corners of phi[0..p] (sized by
  // the caller to at least m x m). Requires valid() and 0 <= p <= kMaxOrder.
  void Evaluate(double theta, int p, std::span<Eigen::MatrixXd> phi) const;

  // phi_0(z) ... phi_p(z) of a complex scalar into out[0..p].
  static void Scalar(std::complex<double> z, int p, std::complex<double>* out);

  // The functions applied to vectors rather than formed as matrices (the exponential method's
  // dense output: three products per output row, where Evaluate costs (p + 1) m^3): the
  // coordinates W^-1 x of a vector (zero beyond x's size, which may be below m), the functions
  // of theta Z on coordinates (PrepareFunctions once per theta, then ApplyFunction: out +=
  // weight diag(phi_k(theta l_i), phi_k(theta B)) c), and Re(W c) of coordinates c. Require
  // valid().
  using ComplexVector = Eigen::Matrix<std::complex<double>, Eigen::Dynamic, 1, 0, kMaxSize, 1>;
  Eigen::Index size() const { return size_; }
  void ToEigenbasis(const Eigen::Ref<const Eigen::VectorXd>& x, ComplexVector& coordinates) const;
  void PrepareFunctions(double theta, int p) const;
  void ApplyFunction(int k, double weight, const ComplexVector& coordinates,
                     ComplexVector& out) const;
  void FromEigenbasis(const ComplexVector& coordinates, Eigen::Ref<Eigen::VectorXd> x) const;
  // How many (nearly) coinciding pairs of eigenvalues are kept as 2 x 2 blocks (for tests).
  int blocks() const { return block_count_; }

 private:
  using Real = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxSize, kMaxSize>;
  // Complex matrices of the reserved capacity, used in their top-left m x m: a fixed capacity of
  // kMaxSize would be 110 KB of std::complex, zeroed by its constructor at every run's start
  // (fresh pages: on `step_1000g` auto's run took 0.138 ms against dopri5's 0.090, callgrind
  // 5,000 more last-level write misses).
  using Complex = Eigen::MatrixXcd;

  // inverse_ = vectors_^-1 by Gauss-Jordan elimination with partial pivoting, in plain loops on
  // the top-left m x m (Eigen's LU and inverse made four zeroed temporaries of full capacity,
  // 36 KB each, per decomposition: 90 % of Decompose's instructions). False when singular.
  bool InvertVectors();
  // The reciprocal condition number of vectors_ in the 1-norm, from inverse_.
  double ReciprocalCondition() const;
  // Replaces the eigenvectors of the closest pair of eigenvalues not yet in a block (real, or a
  // conjugate pair) by an orthonormal basis of their invariant subspace and adds the block;
  // false when there is no such pair or the subspace is not invariant to rounding.
  bool BlockClosestPair();

  Eigen::EigenSolver<Real> solver_{kMaxSize};
  Eigen::ColPivHouseholderQR<Real> null_space_{kMaxSize, kMaxSize};  // BlockClosestPair's
  Real work_;
  Real input_;
  Complex vectors_, inverse_;
  mutable Complex scaled_;  // W diag(phi_k); InvertVectors' elimination
  ComplexVector values_;
  mutable Eigen::Matrix<std::complex<double>, kMaxOrder + 1, kMaxSize> functions_;
  Eigen::Index size_ = 0;
  bool valid_ = false;
  // The 2 x 2 blocks: the columns first and second of W span the subspace, and B = (W^-1 Z W)
  // on them. in_block_[i]: whether eigenvalue i is in one.
  struct Block {
    Eigen::Index first = 0, second = 0;
    Eigen::Matrix2d b;
    Eigen::Matrix2d functions[kMaxOrder + 1];  // of theta B, by PrepareFunctions
  };
  mutable std::array<Block, kMaxSize / 2> blocks_;
  std::array<bool, kMaxSize> in_block_{};
  int block_count_ = 0;
};

}  // namespace sled::runtime
