// The interface between the integrators and what they integrate. The dynamics implements
// OdeSystem for a Model; tests implement it for analytic ODEs. Integrators know nothing of
// segments or joints, only of a flat state vector, its 3-vector groups (for the CVS exponential
// method), events, and optional Jacobians.
#pragma once

#include <cstddef>
#include <limits>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace sled::runtime {

class Archive;              // runtime/run/archive.h
struct StructuredJacobian;  // runtime/integrate/structured_jacobian.h

// y' = f(t, y), with events g_k(t, y) whose sign changes the integrator must locate.
class OdeSystem {
 public:
  virtual ~OdeSystem() = default;

  virtual std::size_t size() const = 0;

  // dy = f(t, y). Returns false when f cannot be evaluated (NaN, a singular system): the
  // integrator then rejects the step or, at the minimum step, fails with the system's reason.
  virtual bool Derivative(double t, std::span<const double> y, std::span<double> dy) = 0;

  // The Jacobian df/dy, row-major n x n, if the system can give it cheaply; the default says it
  // cannot, and implicit methods fall back on finite differences of Derivative.
  virtual bool Jacobian(double t, std::span<const double> y, std::span<double> jacobian) {
    (void)t, (void)y, (void)jacobian;
    return false;
  }

  // The Jacobian approximation A = N + U V^T of structured_jacobian.h at (t, y), where
  // f(t, y) = dy, for a step of about `step`: N the kinematic part, U V^T the stiff part, from
  // which terms too soft to limit such a step may be left out. The exponential and Rosenbrock
  // methods use it (they stay correct with any A; it decides how long their steps can be). It
  // fills at most StructuredRank() columns into `jacobian` (already cleared and sized). False
  // when it cannot be formed (the method then rejects the step). A system with StructuredRank()
  // 0 has none: the methods use the dense Jacobian (Jacobian, or differences) instead.
  virtual bool StructuredJacobianAt(double t, std::span<const double> y, std::span<const double> dy,
                                    double step, StructuredJacobian& jacobian) {
    (void)t, (void)y, (void)dy, (void)step, (void)jacobian;
    return false;
  }
  virtual std::size_t StructuredRank() const { return 0; }

  // How many leading components the error control measures. The rest are quadratures:
  // integrals of quantities of the state (the energy balance's work terms) that feed nothing
  // back, carried along with the state but never the reason a step is rejected or shortened.
  virtual std::size_t ControlledSize() const { return size(); }

  // The magnitude the quadratures are measured against, at (t, y), where Derivative was just
  // evaluated. A method that puts the quadratures in its error test (AdaptiveIntegrator::
  // ControlsQuadratures) weighs each one's error with atol + rtol * max(|value|, scale), as a
  // state's is with atol + rtol * |value|: a work integral that passes through zero (the elastic
  // energy a contact stores and gives back) is then held to the tolerance of the energy that
  // flows, not to the absolute tolerance. The default 0 measures each quadrature against its own
  // magnitude only (CVODE's quadrature error control with the state's tolerances).
  virtual double QuadratureScale(double t, std::span<const double> y) {
    (void)t, (void)y;
    return 0.0;
  }

  // State components that form 3-vectors (a segment's angular velocity, say), as the starting
  // index of each group; the CVS exponential integrator estimates one decay rate per group.
  // Components outside every group are integrated with a decay rate of zero.
  virtual std::vector<std::size_t> VectorGroups() const { return {}; }

  // After an accepted step: renormalise quaternions and the like. Must not change the solution
  // more than the tolerance; it exists so drift does not accumulate.
  virtual void Project(double t, std::span<double> y) { (void)t, (void)y; }

  // The longest step the system allows from (t, y), where Derivative was just evaluated: a
  // bound for what the error test cannot see coming, such as a contact that begins inside a step
  // of free flight (the pair's gap closes at its closing speed). The integrators take no step
  // longer than this (ask it at every step start); the default sets no bound.
  virtual double StepLimit(double t, std::span<const double> y) {
    (void)t, (void)y;
    return std::numeric_limits<double>::infinity();
  }

