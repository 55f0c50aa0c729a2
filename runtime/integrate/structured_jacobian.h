// The Jacobian approximation the exponential and Rosenbrock methods work with:
//
//   A = N + U V^T,
//
// N sparse and nilpotent (N^2 = 0), U and V n x R with R small. For a multibody system N is the
// kinematics, q' = G(q) v, which maps velocities into position rates and nothing back; U V^T is
// the stiffness and damping of the force elements, each column of U the accelerations a unit
// load along one of their directions causes (M^-1 a) and each column of V how that load responds
// to the positions and velocities. The rest of the true Jacobian (gyroscopic and Coriolis terms,
// the change of lever arms with position) is left out: the methods that use A stay correct with
// any A (Rosenbrock-W and exponential Runge-Kutta methods, see rosenbrock.h and
// exponential_rk.h); A only has to hold the stiff part for them to take long steps.
//
// What this structure buys: the space span{b, N b} + span{U, N U} is invariant under A for any
// vector b (A b = N b + U (V^T b), A N b = U (V^T N b), A U = N U + U (V^T U),
// A N U = U (V^T N U)), so every phi-function of A applied to b is exact from the 2R x 2R matrix
//
//   H = [ V^T U   V^T N U ]     (A [U, N U] = [U, N U] H),
//       [ I       0       ]
//
//   phi_k(tau A) b = b/k! + tau N b / (k+1)! + [U, N U] (tau phi_{k+1}(tau H) [V^T b; 0]
//                                                      + tau^2 phi_{k+2}(tau H) [V^T N b; 0]),
//
// (from the power series: the lower-left block of the matrix in the basis [b, N b, U, N U] to the
// power j is H^(j-1) C + H^(j-2) C L with L^2 = 0). With N = 0 the basis is U alone, H = V^T U and
// the last term drops. And the shifted systems of a Rosenbrock method are solved by the
// Sherman-Morrison-Woodbury formula with (alpha I - N)^-1 = (I + N/alpha)/alpha:
// one R x R factorization per step size, O(n R) per solve.
#pragma once

#include <Eigen/Core>
#include <Eigen/LU>
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "runtime/integrate/phi_functions.h"

namespace sled::runtime {

struct StructuredJacobian {
  struct Entry {
    std::size_t row = 0;
    std::size_t col = 0;
    double value = 0.0;
  };

  // Sizes the low-rank part for n states and up to `max_rank` columns, and empties it. The only
  // call that allocates (except `nilpotent` growing past its capacity).
  void Reserve(std::size_t n, std::size_t max_rank);
  // Forgets the entries and columns; keeps the capacity.
  void Clear();  // (stiff_rate too)
  std::size_t size() const { return size_; }
  std::size_t max_rank() const { return static_cast<std::size_t>(u_store.cols()); }
  Eigen::Index rank() const { return rank_; }
  // Appends a column pair (u, v) to the low-rank part; false when it is full.
  bool AddColumns(const Eigen::Ref<const Eigen::VectorXd>& u,
                  const Eigen::Ref<const Eigen::VectorXd>& v);
  // The active columns.
  auto u() { return u_store.leftCols(rank_); }
  auto v() { return v_store.leftCols(rank_); }
  auto u() const { return u_store.leftCols(rank_); }
  auto v() const { return v_store.leftCols(rank_); }
  void set_rank(Eigen::Index rank) { rank_ = rank; }

  // out = N x (out may not alias x).
  void ApplyNilpotent(std::span<const double> x, std::span<double> out) const;
  // out = A x; `scratch` holds V^T x (sized max_rank() once, so no allocation).
  void Apply(std::span<const double> x, std::span<double> out, Eigen::VectorXd& scratch) const;
  // The dense n x n matrix (for tests).
  Eigen::MatrixXd Dense() const;
  // True when N^2 = 0 holds by pattern: no row of an entry is the column of another.
  bool NilpotentByPattern() const;

  // Writes or reads (a checkpoint, runtime/run/archive.h) the entries and columns; the reader must
  // have been Reserved for the same size and rank.
  template <class Archive>
  void Serialize(Archive& archive) {
    auto count = static_cast<std::int64_t>(nilpotent.size());
    archive.Field(count);
    if (archive.reading()) {
      if (!archive.ok() || count < 0 || count > static_cast<std::int64_t>(4 * size_ + 64)) {
        archive.Fail();
        return;
      }
      nilpotent.resize(static_cast<std::size_t>(count));
    }
    for (Entry& entry : nilpotent) archive.Field(entry);
    archive.Field(u_store);
    archive.Field(v_store);
    archive.Field(rank_);
    archive.Field(stiff_rate);
    if (archive.reading() && (rank_ < 0 || rank_ > u_store.cols())) archive.Fail();
  }

  std::vector<Entry> nilpotent;  // N's nonzeros
  // The largest rate [1/s] of the stiff part (of the terms kept and of those left out as too
  // soft for the step): an explicit method's stable step is about 3 / stiff_rate. Set by whoever
  // forms the Jacobian.
  double stiff_rate = 0.0;
  Eigen::MatrixXd u_store;  // n x max_rank; the first rank() columns are U
  Eigen::MatrixXd v_store;  // n x max_rank; the first rank() columns are V

