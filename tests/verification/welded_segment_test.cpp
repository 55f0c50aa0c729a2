// A welded segment (`constraint NAME : welded(VEHICLE -> body.segment)`, a segment whose motion
// is prescribed: ATB's MSEG) against closed forms. On a sled braked by a half-sine the segment's
// points follow the sled's closed-form path exactly, at its initial relative orientation, and the
// weld's reaction on it is m (a - g); on a vehicle spinning at a constant rate they turn with it
// and the reaction is the centripetal m w^2 r (plus the weight). The refusals are E0426.
#include <cmath>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "runtime/model/data.h"
#include "tests/verification/compile.h"

namespace sled::verification {
namespace {

constexpr double kPi = std::numbers::pi;
using runtime::Mat3;
using runtime::Vec3;

Mat3 YawPitchRoll(double yaw, double pitch, double roll) {
  return (Eigen::AngleAxisd(yaw, Vec3::UnitZ()) * Eigen::AngleAxisd(pitch, Vec3::UnitY()) *
          Eigen::AngleAxisd(roll, Vec3::UnitX()))
      .toRotationMatrix();
}

// At each output row: the time, the welded segment's centre of mass and a marker point of it
// (in the ground frame), and the force its base transmits to it (segment frame).
class WeldSink : public RunSink {
 public:
  explicit WeldSink(Vec3 marker) : marker_(std::move(marker)) {}
  void OnRow(const runtime::Model& /*model*/, const runtime::Data& data) override {
    time.push_back(data.time);
    com.push_back(data.position[0]);
    point.push_back(data.position[0] + data.rotation[0] * marker_);
    reaction.push_back(data.joint_wrench[0].tail<3>());
  }
  // At `row`: the centre of mass at `com`, the segment turned by `rotation` (segment to
  // ground), and the base's force on it `force` (ground axes).
  void ExpectAt(std::size_t row, const Vec3& expected_com, const Mat3& rotation, const Vec3& force,
                double position_tolerance, double force_tolerance) const {
    EXPECT_NEAR((com[row] - expected_com).norm(), 0.0, position_tolerance) << "t = " << time[row];
    EXPECT_NEAR((point[row] - (expected_com + rotation * marker_)).norm(), 0.0, position_tolerance)
        << "t = " << time[row];
    EXPECT_NEAR((reaction[row] - rotation.transpose() * force).norm(), 0.0, force_tolerance)
        << "t = " << time[row];
  }
  std::vector<double> time;
  std::vector<Vec3> com, point, reaction;

 private:
  Vec3 marker_;
};

RunResult RunWelded(const std::string& text, WeldSink& sink) {
  const Compiled compiled = CompileText(text);
  EXPECT_EQ(compiled.errors, "");
  if (!compiled.errors.empty()) return {};
  return Simulate(compiled.model(), {}, {&sink});
}

TEST(WeldedSegment, FollowsAHalfSineSledExactlyAndFeelsMassTimesAcceleration) {
  WeldSink sink(Vec3(0.1, 0.2, 0.0));
  const RunResult run = RunWelded(R"(scenario "weld" {
  time { end = 150 ms  output_every = 1 ms }
  integrator dopri5 { tolerance = 1e-10 }
  vehicle sled {
    position = (0.2, 0, 0.5) m
    orientation = (30, 0, 0) deg
    velocity = (8, 3, 0) m/s
    motion = half_sine(delta_v = 10 m/s, duration = 100 ms, axis = -x)
  }
  body rig { segment seat { mass = 4 kg  inertia = (0.1, 0.2, 0.3) kg*m^2 } }
  constraint seat_weld : welded(sled -> rig.seat) {
    at sled = (0.1, 0, 0) m
    at rig.seat = (0, 0, 0) m
  }
  initial rig { orientation = (40, 10, 0) deg }
}
)",
                                  sink);
  ASSERT_FALSE(run.failed()) << run.summary.failure.cause;
  ASSERT_EQ(sink.time.size(), 151u);
  const double m = 4.0, g = 9.80665, dv = 10.0, duration = 0.1;
  const double w = kPi / duration, peak = kPi * dv / (2 * duration);
  const Mat3 sled = YawPitchRoll(30 * kPi / 180, 0, 0);
  const Mat3 seat = YawPitchRoll(40 * kPi / 180, 10 * kPi / 180, 0);
  const Vec3 x = sled.col(0);
  for (std::size_t row = 0; row < sink.time.size(); ++row) {
    const double t = sink.time[row];
    // The pulse along the sled's -x: a = -A sin(w t) up to the duration, then none.
    const double tp = std::min(t, duration);
    const double travel = -peak / w * (tp - std::sin(w * tp) / w) - dv * (t - tp);
    const double a = t < duration ? -peak * std::sin(w * t) : 0.0;
    const Vec3 origin = Vec3(0.2, 0, 0.5) + Vec3(8, 3, 0) * t + x * travel;
    // The sled's push on the seat: m (a - g).
    sink.ExpectAt(row, origin + sled * Vec3(0.1, 0, 0), seat, m * (x * a - Vec3(0, 0, -g)), 1e-9,
                  1e-6 * m * (peak + g));
  }
}

