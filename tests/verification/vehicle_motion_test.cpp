// Prescribed vehicle motion that turns: the tabulated path of a six-degree-of-freedom table and
// an initial angular velocity against closed-form answers, and a free body on a turning vehicle
// that must move in a straight line in the ground frame (the base frame's Euler, Coriolis and
// centrifugal terms all have to be right for that).
#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "runtime/dynamics/vehicle.h"
#include "runtime/run/input_discontinuities.h"
#include "tests/runtime/model_fixtures.h"
#include "tests/verification/verification.h"

namespace sled::verification {
namespace {

using runtime::Mat3;
using runtime::Vec3;
using runtime::VehicleMotion;

// A Model with one vehicle and the given motion, tabulated as the lowering does.
runtime::Model VehicleModel(const VehicleMotion& motion, const Mat3& orientation,
                            const Vec3& angular_velocity, const Vec3& velocity = Vec3::Zero()) {
  runtime::Model model;
  model.gravity.setZero();
  model.vehicle_name = {"car"};
  model.vehicle_motion = {motion};
  model.vehicle_position = {Vec3(1, -2, 0.5)};
  model.vehicle_orientation = {orientation};
  model.vehicle_velocity = {velocity};
  model.vehicle_angular_velocity = {angular_velocity};
  model.vehicle_path = {runtime::TabulateVehiclePath(motion, orientation, angular_velocity)};
  return model;
}

VehicleMotion SixDof(std::vector<std::array<double, 7>> rows) {
  VehicleMotion motion;
  motion.kind = VehicleMotion::Kind::kSixDof;
  motion.six_dof = std::move(rows);
  runtime::IntegrateMotionRows(motion);
  return motion;
}

TEST(VehicleMotion, ThrustAlongTheVehicleWhileItTurnsSteadily) {
  // Acceleration a along the vehicle's x while it turns at w about z: the velocity gained is
  // (a/w)(sin wt, 1 - cos wt, 0) and the displacement (a/w^2)(1 - cos wt, wt - sin wt, 0).
  const double a = 30.0, w = 4.0;
  const runtime::Model model = VehicleModel(SixDof({{0, a, 0, 0, 0, 0, 0}, {2, a, 0, 0, 0, 0, 0}}),
                                            Mat3::Identity(), Vec3(0, 0, w), Vec3(5, 0, 0));
  for (double t : {0.013, 0.25, 0.7, 1.9}) {
    const runtime::VehicleState state = runtime::VehicleAt(model, 0, t);
    const double s = std::sin(w * t), c = std::cos(w * t);
    const Vec3 velocity = Vec3(5, 0, 0) + a / w * Vec3(s, 1 - c, 0);
    const Vec3 position =
        Vec3(1, -2, 0.5) + Vec3(5 * t, 0, 0) + a / (w * w) * Vec3(1 - c, w * t - s, 0);
    EXPECT_NEAR((state.velocity - velocity).norm(), 0, 1e-9) << t;
    EXPECT_NEAR((state.position - position).norm(), 0, 1e-9) << t;
    EXPECT_NEAR((state.acceleration - a * Vec3(c, s, 0)).norm(), 0, 1e-9) << t;
    const Mat3 expected = Eigen::AngleAxisd(w * t, Vec3::UnitZ()).toRotationMatrix();
    EXPECT_NEAR((state.rotation - expected).norm(), 0, 1e-10) << t;
    EXPECT_NEAR((state.angular_velocity - Vec3(0, 0, w)).norm(), 0, 1e-12) << t;
  }
}

TEST(VehicleMotion, AngularAccelerationInVehicleAxesThenASteadyTurn) {
  // alpha about the vehicle's z for 0.2 s, the vehicle tilted by 0.4 rad about x: the turn is
  // about the tilted axis R0 z, by alpha t^2 / 2, then at the constant rate alpha * 0.2.
  const double alpha = 50.0, end = 0.2;
  const Mat3 tilt = Eigen::AngleAxisd(0.4, Vec3::UnitX()).toRotationMatrix();
  const runtime::Model model = VehicleModel(
      SixDof({{0, 0, 0, 0, 0, 0, alpha}, {end, 0, 0, 0, 0, 0, alpha}}), tilt, Vec3::Zero());
  const Vec3 axis = tilt * Vec3::UnitZ();
  for (double t : {0.05, 0.13, 0.2, 0.5}) {
    const runtime::VehicleState state = runtime::VehicleAt(model, 0, t);
    const double angle =
        t <= end ? alpha * t * t / 2 : alpha * end * end / 2 + alpha * end * (t - end);
    const double rate = alpha * std::min(t, end);
    const Mat3 expected = Eigen::AngleAxisd(angle, axis).toRotationMatrix() * tilt;
    EXPECT_NEAR((state.rotation - expected).norm(), 0, 1e-10) << t;
    EXPECT_NEAR((state.angular_velocity - rate * axis).norm(), 0, 1e-10) << t;
    const Vec3 angular_acceleration = t < end ? Vec3(alpha * axis) : Vec3::Zero();
    EXPECT_NEAR((state.angular_acceleration - angular_acceleration).norm(), 0, 1e-10) << t;
    // Turning about its own origin: the vehicle does not move.
    EXPECT_NEAR((state.position - Vec3(1, -2, 0.5)).norm(), 0, 1e-12) << t;
  }
}

TEST(VehicleMotion, ATableWithoutAngularAccelerationStaysInClosedForm) {
  const runtime::Model model = VehicleModel(
      SixDof({{0, 0, 0, 0, 0, 0, 0}, {0.1, -200, 0, 50, 0, 0, 0}}), Mat3::Identity(), Vec3::Zero());
  EXPECT_TRUE(model.vehicle_path[0].empty());
  // a_x ramps to -200 over 0.1 s: v = -1000 t^2, x = -1000 t^3 / 3.
  const runtime::VehicleState state = runtime::VehicleAt(model, 0, 0.1);
  EXPECT_NEAR(state.velocity.x(), -10.0, 1e-12);
  EXPECT_NEAR(state.position.x() - 1, -1000 * 0.001 / 3, 1e-12);
}

// A zigzag acceleration, 0 at the even rows and A at the odd ones, h apart: every row a kink.
// Its velocity and displacement in closed form: v = A t / 2 + P(r) and x = A t^2 / 4 + Q(r),
// r = t mod 2h, with P(r) = A r (r - h) / (2 h) and Q(r) = A (r^3 / 3 - h r^2 / 2) / (2 h) on
// [0, h], P(r) = -P(2h - r) and Q(r) = Q(2h - r) on [h, 2h].
struct Zigzag {
  double amplitude, h;
  std::size_t rows;
  double End() const { return h * static_cast<double>(rows - 1); }
  double Acceleration(double t) const {
    if (t < 0 || t >= End()) return 0.0;
    const double r = std::fmod(t, 2 * h);
    return amplitude * (r <= h ? r / h : (2 * h - r) / h);
  }
  double Velocity(double t) const {
    const double u = std::clamp(t, 0.0, End()), r = std::fmod(u, 2 * h);
    const double p =
        r <= h ? amplitude * r * (r - h) / (2 * h) : -amplitude * (2 * h - r) * (h - r) / (2 * h);
    return amplitude * u / 2 + p;
  }
  double Displacement(double t) const {
    const double u = std::clamp(t, 0.0, End()), r = std::fmod(u, 2 * h);
    const double s = r <= h ? r : 2 * h - r;
    const double q = amplitude * (s * s * s / 3 - h * s * s / 2) / (2 * h);
    return amplitude * u * u / 4 + q + Velocity(End()) * std::max(t - End(), 0.0);
  }
  double Row(std::size_t k) const { return k % 2 == 1 ? amplitude : 0.0; }
  // Rounding over the rows' sums: 1e-12 of the largest velocity and displacement.
  double VelocityTolerance() const { return 1e-12 * std::abs(Velocity(End())); }
  double DisplacementTolerance() const { return 1e-12 * std::abs(Displacement(End() + 0.05)); }
};

// Times on rows, between rows, before the first and after the last.
std::vector<double> ProbeTimes(const Zigzag& z) {
  std::vector<double> times = {-0.01, 0.0, z.End(), z.End() + 0.05};
  for (std::size_t k = 0; k < 40; ++k) {
    const double t = z.End() * static_cast<double>(k) / 39.0;
    times.push_back(z.h * std::round(t / z.h));  // a row
    times.push_back(t + 0.37 * z.h);
  }
  return times;
}

TEST(VehicleMotion, ATabulatedPulseWithAKinkAtEveryRowIsIntegratedExactly) {
  const Zigzag z{150.0, 1e-4, 3003};
  VehicleMotion motion;
  motion.kind = VehicleMotion::Kind::kTable;
  motion.axis = -Vec3::UnitX();
  for (std::size_t k = 0; k < z.rows; ++k) {
    motion.table.push_back({z.h * static_cast<double>(k), z.Row(k)});
  }
  runtime::IntegrateMotionRows(motion);
  const runtime::Model model = VehicleModel(motion, Mat3::Identity(), Vec3::Zero());
  for (const double t : ProbeTimes(z)) {
    const runtime::VehicleState state = runtime::VehicleAt(model, 0, t);
    EXPECT_NEAR(state.acceleration.x(), -z.Acceleration(t), 1e-9 * z.amplitude) << t;
    EXPECT_NEAR(state.velocity.x(), -z.Velocity(t), z.VelocityTolerance()) << t;
    EXPECT_NEAR(state.position.x() - 1, -z.Displacement(t), z.DisplacementTolerance()) << t;
  }
}

TEST(VehicleMotion, TheSameMotionAsASixDegreeOfFreedomTable) {
  // Three zigzags of three amplitudes on the three axes, no angular acceleration: each axis in
  // closed form.
  const Zigzag x{150.0, 1e-4, 3003}, y{-40.0, 1e-4, 3003}, zed{7.0, 1e-4, 3003};
  std::vector<std::array<double, 7>> rows;
  for (std::size_t k = 0; k < x.rows; ++k) {
    rows.push_back({x.h * static_cast<double>(k), x.Row(k), y.Row(k), zed.Row(k), 0, 0, 0});
  }
  const runtime::Model model = VehicleModel(SixDof(rows), Mat3::Identity(), Vec3::Zero());
  ASSERT_TRUE(model.vehicle_path[0].empty());
  for (const double t : ProbeTimes(x)) {
    const runtime::VehicleState state = runtime::VehicleAt(model, 0, t);
    const Zigzag* axes[3] = {&x, &y, &zed};
    for (int a = 0; a < 3; ++a) {
      const Zigzag& w = *axes[a];
      EXPECT_NEAR(state.acceleration[a], w.Acceleration(t), 1e-9 * std::abs(w.amplitude)) << t;
      EXPECT_NEAR(state.velocity[a], w.Velocity(t), w.VelocityTolerance()) << t;
      EXPECT_NEAR(state.position[a] - model.vehicle_position[0][a], w.Displacement(t),
                  w.DisplacementTolerance())
          << t;
    }
  }
}

TEST(VehicleMotion, ATableWhoseRowsWereNotIntegratedIsRefused) {
  VehicleMotion motion;
  motion.kind = VehicleMotion::Kind::kTable;
  motion.table = {{0.0, 1.0}, {1.0, 1.0}};
  const runtime::Model model = VehicleModel(motion, Mat3::Identity(), Vec3::Zero());
  EXPECT_THROW(runtime::VehicleAt(model, 0, 0.5), std::logic_error);
}

TEST(VehicleMotion, EveryRowOfATableIsADiscontinuityTheStepsStopAt) {
  // The rows of a delayed 3,003-row table, inside the run's span, each once.
  const Zigzag z{150.0, 1e-4, 3003};
  std::vector<std::array<double, 7>> rows;
  for (std::size_t k = 0; k < z.rows; ++k) {
    rows.push_back({z.h * static_cast<double>(k), z.Row(k), 0, 0, 0, 0, 0});
  }
  VehicleMotion motion = SixDof(rows);
  motion.start = 0.002;
  runtime::Model model = VehicleModel(motion, Mat3::Identity(), Vec3::Zero());
  model.start_time = 0.0;
  model.end_time = 0.25;
  const std::vector<double> stops = runtime::InputDiscontinuities(model);
  std::vector<double> expected;
  for (const auto& row : rows) {
    if (motion.start + row[0] < model.end_time) expected.push_back(motion.start + row[0]);
  }
  EXPECT_EQ(stops, expected);
}

class FreeBodyOnATurningVehicle : public ::testing::TestWithParam<std::string> {};

TEST_P(FreeBodyOnATurningVehicle, MovesInAStraightLineInTheGroundFrame) {
  // Joint coordinates relative to a vehicle that accelerates and turns about an oblique axis:
  // with no force on it, the body's centre of mass keeps its ground velocity and its
  // orientation in the ground frame stays fixed.
  const Vec3 oblique = Vec3(0.3, -0.5, 1).normalized();
  VehicleMotion motion =
      SixDof({{0, -150, 20, 0, 30 * oblique.x(), 30 * oblique.y(), 30 * oblique.z()},
              {0.1, -50, 0, 40, -20 * oblique.x(), -20 * oblique.y(), -20 * oblique.z()}});
  runtime::Model model =
      VehicleModel(motion, Eigen::AngleAxisd(0.3, Vec3::UnitY()).toRotationMatrix(), Vec3(0, 0, 2),
                   Vec3(12, 0, 0));
  runtime::testing::AddSegment(model, "box", -1, runtime::JointKind::kFree, 2.0,
                               Vec3(0.05, 0.08, 0.11), Vec3::Zero(), Vec3::Zero(), Vec3::UnitY(),
                               {runtime::FrameRef::Kind::kVehicle, 0});
  // Start at r = (0.4, 0.1, 0.3) m in the vehicle, at rest in the ground frame. The free
  // joint's velocity is (w, v) relative to the vehicle in segment axes (= vehicle axes at t = 0):
  // w = -w0 and v = -(v0 + w0 x r), both in vehicle axes.
  const Vec3 r(0.4, 0.1, 0.3);
  const Mat3& R0 = model.vehicle_orientation[0];
  const Vec3 w0 = R0.transpose() * Vec3(0, 0, 2);
  const Vec3 v0 = R0.transpose() * Vec3(12, 0, 0);
  const Vec3 relative = -(v0 + w0.cross(r));
  for (int k = 0; k < 3; ++k) {
    model.q0[static_cast<std::size_t>(k)] = r[k];
    model.v0[static_cast<std::size_t>(k)] = -w0[k];
    model.v0[static_cast<std::size_t>(k) + 3] = relative[k];
  }
  runtime::Data data = runtime::MakeData(model);
  ASSERT_TRUE(runtime::Forward(model, data, nullptr));
  const Vec3 start = data.position[0];
  const Mat3 orientation = data.rotation[0];
  ASSERT_NEAR((orientation - R0).norm(), 0, 1e-12);
  double worst_position = 0, worst_rotation = 0;
  ASSERT_TRUE(
      Simulate(model, data, GetParam(), 1e-10, Linspace(0, 0.3, 30), [&](const runtime::Data& d) {
        worst_position = std::max(worst_position, (d.position[0] - start).norm());
        worst_rotation = std::max(worst_rotation, (d.rotation[0] - orientation).norm());
      }));
  // The vehicle moves by about a metre and turns by about a radian meanwhile.
  EXPECT_GT((runtime::VehicleAt(model, 0, 0.3).position - model.vehicle_position[0]).norm(), 1.0);
  EXPECT_LT(worst_position, 1e-7);
  EXPECT_LT(worst_rotation, 1e-7);
}

INSTANTIATE_TEST_SUITE_P(EveryIntegrator, FreeBodyOnATurningVehicle,
                         ::testing::ValuesIn(AllIntegrators()));

}  // namespace
}  // namespace sled::verification