 private:
  std::size_t size_ = 0;
  Eigen::Index rank_ = 0;
};

// phi_k(tau A) b for a StructuredJacobian A, at tau = h and tau = h/2 (the exponential
// integrator's stages) and at any other tau on request (its dense output).
class StructuredPhi {
 public:
  // The highest k of phi_k(tau A) b the products below may ask for.
  static constexpr int kMaxOrder = 3;

  // Sizes the workspace for n states and up to max_rank columns.
  void Reserve(std::size_t n, std::size_t max_rank);
  // Takes A (the basis [U, N U] and the small matrix H) and computes the functions of h H and
  // (h/2) H. Must be called again whenever A or h changes.
  void Prepare(const StructuredJacobian& a, double h);
  // Computes the functions of tau H for the products at Fraction::kOther (a dense output point).
  // Prepare first. Must not be called with a tau the products at kOther should not use.
  void PrepareOther(double tau) const;

  enum class Fraction { kWhole, kHalf, kOther };
  // out += scale * phi_k(tau A) b, 0 <= k <= kMaxOrder, tau = h, h/2 or the PrepareOther tau.
  // No allocation.
  void Accumulate(int k, Fraction fraction, std::span<const double> b, double scale,
                  std::span<double> out) const;

  // The dense output of an exponential method at tau (0 < tau < h):
  //   out = y0 + sum_{k=1..3} scale[k-1] phi_k(tau A) b[k-1].
  // When Prepare decomposed h H (phi_functions.h), the coordinates of the b_k in its eigenbasis
  // are found at the first call after ForgetDense or Prepare and serve every tau of the step: a
  // row then costs the scalar functions of the eigenvalues and O(n m), where forming the
  // functions of tau H cost (p + 1) m^3 (63 % of `stiff_decay`'s instructions, with 13 steps
  // and 200 rows). Otherwise the functions of tau H are formed (PrepareOther) and applied.
  using DenseVectors = std::array<std::span<const double>, 3>;
  void Dense(double tau, std::span<const double> y0, const DenseVectors& b,
             const std::array<double, 3>& scale, std::span<double> out) const;
  // The b_k of Dense are about to change (a new step with the same A and h).
  void ForgetDense() const { dense_ready_ = false; }

  double step() const { return h_; }

 private:
  // Balances H by a diagonal similarity, scaling the basis to match.
  void Balance();
  // Dense's path through the eigen-decomposition.
  void DenseSpectral(double tau, std::span<const double> y0, const DenseVectors& b,
                     const std::array<double, 3>& scale, std::span<double> out) const;

  const StructuredJacobian* a_ = nullptr;
  double h_ = 0.0;
  mutable double other_tau_ = 0.0;
  Eigen::Index basis_ = 0;  // columns of the basis: R (N = 0) or 2R
  bool has_nilpotent_ = false;
  Eigen::MatrixXd basis_store_;  // n x 2 max_rank: [U, N U]
  Eigen::MatrixXd h_matrix_;     // basis_ x basis_
  std::vector<Eigen::MatrixXd> whole_, half_;
  mutable std::vector<Eigen::MatrixXd> other_;
  mutable PhiFunctions functions_;
  mutable Eigen::MatrixXd scaled_;
  // Scratch for one product (no allocation in Accumulate).
  mutable std::vector<double> nb_;
  mutable Eigen::VectorXd vtb_, vtnb_, small_, coefficients_;
  Eigen::VectorXd balance_;  // D of the balancing
  // Dense's data for the step: N b_k and the eigenbasis coordinates of [V^T b_k; 0] and
  // [V^T N b_k; 0] (balanced), found once per step.
  mutable bool dense_ready_ = false;
  mutable std::array<std::vector<double>, 3> dense_nb_;
  mutable std::array<SpectralPhi::ComplexVector, 3> dense_vtb_, dense_vtnb_;
  mutable SpectralPhi::ComplexVector dense_coefficients_;
};

// Solves (alpha I - A) x = r for a StructuredJacobian A (a Rosenbrock method's stage systems,
// alpha = 1/(h gamma)), by Sherman-Morrison-Woodbury: with P = alpha I - N,
//   x = P^-1 r + P^-1 U S^-1 V^T P^-1 r,   S = I - V^T P^-1 U,   P^-1 = (I + N/alpha)/alpha.
class StructuredShiftedSolver {
 public:
  void Reserve(std::size_t n, std::size_t max_rank);
  // Factors S for this A and alpha; false when S is singular (alpha an eigenvalue of A).
  bool Factor(const StructuredJacobian& a, double alpha);
  // x = (alpha I - A)^-1 r (x may alias r). No allocation.
  void Solve(std::span<const double> r, std::span<double> x) const;

 private:
  const StructuredJacobian* a_ = nullptr;
  double alpha_ = 0.0;
  Eigen::MatrixXd p_inverse_u_;  // n x max_rank: P^-1 U
  Eigen::MatrixXd s_matrix_;
  Eigen::PartialPivLU<Eigen::MatrixXd> lu_;
  mutable std::vector<double> scratch_, nx_;
  mutable Eigen::VectorXd small_, solved_;
};

}  // namespace sled::runtime
