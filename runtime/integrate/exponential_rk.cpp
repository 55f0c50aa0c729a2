#include "runtime/integrate/exponential_rk.h"

#include <algorithm>
#include <limits>

#include "runtime/run/archive.h"

namespace sled::runtime {

ExponentialRungeKutta::ExponentialRungeKutta() = default;

using Fraction = StructuredPhi::Fraction;

void ExponentialRungeKutta::ResizeWorkspace(std::size_t size) {
  source_.Reserve(system());
  phi_.Reserve(size, source_.jacobian().max_rank());
  for (auto* v : {&half_, &whole_, &stage_, &increment_, &f_stage_, &d2_, &d3_, &d4_, &c2_, &c3_,
                  &error_, &product_, &dense_y0_, &dense_f0_, &dense_c2_, &dense_c3_}) {
    v->assign(size, 0.0);
  }
  scratch_.setZero(static_cast<Eigen::Index>(source_.jacobian().max_rank()));
  quadratures_ = std::min(system().ControlledSize(), size);
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
    product_[i] = 2.0 * d3_[i] - d4_[i];
  }
  for (std::size_t i = 0; i < n; ++i) y1_[i] = y_[i] + whole_[i];
  phi_.Accumulate(2, Fraction::kWhole, c2_, h, y1_);
  phi_.Accumulate(3, Fraction::kWhole, c3_, h, y1_);
  // The embedded estimate h kappa (2 D_3 - D_4) + 2h phi_2 (D_3 - D_2), kappa = (phi_1 -
  // 2 phi_2 + 2 phi_3) / 2 (see the header).
  std::fill(error_.begin(), error_.end(), 0.0);
  phi_.Accumulate(1, Fraction::kWhole, product_, 0.5 * h, error_);
  phi_.Accumulate(2, Fraction::kWhole, product_, -h, error_);
  phi_.Accumulate(3, Fraction::kWhole, product_, h, error_);
  for (std::size_t i = 0; i < n; ++i) product_[i] = d3_[i] - d2_[i];
  phi_.Accumulate(2, Fraction::kWhole, product_, 2.0 * h, error_);

  // The end derivative (the next step's f0), and the residual of the step's model there.
  if (!Evaluate(t_ + h, y1_, f1_)) return false;
  // The quadratures (ControlledSize on: the work integrals) feed nothing back and A has no rows
  // for them, so their last stage may as well be the step's end: with D_4 = f(t + h, y1) - f0
  // their weights are Simpson's rule on the midpoint stage and the end, which on a stiff problem
  // is far closer than the stage Y_4 (a damper's work: its velocity at Y_4 is not yet relaxed).
  // Their error estimate is Simpson's against the trapezoidal rule on the same ends,
  // 2h/3 (D_3 - D_4/2): the embedded formula's midpoint rule would take its midpoint from Y_2,
  // the exponential Euler half step, whose stiff velocities are first order, and a damper's
  // power (c v^2, c large) magnifies that into errors the quadrature itself does not have
  // (`viscous_damping`: it set 10,938 steps at 1e-6 where the motion needs about 1,300).
  for (std::size_t i = quadratures_; i < n; ++i) {
    d4_[i] = f1_[i] - f0_[i];
    c2_[i] = 4.0 * d3_[i] - d4_[i];
    c3_[i] = 4.0 * d4_[i] - 8.0 * d3_[i];
    y1_[i] = y_[i] + h * (f0_[i] + 0.5 * c2_[i] + c3_[i] / 6.0);
    error_[i] = 2.0 / 3.0 * h * (d3_[i] - 0.5 * d4_[i]);
  }
  const double embedded = ErrorNorm(error_);
  for (std::size_t i = 0; i < n; ++i) increment_[i] = y1_[i] - y_[i];
  Remainder(f1_, increment_, error_);
  for (std::size_t i = 0; i < n; ++i) error_[i] = h * (error_[i] - d4_[i]);
  const double residual = ErrorNorm(error_);
  *error = std::max(embedded, residual);
  return true;
}

void ExponentialRungeKutta::PrepareDenseOutput() {
  std::copy(y_.begin(), y_.end(), dense_y0_.begin());
  std::copy(f0_.begin(), f0_.end(), dense_f0_.begin());
  std::copy(c2_.begin(), c2_.end(), dense_c2_.begin());
  std::copy(c3_.begin(), c3_.end(), dense_c3_.begin());
  phi_.ForgetDense();
}

void ExponentialRungeKutta::DenseOutput(double theta, std::span<double> y) const {
  // The step's own model at theta h: its phi-functions (of the A and h the step used, still
  // prepared: the next step has not begun) at tau = theta h.
  const double h = dense_step();
  if (theta <= 0.0) {
    std::copy(dense_y0_.begin(), dense_y0_.end(), y.begin());
    return;
  }
  if (theta >= 1.0) {
    std::copy(dense_end().begin(), dense_end().end(), y.begin());
    return;
  }
  const double tau = theta * h;
  phi_.Dense(tau, dense_y0_, {dense_f0_, dense_c2_, dense_c3_},
             {tau, h * theta * theta, h * theta * theta * theta}, y);
}

void ExponentialRungeKutta::StepAccepted() { source_.StepAccepted(); }

void ExponentialRungeKutta::StepRejected() { source_.StepRejected(); }

void ExponentialRungeKutta::SerializeHistory(Archive& archive) {
  source_.Serialize(archive);
  for (auto* v : {&dense_y0_, &dense_f0_, &dense_c2_, &dense_c3_}) archive.Field(*v);
  // The phi-functions follow from A and the step: made again for the last step's dense output
  // (a resumed run reads its first rows from it), and again when the next step needs them.
  if (archive.reading()) {
    prepared_step_ = 0.0;
    if (dense_step() > 0.0 && source_.jacobian().size() == dense_y0_.size()) {
      phi_.Prepare(source_.jacobian(), dense_step());
    }
  }
}

double ExponentialRungeKutta::AdjustStep(double proposed, double current) const {
  if (source_.valid() && proposed >= current && proposed <= kKeepStepRatio * current) {
    return current;
  }
  return proposed;
}

}  // namespace sled::runtime
