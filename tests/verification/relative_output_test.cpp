// Outputs `relative_to` and `expressed_in` a frame (ATB's KREF) against hand computations: a free
// body drifting in a straight line seen from a vehicle spun up in place and from a free body
// spinning about its axis, in gravity-free space, where every motion has a closed form. The
// expected values are worked out here from the closed-form paths (rotation matrices written out in
// sines and cosines), not from the runtime's formulas.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "runtime/run/relative_motion.h"
#include "tests/verification/compile.h"

namespace sled::verification {
namespace {

using runtime::Vec3;

// A frame turned by theta(t) about z through its origin o, observing a point moving as p0 + v t:
// r(t) = Rz(-theta) (p(t) - o). Its derivatives seen from the frame follow by the product rule:
// d/dt Rz(-theta) = -w [e_z]x Rz(-theta) with w = theta', so r' = Rz(-theta) u - w e_z x r (u the
// point's velocity less the origin's, constant) and r'' = -w e_z x Rz(-theta) u - al e_z x r -
// w e_z x r' (al = w').
struct Seen {
  Vec3 position, velocity, acceleration;
};

Vec3 RotateZ(double angle, const Vec3& v) {
  return {std::cos(angle) * v.x() - std::sin(angle) * v.y(),
          std::sin(angle) * v.x() + std::cos(angle) * v.y(), v.z()};
}

struct Turn {
  double angle, rate, acceleration;
};

Seen FromTurningFrame(const Turn& turn, const Vec3& origin, const Vec3& frame_velocity,
                      const Vec3& p0, const Vec3& v, double t) {
  const Vec3 ez = Vec3::UnitZ();
  // The frame's origin moves too (frame_velocity, constant): only v - frame_velocity matters.
  const Vec3 d = p0 + v * t - (origin + frame_velocity * t);
  const Vec3 u = v - frame_velocity;
  const double w = turn.rate;
  Seen seen;
  seen.position = RotateZ(-turn.angle, d);
  const Vec3 turned_u = RotateZ(-turn.angle, u);
  seen.velocity = turned_u - w * ez.cross(seen.position);
  seen.acceleration = -w * ez.cross(turned_u) - turn.acceleration * ez.cross(seen.position) -
                      w * ez.cross(seen.velocity);
  return seen;
}

constexpr double kSpinUp = 3.0;     // rad/s^2 of the turntable, from rest
constexpr double kSpinBody = -2.0;  // rad/s

const char* const kScene = R"(scenario "relative outputs" {
  gravity = (0, 0, 0) m/s^2
  time { end = 600 ms  output_every = 20 ms }
  integrator dopri5 { tolerance = 1e-10 }
  vehicle turntable {
    position = (0.2, -0.1, 0) m
    motion = table(time -> acceleration -> angular_acceleration) {
      0 s -> (0, 0, 0) m/s^2 -> (0, 0, 3) rad/s^2
      1 s -> (0, 0, 0) m/s^2 -> (0, 0, 3) rad/s^2
    }
  }
  body ball {
    segment b { mass = 1 kg  inertia = (0.01, 0.01, 0.01) kg*m^2 }
  }
  body top {
    segment t { mass = 2 kg  inertia = (0.02, 0.02, 0.03) kg*m^2 }
  }
  initial ball { position = (1, 0.5, 0.2) m  velocity = (0.3, -0.2, 0.1) m/s }
  initial top { position = (-0.4, 0.3, 0) m  velocity = (0, 0.1, 0) m/s
                angular_velocity = (0, 0, -2) rad/s }
  output {
    position ball.b at (100, 0, 0) mm relative_to turntable
    velocity ball.b at (100, 0, 0) mm relative_to turntable
    acceleration ball.b at (100, 0, 0) mm relative_to turntable
    position ball.b relative_to top.t as seen_from_top
    velocity ball.b relative_to top.t as seen_from_top
    acceleration ball.b relative_to top.t as seen_from_top
    orientation ball.b relative_to turntable
    angular_velocity ball.b relative_to turntable
    angular_acceleration top.t relative_to turntable
    position ball.b relative_to ground
    acceleration top.t at (100, 0, 0) mm expressed_in turntable
    velocity ball.b expressed_in top.t
    angular_velocity top.t expressed_in turntable
  }
})";

