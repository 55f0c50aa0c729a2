// A large-amplitude pendulum against the exact period T = 4 K(sin(theta0/2)) / omega0, with K the
// complete elliptic integral of the first kind (computed here by the arithmetic–geometric mean,
// independently of the simulator), on every integrator.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

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
  // at t = T) and locate it by linear interpolation of the rate.
  std::vector<double> times = Linspace(0, 1.1 * period, 2200);
  double previous_t = 0, previous_rate = 0, found = -1;
  ASSERT_TRUE(Simulate(model, data, GetParam(), 1e-10, times, [&](const runtime::Data& d) {
    const double rate = d.v[0];
    if (found < 0 && d.time > 0.75 * period && previous_rate > 0 && rate <= 0) {
      found = previous_t + (d.time - previous_t) * previous_rate / (previous_rate - rate);
    }
    previous_t = d.time;
    previous_rate = rate;
  }));
  ASSERT_GT(found, 0);
  // Linear interpolation of the rate over one sample (0.05 % of the period) bounds the
  // accuracy of locating the crossing: rate ~ T^2 curvature.
  EXPECT_NEAR(found, period, 1e-5 * period) << "T = " << period;
}

INSTANTIATE_TEST_SUITE_P(EveryIntegrator, PendulumPeriod, ::testing::ValuesIn(AllIntegrators()));

}  // namespace
}  // namespace sled::verification
