// Joint actuators (`actuator NAME on JOINT`) against closed forms, with no gravity: two free
// segments joined at both centres of mass by a pin about y, so the relative angle obeys
// theta'' = k tau with k = 1/Ia + 1/Ib. A PD actuator towards a fixed target is then the damped
// oscillator theta'' + kd k theta' + kp k (theta - theta0) = 0; towards a ramp the error
// decays from the ramp's rate as one (the target's rate enters the derivative term); and under
// a constant load across the pin the integral term removes the offset kp leaves, the error's
// integral E solving E''' + kd k E'' + kp k E' + ki k E = k load.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "tests/verification/compile.h"

namespace sled::verification {
namespace {

constexpr double kInverseInertia = 1 / 0.2 + 1 / 0.05;  // k: 1/Ia + 1/Ib about y

// The pin's angle at `row`.
double Angle(const runtime::TimeSeries& series, std::size_t row) {
  return ChannelAt(series, "pair.j.joint_angle.axis [rad]", row);
}

std::string Pair(const std::string& end, const std::string& elements) {
  return R"(scenario "actuated" {
  gravity = (0, 0, 0) m/s^2
  time { end = )" +
         end + R"(  output_every = 10 ms }
  integrator dopri5 { tolerance = 1e-10 }
  body pair {
    reference = a
    segment a { mass = 3 kg  inertia = (0.15, 0.2, 0.15) kg*m^2 }
    segment b { mass = 1 kg  inertia = (0.03, 0.05, 0.03) kg*m^2 }
    joint j : pin(a -> b) {
      at a = (0, 0, 0) mm
      at b = (0, 0, 0) mm
      axis = y
    }
  }
  )" + elements +
         R"(
  output { joint_angle pair.j }
}
)";
}

// theta'' + 2 zeta w0 theta' + w0^2 theta = 0 from theta(0) = x0, theta'(0) = v0 (zeta < 1).
double DampedOscillator(double w0, double zeta, double x0, double v0, double t) {
  const double wd = w0 * std::sqrt(1 - zeta * zeta);
  const double decay = zeta * w0;
  return std::exp(-decay * t) * (x0 * std::cos(wd * t) + (v0 + decay * x0) / wd * std::sin(wd * t));
}

TEST(Actuator, APdActuatorMovesThePinLikeADampedOscillator) {
  // kp k = 100 (w0 = 10 rad/s), kd k = 2 (zeta = 0.1), towards 0.3 rad from rest at 0.
  const SceneRun run = RunText(Pair("1 s", R"(actuator motor on pair.j {
    target = 0.3 rad
    proportional = 4 N*m/rad
    derivative = 0.08 N*m*s/rad
  })"));
  ASSERT_EQ(run.errors, "");
  ASSERT_FALSE(run.summary.failed);
  const double kp = 4, kd = 0.08, target = 0.3;
  const double w0 = std::sqrt(kp * kInverseInertia);
  const double zeta = kd * kInverseInertia / (2 * w0);
  for (std::size_t row = 0; row < run.series.rows(); row += 5) {
    const double t = TimeAt(run.series, row);
    const double expected = target + DampedOscillator(w0, zeta, -target, 0, t);
    EXPECT_NEAR(Angle(run.series, row), expected, 1e-7) << t;
  }
  // The actuator's work is the kinetic energy of the two plus nothing else: the balance closes.
  EXPECT_LT(run.summary.energy.relative(), 1e-7);
}