TEST(RelativeOutputs, MatchTheClosedFormsSeenFromASpinningVehicleAndASpinningBody) {
  const SceneRun run = RunText(kScene);
  ASSERT_TRUE(run.errors.empty()) << run.errors;
  const runtime::TimeSeries& s = run.series;
  ASSERT_GT(s.rows(), 20u);
  const Vec3 p0(1, 0.5, 0.2), v(0.3, -0.2, 0.1);
  const Vec3 point(0.1, 0, 0);  // the ball never turns: the point moves with its centre
  const char* const xyz[] = {"x", "y", "z"};
  double worst = 0;
  for (std::size_t row = 0; row < s.rows(); ++row) {
    const double t = TimeAt(s, row);
    const Turn turntable{kSpinUp * t * t / 2, kSpinUp * t, kSpinUp};
    const Turn top{kSpinBody * t, kSpinBody, 0};
    const Seen from_table =
        FromTurningFrame(turntable, Vec3(0.2, -0.1, 0), Vec3::Zero(), p0 + point, v, t);
    const Seen from_top = FromTurningFrame(top, Vec3(-0.4, 0.3, 0), Vec3(0, 0.1, 0), p0, v, t);
    for (int i = 0; i < 3; ++i) {
      const std::string c = xyz[i];
      const std::string table = "ball.b.relative_to.turntable.";
      auto check = [&](const std::string& name, double expected) {
        const double got = ChannelAt(s, name, row);
        worst = std::max(worst, std::fabs(got - expected));
        EXPECT_NEAR(got, expected, 1e-7) << name << " at t = " << t;
      };
      check(table + "position." + c + " [m]", from_table.position[i]);
      check(table + "velocity." + c + " [m/s]", from_table.velocity[i]);
      check(table + "acceleration." + c + " [m/s^2]", from_table.acceleration[i]);
      check("seen_from_top.position." + c + " [m]", from_top.position[i]);
      check("seen_from_top.velocity." + c + " [m/s]", from_top.velocity[i]);
      check("seen_from_top.acceleration." + c + " [m/s^2]", from_top.acceleration[i]);
      // Relative to the ground: the absolute position.
      check("ball.b.relative_to.ground.position." + c + " [m]", (p0 + v * t)[i]);
      // The ball does not turn: seen from the turntable it turns backwards at the table's rate,
      // and the top's rate relative to the table, -2 - 3 t rad/s about z, changes at -3 rad/s^2.
      check(table + "angular_velocity." + c + " [rad/s]", i == 2 ? -turntable.rate : 0.0);
      check("top.t.relative_to.turntable.angular_acceleration." + c + " [rad/s^2]",
            i == 2 ? -kSpinUp : 0.0);
      // Relative to the ground in a turning frame's axes: a point 0.1 m out on the top (turned
      // -2 t) has the centripetal 4 * 0.1 m/s^2 towards the axis, seen in the table's axes
      // (turned by its angle); the ball's velocity in the top's axes is v turned by 2 t.
      const Vec3 centripetal = RotateZ(-turntable.angle + kSpinBody * t, Vec3(-0.4, 0, 0));
      check("top.t.expressed_in.turntable.acceleration." + c + " [m/s^2]", centripetal[i]);
      check("ball.b.expressed_in.top.t.velocity." + c + " [m/s]", RotateZ(2 * t, v)[i]);
      check("top.t.expressed_in.turntable.angular_velocity." + c + " [rad/s]",
            i == 2 ? kSpinBody : 0.0);
    }
    // Yaw of the ball in the table's axes: minus the table's angle, wrapped to (-pi, pi].
    const double yaw = std::remainder(-turntable.angle, 2 * M_PI);
    EXPECT_NEAR(std::remainder(
                    ChannelAt(s, "ball.b.relative_to.turntable.orientation.yaw [rad]", row) - yaw,
                    2 * M_PI),
                0.0, 1e-7)
        << t;
  }
  EXPECT_LT(worst, 1e-7);
}

// The formulas of runtime/run/relative_motion.h at one instant against a hand computation: a point
// at rest in the ground at (1, 0, 0), seen from a frame spinning at 2 rad/s about z at the origin,
// moves backwards round a circle: velocity (0, -2, 0), acceleration 4 towards the centre.
TEST(RelativeOutputs, APointAtRestSeenFromASpinningFrameCirclesBackwards) {
  runtime::FrameMotion ground_point;  // a body at rest at the origin, point at (1, 0, 0)
  runtime::FrameMotion frame;
  frame.angular_velocity = Vec3(0, 0, 2);
  const runtime::RelativePoint seen = runtime::PointRelativeTo(ground_point, Vec3(1, 0, 0), frame);
  EXPECT_NEAR((seen.position - Vec3(1, 0, 0)).norm(), 0, 1e-15);
  EXPECT_NEAR((seen.velocity - Vec3(0, -2, 0)).norm(), 0, 1e-15);
  EXPECT_NEAR((seen.acceleration - Vec3(-4, 0, 0)).norm(), 0, 1e-15);
}

TEST(RelativeOutputs, AreRefusedOnRequestsThatAreNotOfASegment) {
  const Compiled compiled = CompileText(R"(scenario "bad" {
  time { end = 10 ms  output_every = 1 ms }
  body b { segment s { mass = 1 kg  inertia = (0.01, 0.01, 0.01) kg*m^2 } }
  output {
    spring_force s relative_to ground
    position b.s relative_to nowhere
    position b.s expressed_in ground
    velocity b.s relative_to ground expressed_in ground
  }
})");
  EXPECT_NE(compiled.errors.find("`spring_force` takes no `relative_to` clause"), std::string::npos)
      << compiled.errors;
  EXPECT_NE(compiled.errors.find("nowhere"), std::string::npos) << compiled.errors;
  EXPECT_NE(compiled.errors.find("`position` takes no `expressed_in` clause"), std::string::npos)
      << compiled.errors;
  EXPECT_NE(compiled.errors.find("`velocity` takes `relative_to` or `expressed_in`, not both"),
            std::string::npos)
      << compiled.errors;
}

}  // namespace
}  // namespace sled::verification
