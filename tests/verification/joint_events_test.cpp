// Joint events against closed-form answers: a pin joint hitting its stop with restitution e
// rebounds with -e times its closing rate, at the time and angle the kinematics give; an Euler
// joint locks when its spring torque falls below the lock level, at the time the harmonic
// solution gives, and stays locked; a locked joint unlocks when the torque it carries exceeds
// the unlock level.
#include <cmath>

#include <gtest/gtest.h>

#include "runtime/dynamics/vehicle.h"
#include "tests/runtime/model_fixtures.h"
#include "tests/verification/verification.h"

namespace sled::verification {
namespace {

using runtime::JointKind;
using runtime::Vec3;

class JointStop : public ::testing::TestWithParam<std::string> {};

TEST_P(JointStop, ReboundsWithTheRestitution) {
  // No gravity: the arm turns at a constant rate until it meets the stop at 0.5 rad.
  runtime::Model model;
  model.gravity.setZero();
  runtime::testing::AddSegment(model, "arm", -1, JointKind::kPin, 1.0, Vec3(0.01, 0.02, 0.01),
                               Vec3::Zero(), Vec3(0, 0, 0.3), Vec3::UnitY());
  const double stop = 0.5, rate = 2.0, e = 0.6;
  model.joint_stop[0] = stop;
  model.joint_stop_impulse[0] = 1;
  model.joint_restitution[0] = e;
  model.v0[0] = rate;
  runtime::Data data = runtime::MakeData(model);
  const double t_hit = stop / rate;
  double worst = 0;
  runtime::IntegratorStats stats;
  ASSERT_TRUE(Simulate(
      model, data, GetParam(), 1e-10, Linspace(0, 1.0, 100),
      [&](const runtime::Data& d) {
        const double expected = d.time < t_hit ? rate * d.time : stop - e * rate * (d.time - t_hit);
        worst = std::max(worst, std::abs(d.q[0] - expected));
        if (d.time > t_hit) {
          EXPECT_NEAR(d.v[0], -e * rate, 1e-9) << d.time;
        }
      },
      &stats));
  EXPECT_LT(worst, 1e-8);
  EXPECT_EQ(stats.events, 1);
}

class JointLock : public ::testing::TestWithParam<std::string> {};

TEST_P(JointLock, EulerJointLocksAtItsTorqueLevel) {
  // A disc on an Euler joint to the ground with a linear precession spring k: released at
  // psi0 it swings back as psi0 cos(w t); its spring torque k psi falls below the lock level
  // k psi_lock at t = acos(psi_lock / psi0) / w, where the joint locks and stays.
  runtime::Model model;
  model.gravity.setZero();
  const double Iz = 0.05, k = 20.0, psi0 = 0.8, psi_lock = 0.3;
  runtime::testing::AddSegment(model, "disc", -1, JointKind::kEuler, 1.0, Vec3(0.04, 0.04, Iz));
  model.functions.kind = {runtime::FunctionTable::Kind::kPolynomial};
  model.functions.constant = {0};
  model.functions.first = {0};
  model.functions.count = {2};
  model.functions.energy_loss = {0};
  model.functions.permanent_set = {0};
  model.functions.coefficients = {0.0, k};
  model.joint_function[0] = {0, -1, -1};
  model.joint_lock_below[0] = k * psi_lock;
  model.q0[0] = psi0;
  runtime::Data data = runtime::MakeData(model);
  const double w = std::sqrt(k / Iz);
  const double t_lock = std::acos(psi_lock / psi0) / w;
  runtime::IntegratorStats stats;
  ASSERT_TRUE(Simulate(
      model, data, GetParam(), 1e-10, Linspace(0, 0.5, 100),
      [&](const runtime::Data& d) {
        const double expected = d.time < t_lock ? psi0 * std::cos(w * d.time) : psi_lock;
        EXPECT_NEAR(d.q[0], expected, 1e-7) << d.time;
        if (d.time > t_lock) {
          EXPECT_EQ(d.locked[0] & 1, 1) << d.time;
        }
      },
      &stats));
  EXPECT_EQ(stats.events, 1);
}

// A locked joint of `kind` holds a bar on a vehicle whose acceleration ramps up as a = c t; the
// joint carries m l (g + a) about y (the bar stands out horizontally along x, the pin axis y), so
// it unlocks when m l (g + c t) reaches the unlock level. A pin compares the torque about its
// axis, a ball the size of its constraint torque vector (ATB's JTYPE -1 and -2): here the same.
void ExpectUnlockWhereTheTorqueReachesTheLevel(JointKind kind, const std::string& method) {
  runtime::Model model;
  const double m = 2.0, l = 0.5, c = 100.0, level = 30.0;
  model.vehicle_name = {"sled"};
  runtime::VehicleMotion motion;
  motion.kind = runtime::VehicleMotion::Kind::kTable;
  motion.axis = Vec3::UnitZ();
  motion.table = {{0.0, 0.0}, {10.0, c * 10.0}};
  runtime::IntegrateMotionRows(motion);
  model.vehicle_motion = {motion};
  model.vehicle_position = {Vec3::Zero()};
  model.vehicle_orientation = {runtime::Mat3::Identity()};
  model.vehicle_velocity = {Vec3::Zero()};
  runtime::testing::AddSegment(model, "bar", -1, kind, m, Vec3(0.01, 0.01, 0.01), Vec3::Zero(),
                               Vec3(-l, 0, 0), Vec3::UnitY(),
                               {runtime::FrameRef::Kind::kVehicle, 0});
  model.joint_locked[0] = 7;
  model.joint_unlock_above[0] = level;
  runtime::Data data = runtime::MakeData(model);
  const double g = 9.80665;
  const double t_unlock = (level / (m * l) - g) / c;
  ASSERT_GT(t_unlock, 0.0);
  runtime::IntegratorStats stats;
  double first_unlocked = -1;
  ASSERT_TRUE(Simulate(
      model, data, method, 1e-10, Linspace(0, 0.4, 400),
      [&](const runtime::Data& d) {
        if (first_unlocked < 0 && d.locked[0] == 0) first_unlocked = d.time;
        if (d.time < t_unlock - 1e-3) {
          EXPECT_NE(d.locked[0], 0) << d.time;
        }
      },
      &stats));
  ASSERT_GT(first_unlocked, 0);
  EXPECT_NEAR(first_unlocked, t_unlock, 1.0e-3);  // within one output sample
  EXPECT_EQ(stats.events, 1);
}

TEST_P(JointLock, LockedJointUnlocksAboveItsLevel) {
  ExpectUnlockWhereTheTorqueReachesTheLevel(JointKind::kPin, GetParam());
}

TEST_P(JointLock, LockedBallUnlocksWhenItsTorqueVectorReachesTheLevel) {
  ExpectUnlockWhereTheTorqueReachesTheLevel(JointKind::kBall, GetParam());
}

class JointTableKink : public ::testing::TestWithParam<std::string> {};

// The angle of an arm that turns freely at `rate` between -a and a and meets, beyond, a linear
// spring of stiffness k (I theta'' = -k (theta - a)): from 0 it runs to a, swings a half period
// pi / w of the spring (w = sqrt(k / I)), comes back at -rate, and so on.
double PiecewiseOscillator(double t, double a, double rate, double w) {
  const double free = a / rate, swing = std::acos(-1.0) / w;
  const double period = 4 * free + 2 * swing;
  double u = std::fmod(t, period);
  const double side[] = {1.0, -1.0};
  if (u < free) return rate * u;
  u -= free;
  for (const double sign : side) {
    if (u < swing) return sign * (a + rate / w * std::sin(w * u));
    u -= swing;
    if (u < 2 * free || sign < 0) return sign * (a - rate * u);
    u -= 2 * free;
  }
  return 0.0;
}

TEST_P(JointTableKink, ArmOnATabulatedStopFollowsThePiecewiseClosedForm) {
  // A pin joint whose torque table is 0 between -0.2 and 0.2 rad and 200 N*m/rad beyond: the
  // torque's slope jumps at the table's inner rows, which are events (kJointKink), so no step
  // straddles them. Before they were, dopri5 at 1e-8 put the stiff stop of
  // examples/numerics/joint_stops.sled 1e-5 of its range off.
  runtime::Model model;
  model.gravity.setZero();
  const double inertia = 0.02, k = 200, a = 0.2, rate = 2.0;
  runtime::testing::AddSegment(model, "arm", -1, JointKind::kPin, 1.0, Vec3(0.01, inertia, 0.01));
  model.joint_function[0][0] = runtime::testing::AddTableFunction(
      model.functions, {{{-1.0, -k * (1 - a)}, {-a, 0.0}, {a, 0.0}, {1.0, k * (1 - a)}}});
  model.v0[0] = rate;
  runtime::Data data = runtime::MakeData(model);
  const double w = std::sqrt(k / inertia);
  double worst = 0;
  runtime::IntegratorStats stats;
  ASSERT_TRUE(Simulate(
      model, data, GetParam(), 1e-8, Linspace(0, 1.0, 200),
      [&](const runtime::Data& d) {
        worst = std::max(worst, std::abs(d.q[0] - PiecewiseOscillator(d.time, a, rate, w)));
      },
      &stats));
  // Five crossings of the rows in the first second (0.1, 0.131, 0.331, 0.363, 0.563 s ...).
  EXPECT_GE(stats.events, 5);
  EXPECT_LT(worst, 1e-6) << GetParam();
}

INSTANTIATE_TEST_SUITE_P(EveryIntegrator, JointStop, ::testing::ValuesIn(AllIntegrators()));
INSTANTIATE_TEST_SUITE_P(EveryIntegrator, JointLock, ::testing::ValuesIn(AllIntegrators()));
INSTANTIATE_TEST_SUITE_P(EveryIntegrator, JointTableKink, ::testing::ValuesIn(AllIntegrators()));

}  // namespace
}  // namespace sled::verification
