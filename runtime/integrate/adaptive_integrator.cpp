#include "runtime/integrate/adaptive_integrator.h"

#include "runtime/run/archive.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

namespace sled::runtime {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();
constexpr double kNoProbe = std::numeric_limits<double>::quiet_NaN();

bool AllFinite(std::span<const double> values) {
  for (const double value : values) {
    if (!std::isfinite(value)) return false;
  }
  return true;
}

// The index of the first value of `first`, else of `second`, that is not finite; -1 if none.
std::ptrdiff_t FirstNotFinite(std::span<const double> first, std::span<const double> second) {
  for (const std::span<const double> values : {first, second}) {
    for (std::size_t i = 0; i < values.size(); ++i) {
      if (!std::isfinite(values[i])) return static_cast<std::ptrdiff_t>(i);
    }
  }
  return -1;
}

// Stretch the step by up to 1% to land on the target rather than leave a sliver (dopri5.f).
constexpr double kLandingStretch = 1.01;

// Look-ahead for settling event signs after an event, in event tolerances: large enough that a
// handler that reverses and scales a velocity by a restitution of 0.1 or more has moved the
// state back over the surface (see EventLocator::Start).
constexpr double kLookAheadTolerances = 10.0;

// A step retaken for an event it found ends this fraction of the first step past the event as
// located there, and the event is looked for on it first as far before. The first step's stages
// on the other side of the event put that location off, on the flagship mostly by 1e-9 to 1e-6
// of the step (at most 1.8e-5 early and 4.7e-5 late): retaken steps that ended on the location
// itself fell short of the event in 56 of 127 retakes, each then taking one more step to reach
// it; with this reach, 13 of 133. (2e-5 left 6 short but doubled the flagship's error at 1e-8.)
constexpr double kRetakeReach = 1e-6;

// A projection that moves the state by more than this (in the weighted error norm, where 1 is
// the tolerance) re-evaluates the step's end derivative.
constexpr double kProjectionReevaluation = 1e-3;

}  // namespace

void AdaptiveIntegrator::Serialize(Archive& archive) {
  archive.Field(t_);
  archive.Field(y_);
  archive.Field(f0_);
  archive.Field(h_);
  archive.Field(restart_pending_);
  archive.Field(keep_step_);
  archive.Field(commit_pending_);
  archive.Field(event_pending_);
  archive.Field(step_start_);
  // The last step's dense output: a resumed run with other output requests reads its first rows
  // from it.
  archive.Field(dense_t0_);
  archive.Field(dense_t1_);
  archive.Field(dense_h_);
  archive.Field(dense_y1_);
  archive.Field(end_state_);
  archive.Field(dense_y0_);
  archive.Field(dense_f0_);
  archive.Field(dense_f1_);
  archive.Field(restart_step_);
  archive.Field(step_limit_);
  archive.Field(event_stop_);
  archive.Field(redo_spent_);
  archive.Field(event_seen_at_);
  archive.Field(quadrature_scale_);
  archive.Field(stats_);
  controller_.Serialize(archive);
  events_.Serialize(archive);
  SerializeHistory(archive);
}

double AdaptiveIntegrator::ErrorNorm(std::span<const double> error) {
  return WeightedRmsNorm(error.first(controlled_), std::span<const double>(y_).first(controlled_),
                         std::span<const double>(y1_).first(controlled_),
                         options_.relative_tolerance, options_.absolute_tolerance, &largest_,
                         {quadratures_from_, quadrature_scale_});
}

void AdaptiveIntegrator::UpdateQuadratureScale(double t, std::span<const double> y) {
  // Only a method that measures the quadratures needs it (dopri5 would pay for nothing).
  if (controlled_ > quadratures_from_) quadrature_scale_ = system_->QuadratureScale(t, y);
}

