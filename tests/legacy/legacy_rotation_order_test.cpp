// B.3.b IDYPR, the rotation order of a joint's axes (YPR1 in columns 69-74, YPR2 in 75-80), and
// YPR3: ATB's DRCYPR turns by yaw about z, pitch about y and roll about x in the order the three
// numbers give (3, 2, 1 by default, sled's `axes`). The converted joint frame is compared with
// the rotation built here from Eigen's angle-axis rotations, on two_segments' HIP joint.
#include <gtest/gtest.h>

#include <numbers>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <Eigen/Geometry>

#include "legacy_test_deck.h"
#include "sled/compile.h"

namespace sled::lang::legacy {
namespace {

const std::string kDeck = std::string(SLED_SOURCE_ROOT) + "/tests/legacy/corpus/two_segments.ain";

Eigen::Matrix3d About(const Eigen::Vector3d& axis, double degrees) {
  return Eigen::AngleAxisd(degrees * std::numbers::pi / 180, axis).toRotationMatrix();
}

// two_segments with HIP's B.3.b card (the line after B.3.a) replaced by `b3b`.
Converted WithB3b(const std::string& b3b, std::size_t* line) {
  std::vector<std::string> lines = Lines(ReadDeckFile(kDeck));
  *line = LineStarting(lines, "HIP ") + 1;
  lines[*line - 1] = b3b;
  return ConvertText(Join(lines), {}, "deck.ain");
}

TEST(LegacyRotationOrder, YPR1InTheOrderXYZIsTheProductOfItsThreeTurns) {
  // YPR1 (30, 20, 10) deg with IDYPR 1, 2, 3: roll 10 about x, then pitch 20 about y, then yaw
  // 30 about z, each about the axes the earlier turns left: Rx(10) Ry(20) Rz(30).
  std::size_t line = 0;
  const Converted converted = WithB3b(
      "                 30.   20.   10.    0.    0.    0.    0.    0.    0. 1 2 3 0 0 0", &line);
  ASSERT_EQ(converted.errors, 0) << converted.All();
  Compilation compiled = Compile(Source::Text(converted.text, "converted.sled"));
  ASSERT_TRUE(compiled.ok()) << compiled.Render() << converted.text;
  const Eigen::Matrix3d expected = About(Eigen::Vector3d::UnitX(), 10) *
                                   About(Eigen::Vector3d::UnitY(), 20) *
                                   About(Eigen::Vector3d::UnitZ(), 30);
  const Eigen::Matrix3d frame = compiled.model().joint_frame_in_parent.at(1);
  EXPECT_LT((frame - expected).norm(), 1e-9) << frame << "\n" << expected;
  // The default order (blank IDYPR) is Rz(30) Ry(20) Rx(10), unlike the one above.
  const Converted plain =
      WithB3b("                 30.   20.   10.    0.    0.    0.    0.    0.    0.", &line);
  Compilation default_order = Compile(Source::Text(plain.text, "converted.sled"));
  ASSERT_TRUE(default_order.ok()) << default_order.Render();
  const Eigen::Matrix3d zyx = About(Eigen::Vector3d::UnitZ(), 30) *
                              About(Eigen::Vector3d::UnitY(), 20) *
                              About(Eigen::Vector3d::UnitX(), 10);
  EXPECT_LT((default_order.model().joint_frame_in_parent.at(1) - zyx).norm(), 1e-9);
  EXPECT_GT((zyx - expected).norm(), 0.1);
}

TEST(LegacyRotationOrder, YPR2TakesItsOwnOrderAndBadNumbersAreReported) {
  // YPR2 (0, 90, 0) with IDYPR 2, 3, 1: only the pitch turns, about y: the child's frame.
  std::size_t line = 0;
  const Converted converted = WithB3b(
      "                  0.    0.    0.    0.   90.   45.    0.    0.    0. 0 0 0 2 3 1", &line);
  ASSERT_EQ(converted.errors, 0) << converted.All();
  Compilation compiled = Compile(Source::Text(converted.text, "converted.sled"));
  ASSERT_TRUE(compiled.ok()) << compiled.Render() << converted.text;
  const Eigen::Matrix3d expected = About(Eigen::Vector3d::UnitY(), 90) *
                                   About(Eigen::Vector3d::UnitZ(), 0) *
                                   About(Eigen::Vector3d::UnitX(), 45);
  EXPECT_LT((compiled.model().joint_frame_in_child.at(1) - expected).norm(), 1e-9);
  // An axis number above 3 (ATB's STOP 101): E0512 at its three columns.
  const Converted bad = WithB3b(
      "                 30.    0.    0.    0.    0.    0.    0.    0.    0. 4 2 1 0 0 0", &line);
  EXPECT_TRUE(bad.Has(fmt::format("deck.ain:{}:69-74: error[E0512]", line))) << bad.All();
  // YPR3 of a ball joint: W0503 (ATB reads it for Euler joints only).
  const Converted ypr3 =
      WithB3b("                  0.    0.    0.    0.    0.    0.    5.    0.    0.", &line);
  EXPECT_EQ(ypr3.errors, 0) << ypr3.All();
  EXPECT_TRUE(ypr3.Has(fmt::format("deck.ain:{}:51-68: warning[W0503]", line))) << ypr3.All();
}

}  // namespace
}  // namespace sled::lang::legacy
