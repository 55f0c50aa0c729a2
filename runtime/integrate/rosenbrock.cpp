#include "runtime/integrate/rosenbrock.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "runtime/integrate/error_norm.h"
#include "runtime/run/archive.h"

namespace sled::runtime {
namespace {

constexpr int kS = Rosenbrock::kStages;
using Square = std::array<std::array<double, kS>, kS>;
using Row = std::array<double, kS>;

// ROS34PW2 as published (see rosenbrock.h): alpha (strictly lower), Gamma (lower, gamma on the
// diagonal), b and bhat.
constexpr double kGamma = 4.3586652150845900e-01;
constexpr Square kAlpha = {{{0.0, 0.0, 0.0, 0.0},
                            {8.7173304301691801e-01, 0.0, 0.0, 0.0},
                            {8.4457060015369423e-01, -1.1299064236484185e-01, 0.0, 0.0},
                            {0.0, 0.0, 1.0, 0.0}}};
constexpr Square kGammaMatrix = {
    {{kGamma, 0.0, 0.0, 0.0},
     {-8.7173304301691801e-01, kGamma, 0.0, 0.0},
     {-9.0338057013044082e-01, 5.4180672388095326e-02, kGamma, 0.0},
     {2.4212380706095346e-01, -1.2232505839045147e+00, 5.4526025533510214e-01, kGamma}}};
constexpr Row kB = {2.4212380706095346e-01, -1.2232505839045147e+00, 1.5452602553351020e+00,
                    kGamma};
constexpr Row kBHat = {3.7810903145819369e-01, -9.6042292212423178e-02, 5.0e-01,
                       2.1793326075422950e-01};

// The W-free form (Hairer & Wanner II, (7.4)-(7.6)): with u = Gamma k,
//   (1/(h gamma) I - W) u_i = f(t + alpha_i h, y0 + sum_j a_ij u_j) + sum_j (c_ij / h) u_j
//                             + gamma_i h f_t,
//   y1 = y0 + sum_j m_j u_j,  error = sum_j e_j u_j,
// where a = alpha Gamma^-1, c = -Gamma^-1 below the diagonal, m = b Gamma^-1,
// e = (b - bhat) Gamma^-1, alpha_i = sum_j alpha_ij and gamma_i = sum_j gamma_ij.
struct Tableau {
  Square a{};
  Square c{};
  Row m{};
  Row e{};
  Row alpha_sum{};
  Row gamma_sum{};
};

constexpr Tableau MakeTableau() {
  // Gamma^-1 by forward substitution (Gamma is lower triangular).
  Square inverse{};
  for (int col = 0; col < kS; ++col) {
    for (int row = 0; row < kS; ++row) {
      double value = row == col ? 1.0 : 0.0;
      for (int k = 0; k < row; ++k) value -= kGammaMatrix[row][k] * inverse[k][col];
      inverse[row][col] = value / kGammaMatrix[row][row];
    }
  }
  Tableau t;
  for (int i = 0; i < kS; ++i) {
    for (int j = 0; j < kS; ++j) {
      double a = 0.0;
      for (int k = 0; k < kS; ++k) a += kAlpha[i][k] * inverse[k][j];
      t.a[i][j] = j < i ? a : 0.0;
      t.c[i][j] = j < i ? -inverse[i][j] : 0.0;
      t.alpha_sum[i] += kAlpha[i][j];
      t.gamma_sum[i] += kGammaMatrix[i][j];
      t.m[j] += kB[i] * inverse[i][j];
      t.e[j] += (kB[i] - kBHat[i]) * inverse[i][j];
    }
  }
  return t;
}

constexpr Tableau kTableau = MakeTableau();

}  // namespace

void Rosenbrock::ResizeWorkspace(std::size_t size) {
  const auto n = static_cast<Eigen::Index>(size);
  source_.Reserve(system());
  solver_.Reserve(size, source_.jacobian().max_rank());
  time_derivative_.setZero(n);
  for (auto& u : u_) u.setZero(n);
  rhs_.setZero(n);
  stage_.setZero(n);
  f_stage_.setZero(n);
  error_.setZero(n);
  quadratures_ = std::min(system().ControlledSize(), size);
  RestartHistory();
}

void Rosenbrock::RestartHistory() {
  source_.Forget();
  factored_step_ = 0.0;
  time_derivative_age_ = kMaxJacobianAge;  // none
}

JacobianSource::Status Rosenbrock::FormJacobian(double h) {
  const std::size_t n = y_.size();
  const auto ni = static_cast<Eigen::Index>(n);
  const JacobianSource::Status status =
      source_.Form(system(), t_, y_, f0_, h, options(), mutable_stats());
  factored_step_ = 0.0;  // the factorization belongs to the old Jacobian
  if (status != JacobianSource::Status::kOk) return status;
  // The system's own A costs no evaluation: only f_t (one) waits for the reuse rule.
  if (time_derivative_age_ < kMaxJacobianAge) return status;

  // f_t by a forward difference in time; a W-method stays third order with any f_t, so if the
  // system cannot be evaluated there we go on without it.
  const double sqrt_eps = std::sqrt(std::numeric_limits<double>::epsilon());
  const double dt = sqrt_eps * std::max(std::abs(t_), h);
  if (Evaluate(t_ + dt, y_, std::span<double>(f_stage_.data(), n)) && f_stage_.allFinite()) {
    for (Eigen::Index i = 0; i < ni; ++i) {
      time_derivative_(i) = (f_stage_(i) - f0_[static_cast<std::size_t>(i)]) / dt;
    }
  } else {
    time_derivative_.setZero();
  }
  if (!time_derivative_.allFinite()) {
    source_.Forget();
    return JacobianSource::Status::kNotFinite;
  }
  time_derivative_age_ = 0;
  return JacobianSource::Status::kOk;
}

bool Rosenbrock::Factor(double h) {
  factored_step_ = 0.0;
  if (!solver_.Factor(source_.jacobian(), 1.0 / (h * kGamma))) return false;
  factored_step_ = h;
  return true;
}

void Rosenbrock::SerializeHistory(Archive& archive) {
  source_.Serialize(archive);
  archive.Field(time_derivative_);
  archive.Field(time_derivative_age_);
  archive.Field(factored_step_);
  // The factorization follows from the Jacobian and the step: the same one, made again.
  if (archive.reading() && archive.ok() && factored_step_ != 0.0) Factor(factored_step_);
}

bool Rosenbrock::TryStep(double h, double* error) {
  const std::size_t n = y_.size();
  // A retry from the same point keeps the Jacobian formed there.
  // The system's own A with stiff terms costs no evaluation: formed at every step (a stale one
  // misses a stiff element that turns, such as a tether on a swinging ball: 1.3e-3 off at 1e-6
  // with A up to 20 steps old, 5e-5 with a fresh one). f_t, one evaluation, a difference A, n of
  // them, and a kinematic one (no stiff terms: the 60-link chain) are reused.
  // (From what a checkpoint restores: the system's rank and the Jacobian in hand.)
  const bool stiff_terms =
      system().StructuredRank() > 0 && source_.valid() && source_.jacobian().rank() > 0;
  const long max_age = stiff_terms ? 1 : kMaxJacobianAge;
  if (source_.MustForm(h, max_age, kJacobianGrowth, true) ||
      time_derivative_age_ >= kMaxJacobianAge) {
    switch (FormJacobian(h)) {
      case JacobianSource::Status::kOk:
        break;
      case JacobianSource::Status::kEvaluationFailed:
        return false;
      case JacobianSource::Status::kNotFinite:
        // The state is beyond where the system can be differentiated: report it as not finite.
        std::fill(y1_.begin(), y1_.end(), std::numeric_limits<double>::quiet_NaN());
        *error = std::numeric_limits<double>::quiet_NaN();
        return true;
    }
  }
  if (factored_step_ != h) {
    ++mutable_stats().factorizations;
    if (!Factor(h)) return false;
  }

  const Eigen::Map<const Eigen::VectorXd> y0(y_.data(), static_cast<Eigen::Index>(n));
  const Eigen::Map<const Eigen::VectorXd> f0(f0_.data(), static_cast<Eigen::Index>(n));
  for (int i = 0; i < kS; ++i) {
    if (i == 0) {
      rhs_ = f0;
    } else {
      stage_ = y0;
      for (int j = 0; j < i; ++j) {
        if (kTableau.a[i][j] != 0.0) stage_ += kTableau.a[i][j] * u_[j];
      }
      if (!Evaluate(t_ + kTableau.alpha_sum[i] * h, std::span<const double>(stage_.data(), n),
                    std::span<double>(f_stage_.data(), n))) {
        return false;
      }
      rhs_ = f_stage_;
      for (int j = 0; j < i; ++j) rhs_ += (kTableau.c[i][j] / h) * u_[j];
    }
    if (kTableau.gamma_sum[i] != 0.0) rhs_ += (kTableau.gamma_sum[i] * h) * time_derivative_;
    solver_.Solve(std::span<const double>(rhs_.data(), n), std::span<double>(u_[i].data(), n));
  }

  Eigen::Map<Eigen::VectorXd> y1(y1_.data(), static_cast<Eigen::Index>(n));
  y1 = y0;
  error_.setZero();
  for (int j = 0; j < kS; ++j) {
    y1 += kTableau.m[j] * u_[j];
    error_ += kTableau.e[j] * u_[j];
  }
  if (quadratures_ < n && !IntegrateQuadratures(h)) return false;
  *error = ErrorNorm(std::span<const double>(error_.data(), n));
  return true;
}

bool Rosenbrock::IntegrateQuadratures(double h) {
  const std::size_t n = y_.size();
  if (!Evaluate(t_ + h, y1_, f1_)) return false;
  // Rates of zero at both ends: nothing does work here (free flight; an element's contact
  // begins and ends at events), and the midpoint's evaluation would add zero.
  bool working = false;
  for (std::size_t i = quadratures_; i < n; ++i)
    working = working || f0_[i] != 0.0 || f1_[i] != 0.0;
  if (!working) {
    for (std::size_t i = quadratures_; i < n; ++i) {
      y1_[i] = y_[i];
      error_(static_cast<Eigen::Index>(i)) = 0.0;
    }
    return true;
  }
  // The midpoint of the step's cubic Hermite interpolant (its dense output), of stage order 3.
  for (std::size_t i = 0; i < n; ++i) {
    stage_(static_cast<Eigen::Index>(i)) = 0.5 * (y_[i] + y1_[i]) + 0.125 * h * (f0_[i] - f1_[i]);
  }
  if (!Evaluate(t_ + 0.5 * h, std::span<const double>(stage_.data(), n),
                std::span<double>(f_stage_.data(), n))) {
    return false;
  }
  for (std::size_t i = quadratures_; i < n; ++i) {
    const auto k = static_cast<Eigen::Index>(i);
    y1_[i] = y_[i] + h / 6.0 * (f0_[i] + 4.0 * f_stage_(k) + f1_[i]);
    error_(k) = 2.0 / 3.0 * h * (f_stage_(k) - 0.5 * (f0_[i] + f1_[i]));
  }
  return true;
}

void Rosenbrock::StepAccepted() {
  source_.StepAccepted();
  ++time_derivative_age_;
}

void Rosenbrock::StepRejected() {
  // A stale W or f_t may be why the step failed: retry with fresh ones. Fresh ones are exact
  // here, so only the step size changes.
  source_.StepRejected();
  if (time_derivative_age_ > 0) time_derivative_age_ = kMaxJacobianAge;
}

double Rosenbrock::AdjustStep(double proposed, double current) const {
  if (source_.valid() && proposed >= current && proposed <= kKeepStepRatio * current) {
    return current;
  }
  return proposed;
}

}  // namespace sled::runtime