void AdaptiveIntegrator::Reset(OdeSystem& system, double t0, std::span<const double> y0,
                               const IntegratorOptions& options) {
  const std::size_t n = system.size();
  if (y0.size() != n) {
    throw std::invalid_argument("sled::runtime integrator " + std::string(name()) +
                                ": Reset with " + std::to_string(y0.size()) +
                                " initial values for a system of size " + std::to_string(n));
  }
  if (!(options.relative_tolerance >= 0.0) || !(options.absolute_tolerance >= 0.0) ||
      options.relative_tolerance + options.absolute_tolerance <= 0.0) {
    throw std::invalid_argument("sled::runtime integrator " + std::string(name()) +
                                ": tolerances must be non-negative and not both zero");
  }
  if (!(options.min_step >= 0.0) || !(options.max_step >= 0.0) ||
      (options.max_step > 0.0 && options.max_step < options.min_step)) {
    throw std::invalid_argument("sled::runtime integrator " + std::string(name()) +
                                ": need 0 <= min_step <= max_step (max_step 0: no limit)");
  }
  system_ = &system;
  quadratures_from_ = std::min(system.ControlledSize(), n);
  controlled_ = ControlsQuadratures() ? n : quadratures_from_;
  quadrature_scale_ = 0.0;
  options_ = options;
  stats_ = {};
  t_ = t0;
  step_ = 0.0;
  h_ = 0.0;
  y_.assign(y0.begin(), y0.end());
  restart_step_ = 0.0;
  step_limit_ = std::numeric_limits<double>::infinity();
  f0_.assign(n, 0.0);
  y1_.assign(n, 0.0);
  f1_.assign(n, 0.0);
  y_event_.assign(n, 0.0);
  y_project_.assign(n, 0.0);
  dense_y1_.assign(n, 0.0);
  end_state_.assign(n, 0.0);
  dense_y0_.assign(n, 0.0);
  dense_f0_.assign(n, 0.0);
  dense_f1_.assign(n, 0.0);
  dense_t0_ = dense_t1_ = step_start_ = t0;
  dense_h_ = 0.0;
  keep_step_ = false;
  commit_pending_ = false;
  event_pending_ = false;
  event_stop_ = std::numeric_limits<double>::infinity();
  redo_spent_ = false;
  controller_.Configure(ErrorPower());
  events_.Reset(system);
  ResizeWorkspace(n);
  restart_pending_ = true;
}

std::span<double> AdaptiveIntegrator::mutable_state() {
  FinishPending();
  restart_pending_ = true;
  keep_step_ = false;
  return y_;
}

void AdaptiveIntegrator::FinishPending() {
  // The state committed: the step's end as the step ended it, before the projection (where the
  // system was last evaluated, so it need not evaluate it again), or the state an event left.
  std::span<const double> committed = end_state_;
  if (event_pending_) {
    committed = y_;
    event_pending_ = false;
    const std::span<const int> crossings = events_.crossings();
    bool state_changed = false;
    for (std::size_t k = 0; k < crossings.size(); ++k) {
      if (crossings[k] == 0) continue;
      ++stats_.events;
      state_changed =
          system_->HandleEvent(k, crossings[k], t_, y_) == OdeSystem::EventEffect::kStateChanged ||
          state_changed;
    }
    system_->Project(t_, y_);
    restart_pending_ = true;  // the next step restarts f0, the history and the events
    keep_step_ = !state_changed;
  }
  if (commit_pending_) {
    commit_pending_ = false;
    system_->CommitStep(t_, committed);
  }
}

AdvanceResult AdaptiveIntegrator::Step(double t_stop) { return StepOnce(t_stop, 0.0); }

void AdaptiveIntegrator::RestartAt(double t, std::span<const double> y, double first_step) {
  if (system_ == nullptr || y.size() != y_.size()) {
    throw std::logic_error("sled::runtime integrator " + std::string(name()) +
                           ": RestartAt needs a Reset for a system of this size first");
  }
  // Whatever this method left pending was done when it handed the solution over (Settle).
  commit_pending_ = event_pending_ = false;
  t_ = t;
  step_start_ = t;
  std::copy(y.begin(), y.end(), y_.begin());
  restart_step_ = first_step;
  restart_pending_ = true;
  keep_step_ = false;
}

