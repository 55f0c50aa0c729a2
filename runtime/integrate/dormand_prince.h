// Dormand–Prince 5(4): the explicit embedded Runge–Kutta pair of dopri5.f (Hairer, Nørsett &
// Wanner, Solving ODEs I, §II.5 and II.6), with FSAL, the standard embedded error estimate, the
// shared PI controller and the fourth-order continuous extension used for event location.
// For non-stiff problems; on stiff ones its step is stability-bound (h |lambda| <= about 3.3).
#pragma once

#include <cstddef>
#include <span>
#include <string_view>
#include <vector>

#include "runtime/integrate/adaptive_integrator.h"

namespace sled::runtime {

class DormandPrince final : public AdaptiveIntegrator {
 public:
  // Hairer's stiffness detection (dopri5.f): each step estimates h |lambda| from its last two
  // stages, which share the time t + h, as h ||f(t + h, y1) - f(t + h, Y6)|| / ||y1 - Y6||. The
  // problem seems stiff once the estimate exceeded kStiffRatio (near the edge of the stability
  // region on the negative real axis) on kStiffSteps accepted steps without kNonStiffSteps in a
  // row below it in between.
  static constexpr double kStiffRatio = 3.25;
  static constexpr int kStiffSteps = 15;
  static constexpr int kNonStiffSteps = 6;

  std::string_view name() const override { return "dopri5"; }
  int order() const override { return 5; }

  bool seems_stiff() const { return stiff_steps_ >= kStiffSteps; }
  // The estimate of h |lambda| of the last step attempted.
  double stiffness_ratio() const { return stiffness_ratio_; }

 protected:
  int ErrorPower() const override { return 5; }  // the estimate is O(h^5)
  void ResizeWorkspace(std::size_t size) override;
  bool TryStep(double h, double* error) override;
  bool HasEndDerivative() const override { return true; }  // stage 7 is f(t + h, y1)
  void PrepareDenseOutput() override;
  void SerializeHistory(Archive& archive) override;
  void DenseOutput(double theta, std::span<double> y) const override;
  void RestartHistory() override;
  void StepAccepted() override;

 private:
  // Stages 2..6; stage 1 is f0_ and stage 7 is f1_.
  std::vector<double> k2_, k3_, k4_, k5_, k6_;
  std::vector<double> stage_;  // the argument of the next stage evaluation
  std::vector<double> error_;  // the embedded error estimate
  // The continuous extension of the last accepted step, y0 + s (r2 + (1-s) (r3 + s (r4 + (1-s)
  // r5))): r1 = y0, then r2 .. r5.
  std::vector<double> r1_, r2_, r3_, r4_, r5_;
  std::size_t controlled_ = 0;  // system().ControlledSize(): the quadratures are left out
  double stiffness_ratio_ = 0.0;
  int stiff_steps_ = 0;
  int nonstiff_steps_ = 0;
};

}  // namespace sled::runtime