TEST(WeldedSegment, TurnsWithASpinningVehicleAndFeelsTheCentripetalForce) {
  WeldSink sink(Vec3(0.0, 0.0, 0.3));
  const RunResult run = RunWelded(R"(scenario "spin" {
  gravity = (0, 0, 0) m/s^2
  time { end = 1 s  output_every = 10 ms }
  integrator dopri5 { tolerance = 1e-10 }
  vehicle turntable { }
  initial turntable { angular_velocity = (0, 0, 2) rad/s }
  body rig { segment block { mass = 2 kg  inertia = (0.1, 0.1, 0.1) kg*m^2 } }
  constraint hold : welded(turntable -> rig.block) {
    at turntable = (0.5, 0, 0) m
    at rig.block = (0, 0, 0) m
  }
  initial rig { orientation = (0, 90, 0) deg }
}
)",
                                  sink);
  ASSERT_FALSE(run.failed()) << run.summary.failure.cause;
  ASSERT_EQ(sink.time.size(), 101u);
  const double m = 2.0, rate = 2.0, radius = 0.5;
  const Mat3 relative = YawPitchRoll(0, kPi / 2, 0);
  for (std::size_t row = 0; row < sink.time.size(); ++row) {
    const double t = sink.time[row];
    const Mat3 table = YawPitchRoll(rate * t, 0, 0);
    const Vec3 com = table * Vec3(radius, 0, 0);
    // Towards the axis, m w^2 r.
    sink.ExpectAt(row, com, table * relative, -m * rate * rate * com, 1e-8, 1e-6);
  }
}

TEST(WeldedSegment, WeldsThatCannotHoldAReferenceSegmentAreRefused) {
  const std::string scene = R"(scenario "bad welds" {
  time { end = 10 ms  output_every = 1 ms }
  vehicle sled { }
  body pair {
    segment a { mass = 1 kg  inertia = (0.01, 0.01, 0.01) kg*m^2 }
    segment b { mass = 1 kg  inertia = (0.01, 0.01, 0.01) kg*m^2 }
    joint j : ball(a -> b) { at a = (0, 0, 0.1) m  at b = (0, 0, -0.1) m }
  }
  constraint hangs : welded(sled -> pair.b) { at sled = (0, 0, 0) m  at pair.b = (0, 0, 0) m }
  constraint two : welded(pair.a -> pair.b) { at pair.a = (0, 0, 0) m  at pair.b = (0, 0, 0) m }
  constraint first : welded(sled -> pair.a) { at sled = (0, 0, 0) m  at pair.a = (0, 0, 0) m }
  constraint again : welded(ground -> pair.a) { at ground = (0, 0, 0) m  at pair.a = (0, 0, 0) m }
  constraint pin : fixed_point(ground -> pair.a) { at ground = (0, 0, 0) m  at pair.a = (0, 0, 0) m }
  initial pair { angular_velocity = (0, 0, 1) rad/s }
}
)";
  const Compiled compiled = CompileText(scene);
  const std::string& errors = compiled.errors;
  EXPECT_NE(errors.find("E0426]: constraint `hangs` welds `pair.b`, which hangs from a joint"),
            std::string::npos)
      << errors;
  EXPECT_NE(errors.find("E0426]: constraint `two` welds two segments"), std::string::npos)
      << errors;
  EXPECT_NE(errors.find("constraint `again` would hold it twice"), std::string::npos) << errors;
  EXPECT_NE(errors.find("constraint `pin` ties `pair.a`, which constraint `first` welds"),
            std::string::npos)
      << errors;
  EXPECT_NE(errors.find("the initial angular velocity of `pair.a` is not its base's"),
            std::string::npos)
      << errors;
}

}  // namespace
}  // namespace sled::verification