void AdaptiveIntegrator::Settle() { FinishPending(); }

AdvanceResult AdaptiveIntegrator::AdvanceFixed(double t_end, long steps) {
  if (steps <= 0) {
    throw std::invalid_argument("sled::runtime integrator " + std::string(name()) +
                                ": AdvanceFixed needs a positive number of steps");
  }
  const double fixed = (t_end - t_) / static_cast<double>(steps);
  AdvanceResult result;
  result.t = t_;
  while (t_ < t_end) {
    result = StepOnce(t_end, fixed);
    if (result.status != IntegratorStatus::kOk) return result;
  }
  return result;
}

bool AdaptiveIntegrator::Evaluate(double t, std::span<const double> y, std::span<double> dy) {
  ++stats_.evaluations;
  return system_->Derivative(t, y, dy);
}

void AdaptiveIntegrator::Interpolate(double t, std::span<double> y) const {
  if (t >= dense_t1_ || dense_h_ == 0.0) {
    // The end itself: the stored state, bit for bit (a row there reads the evaluation the step
    // already made); before the first step, the state.
    const std::vector<double>& end = dense_h_ == 0.0 ? y_ : end_state_;
    std::copy(end.begin(), end.end(), y.begin());
    return;
  }
  DenseOutput(std::max(0.0, (t - dense_t0_) / dense_h_), y);
}

void AdaptiveIntegrator::PrepareDenseOutput() {
  std::copy(y_.begin(), y_.end(), dense_y0_.begin());
  std::copy(f0_.begin(), f0_.end(), dense_f0_.begin());
  std::copy(f1_.begin(), f1_.end(), dense_f1_.begin());
}

void AdaptiveIntegrator::DenseOutput(double theta, std::span<double> y) const {
  HermiteInterpolate(theta, dense_h_, dense_y0_, dense_f0_, dense_y1_, dense_f1_, y);
}

double AdaptiveIntegrator::MaxStep() const {
  return options_.max_step > 0.0 ? options_.max_step : std::numeric_limits<double>::infinity();
}

double AdaptiveIntegrator::MinStep() const {
  // With min_step 0 the floor is what time can still resolve, so repeated rejections end.
  return std::max(
      {options_.min_step, 4.0 * kEps * std::abs(t_), std::numeric_limits<double>::min()});
}

double AdaptiveIntegrator::ClampStep(double h) const {
  return std::max(std::min(h, MaxStep()), MinStep());
}

double AdaptiveIntegrator::EventTolerance() const {
  return std::max(options_.event_tolerance, 4.0 * kEps * std::abs(t_));
}

