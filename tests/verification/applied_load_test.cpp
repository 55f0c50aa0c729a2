// Applied loads (`load NAME on SEGMENT|JOINT`) against closed forms, with no gravity: a force
// ramp on a free body (x = c t^3 / 6m), a torque across a pin joint through both centres of mass
// (the relative angle is tau (1/Ia + 1/Ib) t^2 / 2), the same across a ball joint about a given
// axis, a force across a slip joint, a body-fixed torque on a segment (w = tau t / I); and the
// energy balance closes with the loads' work as its own term. A constant joint `flexure` is a
// torque against the angle (docs/language.md §8): a hinge released at 30 degrees reaches zero at
// sqrt(2 theta0 / (f k)), where a motor written as a load speeds it up.
#include <cmath>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "tests/verification/compile.h"

namespace sled::verification {
namespace {

constexpr double kPi = std::numbers::pi;

// The column of the channel whose name starts with `prefix`.
std::size_t Column(const runtime::TimeSeries& series, const std::string& prefix) {
  for (std::size_t c = 0; c < series.names.size(); ++c) {
    if (series.names[c].rfind(prefix, 0) == 0) return c + 1;
  }
  ADD_FAILURE() << "no channel " << prefix;
  return 0;
}

double Value(const runtime::TimeSeries& series, std::size_t row, std::size_t column) {
  return series.values[row * series.columns + column];
}

// Two segments joined at both centres of mass by `joint` (its block's extra lines in `details`),
// floating without gravity, and a load across the joint.
std::string Pair(const std::string& joint, const std::string& details, const std::string& load,
                 const std::string& outputs) {
  return R"(scenario "pair" {
  gravity = (0, 0, 0) m/s^2
  time { end = 1 s  output_every = 10 ms }
  integrator dopri5 { tolerance = 1e-10 }
  body pair {
    reference = a
    segment a { mass = 3 kg  inertia = (0.15, 0.2, 0.15) kg*m^2 }
    segment b { mass = 1 kg  inertia = (0.03, 0.05, 0.03) kg*m^2 }
    joint j : )" +
         joint + R"( {
      at a = (0, 0, 0) mm
      at b = (0, 0, 0) mm
      )" +
         details + R"(
    }
  }
  )" + load +
         R"(
  output { )" +
         outputs + R"( }
}
)";
}

TEST(AppliedLoad, AForceRampOnAFreeBodyMovesItAsNewtonSays) {
  const SceneRun run = RunText(R"(scenario "push" {
  gravity = (0, 0, 0) m/s^2
  time { end = 1 s  output_every = 10 ms }
  integrator dopri5 { tolerance = 1e-10 }
  body b { segment s { mass = 2 kg  inertia = (0.1, 0.1, 0.1) kg*m^2 } }
  load push on b.s {
    force = table(time -> force) { 0 s -> 0 N  1 s -> 10 N }
    direction = (1, 1, 0)
  }
  output { position b.s at (0, 0, 0) mm }
}
)");
  ASSERT_EQ(run.errors, "");
  ASSERT_FALSE(run.summary.failed);
  const double c = 10.0, m = 2.0;
  const std::size_t x = Column(run.series, "b.s.position.x"),
                    y = Column(run.series, "b.s.position.y");
  for (std::size_t row = 0; row < run.series.rows(); ++row) {
    const double t = Value(run.series, row, 0);
    const double expected = c * t * t * t / (6 * m) / std::sqrt(2.0);
    EXPECT_NEAR(Value(run.series, row, x), expected, 1e-8) << t;
    EXPECT_NEAR(Value(run.series, row, y), expected, 1e-8) << t;
  }
  // The work of the push is the body's kinetic energy: the balance closes with it.
  const double v = c / (2 * m);  // at t = 1 s
  EXPECT_NEAR(run.summary.energy.applied_work, 0.5 * m * v * v, 1e-8);
  EXPECT_NEAR(run.summary.energy.absorbed, 0.0, 1e-10);
  EXPECT_LT(run.summary.energy.relative(), 1e-8);
}

