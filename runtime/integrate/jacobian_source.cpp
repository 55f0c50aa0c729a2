#include "runtime/integrate/jacobian_source.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sled::runtime {

void JacobianSource::Reserve(OdeSystem& system) {
  const std::size_t n = system.size();
  const std::size_t rank = system.StructuredRank();
  system_structured_ = rank > 0;
  jacobian_.Reserve(n, system_structured_ ? rank : n);
  Forget();
  if (!system_structured_) {
    row_major_.assign(n * n, 0.0);
    perturbed_.assign(n, 0.0);
    f_perturbed_.assign(n, 0.0);
  }
  structured_ = false;
}

JacobianSource::Status JacobianSource::Form(OdeSystem& system, double t, std::span<const double> y,
                                            std::span<const double> f0, double step,
                                            const IntegratorOptions& options,
                                            IntegratorStats& stats) {
  ++stats.jacobians;
  Forget();  // until it is complete
  jacobian_.Clear();
  structured_ = false;
  if (system_structured_) {
    structured_ = system.StructuredJacobianAt(t, y, f0, kReach * step, jacobian_);
    if (!structured_) return Status::kEvaluationFailed;
  } else if (const Status status = FormDense(system, t, y, f0, options, stats);
             status != Status::kOk) {
    return status;
  }
  if (!structured_) {
    // The dense Jacobian's 1-norm: a bound on its spectral radius.
    double norm = 0.0;
    const auto u = jacobian_.u();
    for (Eigen::Index j = 0; j < u.cols(); ++j) norm = std::max(norm, u.col(j).cwiseAbs().sum());
    jacobian_.stiff_rate = norm;
  }
  for (const auto& entry : jacobian_.nilpotent) {
    if (!std::isfinite(entry.value)) return Status::kNotFinite;
  }
  if (!jacobian_.u().allFinite() || !jacobian_.v().allFinite()) return Status::kNotFinite;
  valid_ = at_current_point_ = true;
  age_ = 0;
  step_ = step;
  return Status::kOk;
}

bool JacobianSource::MustForm(double h, long max_age, double growth, bool same_point_serves) {
  if (!valid_) return true;
  if (same_point_serves && at_current_point_) return false;
  return age_ >= max_age || h > growth * step_;
}

JacobianSource::Status JacobianSource::FormDense(OdeSystem& system, double t,
                                                 std::span<const double> y,
                                                 std::span<const double> f0,
                                                 const IntegratorOptions& options,
                                                 IntegratorStats& stats) {
  const std::size_t n = y.size();
  const auto ni = static_cast<Eigen::Index>(n);
  jacobian_.set_rank(ni);
  auto u = jacobian_.u();
  jacobian_.v().setIdentity();
  if (system.Jacobian(t, y, row_major_)) {
    for (Eigen::Index i = 0; i < ni; ++i) {
      for (Eigen::Index j = 0; j < ni; ++j) {
        u(i, j) = row_major_[static_cast<std::size_t>(i * ni + j)];
      }
    }
    return Status::kOk;
  }
  const double sqrt_eps = std::sqrt(std::numeric_limits<double>::epsilon());
  const double rtol = options.relative_tolerance;
  const double small = std::max(rtol > 0.0 ? options.absolute_tolerance / rtol : 1.0, 1e-8);
  std::copy(y.begin(), y.end(), perturbed_.begin());
  for (std::size_t j = 0; j < n; ++j) {
    double delta = sqrt_eps * std::max(std::abs(y[j]), small);
    // Retry the other way if the system cannot be evaluated on this side.
    bool ok = false;
    for (const double sign : {1.0, -1.0}) {
      perturbed_[j] = y[j] + sign * delta;
      const double actual = perturbed_[j] - y[j];  // the increment as represented
      ++stats.evaluations;
      if (system.Derivative(t, perturbed_, f_perturbed_)) {
        delta = actual;
        ok = true;
        break;
      }
    }
    perturbed_[j] = y[j];
    if (!ok) return Status::kEvaluationFailed;
    const auto col = static_cast<Eigen::Index>(j);
    for (Eigen::Index i = 0; i < ni; ++i) {
      const auto row = static_cast<std::size_t>(i);
      u(i, col) = (f_perturbed_[row] - f0[row]) / delta;
    }
  }
  return Status::kOk;
}

}  // namespace sled::runtime