  // What the system carries from one accepted step to the next outside the state (a history
  // that only changes between steps). The integrator calls it with the step's end state, as the
  // step ended it before the projection, when the next step begins (after the caller has read
  // the step's dense output), and after an event with the state the event left.
  virtual void CommitStep(double t, std::span<const double> y) { (void)t, (void)y; }

  // Events: the integrator locates each sign change of g_k within a step (to `event_tolerance`
  // in time), stops there, and calls HandleEvent, which may change y (an impulse) and the
  // system itself (a joint locks). After an event the integrator restarts its history.
  virtual std::size_t EventCount() const { return 0; }
  // How many points inside each accepted step the event functions are also evaluated at (on the
  // step's continuous extension, one evaluation each), for event functions that can cross and
  // cross back within one step, where the signs at the step's ends see nothing (a locked joint's
  // constraint torque passing its unlock level for a moment). 0: the ends only.
  virtual std::size_t EventSamples() const { return 0; }
  virtual void Events(double t, std::span<const double> y, std::span<double> g) {
    (void)t, (void)y, (void)g;
  }
  // Which sign changes of g_k are events: -1 only falls through zero, +1 only rises, 0 both.
  // A crossing the other way is no event: the step is neither stopped nor taken again there (a
  // loading history's turn function rises again, through zero or by a jump to 1, where nothing
  // happens).
  virtual int EventDirection(std::size_t k) const {
    (void)k;
    return 0;
  }
  // `direction` is +1 when g_k went from negative to positive, -1 the other way. Returns
  // kStateChanged when it changed y (an impulse): the integrator then starts afresh with its
  // starting-step heuristic; kModeChanged when only the system's equations changed (a joint locks
  // its axes' equations, a loading history turns): the next step keeps the step size.
  enum class EventEffect { kModeChanged, kStateChanged };
  virtual EventEffect HandleEvent(std::size_t k, int direction, double t, std::span<double> y) {
    (void)k, (void)direction, (void)t, (void)y;
    return EventEffect::kModeChanged;
  }

  // Why Derivative last returned false, for the failure report.
  virtual std::string FailureReason() const { return {}; }
};

// The smallest relative tolerance a double can meet: a step's own rounding errors are a few
// ulps of the state per stage, and the error test needs the tolerance well above them (dopri5.f
// refuses below 10 ulps). 100 ulps: 2.2e-14.
inline constexpr double kMinRelativeTolerance = 100.0 * 2.220446049250313e-16;

// The smallest absolute tolerance: kMinRelativeTolerance of a thousandth of an SI unit. The
// absolute tolerance weighs a state component near zero (a joint angle, a velocity at rest),
// whose rounding error is that of the terms it is made of: a thousandth of a metre, metre per
// second or radian is the finest scale a crash scene's state has (a millimetre, a milliradian),
// and 100 ulps of it is what a step's rounding leaves. Below it, such a component fails the
// error test on rounding alone (1e-300 held a velocity at rest to nothing: every step shrank to
// the minimum). It is also the default (a thousandth of `tolerance`) at the tightest tolerance.
inline constexpr double kMinAbsoluteTolerance = 1e-3 * kMinRelativeTolerance;

struct IntegratorOptions {
  double relative_tolerance = 1e-6;
  double absolute_tolerance = 1e-9;
  double min_step = 1e-12;
  double max_step = 0.0;      // 0: no limit beyond the output step
  double initial_step = 0.0;  // 0: chosen by the integrator
  double event_tolerance = 1e-12;
  // Where the run ends (infinity: not known). `auto` weighs a switch against the time left.
  double end_time = std::numeric_limits<double>::infinity();
};

