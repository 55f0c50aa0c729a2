// Quadratures measured against the system's scale (OdeSystem::QuadratureScale), by the methods
// that put them in their error test (exponential, Rosenbrock). A mass shot at a wall, whose
// contact spring's work is the quadrature: the work integral starts at zero where the contact
// begins, as at a located touch, and the contact's kink lies inside the first step (the event
// leaves the state within its tolerance of the surface). Measured against its own magnitude (a
// few nanojoules there), the quadrature's error at the kink is of its own size whatever the step,
// and the run stops at the minimum step; measured against the energy that flows, it costs few
// steps beyond the motion's and is right to the tolerance of that energy.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "runtime/integrate/make_integrator.h"
#include "runtime/integrate/ode.h"

namespace sled::runtime {
namespace {

// A unit mass at x against a wall at x = 0 with a hardening contact spring, x'' = F(x) with
// F = -k x - k3 x^3 for x < 0 and 0 in front of the wall; y = [x, v, W] with W the spring's work
// on the mass (W' = F v), the quadrature; `with_work` false leaves W out (size 2).
// QuadratureScale: the largest of the kinetic energy and |W| when `scaled`, else 0 (each
// quadrature against its own magnitude only).
class ContactWork : public OdeSystem {
 public:
  ContactWork(bool with_work, bool scaled) : with_work_(with_work), scaled_(scaled) {}
  std::size_t size() const override { return with_work_ ? 3 : 2; }
  std::size_t ControlledSize() const override { return 2; }
  bool Derivative(double, std::span<const double> y, std::span<double> dy) override {
    const double x = std::min(y[0], 0.0);
    const double force = -kStiffness * x - kHardening * x * x * x;
    dy[0] = y[1];
    dy[1] = force;
    if (with_work_) dy[2] = force * y[1];
    return true;
  }
  // The motion's rows only: like a multibody system's, the methods' A has none for the
  // quadratures (they feed nothing back; any A serves these methods).
  bool Jacobian(double, std::span<const double> y, std::span<double> jacobian) override {
    const std::size_t n = size();
    std::fill(jacobian.begin(), jacobian.end(), 0.0);
    jacobian[0 * n + 1] = 1.0;
    if (y[0] < 0.0) jacobian[1 * n + 0] = -kStiffness - 3.0 * kHardening * y[0] * y[0];
    return true;
  }
  double QuadratureScale(double, std::span<const double> y) override {
    return scaled_ ? std::max(0.5 * y[1] * y[1], std::abs(y[2])) : 0.0;
  }

  static constexpr double kStiffness = 1e6;  // N/m
  static constexpr double kHardening = 1e6;  // N/m^3

 private:
  bool with_work_, scaled_;
};

struct Outcome {
  bool ok = false;
  long steps = 0;
  double work_error = 0.0;  // |W - closed form| over the initial kinetic energy
};

// From x0 (at or just in front of the wall) at 1 km/s into it, to 2 ms, most of the way to
// where it stops (about 2.3 ms).
Outcome Integrate(const std::string& method, ContactWork& system, double tolerance, double x0) {
  std::unique_ptr<Integrator> integrator = MakeIntegrator(method);
  std::vector<double> y0 = {x0, -1000.0, 0.0};
  y0.resize(system.size());
  // sled's defaults: the absolute tolerance a thousandth of the relative one, 1 ns minimum step.
  IntegratorOptions options;
  options.relative_tolerance = tolerance;
  options.absolute_tolerance = 1e-3 * tolerance;
  options.min_step = 1e-9;
  integrator->Reset(system, 0.0, y0, options);
  Outcome outcome;
  outcome.ok = integrator->Advance(2e-3).status == IntegratorStatus::kOk;
  outcome.steps = integrator->stats().steps;
  if (outcome.ok && system.size() == 3) {
    // The work done on the mass is its kinetic energy's change.
    const std::span<const double> y = integrator->state();
    const double initial = 0.5 * y0[1] * y0[1];
    outcome.work_error = std::abs(y[2] - (0.5 * y[1] * y[1] - initial)) / initial;
  }
  return outcome;
}

class QuadratureScaled : public ::testing::TestWithParam<std::string> {};

// Where the run starts: on the wall, 1 ps of flight in front of it (where a located touch leaves
// the state: the event tolerance is 1 ps), 1 ns in front of it.
constexpr double kStarts[] = {0.0, 1e-9, 1e-6};

TEST_P(QuadratureScaled, TheWorkIsRightToTheToleranceOfTheEnergyForFewExtraSteps) {
  for (const double tolerance : {1e-4, 1e-6, 1e-8}) {
    for (const double x0 : kStarts) {
      ContactWork motion(false, false);
      ContactWork measured(true, true);
      const Outcome alone = Integrate(GetParam(), motion, tolerance, x0);
      const Outcome with_work = Integrate(GetParam(), measured, tolerance, x0);
      const std::string where =
          GetParam() + " tol " + std::to_string(tolerance) + " x0 " + std::to_string(x0);
      ASSERT_TRUE(alone.ok && with_work.ok) << where;
      std::printf("  %s: work error %.2f tolerances, %ld steps against %ld without the work\n",
                  where.c_str(), with_work.work_error / tolerance, with_work.steps, alone.steps);
      // Measured: 0.06 (exponential) and 0.84 (Rosenbrock) tolerances of the energy at most.
      EXPECT_LT(with_work.work_error, 10.0 * tolerance) << where;
      // Measured: 1.92x (exponential, whose steps on the motion alone are long: it is exact on
      // the linear spring) and 0.95x (Rosenbrock).
      EXPECT_LE(with_work.steps, 2.0 * static_cast<double>(alone.steps) + 2) << where;
    }
  }
}

TEST_P(QuadratureScaled, AgainstItsOwnMagnitudeTheKinkStopsTheRunAtTheMinimumStep) {
  // Why the scale: the kink 1 ps into the first step puts an error of the work's own size into
  // every step short enough to hold the motion, and with no scale that size is all it is
  // measured against. (Both methods ran with the default minimum step before the scale.)
  ContactWork own(true, false);
  EXPECT_FALSE(Integrate(GetParam(), own, 1e-8, 1e-9).ok) << GetParam();
  ContactWork scaled(true, true);
  EXPECT_TRUE(Integrate(GetParam(), scaled, 1e-8, 1e-9).ok) << GetParam();
}

INSTANTIATE_TEST_SUITE_P(ImplicitSide, QuadratureScaled,
                         ::testing::Values("exponential", "rosenbrock"));

}  // namespace
}  // namespace sled::runtime
