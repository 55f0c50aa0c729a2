// G.3.a of a segment that hangs from a joint: ATB gives each segment its own orientation (from
// the ground, from an earlier segment's or a vehicle's axes by ID4, or about the joint's axes
// with a negative ID4; a blank card is level with the ground); sled poses it by its joint's
// angles. The converter's angles are checked against rotations worked out by hand, and the
// compiled Model's segment orientation against ATB's direction cosines (DRCIJK).
#include <gtest/gtest.h>

#include <cmath>
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

// The corpus deck two_segments.ain (UPPR the reference segment, LOWR on the ball joint HIP)
// with its two G.3.a cards replaced and, when given, HIP's B.3.b card.
Converted WithOrientations(const std::string& upper, const std::string& lower,
                           const std::string& b3b = "") {
  std::vector<std::string> lines =
      Lines(ReadDeckFile(std::string(SLED_SOURCE_ROOT) + "/tests/legacy/corpus/two_segments.ain"));
  const std::size_t g2 = LineStarting(lines, "        0.        0.      -10.");
  lines[g2] = upper;
  lines[g2 + 1] = lower;
  if (!b3b.empty()) lines[LineStarting(lines, "HIP ")] = b3b;
  return ConvertText(Join(lines));
}

// A G.3.a card: yaw, pitch, roll (6F10.0 with no angular velocity) and ID4 in columns 70-72.
std::string G3a(double yaw, double pitch, double roll, int id4 = 0) {
  return fmt::format("{:10.1f}{:10.1f}{:10.1f}{:30}{:9}{:3}", yaw, pitch, roll, "", "", id4);
}

Eigen::Matrix3d Ypr(double yaw, double pitch, double roll) {
  constexpr double d = std::numbers::pi / 180;
  return (Eigen::AngleAxisd(yaw * d, Eigen::Vector3d::UnitZ()) *
          Eigen::AngleAxisd(pitch * d, Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(roll * d, Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

// LOWR's orientation in the ground's axes at the start, from the compiled scenario.
Eigen::Matrix3d LowerRotation(const Converted& converted) {
  Compilation compiled = Compile(Source::Text(converted.text, "posture.sled"));
  EXPECT_TRUE(compiled.ok()) << compiled.Render() << converted.text;
  if (!compiled.ok()) return Eigen::Matrix3d::Zero();
  const runtime::Model& model = compiled.model();
  runtime::Data data = runtime::MakeData(model);
  runtime::ComputeKinematics(model, data);
  return data.rotation.at(1);
}

TEST(LegacyPosture, AJointedSegmentTurnedFromTheGroundTurnsItsJoint) {
  // UPPR level, LOWR yawed 30 deg from the ground: HIP's angles are (30, 0, 0).
  const Converted converted = WithOrientations(G3a(0, 0, 0), G3a(30, 0, 0));
  ASSERT_EQ(converted.errors, 0) << converted.All();
  EXPECT_NE(converted.text.find("  initial pair.hip {\n    angles = (30, 0, 0) deg\n  }"),
            std::string::npos)
      << converted.text;
  EXPECT_LE((LowerRotation(converted) - Ypr(30, 0, 0)).norm(), 1e-12);
}

TEST(LegacyPosture, ABlankCardLeavesTheSegmentLevelUnderATurnedReference) {
  // UPPR yawed 90 deg; LOWR's blank card keeps it level (ATB: ID4 = 0, yaw 0 from the ground),
  // so HIP turns it back: Rz(90)^T = Rz(-90).
  const Converted converted = WithOrientations(G3a(90, 0, 0), G3a(0, 0, 0));
  ASSERT_EQ(converted.errors, 0) << converted.All();
  EXPECT_NE(converted.text.find("angles = (-90, 0, 0) deg"), std::string::npos) << converted.text;
  EXPECT_LE((LowerRotation(converted) - Eigen::Matrix3d::Identity()).norm(), 1e-12);
}

TEST(LegacyPosture, IdFourNamesTheFrameTheAnglesTurnFrom) {
  // UPPR yawed 90 deg. ID4 = 1 (UPPR's axes), pitch 20: R = Rz(90) Ry(20), so HIP's rotation
  // is Rz(90)^T Rz(90) Ry(20) = Ry(20). ID4 = -1 (about HIP's axes, UPPR its proximal segment):
  // the angles are the joint's own, Ry(20) again.
  for (const int id4 : {1, -1}) {
    const Converted converted = WithOrientations(G3a(90, 0, 0), G3a(0, 20, 0, id4));
    ASSERT_EQ(converted.errors, 0) << id4 << "\n" << converted.All();
    EXPECT_NE(converted.text.find("angles = (0, 20, 0) deg"), std::string::npos) << converted.text;
    EXPECT_LE((LowerRotation(converted) - Ypr(90, 0, 0) * Ypr(0, 20, 0)).norm(), 1e-12);
  }
}

TEST(LegacyPosture, TheJointsAxesEnterTheAngles) {
  // B.3.b: HIP's axes are pitched 30 deg in LOWR (YPR2) and level in UPPR (YPR1). Both segments
  // level (blank cards): R_J = Y(YPR1)^T I Y(YPR2) = Ry(30), and LOWR stays level.
  const std::string b3b =
      fmt::format("{:14}{:6}{:6}{:6}{:6}{:6}{:6}", "", "0.", "0.", "0.", "0.", "30.", "0.");
  const Converted converted = WithOrientations(G3a(0, 0, 0), G3a(0, 0, 0), b3b);
  ASSERT_EQ(converted.errors, 0) << converted.All();
  EXPECT_NE(converted.text.find("      axes lowr = (0, 30, 0) deg\n"), std::string::npos)
      << converted.text;
  EXPECT_NE(converted.text.find("angles = (0, 30, 0) deg"), std::string::npos) << converted.text;
  EXPECT_LE((LowerRotation(converted) - Eigen::Matrix3d::Identity()).norm(), 1e-12);
}

TEST(LegacyPosture, ReferencesAtbStopsOnAreInvalid) {
  // ID4 = -2: LOWR hangs from segment 1 (ATB's STOP 25); ID4 = 2: not a segment before LOWR
  // (STOP 24); ID4 on the reference segment: sled turns it from the ground.
  EXPECT_TRUE(WithOrientations(G3a(0, 0, 0), G3a(0, 20, 0, -2)).Has(":70-72: error[E0512]"));
  EXPECT_TRUE(WithOrientations(G3a(0, 0, 0), G3a(0, 20, 0, 2)).Has(":70-72: error[E0512]"));
  EXPECT_TRUE(WithOrientations(G3a(0, 10, 0, 2), G3a(0, 0, 0)).Has(":70-72: error[E0507]"));
}

}  // namespace
}  // namespace sled::lang::legacy