double AdaptiveIntegrator::InitialStep() {
  // dopri5.f HINIT: a step whose Euler increment is 1% of the state, then refined by a second
  // derivative estimate so that h^order * max(|f|, |f'|) is about 0.01 in the weighted norm.
  // Measured on the controlled components only, as the error test is.
  const std::size_t n = controlled_;
  const double rtol = options_.relative_tolerance;
  const double atol = options_.absolute_tolerance;
  // With atol = 0 a zero component would have weight 0; the smallest normal double stands in.
  // (The quadratures as ErrorNorm weighs them.)
  const auto weight = [&](std::size_t i, double y) {
    const double floor = i >= quadratures_from_ ? quadrature_scale_ : 0.0;
    return std::max(atol + rtol * std::max(std::abs(y), floor), std::numeric_limits<double>::min());
  };
  double dnf = 0.0;
  double dny = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double w = weight(i, y_[i]);
    dnf += (f0_[i] / w) * (f0_[i] / w);
    dny += (y_[i] / w) * (y_[i] / w);
  }
  double h = (dnf <= 1e-10 || dny <= 1e-10) ? 1e-6 : std::sqrt(dny / dnf) * 0.01;
  if (!(h > 0.0) || !std::isfinite(h)) h = 1e-6;
  h = std::min(h, MaxStep());
  // y1_ and f1_ are free between steps: use them for the trial Euler step.
  for (std::size_t i = 0; i < y_.size(); ++i) y1_[i] = y_[i] + h * f0_[i];
  if (!Evaluate(t_ + h, y1_, f1_) || !AllFinite(f1_)) return h;
  double der2 = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double scaled = (f1_[i] - f0_[i]) / weight(i, y_[i]);
    der2 += scaled * scaled;
  }
  der2 = std::sqrt(der2) / h;
  const double der12 = std::max(der2, std::sqrt(dnf));
  double h1 = der12 <= 1e-15 ? std::max(1e-6, h * 1e-3)
                             : std::pow(0.01 / der12, 1.0 / static_cast<double>(order()));
  if (!(h1 > 0.0) || !std::isfinite(h1)) h1 = h;
  return std::min({100.0 * h, h1, MaxStep()});
}

bool AdaptiveIntegrator::Restart(bool fixed, AdvanceResult* result) {
  result->t = t_;
  if (!AllFinite(y_)) {
    result->status = IntegratorStatus::kNotFinite;
    result->reason = "the state is not finite";
    result->component = FirstNotFinite(y_, {});
    return false;
  }
  if (!Evaluate(t_, y_, f0_)) {
    result->status = IntegratorStatus::kEvaluationFailed;
    result->reason = system_->FailureReason();
    return false;
  }
  if (!AllFinite(f0_)) {
    result->status = IntegratorStatus::kNotFinite;
    result->reason = "the derivative is not finite at the start";
    result->component = FirstNotFinite(f0_, {});
    return false;
  }
  step_limit_ = system_->StepLimit(t_, y_);
  UpdateQuadratureScale(t_, y_);
  controller_.Restart();
  RestartHistory();
  if (events_.active()) {
    events_.Start(t_, y_, f0_, kLookAheadTolerances * EventTolerance(), y_event_);
  }
  if (!fixed && restart_step_ > 0.0) {  // (RestartAt's first step)
    h_ = ClampStep(restart_step_);
  } else if (!fixed && !(keep_step_ && h_ > 0.0)) {  // (after an event that changed no state)
    h_ = ClampStep(options_.initial_step > 0.0 ? options_.initial_step : InitialStep());
  }
  restart_pending_ = false;
  keep_step_ = false;
  // RestartAt's first step is for the first step after it only. (Kept, it set the first step
  // after every later event too: on the flagship, after `auto` first handed back to dopri5, each
  // of about 100 events was followed by a step of 6.1e-5 s where 5e-4 s passed the error test.)
  restart_step_ = 0.0;
  event_stop_ = std::numeric_limits<double>::infinity();
  redo_spent_ = false;
  return true;
}

AdvanceResult AdaptiveIntegrator::Fail(Failure failure, double h, double error) {
  // Only failure reports build strings; the step loop itself never allocates.
  AdvanceResult result;
  result.t = t_;
  switch (failure) {
    case Failure::kEvaluation:
      result.status = IntegratorStatus::kEvaluationFailed;
      result.reason = system_->FailureReason();
      if (result.reason.empty()) result.reason = "the derivative could not be evaluated";
      break;
    case Failure::kNotFinite:
      result.status = IntegratorStatus::kNotFinite;
      result.reason = "the state or its derivative became NaN or infinite";
      result.component = FirstNotFinite(y1_, f1_);
      if (result.component < 0 && std::isnan(largest_.weighted)) {
        result.component = static_cast<std::ptrdiff_t>(largest_.index);
      }
      break;
    case Failure::kErrorTest:
    case Failure::kNone:
      result.status = IntegratorStatus::kMinStepReached;
      result.reason = fmt::format(
          "the error test failed at the minimum step (step {:.3g}, weighted error {:.3g})", h,
          error);
      if (largest_.weighted >= 0) result.component = static_cast<std::ptrdiff_t>(largest_.index);
      break;
  }
  return result;
}

