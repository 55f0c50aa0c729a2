// B.3.a JTYPE 1 and -1, ATB's pinned joint (unlocked and locked): a sled `pin` about HB, the y
// axis of the joint's axes in the proximal segment (OUTPUT_JOINTS, UPDATE_JOINTS), with B.5.a's
// lock levels as `unlock_above` and `lock_below` (UPDATE_JOINTS compares the torque about the
// pin with them), and a G.3.a posture about the pin as its angle. On two_segments' HIP joint.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include <fmt/format.h>

#include "legacy_test_deck.h"
#include "sled/compile.h"

namespace sled::lang::legacy {
namespace {

constexpr double kPoundInch = 4.4482216152605 * 0.0254;  // N*m

struct PinDeck {
  std::vector<std::string> lines =
      Lines(ReadDeckFile(std::string(SLED_SOURCE_ROOT) + "/tests/legacy/corpus/two_segments.ain"));
  std::size_t hip = LineStarting(lines, "HIP ");
  std::size_t b4 = LineStarting(lines, "  100.    0.");
  std::size_t b5 = LineStarting(lines, "    2.    0.    1.");
  std::size_t g3 = LineStarting(lines, "# ---- H cards") - 1;  // LOWR's G.3.a, the last G card
  std::string& Line(std::size_t number) { return lines[number - 1]; }
  explicit PinDeck(const char* jtype) { Line(hip).replace(10, 4, jtype); }
  Converted Convert() const { return ConvertText(Join(lines), {}, "deck.ain"); }
};

TEST(LegacyPin, JtypeOneIsAPinAboutTheYAxisOfItsJointAxes) {
  PinDeck deck("   1");
  // YPR1 and YPR2 (0, 0, 90): the joint axes rolled 90 degrees about x in both segments (so
  // the level posture of G.3.a's blank cards is the pin at 0), their y the segment's z.
  deck.Line(deck.hip + 1) = "                  0.    0.   90.    0.    0.   90.";
  const Converted converted = deck.Convert();
  ASSERT_EQ(converted.errors, 0) << converted.All();
  EXPECT_NE(converted.text.find("joint hip : pin(uppr -> lowr)"), std::string::npos)
      << converted.text;
  EXPECT_NE(converted.text.find("axis = (0, 0, 1)"), std::string::npos) << converted.text;
  // The B.4.a torsion spring (50 lb*in/deg) never acts on a pin: left out with W0503.
  EXPECT_TRUE(converted.Has(fmt::format("deck.ain:{}:37-72: warning[W0503]", deck.b4)))
      << converted.All();
  Compilation compiled = Compile(Source::Text(converted.text, "converted.sled"));
  ASSERT_TRUE(compiled.ok()) << compiled.Render() << converted.text;
  const runtime::Model& model = compiled.model();
  EXPECT_EQ(model.joint_kind.at(1), runtime::JointKind::kPin);
  // In the joint frame the axis is the frame's own y.
  EXPECT_LT((model.joint_axis.at(1) - runtime::Vec3(0, 1, 0)).norm(), 1e-12);
  EXPECT_EQ(model.joint_locked.at(1), 0);
}

TEST(LegacyPin, ALockedPinTakesB5sLevels) {
  // JTYPE -1 (locked), VISC(4) 50 lb*in (unlock above), VISC(5) 10 lb*in (lock below).
  PinDeck deck("  -1");
  deck.Line(deck.b5).replace(18, 12, "   50.   10.");
  const Converted converted = deck.Convert();
  deck_testing::ExpectLockedWithB5Levels(converted);
  Compilation compiled = Compile(Source::Text(converted.text, "converted.sled"));
  ASSERT_TRUE(compiled.ok()) << compiled.Render() << converted.text;
  const runtime::Model& model = compiled.model();
  EXPECT_NE(model.joint_locked.at(1), 0);
  EXPECT_NEAR(model.joint_unlock_above.at(1), 50 * kPoundInch, 1e-12);
  EXPECT_NEAR(model.joint_lock_below.at(1), 10 * kPoundInch, 1e-12);
}

TEST(LegacyPin, ALockByAngularVelocityAloneIsRefused) {
  // VISC(6) (columns 49-54) without VISC(5): ATB locks the pin by its speed; sled cannot.
  PinDeck deck("   1");
  deck.Line(deck.b5).replace(48, 6, "   0.1");
  const Converted converted = deck.Convert();
  EXPECT_TRUE(converted.Has(fmt::format("deck.ain:{}:49-54: error[E0507]", deck.b5)))
      << converted.All();
}

TEST(LegacyPin, APostureAboutThePinIsItsAngleAnotherIsRefused) {
  // LOWR pitched 30 degrees about the joint's axes (G.3.a ID4 = -1): a turn about y.
  PinDeck deck("   1");
  deck.Line(deck.g3) = "        0.       30.        0.        0.        0.        0.  0  0  0 -1";
  const Converted converted = deck.Convert();
  ASSERT_EQ(converted.errors, 0) << converted.All();
  EXPECT_NE(converted.text.find("angles = (30, 0, 0) deg"), std::string::npos) << converted.text;
  // A yaw about the joint's z is not a turn the pin makes.
  deck.Line(deck.g3) = "       30.        0.        0.        0.        0.        0.  0  0  0 -1";
  EXPECT_TRUE(deck.Convert().Has(fmt::format("deck.ain:{}:", deck.g3)));
  EXPECT_GT(deck.Convert().errors, 0);
}

}  // namespace
}  // namespace sled::lang::legacy