struct IntegratorStats {
  long steps = 0;  // accepted
  long rejected = 0;
  long evaluations = 0;     // calls of Derivative
  long jacobians = 0;       // Jacobians formed (analytic or by differences)
  long factorizations = 0;  // linear systems factored (implicit methods)
  long events = 0;
  // Accepted steps of the exponential method in which at least one 3-vector group was integrated
  // with a decay rate (the rest were plain third-order Runge-Kutta steps); 0 for other methods.
  long decaying_steps = 0;
  // The largest weighted local error estimate of any accepted step (1 = exactly the tolerance).
  // (A global error estimate needs a second run: output/post/global_error.h.)
  double max_local_error = 0.0;
  // `auto` only: what each of its two methods integrated (steps, simulated seconds and wall
  // seconds of the integrator's own work), and how often it switched between them.
  struct Share {
    long steps = 0;
    double simulated = 0.0;
    double wall_seconds = 0.0;
  };
  Share explicit_share;     // dopri5
  Share exponential_share;  // the exponential method
  long switches = 0;
};

enum class IntegratorStatus {
  kOk,
  kMinStepReached,    // the error test failed at the minimum step: never silently accepted
  kEvaluationFailed,  // Derivative returned false at the minimum step
  kNotFinite,         // the state became NaN or infinite
};

struct AdvanceResult {
  IntegratorStatus status = IntegratorStatus::kOk;
  double t = 0.0;  // where the integration stopped (the target time when kOk)
  std::string reason;
  // On a failure, the state component it is in when the integrator can tell (the largest
  // weighted error at the minimum step, the first value that is not finite); -1 otherwise.
  std::ptrdiff_t component = -1;
};

// One interface for every method.
//
// Stepping. Step(t_stop) takes one accepted step from time() towards t_stop and never past it:
// the step ends at t_stop exactly when it reaches it (stretched by up to 1% rather than leave a
// sliver), or earlier where the error control or an event (located inside the step) ends it.
// Callers pass as t_stop the next time the solution must not be stepped over: the end of the run
// and the input's discontinuities (a pulse's kinks, a table's breakpoints). Output times are not
// stops: they are read from the dense output.
//
// Dense output. After a step, Interpolate(t, y) gives the method's continuous extension of the
// step just taken, for step_start() <= t <= time() (dopri5: Shampine's fourth-order
// interpolant; the exponential method: its own exponential model of the step; rosenbrock: cubic
// Hermite from the end values and derivatives). At time() it returns the step's end state before
// projection, and at a located event the state before the event's change. The system's
// step-to-step histories (OdeSystem::CommitStep) are committed only when the next step begins,
// so the caller evaluates anything on the step just taken with the histories that step used.
//
// Advance(t_end) is Step(t_end) until time() == t_end, for callers that need the state exactly
// at given times (tests, fixed-interval drivers); it lands on t_end, which Step only does at a
// stop.
class Integrator {
 public:
  virtual ~Integrator() = default;
  virtual std::string_view name() const = 0;
  virtual int order() const = 0;
  // Starts a solution at (t0, y0). Allocates all workspace here, never in Step or Advance.
  virtual void Reset(OdeSystem& system, double t0, std::span<const double> y0,
                     const IntegratorOptions& options) = 0;
  // One accepted step towards t_stop (see above). Returns kOk with t = time() after it; a call
  // with time() >= t_stop takes no step. On a failure the state stays at the last accepted step.
  virtual AdvanceResult Step(double t_stop) = 0;
  // Steps until time() == t_end exactly.
  AdvanceResult Advance(double t_end) {
    AdvanceResult result;
    result.t = time();
    while (time() < t_end) {
      result = Step(t_end);
      if (result.status != IntegratorStatus::kOk) return result;
    }
    result.t = time();
    return result;
  }
  virtual double time() const = 0;
  // Where the last step started (time() before the first step).
  virtual double step_start() const = 0;
  // The continuous extension of the last step at step_start() <= t <= time(). Must not allocate.
  virtual void Interpolate(double t, std::span<double> y) const = 0;
  virtual std::span<const double> state() const = 0;
  // Lets the caller change the state between calls (an external event); restarts history.
  virtual std::span<double> mutable_state() = 0;
  virtual const IntegratorStats& stats() const = 0;
  // Writes or reads (archive.reading()) everything the method carries from one step to the
  // next, after Reset with the same system and options: a run restored from it continues bit
  // for bit as the saved one would have.
  virtual void Serialize(Archive& archive) = 0;
};

}  // namespace sled::runtime
