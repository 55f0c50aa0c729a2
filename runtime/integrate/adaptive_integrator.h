// The step loop every method shares: step-size control, rejection, the minimum and maximum step,
// landing on a stop, non-finite and failed evaluations, projection, event location, the dense
// output's bookkeeping and the statistics. A method supplies one step attempt with its local
// error estimate (TryStep) and, optionally, its own continuous extension (PrepareDenseOutput and
// DenseOutput; the default is a cubic Hermite interpolant); everything else is here, once.
//
// To add a method: derive from AdaptiveIntegrator, implement name, order, ErrorPower,
// ResizeWorkspace and TryStep (fill y1_ from y_, f0_ and the step, and the weighted error), and
// if the method has a better interpolant than the cubic Hermite one, PrepareDenseOutput (called
// once per accepted step, before y_ and f0_ move on: store what DenseOutput needs) and
// DenseOutput. The event locator and the output rows both read DenseOutput; a step that finds
// an event inside it is taken again to end on it.
#pragma once

#include <cstddef>
#include <limits>
#include <span>
#include <string_view>
#include <vector>

#include "runtime/integrate/error_norm.h"
#include "runtime/integrate/events.h"
#include "runtime/integrate/ode.h"

namespace sled::runtime {

class AdaptiveIntegrator : public Integrator, protected StepInterpolant {
 public:
  void Reset(OdeSystem& system, double t0, std::span<const double> y0,
             const IntegratorOptions& options) final;
  AdvanceResult Step(double t_stop) final;
  // Continues from (t, y), as after an external change of the state (the method's history and
  // the events start afresh there; the statistics go on), trying `first_step` first (0: the
  // starting-step heuristic). Needs a Reset for the same system before; never allocates.
  void RestartAt(double t, std::span<const double> y, double first_step);
  // Does now what the last step left for the next one (its event, the system's CommitStep): for
  // a driver that hands the solution to another method (`auto`).
  void Settle();

  // Takes `steps` equal steps to t_end with no error control (for convergence studies and
  // tests): the local error estimates still go into the statistics, but never reject a step.
  // Events are still located; after one, the remaining steps keep the same size.
  AdvanceResult AdvanceFixed(double t_end, long steps);

  double time() const final { return t_; }
  double step_start() const final { return step_start_; }
  // The dense output of the step [step_start(), time()] (and, while a step is being checked for
  // events, of the step attempted).
  void Interpolate(double t, std::span<double> y) const final;
  std::span<const double> state() const final { return y_; }
  std::span<double> mutable_state() final;
  const IntegratorStats& stats() const final { return stats_; }
  void Serialize(Archive& archive) final;

  // The step size the next step will try (after Reset: 0 until the first Advance chooses one).
  double step_size() const { return h_; }

 protected:
  AdaptiveIntegrator() = default;

  // The power k of h in the local error estimate (lower embedded order + 1), for the controller.
  virtual int ErrorPower() const = 0;
  // Sizes the method's workspace for `size` states. Called from Reset; the only place a method
  // may allocate.
  virtual void ResizeWorkspace(std::size_t size) = 0;
  // Forgets what the method carries from step to step (Jacobian, decay rates): after Reset, an
  // event or an external change of the state.
  virtual void RestartHistory() {}
  // One attempt from (t_, y_), where f0_ = f(t_, y_), with step h: fills y1_ and sets *error to
  // the weighted local error estimate. Returns false when Derivative failed.
  virtual bool TryStep(double h, double* error) = 0;
  // True when TryStep also leaves f(t_ + h, y1_) in f1_ (FSAL); otherwise the loop evaluates it
  // after the error test passes, and it becomes the next step's f0_.
  virtual bool HasEndDerivative() const { return false; }
  // True when the next step may start from the end derivative of a state that the projection
  // then moved by less than kProjectionReevaluation of the tolerance. A method whose stages or
  // difference Jacobian rely on f0_ being exactly f(t_, y_) says false.
  virtual bool ToleratesProjectedStart() const { return true; }
  // Whether the error control also measures the system's quadratures (OdeSystem::
  // ControlledSize). A method whose stages are not accurate states on a stiff problem (the
  // exponential and Rosenbrock methods: stage order 1 or 2) integrates a quadrature of them, such
  // as a damper's dissipated work, only as well as its error test sees it: it says true.
  virtual bool ControlsQuadratures() const { return false; }
  // What the method itself carries between steps (decay rates, a Jacobian, its dense output's
  // data), for Serialize.
  virtual void SerializeHistory(Archive& archive) { (void)archive; }
  // Told after each accepted or rejected attempt.
  virtual void StepAccepted() {}
  virtual void StepRejected() {}
  // Lets a method keep the current step when the controller asks for a slightly different one
  // (the Rosenbrock method does, to reuse its factorization). Default: take the proposal.
  virtual double AdjustStep(double proposed, double current) const {
    (void)current;
    return proposed;
  }
  // After a step passed the error test, before y_ and f0_ move on: stores what DenseOutput
  // needs for the step from (t_, y_) to (t_ + step_, y1_). Default: y_, f0_ and f1_ for the
  // cubic Hermite interpolant (y1_ is kept by the loop).
  virtual void PrepareDenseOutput();
  // y at the fraction theta (0 <= theta <= 1) of the step PrepareDenseOutput stored, whose end
  // state is dense_end(). Default: cubic Hermite, third order.
  virtual void DenseOutput(double theta, std::span<double> y) const;
  // The stored step's size and its end state at dense_step() (before projection).
  double dense_step() const { return dense_h_; }
  std::span<const double> dense_end() const { return dense_y1_; }

