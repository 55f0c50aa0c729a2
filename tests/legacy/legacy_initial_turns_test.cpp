// G.3.a's rotation orders (ID1 to ID3) and the angular velocity of a segment that hangs from a
// joint. ATB's DRCYPR builds the direction cosines (ground to segment) as the product of turns
// about the listed axes, each by the angle it pairs with the axis (yaw about z, pitch about y,
// roll about x), and INPUT_ORIENT's default order is 1, 2, 3: the segment's axes in the ground's
// are R = Rx(roll) Ry(pitch) Rz(yaw). COMPUTE_INIT_ANG_VEL starts every segment with its card's
// angular velocity in its own axes (I3 = 1). The compiled Model's rotations and angular
// velocities are checked against these products worked out with Eigen.
#include <gtest/gtest.h>

#include <numbers>
#include <string>

#include <fmt/format.h>
#include <Eigen/Geometry>

#include "tests/legacy/legacy_test_deck.h"

#include "runtime/dynamics/dynamics.h"
#include "sled/compile.h"

namespace sled::lang::legacy {
namespace {

using namespace deck_testing;  // NOLINT(google-build-using-namespace): the deck helpers

constexpr double kDeg = std::numbers::pi / 180;

// The corpus deck two_segments.ain (UPPR the reference segment, LOWR on the ball joint HIP,
// I3 = 1) with its two G.3.a cards replaced, and HIP's JTYPE when given.
Converted WithCards(const std::string& upper, const std::string& lower, int hip_type = 0) {
  std::vector<std::string> lines =
      Lines(ReadDeckFile(std::string(SLED_SOURCE_ROOT) + "/tests/legacy/corpus/two_segments.ain"));
  const std::size_t g2 = LineStarting(lines, "        0.        0.      -10.");
  lines[g2] = upper;
  lines[g2 + 1] = lower;
  std::string& hip = lines[LineStarting(lines, "HIP ") - 1];
  hip.replace(10, 4, fmt::format("{:4}", hip_type));
  return ConvertText(Join(lines));
}

struct G3a {
  double yaw = 0, pitch = 0, roll = 0;
  Eigen::Vector3d omega = Eigen::Vector3d::Zero();  // deg/s in the segment's axes
  int id1 = 0, id2 = 0, id3 = 0, id4 = 0;
  std::string Card() const {
    return fmt::format("{:10.1f}{:10.1f}{:10.1f}{:10.1f}{:10.1f}{:10.1f}{:3}{:3}{:3}{:3}", yaw,
                       pitch, roll, omega.x(), omega.y(), omega.z(), id1, id2, id3, id4);
  }
};

Eigen::Matrix3d About(const Eigen::Vector3d& axis, double degrees) {
  return Eigen::AngleAxisd(degrees * kDeg, axis).toRotationMatrix();
}
const Eigen::Vector3d kX = Eigen::Vector3d::UnitX(), kY = Eigen::Vector3d::UnitY(),
                      kZ = Eigen::Vector3d::UnitZ();

struct Start {
  Eigen::Matrix3d rotation[2];
  Eigen::Vector3d omega[2];  // rad/s in the ground's axes
};

Start Compiled(const Converted& converted) {
  Start start{};
  Compilation compiled = Compile(Source::Text(converted.text, "turns.sled"));
  EXPECT_TRUE(compiled.ok()) << compiled.Render() << converted.text;
  if (!compiled.ok()) return start;
  const runtime::Model& model = compiled.model();
  runtime::Data data = runtime::MakeData(model);
  runtime::ComputeKinematics(model, data);
  for (std::size_t s = 0; s < 2; ++s) {
    start.rotation[s] = data.rotation.at(s);
    start.omega[s] = data.rotation.at(s) * data.velocity.at(s).head<3>();
  }
  return start;
}

TEST(LegacyInitialTurns, TheDefaultOrderTurnsYawFirstAboutTheGroundsAxes) {
  // A blank ID1 is 1, 2, 3: R = Rx(roll) Ry(pitch) Rz(yaw), not sled's Rz Ry Rx.
  const Converted converted = WithCards(G3a{30, 20, 10}.Card(), G3a{}.Card());
  ASSERT_EQ(converted.errors, 0) << converted.All();
  const Eigen::Matrix3d atb = About(kX, 10) * About(kY, 20) * About(kZ, 30);
  const Start start = Compiled(converted);
  EXPECT_LE((start.rotation[0] - atb).norm(), 1e-9) << converted.text;
  EXPECT_GT((atb - About(kZ, 30) * About(kY, 20) * About(kX, 10)).norm(), 0.1);  // they differ
  // LOWR's blank card keeps it level: HIP turns it back.
  EXPECT_LE((start.rotation[1] - Eigen::Matrix3d::Identity()).norm(), 1e-9);
}

TEST(LegacyInitialTurns, AnOrderOfAxesIsConvertedExactly) {
  // 3, 2, 1: Rz(yaw) Ry(pitch) Rx(roll). 3, 1, -3 (z-x-z): the -3 takes the angle DRCYPR's sum
  // rule gives it (sum 1, 1 + 3 - 2 = 2, the pitch): Rz(yaw) Rx(roll) Rz(pitch). On LOWR about
  // HIP's axes (ID4 = -1), under UPPR yawed 90 deg.
  const Converted zyx = WithCards(G3a{30, 20, 10, {}, 3, 2, 1}.Card(), G3a{}.Card());
  ASSERT_EQ(zyx.errors, 0) << zyx.All();
  EXPECT_LE((Compiled(zyx).rotation[0] - About(kZ, 30) * About(kY, 20) * About(kX, 10)).norm(),
            1e-9);
  const Converted zxz = WithCards(G3a{90}.Card(), G3a{40, 25, 15, {}, 3, 1, -3, -1}.Card());
  ASSERT_EQ(zxz.errors, 0) << zxz.All();
  const Eigen::Matrix3d hip = About(kZ, 40) * About(kX, 15) * About(kZ, 25);
  EXPECT_LE((Compiled(zxz).rotation[1] - About(kZ, 90) * hip).norm(), 1e-9) << zxz.text;
}

TEST(LegacyInitialTurns, OrdersAtbStopsOnAreInvalidAndProjectionsRefused) {
  // STOP 230 (an axis of 4), 231 (two turns in a row about x), 232 (first and third the same,
  // the third not negative); ID1 < 0 reads G.3.b, whose reader is not in the reference.
  for (const G3a& card :
       {G3a{10, 0, 0, {}, 4, 1, 2}, G3a{10, 0, 0, {}, 1, 1, 2}, G3a{10, 0, 0, {}, 1, 2, 1}}) {
    EXPECT_TRUE(WithCards(card.Card(), G3a{}.Card()).Has(":61-69: error[E0512]")) << card.Card();
  }
  EXPECT_TRUE(WithCards(G3a{0, 0, 0, {}, -1}.Card(), G3a{}.Card()).Has(":61-63: error[E0507]"));
  // ID2 and ID3 without ID1: ATB's default, the two ignored with a warning.
  const Converted ignored = WithCards(G3a{10, 0, 0, {}, 0, 2, 1}.Card(), G3a{}.Card());
  EXPECT_EQ(ignored.errors, 0) << ignored.All();
  EXPECT_TRUE(ignored.Has(":61-69: warning[W0503]")) << ignored.All();
}

TEST(LegacyInitialTurns, AJointedSegmentStartsWithItsCardsAngularVelocity) {
  // UPPR yawed 90 deg spinning at 10 deg/s about its z; LOWR level with 5 deg/s about its x
  // (the ground's x). ATB's angular velocities are absolute, each in the segment's own axes.
  G3a lower;
  lower.omega = {5, 0, 0};
  G3a upper{90};
  upper.omega = {0, 0, 10};
  const Converted converted = WithCards(upper.Card(), lower.Card());
  ASSERT_EQ(converted.errors, 0) << converted.All();
  const Start start = Compiled(converted);
  EXPECT_LE((start.omega[0] - Eigen::Vector3d(0, 0, 10 * kDeg)).norm(), 1e-9) << converted.text;
  EXPECT_LE((start.omega[1] - Eigen::Vector3d(5 * kDeg, 0, 0)).norm(), 1e-9) << converted.text;
  // A blank LOWR card under the spinning UPPR: ATB starts LOWR at rest, not turning with UPPR.
  const Converted still = WithCards(upper.Card(), G3a{}.Card());
  ASSERT_EQ(still.errors, 0) << still.All();
  EXPECT_LE(Compiled(still).omega[1].norm(), 1e-12) << still.text;
}

TEST(LegacyInitialTurns, APinGivesOnlyARateAboutItsAxis) {
  // HIP a pin (JTYPE 1) about the y axis of its axes, the ground's y with both level: 5 deg/s
  // about y converts, about x it is refused (what ATB does with it is not in the reference).
  G3a about_y;
  about_y.omega = {0, 5, 0};
  const Converted pin = WithCards(G3a{}.Card(), about_y.Card(), 1);
  ASSERT_EQ(pin.errors, 0) << pin.All();
  EXPECT_LE((Compiled(pin).omega[1] - Eigen::Vector3d(0, 5 * kDeg, 0)).norm(), 1e-9) << pin.text;
  G3a about_x;
  about_x.omega = {5, 0, 0};
  EXPECT_TRUE(WithCards(G3a{}.Card(), about_x.Card(), 1).Has("error[E0507]"));
}

}  // namespace
}  // namespace sled::lang::legacy