TEST(AppliedLoad, ATorqueAcrossAPinJointTurnsBothSegments) {
  const SceneRun run = RunText(Pair(
      "pin(a -> b)", "axis = y", "load motor on pair.j { torque = 2 N*m }", "joint_angle pair.j"));
  ASSERT_EQ(run.errors, "");
  const double k = 1 / 0.2 + 1 / 0.05;  // 1/Ia + 1/Ib about y
  const std::size_t angle = Column(run.series, "pair.j.joint_angle");
  for (std::size_t row = 0; row < run.series.rows(); row += 10) {
    const double t = Value(run.series, row, 0);
    const double expected = 0.5 * 2.0 * k * t * t;
    EXPECT_NEAR(Value(run.series, row, angle), expected, 1e-7 * std::max(1.0, expected)) << t;
  }
  EXPECT_LT(run.summary.energy.relative(), 1e-8);
}

TEST(AppliedLoad, ATorqueAcrossABallJointTurnsAboutItsAxis) {
  const SceneRun run = RunText(Pair(
      "ball(a -> b)", "",
      "load motor on pair.j {\n    torque = table(time -> torque) { 0 s -> 0 N*m  1 s -> 1 N*m }\n"
      "    axis = y\n  }\n  ",
      "angular_velocity pair.a\n    angular_velocity pair.b"));
  ASSERT_EQ(run.errors, "");
  // tau = t N*m/s: each side's angular velocity about y is -+ t^2 / (2 I).
  const std::size_t wa = Column(run.series, "pair.a.angular_velocity.y");
  const std::size_t wb = Column(run.series, "pair.b.angular_velocity.y");
  for (std::size_t row = 0; row < run.series.rows(); row += 10) {
    const double t = Value(run.series, row, 0);
    EXPECT_NEAR(Value(run.series, row, wa), -t * t / (2 * 0.2), 1e-8) << t;
    EXPECT_NEAR(Value(run.series, row, wb), t * t / (2 * 0.05), 1e-8) << t;
  }
}

TEST(AppliedLoad, AForceAcrossASlipJointPushesTheTwoApart) {
  const SceneRun pushed = RunText(R"(scenario "slide" {
  gravity = (0, 0, 0) m/s^2
  time { end = 1 s  output_every = 10 ms }
  integrator dopri5 { tolerance = 1e-10 }
  body pair {
    reference = a
    segment a { mass = 3 kg  inertia = (0.15, 0.2, 0.15) kg*m^2 }
    segment b { mass = 1 kg  inertia = (0.03, 0.05, 0.03) kg*m^2 }
    joint j : slip(a -> b) {
      at a = (0, 0, 0) mm
      at b = (0, 0, 0) mm
      axis = x
    }
  }
  load actuator on pair.j { force = 6 N }
  output { joint_angle pair.j }
}
)");
  ASSERT_EQ(pushed.errors, "");
  const std::size_t d = Column(pushed.series, "pair.j.joint_displacement");
  for (std::size_t row = 0; row < pushed.series.rows(); row += 10) {
    const double t = Value(pushed.series, row, 0);
    EXPECT_NEAR(Value(pushed.series, row, d), 0.5 * 6.0 * (1 / 3.0 + 1 / 1.0) * t * t, 1e-8) << t;
  }
  EXPECT_NEAR(pushed.summary.energy.applied_work,
              0.5 * 3.0 * std::pow(6.0 / 3.0, 2) + 0.5 * 1.0 * std::pow(6.0, 2), 1e-7);
}