  // The weighted RMS norm (error_norm.h) of a local error estimate for the step from y_ to
  // y1_, over the components the method's error control measures (ControlledSize, or all with
  // the quadratures, which are measured against the system's QuadratureScale too).
  // Also notes the component with the largest weighted error of the attempt, for a failure.
  double ErrorNorm(std::span<const double> error);

  // Calls Derivative and counts it.
  bool Evaluate(double t, std::span<const double> y, std::span<double> dy);

  OdeSystem& system() const { return *system_; }
  const IntegratorOptions& options() const { return options_; }
  IntegratorStats& mutable_stats() { return stats_; }

  // The current state and the step being attempted, shared with the methods.
  double t_ = 0.0;
  double step_ = 0.0;       // size of the step being attempted
  std::vector<double> y_;   // state at t_
  std::vector<double> f0_;  // f(t_, y_)
  std::vector<double> y1_;  // candidate at t_ + step_
  std::vector<double> f1_;  // f(t_ + step_, y1_) once known

 private:
  enum class Failure { kNone, kEvaluation, kNotFinite, kErrorTest };

  // One attempt of a step of size h: the method's step, its error test (unless `fixed`) and the
  // end derivative; what failed, if anything.
  Failure Attempt(double h, bool fixed, double* error);
  // One accepted step towards t_stop (fixed_step > 0: of that size, without error control).
  AdvanceResult StepOnce(double t_stop, double fixed_step);
  // What the last step left for the next one to do first: the event it ended at (the system's
  // HandleEvent, the projection and a restart), then the system's CommitStep.
  void FinishPending();
  // Evaluates f0_ at the current state, restarts history and events, and (adaptive runs) picks
  // a first step. Returns false with `result` filled when the state cannot be started from.
  bool Restart(bool fixed, AdvanceResult* result);
  // Hairer's starting-step heuristic (dopri5.f HINIT), one extra evaluation.
  double InitialStep();
  double MinStep() const;
  double MaxStep() const;
  double ClampStep(double h) const;
  double EventTolerance() const;
  // The system's QuadratureScale at (t, y), just evaluated there, when the method measures the
  // quadratures.
  void UpdateQuadratureScale(double t, std::span<const double> y);
  AdvanceResult Fail(Failure failure, double h, double error);

  OdeSystem* system_ = nullptr;
  IntegratorOptions options_;
  IntegratorStats stats_;
  StepSizeController controller_;
  EventLocator events_;
  double h_ = 0.0;                    // next step to try
  std::size_t controlled_ = 0;        // how many components the error test measures
  std::size_t quadratures_from_ = 0;  // system().ControlledSize(): where the quadratures begin
  // The system's QuadratureScale at the current step start (0 while the method leaves the
  // quadratures out).
  double quadrature_scale_ = 0.0;
  bool restart_pending_ = true;
  // After an event that only changed the system's equations: the restart keeps the step size.
  bool keep_step_ = false;
  bool commit_pending_ = false;  // the last step's CommitStep is still to be made
  bool event_pending_ = false;   // the last step ended at an event not yet handled
  double step_start_ = 0.0;      // start of the last accepted step
  // The dense output's step: from dense_t0_ over dense_h_ (its end state before projection
  // dense_y1_), read up to dense_t1_ (the step's end, or the event that cut it short), where the
  // state is end_state_ (bit for bit what the step ended with); and the Hermite default's data.
  double dense_t0_ = 0.0;
  double dense_t1_ = 0.0;
  double dense_h_ = 0.0;
  std::vector<double> dense_y1_;
  std::vector<double> end_state_;
  std::vector<double> dense_y0_, dense_f0_, dense_f1_;
  double restart_step_ = 0.0;  // RestartAt's first step (0: none)
  // An event an attempt found inside its step, which the next attempts land on (infinity: none;
  // see StepOnce).
  double event_stop_ = std::numeric_limits<double>::infinity();
  bool redo_spent_ = false;     // the step was retaken for the event it found (StepOnce)
  double event_seen_at_ = 0.0;  // the end of the step that found it
  // The system's StepLimit at the current step start (infinity: none).
  double step_limit_ = std::numeric_limits<double>::infinity();

  std::vector<double> y_event_;    // state at a located event
  std::vector<double> y_project_;  // copy to see whether Project changed the state
  LargestComponent largest_;       // of the error estimates of the attempt under way
};

}  // namespace sled::runtime