AdaptiveIntegrator::Failure AdaptiveIntegrator::Attempt(double h, bool fixed, double* error) {
  if (!TryStep(h, error)) return Failure::kEvaluation;
  if (!AllFinite(y1_) || std::isnan(*error)) return Failure::kNotFinite;
  if (!fixed && !(*error <= 1.0)) return Failure::kErrorTest;
  if (!HasEndDerivative() && !Evaluate(t_ + h, y1_, f1_)) return Failure::kEvaluation;
  if (!AllFinite(f1_)) return Failure::kNotFinite;
  return Failure::kNone;
}

AdvanceResult AdaptiveIntegrator::StepOnce(double t_stop, double fixed_step) {
  if (system_ == nullptr) {
    throw std::logic_error("sled::runtime integrator " + std::string(name()) +
                           ": Step before Reset");
  }
  FinishPending();
  const bool fixed = fixed_step > 0.0;
  AdvanceResult result;
  result.t = t_;
  if (!(t_ < t_stop)) return result;

  // Where a retaken step looks for its event first (see kRetakeReach; NaN: nowhere).
  double event_probe = kNoProbe;
  for (;;) {
    if (restart_pending_ && !Restart(fixed, &result)) return result;

    const double natural =
        fixed ? fixed_step : std::min({h_, MaxStep(), std::max(step_limit_, MinStep())});
    // The step lands on t_stop, or on an event an earlier attempt found inside its step.
    const bool to_event = event_stop_ < t_stop;
    const double stop = to_event ? event_stop_ : t_stop;
    double h = natural;
    bool last = false;
    if (t_ + kLandingStretch * h >= stop) {
      h = stop - t_;
      last = true;
    }
    step_ = h;

    double error = 0.0;
    largest_ = {};
    const Failure failure = Attempt(h, fixed, &error);

    if (failure != Failure::kNone) {
      ++stats_.rejected;
      StepRejected();
      if (fixed || h <= MinStep()) return Fail(failure, h, error);
      const double smaller = failure == Failure::kErrorTest ? controller_.Rejected(h, error)
                                                            : h * StepSizeController::kMinFactor;
      h_ = std::max(smaller, MinStep());
      continue;
    }

    // Accepted: the dense output of the step, then events, projection and the next step size.
    const double t1 = last ? stop : t_ + h;
    if (last && to_event) event_stop_ = std::numeric_limits<double>::infinity();
    ++stats_.steps;
    stats_.max_local_error = std::max(stats_.max_local_error, error);
    std::copy(y1_.begin(), y1_.end(), dense_y1_.begin());
    std::copy(y1_.begin(), y1_.end(), end_state_.begin());
    dense_t0_ = t_;
    dense_t1_ = t1;
    dense_h_ = h;
    PrepareDenseOutput();
    step_start_ = t_;
    commit_pending_ = true;

    // The end of the bracket an event is located in: the step's end, or the first point inside
    // the step where an event function had crossed. The points inside are looked at even when
    // some function crossed by the end: the bracket's ends alone do not show another that
    // crossed and crossed back before (lock_cascade's hinge_3 fell below its unlock level and
    // rose above it again within a step that also unlocked hinge_2, and never unlocked).
    double t_found = t1;
    bool found = false;
    if (events_.active()) {
      found = events_.Check(t1, y1_);
      found = events_.CheckInside(*this, t_, t1, y_event_, t_found) || found;
    }
    if (found) {
      const double t_event = events_.Locate(*this, t_, t_found, EventTolerance(), y_event_,
                                            last && to_event ? event_probe : kNoProbe);
      if (t_event < t1 && !redo_spent_) {
        // The step went past an event: its stages there saw the equations of the other side
        // (a contact's force switching on, a stop's impulse due, a kink of a force law), which
        // its error estimate does not measure and its dense output does not model, so the state
        // it interpolates at the event is only first-order right (an elastic ball lost 3e-4 of
        // its energy per bounce with dopri5 at 1e-6). Take the step again, to land on the event:
        // all of that step but a sliver (kRetakeReach) is on this side of it.
        --stats_.steps;
        ++stats_.rejected;
        commit_pending_ = false;
        StepRejected();
        event_stop_ = std::min(t_event + kRetakeReach * h, t1);
        event_probe = t_event - kRetakeReach * h;
        event_seen_at_ = t1;
        // It ends a little past the event (kRetakeReach), so that the event lands inside it.
        // One retake per event: when the retaken step finds it later than located (an event
        // function that creeps to zero, as a venting bag's pressure to the ambient one, or jumps),
        // the step that finds it next ends there, as before, rather than retake after retake
        // crawl towards it.
        redo_spent_ = true;
        continue;
      }
      redo_spent_ = false;
      // The step ends at the event, with the state before it; the event's change waits for
      // the next step, so whatever the caller evaluates on this step sees the system as the
      // step did.
      event_stop_ = std::numeric_limits<double>::infinity();
      StepAccepted();
      t_ = t_event;
      std::copy(y_event_.begin(), y_event_.end(), y_.begin());
      dense_t1_ = t_event;
      std::copy(y_event_.begin(), y_event_.end(), end_state_.begin());
      event_pending_ = true;
      result.t = t_;
      return result;
    }

    // The retaken step ended before the event it was retaken for: the next one ends where the
    // first step saw it, so an event whose function soon crosses back (a lock level passed for a
    // moment) is not stepped over.
    if (last && to_event && redo_spent_ && event_seen_at_ > t1) event_stop_ = event_seen_at_;

    // Project, and re-evaluate the end derivative only if the projection moved the state by
    // more than a small fraction of the tolerance, so the next step (and the FSAL stage) starts
    // from a consistent pair. Renormalising quaternions moves the state on every step, by the
    // step's own error (1e-4 to 1e-12 of the tolerance on the numerics suite and the flagship);
    // a derivative that far from consistent changes the next step by far less than its error,
    // and re-evaluating it cost one evaluation per step on every scene with a ball joint.
    // The next step's limit, from the state the step reached (where the system was just
    // evaluated: the FSAL stage or the end derivative).
    step_limit_ = system_->StepLimit(t1, y1_);
    UpdateQuadratureScale(t1, y1_);
    std::copy(y1_.begin(), y1_.end(), y_project_.begin());
    system_->Project(t1, y1_);
    for (std::size_t i = 0; i < y1_.size(); ++i) y_project_[i] = y1_[i] - y_project_[i];
    const double moved = ErrorNorm(y_project_);
    // (Written so that a NaN difference re-evaluates, and the non-finite result is reported.)
    if (!(moved <= kProjectionReevaluation) || (moved > 0.0 && !ToleratesProjectedStart())) {
      if (!Evaluate(t1, y1_, f1_) || !AllFinite(f1_)) {
        ++stats_.rejected;
        commit_pending_ = false;
        return Fail(Failure::kEvaluation, h, error);
      }
    }
    std::copy(y1_.begin(), y1_.end(), y_.begin());
    std::copy(f1_.begin(), f1_.end(), f0_.begin());
    t_ = t1;
    events_.Advance();
    StepAccepted();

    if (!fixed) {
      double next = controller_.Accepted(h, error);
      // A step shortened to land on t_stop says nothing against the step it replaced.
      if (last && h < natural && next >= h) next = std::max(next, natural);
      h_ = ClampStep(AdjustStep(next, h));
    }
    result.t = t_;
    return result;
  }
}

}  // namespace sled::runtime
