#include "runtime/integrate/structured_jacobian.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <stdexcept>

namespace sled::runtime {
namespace {

// The functions of H the products need: phi_{k+1} and phi_{k+2} for k <= kMaxOrder.
constexpr int kHighest = StructuredPhi::kMaxOrder + 2;

Eigen::Map<const Eigen::VectorXd> AsVector(std::span<const double> x) {
  return {x.data(), static_cast<Eigen::Index>(x.size())};
}
Eigen::Map<Eigen::VectorXd> AsVector(std::span<double> x) {
  return {x.data(), static_cast<Eigen::Index>(x.size())};
}

}  // namespace

void StructuredJacobian::Reserve(std::size_t n, std::size_t max_rank) {
  size_ = n;
  const auto rows = static_cast<Eigen::Index>(n);
  const auto cols = static_cast<Eigen::Index>(max_rank);
  u_store.setZero(rows, cols);
  v_store.setZero(rows, cols);
  nilpotent.reserve(2 * n);
  Clear();
}

void StructuredJacobian::Clear() {
  nilpotent.clear();
  rank_ = 0;
  stiff_rate = 0.0;
}

bool StructuredJacobian::AddColumns(const Eigen::Ref<const Eigen::VectorXd>& u,
                                    const Eigen::Ref<const Eigen::VectorXd>& v) {
  if (rank_ >= u_store.cols()) return false;
  u_store.col(rank_) = u;
  v_store.col(rank_) = v;
  ++rank_;
  return true;
}

void StructuredJacobian::ApplyNilpotent(std::span<const double> x, std::span<double> out) const {
  std::fill(out.begin(), out.end(), 0.0);
  for (const Entry& e : nilpotent) out[e.row] += e.value * x[e.col];
}

void StructuredJacobian::Apply(std::span<const double> x, std::span<double> out,
                               Eigen::VectorXd& scratch) const {
  ApplyNilpotent(x, out);
  if (rank_ == 0) return;
  if (scratch.size() < rank_) scratch.resize(u_store.cols());
  auto vtx = scratch.head(rank_);
  vtx.noalias() = v().transpose() * AsVector(x);
  AsVector(out).noalias() += u() * vtx;
}

Eigen::MatrixXd StructuredJacobian::Dense() const {
  const auto n = static_cast<Eigen::Index>(size_);
  Eigen::MatrixXd dense = u() * v().transpose();
  if (dense.rows() != n) dense.setZero(n, n);
  for (const Entry& e : nilpotent) {
    dense(static_cast<Eigen::Index>(e.row), static_cast<Eigen::Index>(e.col)) += e.value;
  }
  return dense;
}

bool StructuredJacobian::NilpotentByPattern() const {
  std::vector<char> is_row(size_, 0);
  for (const Entry& e : nilpotent) is_row[e.row] = 1;
  for (const Entry& e : nilpotent) {
    if (is_row[e.col]) return false;
  }
  return true;
}

void StructuredPhi::Reserve(std::size_t n, std::size_t max_rank) {
  const auto rows = static_cast<Eigen::Index>(n);
  const auto cols = static_cast<Eigen::Index>(2 * max_rank);
  basis_store_.setZero(rows, cols);
  h_matrix_.setZero(cols, cols);
  scaled_.setZero(cols, cols);
  const auto count = static_cast<std::size_t>(kHighest + 1);
  for (auto* set : {&whole_, &half_, &other_}) {
    set->assign(count, Eigen::MatrixXd::Zero(cols, cols));
  }
  functions_.Reserve(cols, kHighest);
  nb_.assign(n, 0.0);
  vtb_.setZero(static_cast<Eigen::Index>(max_rank));
  vtnb_.setZero(static_cast<Eigen::Index>(max_rank));
  small_.setZero(cols);
  coefficients_.setZero(cols);
  balance_.setOnes(cols);
  for (auto& nb : dense_nb_) nb.assign(n, 0.0);
  dense_ready_ = false;
  a_ = nullptr;
}

void StructuredPhi::Prepare(const StructuredJacobian& a, double h) {
  if (static_cast<Eigen::Index>(2 * a.rank()) > basis_store_.cols() ||
      static_cast<Eigen::Index>(a.size()) != basis_store_.rows()) {
    throw std::logic_error("StructuredPhi::Prepare: Reserve for this size and rank first");
  }
  a_ = &a;
  h_ = h;
  other_tau_ = 0.0;
  dense_ready_ = false;
  const Eigen::Index r = a.rank();
  has_nilpotent_ = !a.nilpotent.empty();
  basis_ = has_nilpotent_ ? 2 * r : r;
  auto basis = basis_store_.leftCols(basis_);
  basis.leftCols(r) = a.u();
  if (has_nilpotent_) {
    for (Eigen::Index j = 0; j < r; ++j) {
      const auto n = static_cast<std::size_t>(a.u_store.rows());
      a.ApplyNilpotent(std::span<const double>(a.u_store.col(j).data(), n),
                       std::span<double>(basis_store_.col(r + j).data(), n));
    }
  }
  auto hm = h_matrix_.topLeftCorner(basis_, basis_);
  hm.setZero();
  hm.topLeftCorner(r, r).noalias() = a.v().transpose() * a.u();
  if (has_nilpotent_) {
    hm.topRightCorner(r, r).noalias() = a.v().transpose() * basis_store_.middleCols(r, r);
    hm.bottomLeftCorner(r, r).setIdentity();
  }
  if (basis_ == 0) return;
  Balance();
  scaled_.topLeftCorner(basis_, basis_) = h * hm;
  functions_.Compute(scaled_.topLeftCorner(basis_, basis_), kHighest,
                     std::span<Eigen::MatrixXd>(whole_), std::span<Eigen::MatrixXd>(half_));
}

void StructuredPhi::Balance() {
  // Parlett & Reinsch's balancing by powers of two (exact): D^-1 H D with row and column norms
  // alike. A stiff spring makes H's blocks differ by k/m against 1; balanced, H's norm is about
  // its spectral radius, which saves squarings and keeps the phi-functions accurate. The basis
  // takes D (its columns scaled), the coordinates D^-1.
  auto hm = h_matrix_.topLeftCorner(basis_, basis_);
  auto d = balance_.head(basis_);
  d.setOnes();
  for (int sweep = 0; sweep < 20; ++sweep) {
    bool changed = false;
    for (Eigen::Index i = 0; i < basis_; ++i) {
      const double column = hm.col(i).cwiseAbs().sum() - std::abs(hm(i, i));
      const double row = hm.row(i).cwiseAbs().sum() - std::abs(hm(i, i));
      if (column == 0.0 || row == 0.0) continue;
      int exponent = 0;
      std::frexp(std::sqrt(row / column), &exponent);
      if (exponent == 0 || exponent == 1) continue;  // within a factor of two
      const double f = std::ldexp(1.0, exponent);
      hm.col(i) *= f;
      hm.row(i) /= f;
      d[i] *= f;
      changed = true;
    }
    if (!changed) break;
  }
  for (Eigen::Index i = 0; i < basis_; ++i) basis_store_.col(i) *= d[i];
}

void StructuredPhi::PrepareOther(double tau) const {
  if (a_ == nullptr) throw std::logic_error("StructuredPhi::PrepareOther before Prepare");
  other_tau_ = tau;
  if (basis_ == 0) return;
  // The functions of tau H = (tau / h) (h H), from the decomposition Prepare's Compute made of
  // h H when it had one (phi_functions.h): a dense output row costs no squarings.
  functions_.ComputeScaled(tau / h_, kHighest, std::span<Eigen::MatrixXd>(other_));
}

void StructuredPhi::Accumulate(int k, Fraction fraction, std::span<const double> b, double scale,
                               std::span<double> out) const {
  if (a_ == nullptr || k < 0 || k > kMaxOrder) {
    throw std::logic_error("StructuredPhi::Accumulate: Prepare first; 0 <= k <= kMaxOrder");
  }
  const double tau = fraction == Fraction::kWhole  ? h_
                     : fraction == Fraction::kHalf ? 0.5 * h_
                                                   : other_tau_;
  const std::vector<Eigen::MatrixXd>& functions = fraction == Fraction::kWhole  ? whole_
                                                  : fraction == Fraction::kHalf ? half_
                                                                                : other_;
  const StructuredJacobian& a = *a_;
  const Eigen::Index r = a.rank();
  auto out_vector = AsVector(out);
  const auto b_vector = AsVector(b);
  out_vector += (scale * InverseFactorial(k)) * b_vector;
  if (has_nilpotent_) {
    a.ApplyNilpotent(b, nb_);
    out_vector += (scale * tau * InverseFactorial(k + 1)) * AsVector(std::span<double>(nb_));
  }
  if (r == 0) return;
  // Coordinates in the balanced basis: D^-1 on the first r.
  const auto d = balance_.head(r);
  auto vtb = vtb_.head(r);
  vtb.noalias() = a.v().transpose() * b_vector;
  vtb.array() /= d.array();
  auto small = small_.head(basis_);
  const auto ku = static_cast<std::size_t>(k);
  small.noalias() = tau * functions[ku + 1].topLeftCorner(basis_, r).lazyProduct(vtb);
  if (has_nilpotent_) {
    auto vtnb = vtnb_.head(r);
    vtnb.noalias() = a.v().transpose() * AsVector(std::span<const double>(nb_));
    vtnb.array() /= d.array();
    small.noalias() += (tau * tau) * functions[ku + 2].topLeftCorner(basis_, r).lazyProduct(vtnb);
  }
  out_vector.noalias() += scale * (basis_store_.leftCols(basis_) * small);
}

void StructuredPhi::Dense(double tau, std::span<const double> y0, const DenseVectors& b,
                          const std::array<double, 3>& scale, std::span<double> out) const {
  if (a_ == nullptr) throw std::logic_error("StructuredPhi::Dense before Prepare");
  if (basis_ > 0 && functions_.spectral()) {
    DenseSpectral(tau, y0, b, scale, out);
    return;
  }
  PrepareOther(tau);
  std::copy(y0.begin(), y0.end(), out.begin());
  for (int k = 1; k <= 3; ++k) {
    const auto j = static_cast<std::size_t>(k - 1);
    Accumulate(k, Fraction::kOther, b[j], scale[j], out);
  }
}

void StructuredPhi::DenseSpectral(double tau, std::span<const double> y0, const DenseVectors& b,
                                  const std::array<double, 3>& scale, std::span<double> out) const {
  const StructuredJacobian& a = *a_;
  const SpectralPhi& spectral = functions_.decomposition();
  const Eigen::Index r = a.rank();
  const auto d = balance_.head(r);
  if (!dense_ready_) {
    // As Accumulate's coordinates, once per step: W^-1 [D^-1 V^T b; 0] and the same of N b.
    for (std::size_t j = 0; j < 3; ++j) {
      auto vtb = vtb_.head(r);
      vtb.noalias() = a.v().transpose() * AsVector(b[j]);
      vtb.array() /= d.array();
      spectral.ToEigenbasis(vtb, dense_vtb_[j]);
      if (has_nilpotent_) {
        a.ApplyNilpotent(b[j], dense_nb_[j]);
        auto vtnb = vtnb_.head(r);
        vtnb.noalias() = a.v().transpose() * AsVector(std::span<const double>(dense_nb_[j]));
        vtnb.array() /= d.array();
        spectral.ToEigenbasis(vtnb, dense_vtnb_[j]);
      }
    }
    dense_ready_ = true;
  }
  // The part outside the basis: b_k / k! + tau N b_k / (k+1)!.
  auto result = AsVector(out);
  result = AsVector(y0);
  for (std::size_t j = 0; j < 3; ++j) {
    const int k = static_cast<int>(j) + 1;
    result += (scale[j] * InverseFactorial(k)) * AsVector(b[j]);
    if (has_nilpotent_) {
      result += (scale[j] * tau * InverseFactorial(k + 1)) *
                AsVector(std::span<const double>(dense_nb_[j]));
    }
  }
  // The basis part: phi_j(tau H) = W diag(phi_j(theta lambda)) W^-1, theta = tau / h, applied
  // to the coordinates, summed in the eigenbasis and taken back once.
  const double theta = tau / h_;
  dense_coefficients_.setZero(spectral.size());
  spectral.PrepareFunctions(theta, kHighest);
  for (std::size_t j = 0; j < 3; ++j) {
    const int k = static_cast<int>(j) + 1;
    spectral.ApplyFunction(k + 1, scale[j] * tau, dense_vtb_[j], dense_coefficients_);
    if (has_nilpotent_) {
      spectral.ApplyFunction(k + 2, scale[j] * tau * tau, dense_vtnb_[j], dense_coefficients_);
    }
  }
  auto small = small_.head(basis_);
  spectral.FromEigenbasis(dense_coefficients_, small);
  result.noalias() += basis_store_.leftCols(basis_) * small;
}

void StructuredShiftedSolver::Reserve(std::size_t n, std::size_t max_rank) {
  const auto rows = static_cast<Eigen::Index>(n);
  const auto cols = static_cast<Eigen::Index>(max_rank);
  p_inverse_u_.setZero(rows, cols);
  s_matrix_.setZero(cols, cols);
  lu_ = Eigen::PartialPivLU<Eigen::MatrixXd>(cols);
  scratch_.assign(n, 0.0);
  nx_.assign(n, 0.0);
  small_.setZero(cols);
  solved_.setZero(cols);
  a_ = nullptr;
}

bool StructuredShiftedSolver::Factor(const StructuredJacobian& a, double alpha) {
  a_ = &a;
  alpha_ = alpha;
  const Eigen::Index r = a.rank();
  if (r == 0) return true;
  const auto n = a.size();
  // P^-1 U = (U + N U / alpha) / alpha.
  for (Eigen::Index j = 0; j < r; ++j) {
    a.ApplyNilpotent(std::span<const double>(a.u_store.col(j).data(), n), nx_);
    p_inverse_u_.col(j) = (a.u_store.col(j) + AsVector(std::span<double>(nx_)) / alpha) / alpha;
  }
  // S, padded with the identity to the full capacity so the factorization's storage never
  // changes size (and never allocates) as the rank does.
  s_matrix_.setIdentity();
  auto s = s_matrix_.topLeftCorner(r, r);
  s.noalias() -= a.v().transpose() * p_inverse_u_.leftCols(r);
  lu_.compute(s_matrix_);
  // Singular: a pivot that is rounding against the largest.
  const auto pivots = lu_.matrixLU().diagonal().head(r).cwiseAbs();
  const double largest = pivots.maxCoeff();
  return std::isfinite(largest) && pivots.minCoeff() > 1e-14 * largest;
}

void StructuredShiftedSolver::Solve(std::span<const double> r, std::span<double> x) const {
  const StructuredJacobian& a = *a_;
  const std::size_t n = a.size();
  // y = P^-1 r = (r + N r / alpha) / alpha.
  a.ApplyNilpotent(r, nx_);
  for (std::size_t i = 0; i < n; ++i) scratch_[i] = (r[i] + nx_[i] / alpha_) / alpha_;
  auto y = AsVector(std::span<double>(scratch_));
  auto out = AsVector(x);
  const Eigen::Index rank = a.rank();
  if (rank == 0) {
    out = y;
    return;
  }
  small_.setZero();
  small_.head(rank).noalias() = a.v().transpose() * y;
  solved_.noalias() = lu_.solve(small_);
  out = y;
  out.noalias() += p_inverse_u_.leftCols(rank) * solved_.head(rank);
}

}  // namespace sled::runtime
