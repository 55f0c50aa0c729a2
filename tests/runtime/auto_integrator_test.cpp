// `auto` (runtime/integrate/auto_integrator.h): dopri5 where the problem is not stiff, the
// exponential method while it is, and back; checked on a ball that lands on a stiff, damped
// floor, rests on it, and is lifted off again by a force that switches on later, against a
// Dormand-Prince reference at a far tighter tolerance.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <cstdio>
#include <span>
#include <vector>

#include "runtime/integrate/auto_integrator.h"
#include "runtime/integrate/dormand_prince.h"
#include "runtime/integrate/make_integrator.h"
#include "runtime/integrate/structured_jacobian.h"
#include "tests/runtime/ode_test_helpers.h"

namespace sled::runtime {
namespace {

using testing::MaxAbsDifference;
using testing::Tolerance;

// Height x and velocity v of a unit mass under gravity, on a floor (x < 0) of stiffness k and
// damping c (a smooth onset: the force grows as x^2 over the first 0.1 mm, so the problem stays
// smooth enough for any method), lifted from t = 1 s by a force of 3 g. Its structured
// Jacobian holds the floor's stiffness and damping while in contact.
class RestingBall : public OdeSystem {
 public:
  static constexpr double kStiffness = 1e7;
  static constexpr double kDamping = 2e3;
  static constexpr double kOnset = 1e-4;
  std::size_t size() const override { return 2; }
  static double FloorForce(double x, double v) {
    if (x >= 0.0) return 0.0;
    const double depth = -x;
    const double spring = depth < kOnset ? kStiffness * depth * depth / (2 * kOnset)
                                         : kStiffness * (depth - kOnset / 2);
    const double ramp = std::min(depth / kOnset, 1.0);
    return spring - ramp * kDamping * v;
  }
  bool Derivative(double t, std::span<const double> y, std::span<double> dy) override {
    dy[0] = y[1];
    dy[1] = -9.81 + FloorForce(y[0], y[1]) + (t > 1.0 ? 3 * 9.81 : 0.0);
    return true;
  }
  std::size_t StructuredRank() const override { return 1; }
  bool StructuredJacobianAt(double, std::span<const double> y, std::span<const double>, double step,
                            StructuredJacobian& jacobian) override {
    jacobian.nilpotent.push_back({0, 1, 1.0});
    const double d = 1e-9;
    const double k = -(FloorForce(y[0] + d, y[1]) - FloorForce(y[0] - d, y[1])) / (2 * d);
    const double c = -(FloorForce(y[0], y[1] + d) - FloorForce(y[0], y[1] - d)) / (2 * d);
    jacobian.stiff_rate = std::max(std::abs(c), std::sqrt(std::abs(k)));
    if (step * jacobian.stiff_rate >= 0.2) {
      jacobian.AddColumns(Eigen::Vector2d(0, 1), Eigen::Vector2d(-k, -c));
    }
    return true;
  }
};

TEST(AutoIntegrator, SwitchesToTheExponentialMethodWhileStiffAndBack) {
  const double y0[] = {0.05, 0.0};
  const double t_end = 1.5;
  RestingBall reference_system;
  DormandPrince reference;
  reference.Reset(reference_system, 0.0, y0, Tolerance(1e-12));
  ASSERT_EQ(reference.Advance(t_end).status, IntegratorStatus::kOk);
  for (const double tol : {1e-4, 1e-6}) {
    RestingBall system;
    AutoIntegrator automatic;
    automatic.Reset(system, 0.0, y0, Tolerance(tol));
    ASSERT_EQ(automatic.Advance(t_end).status, IntegratorStatus::kOk);
    const IntegratorStats& s = automatic.stats();
    RestingBall explicit_system;
    DormandPrince dopri5;
    dopri5.Reset(explicit_system, 0.0, y0, Tolerance(tol));
    ASSERT_EQ(dopri5.Advance(t_end).status, IntegratorStatus::kOk);
    const double error = std::abs(automatic.state()[0] - reference.state()[0]);
    std::printf(
        "  tol %.0e: auto %ld steps (dopri5 %ld, exponential %ld; %.3f s and %.3f s of the run), "
        "%d switches, error %.2e; dopri5 alone %ld steps, error %.2e\n",
        tol, s.steps, s.explicit_share.steps, s.exponential_share.steps, s.explicit_share.simulated,
        s.exponential_share.simulated, static_cast<int>(s.switches), error, dopri5.stats().steps,
        std::abs(dopri5.state()[0] - reference.state()[0]));
    // It went stiff on the floor and came back for the flight after the lift.
    EXPECT_GE(s.switches, 2);
    EXPECT_FALSE(automatic.stiff_mode());
    EXPECT_GT(s.exponential_share.simulated, 0.5);
    EXPECT_NEAR(s.explicit_share.simulated + s.exponential_share.simulated, t_end, 1e-12);
    EXPECT_EQ(s.steps, s.explicit_share.steps + s.exponential_share.steps);
    // Accurate, and with fewer steps than dopri5, held at h sqrt(k) < 3.3 on the floor; the
    // exponential method rests there in steps dopri5 would need hundreds for.
    EXPECT_LT(error, 100 * tol);
    EXPECT_LT(s.steps, 0.6 * static_cast<double>(dopri5.stats().steps));
    EXPECT_LT(s.exponential_share.steps, 30);
  }
}

TEST(AutoIntegrator, IsDopri5WhereNothingIsStiff) {
  // A pendulum: auto never leaves dopri5, step for step.
  class Pendulum : public OdeSystem {
   public:
    std::size_t size() const override { return 2; }
    bool Derivative(double, std::span<const double> y, std::span<double> dy) override {
      dy[0] = y[1];
      dy[1] = -9.81 * std::sin(y[0]);
      return true;
    }
  };
  const double y0[] = {1.0, 0.0};
  Pendulum a, b;
  AutoIntegrator automatic;
  DormandPrince dopri5;
  automatic.Reset(a, 0.0, y0, Tolerance(1e-8));
  dopri5.Reset(b, 0.0, y0, Tolerance(1e-8));
  ASSERT_EQ(automatic.Advance(10.0).status, IntegratorStatus::kOk);
  ASSERT_EQ(dopri5.Advance(10.0).status, IntegratorStatus::kOk);
  EXPECT_EQ(automatic.stats().switches, 0);
  EXPECT_EQ(automatic.stats().steps, dopri5.stats().steps);
  EXPECT_EQ(automatic.state()[0], dopri5.state()[0]);
  EXPECT_EQ(automatic.stats().exponential_share.steps, 0);
}

}  // namespace
}  // namespace sled::runtime
