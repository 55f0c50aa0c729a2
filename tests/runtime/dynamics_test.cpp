// The articulated-body dynamics against closed-form accelerations: a free rigid body (Euler's
// equations), a pendulum on a pin, a ball-jointed pendulum, a free-falling chain, a moving base.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "runtime/dynamics/dynamics.h"
#include "runtime/forces/forces.h"
#include "tests/runtime/model_fixtures.h"

namespace sled::runtime {
namespace {

using testing::AddSegment;

TEST(Dynamics, TorqueFreeBodyFollowsEulersEquations) {
  Model model;
  model.gravity.setZero();
  const Vec3 I(0.1, 0.2, 0.3);
  AddSegment(model, "body", -1, JointKind::kFree, 2.0, I);
  Data data = MakeData(model);
  const Vec3 w(1.0, -2.0, 0.5);
  for (int k = 0; k < 3; ++k) data.v[static_cast<std::size_t>(k)] = w[k];
  ASSERT_TRUE(Forward(model, data, nullptr));
  // I wdot = -w x I w
  const Vec3 expected = -(w.cross(I.asDiagonal() * w)).cwiseQuotient(I);
  for (int k = 0; k < 3; ++k)
    EXPECT_NEAR(data.vdot[static_cast<std::size_t>(k)], expected[k], 1e-12);
}

TEST(Dynamics, PinPendulumAccelerationMatchesClosedForm) {
  Model model;
  const double m = 1.5, l = 0.4, Iy = 0.02;
  // Pivot at the ground origin, the centre of mass l below the pivot when the angle is zero.
  AddSegment(model, "link", -1, JointKind::kPin, m, Vec3(0.02, Iy, 0.02), Vec3::Zero(),
             Vec3(0, 0, l), Vec3::UnitY());
  Data data = MakeData(model);
  for (double angle : {0.3, 1.0, 2.5}) {
    data.q[0] = angle;
    data.v[0] = 0.7;
    ASSERT_TRUE(Forward(model, data, nullptr));
    const double g = 9.80665;
    const double expected = -m * g * l * std::sin(angle) / (Iy + m * l * l);
    EXPECT_NEAR(data.vdot[0], expected, 1e-12) << angle;
  }
}

TEST(Dynamics, BallPendulumSwingsLikeThePinOne) {
  Model model;
  const double m = 1.5, l = 0.4, Iy = 0.02;
  AddSegment(model, "link", -1, JointKind::kBall, m, Vec3(0.02, Iy, 0.02), Vec3::Zero(),
             Vec3(0, 0, l));
  Data data = MakeData(model);
  const double angle = 0.8;
  const Eigen::Quaterniond q(Eigen::AngleAxisd(angle, Vec3::UnitY()));
  data.q = {q.w(), q.x(), q.y(), q.z()};
  ASSERT_TRUE(Forward(model, data, nullptr));
  const double expected = -m * 9.80665 * l * std::sin(angle) / (Iy + m * l * l);
  EXPECT_NEAR(data.vdot[1], expected, 1e-12);
  EXPECT_NEAR(data.vdot[0], 0.0, 1e-12);
  EXPECT_NEAR(data.vdot[2], 0.0, 1e-12);
}

TEST(Dynamics, FreeFallingChainHasNoJointForces) {
  Model model;
  AddSegment(model, "a", -1, JointKind::kFree, 2.0, Vec3(0.1, 0.1, 0.1));
  AddSegment(model, "b", 0, JointKind::kBall, 1.0, Vec3(0.05, 0.05, 0.05), Vec3(0, 0, -0.2),
             Vec3(0, 0, 0.2));
  AddSegment(model, "c", 1, JointKind::kPin, 0.5, Vec3(0.01, 0.01, 0.01), Vec3(0, 0, -0.2),
             Vec3(0, 0, 0.1));
  Data data = MakeData(model);
  // Tilt the chain and spin nothing: every segment falls with g, no joint transmits force.
  const Eigen::Quaterniond tilt(Eigen::AngleAxisd(0.4, Vec3(1, 1, 0).normalized()));
  data.q[3] = tilt.w();
  data.q[4] = tilt.x();
  data.q[5] = tilt.y();
  data.q[6] = tilt.z();
  data.q[11] = 0.7;
  ASSERT_TRUE(Forward(model, data, nullptr));
  for (std::size_t s = 1; s < 3; ++s) {
    EXPECT_LT(data.joint_wrench[s].norm(), 1e-10) << s;
    const Vec3 a_world = data.rotation[s] * data.acceleration[s].tail<3>();
    EXPECT_NEAR((a_world - model.gravity).norm(), 0.0, 1e-10) << s;
  }
  for (std::size_t k = 6; k < data.vdot.size(); ++k) EXPECT_NEAR(data.vdot[k], 0.0, 1e-10);
}

TEST(Dynamics, JointWrenchOfAHangingPendulumCarriesItsWeight) {
  Model model;
  const double m = 3.0;
  AddSegment(model, "link", -1, JointKind::kPin, m, Vec3(0.02, 0.02, 0.02), Vec3::Zero(),
             Vec3(0, 0, 0.5), Vec3::UnitY());
  Data data = MakeData(model);
  ASSERT_TRUE(Forward(model, data, nullptr));
  // At rest, hanging straight down: the pivot pushes up with m g.
  EXPECT_NEAR(data.joint_wrench[0].tail<3>().z(), m * 9.80665, 1e-10);
  EXPECT_NEAR(data.vdot[0], 0.0, 1e-12);
}

}  // namespace
}  // namespace sled::runtime
