// `auto`, the default method: Dormand-Prince 5(4) while the problem is not stiff, the exponential
// method while it is, and back, in the spirit of LSODA (Petzold, SIAM J. Sci. Stat. Comput. 4
// (1983) 136-148) and of DifferentialEquations.jl's AutoTsit5(Rosenbrock23()), with the
// exponential method (exponential_rk.h) on the stiff side.
//
// - To the exponential method: when Hairer's estimate of h |lambda| (dopri5.f, DormandPrince::
//   stiffness_ratio) has been above kStiffRatio on kStiffSteps accepted steps in a row. Its
//   step is then set by stability, not accuracy, and the exponential method, stable at any step
//   for the stiff part of its Jacobian, takes what accuracy allows. The estimate sees the stiff
//   mode only in part (along y1 - Y6), so the threshold is below the edge of the stability
//   region (3.3): dopri5's own test (above 3.25 on 15 steps without 6 below in between) handed
//   `viscous_damping` over only at 0.23 s of its 1 s, this one at 0.06 s. A wrong guess costs
//   little: the exponential method hands back after kMinSteps steps, and each hand-back from a
//   stint in which it never went beyond what dopri5 could take doubles the steps dopri5 keeps the
//   problem before it may hand over again (up to kMaxExplicitSteps), so the two cannot chatter.
//   A stint whose first step ends with h rho <= kNotStiff (rho as below) hands back at once.
//   Nor does it hand over when the run ends within kWorthSteps of dopri5's present steps
//   (IntegratorOptions::end_time): a step of the exponential method costs several of dopri5's
//   (its structured Jacobian and phi-functions: on `step_1000g` about 200,000 instructions
//   against 40,000, on the flagship 4.9e6 against 0.72e6), so a stiff stretch that dopri5
//   finishes in a handful of stable steps is cheaper left to it. `step_1000g` (a critically
//   damped spring, stiff all run long) handed over with 6 and 4 such steps left at 1e-2 and
//   1e-3 and cost 1.97e6 and 1.91e6 instructions in the run against dopri5's 1.14e6 and
//   1.18e6; now 1.18e6 and 1.23e6 (callgrind).
// - Back to dopri5: when the exponential method's steps have stayed below kHandBackStep / rho for
//   kSettleSteps steps in a row, with rho the largest rate of the force elements' stiff terms
//   (its Jacobian's stiff_rate): about 2.5 times dopri5's stable step 3.3 / rho. A step of the
//   exponential method costs several of dopri5's (four evaluations, the structured Jacobian and
//   the phi-functions of its stiff subspace: on the flagship 4.9e6 instructions against 0.72e6),
//   so dopri5 at its stable step is then the cheaper method. (With the bound at 2, dopri5's own
//   step, the flagship's exponential stints took 195 steps at h rho of 0 to 16, mostly 2 to 6,
//   and auto 2.54e9 instructions at 1e-3 against dopri5's 1.53e9; at 8, 1.85e9; at 16, 1.95e9.)
//   dopri5 takes over at a step it can take stably, kExplicitStable / rho. A contact that
//   separates, a belt that goes slack or a stop that is left makes rho fall and hands the
//   problem back.
// - Each method takes at least kMinSteps steps before it may hand over, so the two cannot chatter.
//
// A switch is decided after a step and made when the next step begins (the caller reads the
// step's dense output from the method that took it in between): the old method settles what its
// step left (its event, the system's CommitStep), and the new one restarts from its state, as
// after an event (the system's histories and events carry over). Statistics are summed over both;
// stats().explicit_share and exponential_share say how many steps, how much simulated time and how
// much of the integrator's wall time each method had, and stats().switches how often it switched.
#pragma once

#include <span>
#include <string_view>
#include <vector>

#include "runtime/integrate/dormand_prince.h"
#include "runtime/integrate/exponential_rk.h"
#include "runtime/integrate/ode.h"

namespace sled::runtime {

class AutoIntegrator final : public Integrator {
 public:
  static constexpr long kMinSteps = 10;
  static constexpr long kSettleSteps = 10;
  static constexpr double kExplicitStable = 2.0;
  static constexpr double kHandBackStep = 8.0;
  static constexpr long kStiffSteps = 3;
  static constexpr double kNotStiff = 1.0;
  static constexpr double kStiffRatio = 2.0;
  static constexpr long kMaxExplicitSteps = 640;
  static constexpr double kWorthSteps = 8.0;

  // User-provided (defined out of line), as ExponentialRungeKutta's: no zeroing of the whole
  // object by std::make_unique.
  AutoIntegrator();

  std::string_view name() const override { return "auto"; }
  int order() const override { return active().order(); }
  void Reset(OdeSystem& system, double t0, std::span<const double> y0,
             const IntegratorOptions& options) override;
  AdvanceResult Step(double t_stop) override;
  double time() const override { return active().time(); }
  double step_start() const override { return active().step_start(); }
  // The last step's dense output, by the method that took it (a switch waits for the next Step).
  void Interpolate(double t, std::span<double> y) const override { active().Interpolate(t, y); }
  std::span<const double> state() const override { return active().state(); }
  std::span<double> mutable_state() override { return active().mutable_state(); }
  const IntegratorStats& stats() const override;
  void Serialize(Archive& archive) override;

  // Which method has the solution now.
  bool stiff_mode() const { return stiff_; }

 private:
  AdaptiveIntegrator& active() {
    return stiff_ ? static_cast<AdaptiveIntegrator&>(exponential_)
                  : static_cast<AdaptiveIntegrator&>(explicit_);
  }
  const AdaptiveIntegrator& active() const {
    return stiff_ ? static_cast<const AdaptiveIntegrator&>(exponential_)
                  : static_cast<const AdaptiveIntegrator&>(explicit_);
  }
  // Hands the solution to the other method, starting it with `first_step`.
  void Switch(double first_step);
  // Decided after a step, made before the next one (the caller reads the step's dense output in
  // between); 0: none.
  double pending_switch_step_ = 0.0;
  // Whether the method that has the solution should hand it over, after its last step.
  bool ShouldSwitch();
  // Whether dopri5, held at its stable step, would take more than kWorthSteps steps to the end
  // of the run: fewer cost less than the exponential method's first steps.
  bool WorthHandingOver() const;

  OdeSystem* system_ = nullptr;
  IntegratorOptions options_;
  DormandPrince explicit_;
  ExponentialRungeKutta exponential_;
  bool stiff_ = false;
  long steps_in_mode_ = 0;
  long settled_steps_ = 0;
  long stiff_steps_ = 0;                 // dopri5's steps in a row held by stability
  long explicit_min_steps_ = kMinSteps;  // grows after each hand-back that was not needed
  // The sum of both methods' statistics, with the shares.
  mutable IntegratorStats total_;
  IntegratorStats::Share explicit_share_, exponential_share_;  // of the modes that ended
  long switches_ = 0;
  double mode_start_time_ = 0.0;
  double mode_wall_seconds_ = 0.0;
  std::vector<double> handover_;  // the state at a switch
};

}  // namespace sled::runtime
