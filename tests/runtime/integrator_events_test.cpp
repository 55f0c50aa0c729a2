// Event location, dense output and failure reports of every integrator: the bouncing ball, the
// state at an event, a failing derivative, a blow-up and a minimum step too large.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <memory>
#include <numbers>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "runtime/integrate/adaptive_integrator.h"
#include "runtime/integrate/dormand_prince.h"
#include "runtime/integrate/exponential.h"
#include "runtime/integrate/make_integrator.h"
#include "runtime/integrate/ode.h"
#include "runtime/integrate/rosenbrock.h"
#include "tests/runtime/integrator_test_systems.h"
#include "tests/runtime/ode_test_helpers.h"

namespace sled::runtime {
namespace {

using testing::BlowsUp;
using testing::BouncingBall;
using testing::EveryMethod;
using testing::FailsAboveOne;
using testing::Kepler;
using testing::LinearSystem;
using testing::Make;
using testing::MaxAbsDifference;
using testing::Tolerance;

// An integrator for the ball dropped from 1 m at rest, at a tolerance of 1e-8.
std::unique_ptr<Integrator> Dropped(BouncingBall& ball, const char* method) {
  ball.Reserve();
  auto integrator = Make(method);
  const double y0[] = {1.0, 0.0};
  integrator->Reset(ball, 0.0, y0, Tolerance(1e-8));
  return integrator;
}

// (d) Event location: the bouncing ball.
TEST_P(EveryMethod, BouncingBallFindsImpactsAndApexes) {
  BouncingBall ball;
  auto integrator = Dropped(ball, GetParam());
  // Output every 50 ms: events and output times interleave.
  for (int k = 1; k <= 40; ++k) {
    ASSERT_EQ(integrator->Advance(0.05 * k).status, IntegratorStatus::kOk);
  }
  EXPECT_EQ(integrator->time(), 2.0);
  const double t1 = std::sqrt(2.0 / BouncingBall::kG);
  ASSERT_GE(ball.impacts.size(), 2u);
  EXPECT_NEAR(ball.impacts[0], 0.451524, 1e-6);
  EXPECT_NEAR(ball.impacts[0], t1, 1e-9);
  // Each flight lasts e times the previous one (2 t1 e for the first full arc).
  EXPECT_NEAR(ball.impacts[1], t1 + 2.0 * BouncingBall::kRestitution * t1, 1e-9);
  ASSERT_GE(ball.apexes.size(), 2u);
  EXPECT_NEAR(ball.apexes[0], 0.64, 1e-9);
  EXPECT_NEAR(ball.apexes[1], 0.4096, 1e-9);
  // Impacts at 0.45, 1.17, 1.75 s and apexes at 0.81, 1.46, 1.98 s before t = 2, and no
  // spurious event right after an impact (the ball leaving the floor).
  EXPECT_EQ(ball.impacts.size(), 3u);
  EXPECT_EQ(ball.apexes.size(), 3u);
  EXPECT_EQ(integrator->stats().events, 6);
}

// Dense output: the damped rotation read between step ends is as accurate as at them, steps
// go past any output time (only t_stop is landed on), and the interpolant joins the step ends.
TEST_P(EveryMethod, DenseOutputFollowsTheSolutionBetweenStepEnds) {
  const double a = -0.1, b = 2.0;
  LinearSystem oscillator(2, {a, -b, b, a});
  auto exact = [&](double t) {
    const double decay = std::exp(a * t);
    return std::array<double, 2>{decay * std::cos(b * t), decay * std::sin(b * t)};
  };
  for (const double tol : {1e-4, 1e-7}) {
    auto integrator = Make(GetParam());
    const double y0[] = {1.0, 0.0};
    integrator->Reset(oscillator, 0.0, y0, Tolerance(tol));
    double worst_end = 0.0, worst_between = 0.0;
    long steps = 0;
    std::array<double, 2> y{};
    while (integrator->time() < 10.0) {
      const double before = integrator->time();
      const std::array<double, 2> start = {integrator->state()[0], integrator->state()[1]};
      ASSERT_EQ(integrator->Step(10.0).status, IntegratorStatus::kOk);
      ++steps;
      EXPECT_EQ(integrator->step_start(), before);
      EXPECT_LE(integrator->time(), 10.0);
      integrator->Interpolate(before, y);
      EXPECT_EQ(y, start);  // the interpolant starts where the step did
      for (const double f : {0.25, 0.5, 0.75}) {
        const double t = before + f * (integrator->time() - before);
        integrator->Interpolate(t, y);
        worst_between = std::max(worst_between, MaxAbsDifference(y, exact(t)));
      }
      integrator->Interpolate(integrator->time(), y);
      EXPECT_EQ(y[0], integrator->state()[0]);  // the end itself, bit for bit (no projection)
      worst_end =
          std::max(worst_end, MaxAbsDifference(integrator->state(), exact(integrator->time())));
    }
    EXPECT_EQ(integrator->time(), 10.0);  // the stop is landed on
    EXPECT_EQ(steps, integrator->stats().steps);
    // Between step ends within a few times the error at them.
    EXPECT_LT(worst_between, 3.0 * worst_end + tol) << GetParam() << " tol " << tol;
    EXPECT_LT(worst_between, 100.0 * tol) << GetParam() << " tol " << tol;
  }
}

// A linear decay inside a vector group is the exponential method's own model: its dense output
// is exact at every point of the step, however stiff (h lambda = -50), where a cubic Hermite
// interpolant would swing to -7 of the initial value.
TEST(ExponentialTest, DenseOutputOfALinearDecayIsExactInsideTheStep) {
  const double k = 50.0;
  LinearSystem decay(3, {-k, 0, 0, 0, -k, 0, 0, 0, -k}, {0});
  ExponentialIntegrator integrator;
  const double y0[] = {1.0, -2.0, 0.5};
  integrator.Reset(decay, 0.0, y0, Tolerance(1e-6));
  ASSERT_EQ(integrator.AdvanceFixed(1.0, 1).status, IntegratorStatus::kOk);
  std::array<double, 3> y{};
  for (const double t : {0.001, 0.01, 0.1, 0.5, 0.9}) {
    integrator.Interpolate(t, y);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(y[i], y0[i] * std::exp(-k * t), 1e-12) << t;
  }
}

// A step that reaches an event ends there with the state before it; the system's handler (and
// the histories' commit) runs when the next step begins.
TEST_P(EveryMethod, AStepEndsAtAnEventWithTheStateBeforeIt) {
  BouncingBall ball;
  auto integrator = Dropped(ball, GetParam());
  while (ball.impacts.empty()) {
    ASSERT_EQ(integrator->Step(2.0).status, IntegratorStatus::kOk);
    if (std::abs(integrator->time() - std::sqrt(2.0 / BouncingBall::kG)) < 1e-9) {
      EXPECT_TRUE(ball.impacts.empty());
      EXPECT_LT(integrator->state()[1], 0.0);  // still falling: the impulse waits
      EXPECT_NEAR(integrator->state()[0], 0.0, 1e-9);
    }
  }
  EXPECT_GT(integrator->state()[1], 0.0);  // the next step began with the rebound
}

// (e) Failures are reported with their time and cause.
TEST_P(EveryMethod, FailingDerivativeIsReportedWithTimeAndReason) {
  FailsAboveOne system;
  auto integrator = Make(GetParam());
  const double y0[] = {0.0};
  integrator->Reset(system, 0.0, y0, Tolerance(1e-6));
  const AdvanceResult result = integrator->Advance(2.0);
  EXPECT_EQ(result.status, IntegratorStatus::kEvaluationFailed);
  EXPECT_EQ(result.reason, "y exceeds 1");
  EXPECT_LE(result.t, 1.0);
  EXPECT_GT(result.t, 1.0 - 1e-6);
  EXPECT_EQ(result.t, integrator->time());
}

TEST_P(EveryMethod, BlowUpIsReportedAsNotFinite) {
  BlowsUp system;
  auto integrator = Make(GetParam());
  const double y0[] = {1e290};
  integrator->Reset(system, 0.0, y0, Tolerance(1e-6));
  const AdvanceResult result = integrator->Advance(1.0);
  EXPECT_EQ(result.status, IntegratorStatus::kNotFinite);
  EXPECT_FALSE(result.reason.empty());
  // It stops where the state was last finite: within the last few ulps of the double range.
  EXPECT_GT(result.t, 0.03);
  EXPECT_LT(result.t, 0.05);
  EXPECT_EQ(result.t, integrator->time());
  EXPECT_TRUE(std::isfinite(integrator->state()[0]));
}

// (f) A minimum step too large for the tolerance is reported, never accepted silently.
TEST_P(EveryMethod, MinimumStepTooLargeIsReported) {
  Kepler kepler;
  auto integrator = Make(GetParam());
  IntegratorOptions options = Tolerance(1e-12);
  options.min_step = 0.5;
  integrator->Reset(kepler, 0.0, Kepler::Initial(0.5), options);
  const AdvanceResult result = integrator->Advance(10.0);
  EXPECT_EQ(result.status, IntegratorStatus::kMinStepReached);
  EXPECT_LT(result.t, 10.0);
  EXPECT_NE(result.reason.find("minimum step"), std::string::npos);
  EXPECT_GT(integrator->stats().rejected, 0);
}

// (g) The exponential method is exact for y' = -k y in a single step of any size.

// RestartAt's first step (what `auto` hands over with) is for the first step after it only: the
// step after a later event that changed no state keeps the size the steps had. (It used to be
// taken again after every event: after `auto`'s first hand-back on the flagship, a step of
// 6.1e-5 s after each of about 100 events, where 5e-4 s passed the error test.)
TEST(RestartAt, FirstStepIsForTheFirstStepOnly) {
  BouncingBall ball;
  ball.Reserve();
  DormandPrince integrator;
  const double y0[] = {1.0, 0.0};
  integrator.Reset(ball, 0.0, y0, Tolerance(1e-8));
  const double first_step = 1e-7;
  integrator.RestartAt(0.0, y0, first_step);
  ASSERT_EQ(integrator.Step(2.0).status, IntegratorStatus::kOk);
  EXPECT_DOUBLE_EQ(integrator.time(), first_step);
  // To the first apex (an event that changes no state), then one more step.
  while (ball.apexes.empty()) ASSERT_EQ(integrator.Step(2.0).status, IntegratorStatus::kOk);
  const double kept = integrator.step_size();
  ASSERT_GT(kept, 1e3 * first_step);
  ASSERT_EQ(integrator.Step(2.0).status, IntegratorStatus::kOk);
  EXPECT_GT(integrator.time() - integrator.step_start(), 1e3 * first_step);
}

}  // namespace
}  // namespace sled::runtime
