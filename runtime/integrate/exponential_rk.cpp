#include "runtime/integrate/exponential_rk.h"

#include <algorithm>
#include <limits>

#include "runtime/archive.h"

namespace sled::runtime {

using Fraction = StructuredPhi::Fraction;

void ExponentialRungeKutta::ResizeWorkspace(std::size_t size) {
  source_.Reserve(system());
  phi_.Reserve(size, source_.jacobian().max_rank());
  for (auto* v : {&half_, &whole_, &stage_, &increment_, &f_stage_, &d2_, &d3_, &d4_, &c2_, &c3_,
                  &error_, &product_}) {
    v->assign(size, 0.0);
  }
  scratch_.setZero(static_cast<Eigen::Index>(source_.jacobian().max_rank()));
  RestartHistory();
}

void ExponentialRungeKutta::RestartHistory() {
  source_.Forget();
  prepared_step_ = 0.0;
}

JacobianSource::Status ExponentialRungeKutta::EnsureJacobian(double h) {
  // The system chose the stiff terms for the step it was told, so a much changed step needs a
  // fresh A even at the same point.
  if (source_.MustForm(h, kMaxJacobianAge, kJacobianGrowth, false)) {
    prepared_step_ = 0.0;
    const JacobianSource::Status status =
        source_.Form(system(), t_, y_, f0_, h, options(), mutable_stats());
    if (status != JacobianSource::Status::kOk) return status;
  }
  if (prepared_step_ != h) {
    phi_.Prepare(source_.jacobian(), h);
    prepared_step_ = h;
  }
  return JacobianSource::Status::kOk;
}

void ExponentialRungeKutta::Remainder(std::span<const double> f_stage,
                                      std::span<const double> increment, std::span<double> d) {
  source_.jacobian().Apply(increment, product_, scratch_);
  for (std::size_t i = 0; i < d.size(); ++i) d[i] = f_stage[i] - f0_[i] - product_[i];
}

bool ExponentialRungeKutta::TryStep(double h, double* error) {
  switch (EnsureJacobian(h)) {
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
  const std::size_t n = y_.size();

  // Y_2 = y + h/2 phi_1(hA/2) f.
  std::fill(half_.begin(), half_.end(), 0.0);
  phi_.Accumulate(1, Fraction::kHalf, f0_, 0.5 * h, half_);
  for (std::size_t i = 0; i < n; ++i) stage_[i] = y_[i] + half_[i];
  if (!Evaluate(t_ + 0.5 * h, stage_, f_stage_)) return false;
  Remainder(f_stage_, half_, d2_);

  // Y_3 = Y_2 + h/2 phi_2(hA/2) D_2.
  std::copy(half_.begin(), half_.end(), increment_.begin());
  phi_.Accumulate(2, Fraction::kHalf, d2_, 0.5 * h, increment_);
  for (std::size_t i = 0; i < n; ++i) stage_[i] = y_[i] + increment_[i];
  if (!Evaluate(t_ + 0.5 * h, stage_, f_stage_)) return false;
  Remainder(f_stage_, increment_, d3_);

  // Y_4 = y + h phi_1(hA) f + 2h phi_2(hA) D_3.
  std::fill(whole_.begin(), whole_.end(), 0.0);
  phi_.Accumulate(1, Fraction::kWhole, f0_, h, whole_);
  std::copy(whole_.begin(), whole_.end(), increment_.begin());
  phi_.Accumulate(2, Fraction::kWhole, d3_, 2.0 * h, increment_);
  for (std::size_t i = 0; i < n; ++i) stage_[i] = y_[i] + increment_[i];
  if (!Evaluate(t_ + h, stage_, f_stage_)) return false;
  Remainder(f_stage_, increment_, d4_);

  // y_1 and the error estimate.
  for (std::size_t i = 0; i < n; ++i) {
    c2_[i] = 4.0 * d3_[i] - d4_[i];
    c3_[i] = 4.0 * d4_[i] - 8.0 * d3_[i];
    product_[i] = c2_[i] - 2.0 * d2_[i];
  }
  for (std::size_t i = 0; i < n; ++i) y1_[i] = y_[i] + whole_[i];
  phi_.Accumulate(2, Fraction::kWhole, c2_, h, y1_);
  phi_.Accumulate(3, Fraction::kWhole, c3_, h, y1_);
  std::fill(error_.begin(), error_.end(), 0.0);
  phi_.Accumulate(2, Fraction::kWhole, product_, h, error_);
  phi_.Accumulate(3, Fraction::kWhole, c3_, h, error_);
  const double embedded = ErrorNorm(error_);

  // The end derivative (the next step's f0), and the residual of the step's model there.
  if (!Evaluate(t_ + h, y1_, f1_)) return false;
  for (std::size_t i = 0; i < n; ++i) increment_[i] = y1_[i] - y_[i];
  Remainder(f1_, increment_, error_);
  for (std::size_t i = 0; i < n; ++i) error_[i] = h * (error_[i] - d4_[i]);
  const double residual = ErrorNorm(error_);
  *error = std::max(embedded, residual);
  return true;
}

void ExponentialRungeKutta::Interpolate(double t, std::span<double> y) const {
  const double h = step_;
  const double theta = h != 0.0 ? (t - t_) / h : 0.0;
  if (theta <= 0.0) {
    std::copy(y_.begin(), y_.end(), y.begin());
    return;
  }
  if (theta >= 1.0) {
    std::copy(y1_.begin(), y1_.end(), y.begin());
    return;
  }
  const double tau = theta * h;
  phi_.PrepareOther(tau);
  std::copy(y_.begin(), y_.end(), y.begin());
  phi_.Accumulate(1, Fraction::kOther, f0_, tau, y);
  phi_.Accumulate(2, Fraction::kOther, c2_, h * theta * theta, y);
  phi_.Accumulate(3, Fraction::kOther, c3_, h * theta * theta * theta, y);
}

void ExponentialRungeKutta::StepAccepted() { source_.StepAccepted(); }

void ExponentialRungeKutta::StepRejected() { source_.StepRejected(); }

void ExponentialRungeKutta::SerializeHistory(Archive& archive) {
  source_.Serialize(archive);
  // The phi-functions follow from A and the step: the same ones, made again when next needed.
  if (archive.reading()) prepared_step_ = 0.0;
}

double ExponentialRungeKutta::AdjustStep(double proposed, double current) const {
  if (source_.valid() && proposed >= current && proposed <= kKeepStepRatio * current) {
    return current;
  }
  return proposed;
}

}  // namespace sled::runtime