TEST(Actuator, ARampTargetIsFollowedWithTheTargetRateInTheDerivativeTerm) {
  // theta0 = r t: the error e = theta - r t obeys the same oscillator from e(0) = 0,
  // e'(0) = -r, and dies out: no lag is left behind the ramp.
  const SceneRun run = RunText(Pair("2 s", R"(actuator motor on pair.j {
    target = table(time -> angle) { 0 s -> 0 rad  10 s -> 5 rad }
    proportional = 4 N*m/rad
    derivative = 0.08 N*m*s/rad
  })"));
  ASSERT_EQ(run.errors, "");
  const double r = 0.5;
  const double w0 = std::sqrt(4 * kInverseInertia);
  const double zeta = 0.08 * kInverseInertia / (2 * w0);
  for (std::size_t row = 0; row < run.series.rows(); row += 5) {
    const double t = TimeAt(run.series, row);
    const double expected = r * t + DampedOscillator(w0, zeta, 0, -r, t);
    EXPECT_NEAR(Angle(run.series, row), expected, 1e-7) << t;
  }
}

// x''' + 4 x'' + 14 x' + 20 x = c from rest, whose characteristic polynomial is
// (s + 2)(s^2 + 2 s + 10): x = c/20 + A e^{-2t} + e^{-t} (B cos 3t + C sin 3t). Returns x'.
double IntegralResponseRate(double c, double t) {
  // x(0) = 0: A + B = -c/20; x'(0) = 0: -2A - B + 3C = 0; x''(0) = 0: 4A - 8B - 6C = 0.
  // From the second, C = (2A + B)/3; the third gives 4A - 8B - 4A - 2B = 0, so B = 0.
  const double b = 0.0, a = -c / 20 - b, cc = (2 * a + b) / 3;
  const double e = std::exp(-t);
  return -2 * a * std::exp(-2 * t) + e * (-(b * std::cos(3 * t) + cc * std::sin(3 * t)) +
                                          (-3 * b * std::sin(3 * t) + 3 * cc * std::cos(3 * t)));
}

TEST(Actuator, TheIntegralTermRemovesTheOffsetOfAConstantLoad) {
  // kd k = 4, kp k = 14, ki k = 20; a load of 0.1 N*m across the pin: c = 2.5.
  const std::string load = "load push on pair.j { torque = 0.1 N*m }\n  ";
  const SceneRun pid = RunText(Pair("10 s", load + R"(actuator motor on pair.j {
    target = 0 rad
    proportional = 0.56 N*m/rad
    derivative = 0.16 N*m*s/rad
    integral = 0.8 N*m/rad/s
  })"));
  ASSERT_EQ(pid.errors, "");
  ASSERT_FALSE(pid.summary.failed);
  const double c = 0.1 * kInverseInertia;
  for (std::size_t row = 0; row < pid.series.rows(); row += 5) {
    const double t = TimeAt(pid.series, row);
    EXPECT_NEAR(Angle(pid.series, row), IntegralResponseRate(c, t), 1e-7) << t;
  }
  const std::size_t last = pid.series.rows() - 1;
  EXPECT_NEAR(Angle(pid.series, last), 0.0, 1e-4);
  // Without the integral the pin settles at the offset load / kp.
  const SceneRun pd = RunText(Pair("10 s", load + R"(actuator motor on pair.j {
    target = 0 rad
    proportional = 0.56 N*m/rad
    derivative = 0.16 N*m*s/rad
  })"));
  ASSERT_EQ(pd.errors, "");
  EXPECT_NEAR(Angle(pd.series, pd.series.rows() - 1), 0.1 / 0.56, 1e-4);
}

TEST(Actuator, OnlyAPinJointTakesAnActuator) {
  const SceneRun run = RunText(R"(scenario "ball" {
  body pair {
    reference = a
    segment a { mass = 3 kg  inertia = (0.15, 0.2, 0.15) kg*m^2 }
    segment b { mass = 1 kg  inertia = (0.03, 0.05, 0.03) kg*m^2 }
    joint j : ball(a -> b) { at a = (0, 0, 0) mm  at b = (0, 0, 0) mm }
  }
  actuator motor on pair.j { target = 0 rad  proportional = 1 N*m/rad }
}
)");
  EXPECT_NE(run.errors.find("E0205"), std::string::npos) << run.errors;
  EXPECT_NE(run.errors.find("not a pin joint"), std::string::npos) << run.errors;
}

}  // namespace
}  // namespace sled::verification
