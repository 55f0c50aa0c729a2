// A large-amplitude pendulum against the exact period T = 4 K(sin(theta0/2)) / omega0, with K the
// complete elliptic integral of the first kind (computed here by the arithmetic–geometric mean,
// independently of the simulator), on every integrator.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "runtime/dynamics/constraints.h"
#include "tests/runtime/model_fixtures.h"
#include "tests/verification/verification.h"

namespace sled::verification {
namespace {

// K(k) = pi / (2 AGM(1, sqrt(1 - k^2))).
double EllipticK(double k) {
  double a = 1.0, b = std::sqrt(1.0 - k * k);
  for (int i = 0; i < 60 && std::abs(a - b) > 1e-16 * a; ++i) {
    const double next = (a + b) / 2;
    b = std::sqrt(a * b);
    a = next;
  }
  return std::numbers::pi / (2 * a);
}

// The time of the first return to the starting angle: the swing rate crossing zero from above
// after three quarters of the expected period, located by linear interpolation of the rate
// between samples.
class FirstReturn {
 public:
  explicit FirstReturn(double period) : period_(period) {}
  void Sample(double t, double rate) {
    if (found_ < 0 && t > 0.75 * period_ && previous_rate_ > 0 && rate <= 0) {
      found_ = previous_t_ + (t - previous_t_) * previous_rate_ / (previous_rate_ - rate);
    }
    previous_t_ = t;
    previous_rate_ = rate;
  }
  double found() const { return found_; }

 private:
  double period_;
  double previous_t_ = 0, previous_rate_ = 0, found_ = -1;
};

class PendulumPeriod : public ::testing::TestWithParam<std::string> {};

TEST_P(PendulumPeriod, MatchesTheEllipticIntegral) {
  runtime::Model model;
  const double m = 2.0, l = 0.8, I = 0.01;  // I about the centre of mass, about the pin
  runtime::testing::AddSegment(model, "bob", -1, runtime::JointKind::kPin, m,
                               runtime::Vec3(I, I, I), runtime::Vec3::Zero(),
                               runtime::Vec3(0, 0, l), runtime::Vec3::UnitY());
  const double theta0 = 2.5;  // rad: far from the small-angle regime
  model.q0[0] = theta0;
  runtime::Data data = runtime::MakeData(model);
  const double g = 9.80665;
  const double omega0 = std::sqrt(m * g * l / (I + m * l * l));
  const double period = 4 * EllipticK(std::sin(theta0 / 2)) / omega0;

  // Sample densely around the first return to theta0 (angular velocity crossing zero from above
  // at t = T).
  FirstReturn first_return(period);
  ASSERT_TRUE(Simulate(model, data, GetParam(), 1e-10, Linspace(0, 1.1 * period, 2200),
                       [&](const runtime::Data& d) { first_return.Sample(d.time, d.v[0]); }));
  const double found = first_return.found();
  ASSERT_GT(found, 0);
  // Linear interpolation of the rate over one sample (0.05 % of the period) bounds the
  // accuracy of locating the crossing: rate ~ T^2 curvature.
  EXPECT_NEAR(found, period, 1e-5 * period) << "T = " << period;
}

TEST_P(PendulumPeriod, AMasslessRodHeldByAConstraintSwingsItsBobAsAPointMass) {
  // A singular segment suitably constrained: a massless rod pinned (about y) to the bob's
  // centre of mass, its far end held at the ground by a fixed-point constraint. The rod has no
  // inertia, so the tree's articulated-body recursion fails and the tree's equations are solved
  // with the constraint. The bob turns freely on the pin, so it swings as a point mass on a rod
  // of length l: T = 4 K(sin(theta0/2)) sqrt(l/g).
  runtime::Model model;
  const double m = 2.0, l = 0.8, I = 0.01, theta0 = 2.5;
  runtime::testing::AddSegment(model, "bob", -1, runtime::JointKind::kFree, m,
                               runtime::Vec3(I, I, I));
  runtime::testing::AddSegment(model, "rod", 0, runtime::JointKind::kPin, 0.0,
                               runtime::Vec3::Zero(), runtime::Vec3::Zero(),
                               runtime::Vec3(0, 0, -l), runtime::Vec3::UnitY());
  runtime::testing::AddConstraint(model, "pivot", runtime::Model::ConstraintKind::kFixedPoint,
                                  {runtime::FrameRef::Kind::kSegment, 1}, runtime::Vec3::Zero(), {},
                                  runtime::Vec3::Zero());
  // The bob at theta0 from hanging (turned about y), the rod turned with it.
  model.q0[0] = -l * std::sin(theta0);
  model.q0[2] = -l * std::cos(theta0);
  model.q0[7] = theta0;
  runtime::Data data = runtime::MakeData(model);
  ASSERT_FALSE(data.constraints->setup_failed) << data.constraints->setup_failure.cause;
  const double g = 9.80665;
  const double period = 4 * EllipticK(std::sin(theta0 / 2)) * std::sqrt(l / g);
  FirstReturn first_return(period);
  ASSERT_TRUE(Simulate(model, data, GetParam(), 1e-10, Linspace(0, 1.1 * period, 2200),
                       [&](const runtime::Data& d) {
                         // The swing rate from the bob's position and velocity:
                         // l^2 phi' = z x' - x z'.
                         const runtime::Vec3 p = d.position[0];
                         const runtime::Vec3 v = d.rotation[0] * d.velocity[0].tail<3>();
                         first_return.Sample(d.time, (p.z() * v.x() - p.x() * v.z()) / (l * l));
                       }));
  const double found = first_return.found();
  ASSERT_GT(found, 0);
  EXPECT_NEAR(found, period, 1e-5 * period) << "T = " << period;
}

INSTANTIATE_TEST_SUITE_P(EveryIntegrator, PendulumPeriod, ::testing::ValuesIn(AllIntegrators()));

}  // namespace
}  // namespace sled::verification
