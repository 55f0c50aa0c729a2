// Event location shared by every integrator. After an accepted step the integrator evaluates
// the system's event functions g_k at the step end; for every sign change it locates the root on
// a continuous interpolant of the step (the method's dense output, or a cubic Hermite from the
// end values and derivatives) by a safeguarded Illinois iteration, stops at the earliest root, and
// hands the crossing components to the system. A step that went past an event is taken again to end
// on it (AdaptiveIntegrator::StepOnce), so the state handed over comes from a step whose stages did
// not see the other side of the event.
#pragma once

#include <cstddef>
#include <limits>
#include <span>
#include <vector>

#include "runtime/integrate/ode.h"

namespace sled::runtime {

// A continuous solution over the step just accepted, from t0 to t1.
class StepInterpolant {
 public:
  virtual ~StepInterpolant() = default;
  // y(t) for t0 <= t <= t1. Must not allocate.
  virtual void Interpolate(double t, std::span<double> y) const = 0;
};

// The cubic Hermite interpolant on [t0, t0 + h] through (y0, f0) and (y1, f1), at
// theta = (t - t0) / h. Third order, so it keeps the accuracy of the third-order methods.
void HermiteInterpolate(double theta, double h, std::span<const double> y0,
                        std::span<const double> f0, std::span<const double> y1,
                        std::span<const double> f1, std::span<double> y);

class EventLocator {
 public:
  // Sizes the buffers for the system's events (allocates; call from Reset).
  void Reset(OdeSystem& system);
  bool active() const { return count_ > 0; }

  // Evaluates g at the start of a run of steps (after a reset or an event). A component that is
  // exactly zero there, or whose event was just handled, takes its sign from g a little later:
  // at (t + look_ahead, y + look_ahead * dy). So the root just handled is not found again when
  // the handler leaves the state on (or a rounding error beyond) the surface g = 0, as a
  // bouncing ball's reversed velocity does.
  void Start(double t, std::span<const double> y, std::span<const double> dy, double look_ahead,
             std::span<double> scratch);

  // After an accepted step ending at (t1, y1): evaluates g there and says whether any component
  // changed sign since the step start.
  bool Check(double t1, std::span<const double> y1);

  // After Check (whatever it found at the step's end): evaluates g at the system's
  // EventSamples() points evenly inside [t0, t1] on `interpolant`; true, with `t_found` the first
  // of them where a component has crossed since the step start (g there becomes the bracket's
  // high end for Locate), when one has. `y` is scratch.
  bool CheckInside(const StepInterpolant& interpolant, double t0, double t1, std::span<double> y,
                   double& t_found);

  // Locates the earliest root in [t0, t1] to `tolerance` in time on `interpolant`, and returns
  // the end of the final bracket: a time just past the root, where every crossing component has
  // its new sign. Leaves y at that time in `y` and records the crossing components. `t_probe`,
  // when inside (t0, t1), is tried first: a guess that makes the first bracket narrow.
  double Locate(const StepInterpolant& interpolant, double t0, double t1, double tolerance,
                std::span<double> y, double t_probe = std::numeric_limits<double>::quiet_NaN());

  // After Locate: +1 or -1 for each component that crossed (g went up or down), 0 for the others.
  std::span<const int> crossings() const { return crossing_; }

  // No event in the step: the end values become the next step's start values.
  void Advance();

  // What it carries between steps, for checkpoints (runtime/run/archive.h).
  template <class Archive>
  void Serialize(Archive& archive) {
    archive.Field(g_start_);
    archive.Field(g_end_);
    archive.Field(crossing_);
    archive.Field(settle_);
  }

 private:
  // Index of the component whose secant root on [lo, hi] comes first, or -1 if none changes sign.
  long EarliestCrossing(std::span<const double> g_low, std::span<const double> g_high) const;

  OdeSystem* system_ = nullptr;
  std::size_t count_ = 0;
  std::size_t samples_ = 0;      // OdeSystem::EventSamples, read once in Reset
  std::vector<double> g_start_;  // at the step start
  std::vector<double> g_end_;    // at the step end
  std::vector<double> g_low_;    // Illinois bracket
  std::vector<double> g_high_;
  std::vector<double> g_mid_;
  std::vector<int> crossing_;
  std::vector<signed char> direction_;  // OdeSystem::EventDirection, read once in Reset
  std::vector<char> settle_;            // components whose start sign comes from the look-ahead
};

}  // namespace sled::runtime