TEST(AppliedLoad, ABodyFixedTorqueSpinsASegmentAboutItsAxis) {
  // Axis z of the segment, turned 90 degrees about x at the start: the ground's -y.
  const SceneRun run = RunText(R"(scenario "spin" {
  gravity = (0, 0, 0) m/s^2
  time { end = 1 s  output_every = 10 ms }
  integrator dopri5 { tolerance = 1e-10 }
  body b { segment s { mass = 1 kg  inertia = (0.2, 0.25, 0.4) kg*m^2 } }
  load spin on b.s { torque = 0.8 N*m  axis = z  frame = segment }
  initial b { orientation = (0, 0, 90) deg }
  output { angular_velocity b.s }
}
)");
  ASSERT_EQ(run.errors, "");
  const std::size_t wz = Column(run.series, "b.s.angular_velocity.z");
  for (std::size_t row = 0; row < run.series.rows(); row += 10) {
    const double t = Value(run.series, row, 0);
    EXPECT_NEAR(Value(run.series, row, wz), 0.8 * t / 0.4, 1e-9) << t;
  }
  EXPECT_NEAR(run.summary.energy.applied_work, 0.5 * 0.4 * std::pow(0.8 / 0.4, 2), 1e-8);
}

TEST(AppliedLoad, AnOffsetBodyFixedForceClosesTheEnergyBalance) {
  const SceneRun run = RunText(R"(scenario "thruster" {
  gravity = (0, 0, 0) m/s^2
  time { end = 1 s  output_every = 10 ms }
  integrator dopri5 { tolerance = 1e-10 }
  body b { segment s { mass = 1.5 kg  inertia = (0.02, 0.03, 0.04) kg*m^2 } }
  load thruster on b.s { force = 3 N  direction = x  point = (0, 100, 20) mm  frame = segment }
  output { position b.s at (0, 0, 0) mm }
}
)");
  ASSERT_EQ(run.errors, "");
  ASSERT_FALSE(run.summary.failed);
  EXPECT_GT(run.summary.energy.applied_work, 0.1);
  EXPECT_NEAR(run.summary.energy.kinetic, run.summary.energy.applied_work,
              1e-7 * run.summary.energy.applied_work);
}

// A hinge between two segments released at theta0 with a constant `flexure` f: the joint's
// torque resists the angle, so the relative angle falls as theta0 - f k t^2 / 2 and reaches
// zero at sqrt(2 theta0 / (f k)).
TEST(AppliedLoad, AConstantFlexureResistsTheAngleWhereALoadDrivesIt) {
  const std::string flexure = R"(scenario "detent" {
  gravity = (0, 0, 0) m/s^2
  time { end = 200 ms  output_every = 1 ms }
  integrator dopri5 { tolerance = 1e-10 }
  body pair {
    reference = a
    segment a { mass = 3 kg  inertia = (0.15, 0.2, 0.15) kg*m^2 }
    segment b { mass = 1 kg  inertia = (0.03, 0.05, 0.03) kg*m^2 }
    joint j : pin(a -> b) {
      at a = (0, 0, 0) mm
      at b = (0, 0, 0) mm
      axis = y
      flexure = 0.5 N*m
    }
  }
  initial pair.j { angles = (30, 0, 0) deg }
  output { joint_angle pair.j }
}
)";
  const SceneRun run = RunText(flexure);
  ASSERT_EQ(run.errors, "");
  const double k = 1 / 0.2 + 1 / 0.05, theta0 = kPi / 6;
  const double zero_at = std::sqrt(2 * theta0 / (0.5 * k));  // 0.145 s
  const std::size_t angle = Column(run.series, "pair.j.joint_angle");
  for (std::size_t row = 0; row < run.series.rows(); ++row) {
    const double t = Value(run.series, row, 0);
    if (t > zero_at - 2e-3) break;
    EXPECT_NEAR(Value(run.series, row, angle), theta0 - 0.25 * k * t * t, 1e-7) << t;
  }
  // The same torque as a load across the joint opens it further.
  std::string motor = flexure;
  motor.replace(motor.find("      flexure = 0.5 N*m\n"), 24, "");
  motor.replace(motor.find("  initial"), 0, "  load motor on pair.j { torque = 0.5 N*m }\n");
  const SceneRun driven = RunText(motor);
  ASSERT_EQ(driven.errors, "");
  const std::size_t last = driven.series.rows() - 1;
  const double t = Value(driven.series, last, 0);
  EXPECT_NEAR(Value(driven.series, last, Column(driven.series, "pair.j.joint_angle")),
              theta0 + 0.25 * k * t * t, 1e-7);
}

}  // namespace
}  // namespace sled::verification
