#include "runtime/integrate/rosenbrock.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "runtime/integrate/error_norm.h"
#include "runtime/integrate/rosenbrock_tableaus.h"
#include "runtime/run/archive.h"

namespace sled::runtime {

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
  // Against f0_, the derivative the step starts from, even where that is the one before a
  // projection (ToleratesProjectedStart): a fresh evaluation at (t, y) and the one at (t + dt, y)
  // may come out of different factorizations of the constraint solver (a fresh one and a
  // refactorization with older pivots), whose rounding, divided by dt, swamped f_t: the four-bar
  // linkage (examples/four_bar.sled) took 156,961 steps instead of 3,002.
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

const RosenbrockTableau& Rosenbrock::MethodFor(double h) const {
  return h * source_.jacobian().stiff_rate < kStiffStep ? kRahunanthanStanescu4 : kRos34pw2;
}

bool Rosenbrock::Factor(double h) {
  factored_step_ = 0.0;
  const double gamma = MethodFor(h).gamma;
  if (!solver_.Factor(source_.jacobian(), 1.0 / (h * gamma))) return false;
  factored_step_ = h;
  factored_gamma_ = gamma;
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
  const RosenbrockTableau& method = MethodFor(h);
  if (factored_step_ != h || factored_gamma_ != method.gamma) {
    ++mutable_stats().factorizations;
    if (!Factor(h)) return false;
  }

  const Eigen::Map<const Eigen::VectorXd> y0(y_.data(), static_cast<Eigen::Index>(n));
  const Eigen::Map<const Eigen::VectorXd> f0(f0_.data(), static_cast<Eigen::Index>(n));
  for (int i = 0; i < method.stages; ++i) {
    if (i == 0) {
      rhs_ = f0;
    } else {
      stage_ = y0;
      for (int j = 0; j < i; ++j) {
        if (method.a[i][j] != 0.0) stage_ += method.a[i][j] * u_[j];
      }
      if (!Evaluate(t_ + method.alpha_sum[i] * h, std::span<const double>(stage_.data(), n),
                    std::span<double>(f_stage_.data(), n))) {
        return false;
      }
      rhs_ = f_stage_;
      for (int j = 0; j < i; ++j) rhs_ += (method.c[i][j] / h) * u_[j];
    }
    if (method.gamma_sum[i] != 0.0) rhs_ += (method.gamma_sum[i] * h) * time_derivative_;
    solver_.Solve(std::span<const double>(rhs_.data(), n), std::span<double>(u_[i].data(), n));
  }

  Eigen::Map<Eigen::VectorXd> y1(y1_.data(), static_cast<Eigen::Index>(n));
  y1 = y0;
  error_.setZero();
  for (int j = 0; j < method.stages; ++j) {
    y1 += method.m[j] * u_[j];
    error_ += method.e[j] * u_[j];
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
    const double simpson = y_[i] + h / 6.0 * (f0_[i] + 4.0 * f_stage_(k) + f1_[i]);
    error_(k) = simpson - y1_[i];  // against the stages' own quadrature, also of order 4
    y1_[i] = simpson;
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
