// B.3.a IEULER, TENS_MAX and COMP_MAX, and B.5.a's lock levels (VISC(4), VISC(5), VISC(6)), as
// ATB's UPDATE_JOINTS uses them: a slip joint with a negative IEULER starts locked and slides
// once its axial force leaves [TENS_MAX, COMP_MAX]; the levels are never tested for a joint of
// JTYPE 0; JTYPE 2 and -2 are the ball joint they lock. Converted on two_segments' HIP joint
// and compared with the compiled Model.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include <fmt/format.h>

#include "legacy_test_deck.h"
#include "sled/compile.h"

namespace sled::lang::legacy {
namespace {

const std::string kDeck = std::string(SLED_SOURCE_ROOT) + "/tests/legacy/corpus/two_segments.ain";

// two_segments' lines, and the number of HIP's B.3.a line and of its B.5.a line.
struct HipDeck {
  std::vector<std::string> lines = Lines(ReadDeckFile(kDeck));
  std::size_t hip = LineStarting(lines, "HIP ");
  std::size_t b4 = LineStarting(lines, "  100.    0.");
  std::size_t b5 = LineStarting(lines, "    2.    0.    1.");
  std::string& Line(std::size_t number) { return lines[number - 1]; }
  // HIP as a slip joint (JTYPE 5), its B.4.a torsion spring (which a slip joint lacks) blank,
  // with `ieuler_tens_comp` in columns 51-66 (IEULER, TENS_MAX, COMP_MAX).
  HipDeck& Slip(const std::string& ieuler_tens_comp) {
    Line(hip).replace(10, 4, "   5");
    Line(hip).replace(50, 16, ieuler_tens_comp);
    Line(b4).replace(36, 36, std::string(36, ' '));
    return *this;
  }
  Converted Convert() const { return ConvertText(Join(lines), {}, "deck.ain"); }
};

TEST(LegacyJointLock, ALockedSlipJointWithASymmetricBandConvertsToItsUnlockLevel) {
  const Converted converted = HipDeck().Slip("  -1 -100.  100.").Convert();
  ASSERT_EQ(converted.errors, 0) << converted.All();
  EXPECT_NE(converted.text.find("locked = true"), std::string::npos) << converted.text;
  EXPECT_NE(converted.text.find("unlock_above = 100 lbf"), std::string::npos) << converted.text;
  Compilation compiled = Compile(Source::Text(converted.text, "converted.sled"));
  ASSERT_TRUE(compiled.ok()) << compiled.Render() << converted.text;
  const runtime::Model& model = compiled.model();
  const std::size_t lowr = 1;  // the joint's child
  EXPECT_NE(model.joint_locked.at(lowr), 0);
  EXPECT_NEAR(model.joint_unlock_above.at(lowr), 100 * 4.4482216152605, 1e-9);
  EXPECT_LT(model.joint_lock_below.at(lowr), 0);  // ATB never relocks it
}

TEST(LegacyJointLock, ALockedSlipJointWithoutLimitsStaysLocked) {
  const Converted converted = HipDeck().Slip("  -1    0.    0.").Convert();
  ASSERT_EQ(converted.errors, 0) << converted.All();
  EXPECT_NE(converted.text.find("locked = true"), std::string::npos) << converted.text;
  EXPECT_EQ(converted.text.find("unlock_above"), std::string::npos) << converted.text;
}

TEST(LegacyJointLock, ANegativeJtypeLocksASlipJoint) {
  // JTYPE -5 with IEULER 1 (with IEULER 0 it would be an Euler joint): ATB's locked state, never
  // unlocked without B.5.a's VISC(4).
  HipDeck deck;
  deck.Slip("   1    0.    0.").Line(deck.hip).replace(10, 4, "  -5");
  const Converted converted = deck.Convert();
  ASSERT_EQ(converted.errors, 0) << converted.All();
  EXPECT_NE(converted.text.find("locked = true"), std::string::npos) << converted.text;
  // With IEULER's lock as well, TENS_MAX and COMP_MAX would release one lock of two: refused.
  HipDeck both;
  both.Slip("  -1 -100.  100.").Line(both.hip).replace(10, 4, "  -5");
  EXPECT_TRUE(both.Convert().Has(fmt::format("deck.ain:{}:55-66: error[E0507]", both.hip)));
}

TEST(LegacyJointLock, AnAsymmetricBandIsRefusedAndOtherJointsIgnoreTheLimits) {
  HipDeck deck;
  const std::size_t line = deck.hip;
  const Converted asymmetric = deck.Slip("  -1  -50.  100.").Convert();
  EXPECT_TRUE(asymmetric.Has(fmt::format("deck.ain:{}:55-66: error[E0507]", line)))
      << asymmetric.All();
  // A ball joint (JTYPE 0), and a slip joint that is not locked (IEULER 0): W0503.
  HipDeck ball_deck;
  ball_deck.Line(line).replace(54, 12, " -100.  100.");
  const Converted ball = ball_deck.Convert();
  EXPECT_EQ(ball.errors, 0) << ball.All();
  EXPECT_TRUE(ball.Has(fmt::format("deck.ain:{}:55-66: warning[W0503]", line))) << ball.All();
  EXPECT_EQ(ball.text.find("unlock_above"), std::string::npos) << ball.text;
  const Converted sliding = HipDeck().Slip("   0 -100.  100.").Convert();
  EXPECT_TRUE(sliding.Has(fmt::format("deck.ain:{}:55-66: warning[W0503]", line))) << sliding.All();
  EXPECT_EQ(sliding.text.find("locked"), std::string::npos) << sliding.text;
}

// B.5.a: the three levels (VISC(4) 50, VISC(5) 10 in columns 19-30) of a ball joint are left
// out (W0503); of a slip joint refused.
TEST(LegacyJointLock, LockLevelsOfABallJointAreLeftOutAsATBLeavesThem) {
  HipDeck ball;
  ball.Line(ball.b5).replace(18, 12, "   50.   10.");
  const Converted left_out = ball.Convert();
  EXPECT_EQ(left_out.errors, 0) << left_out.All();
  EXPECT_TRUE(left_out.Has(fmt::format("deck.ain:{}:19-54: warning[W0503]", ball.b5)))
      << left_out.All();
  HipDeck slip;
  slip.Line(slip.b5).replace(18, 12, "   50.   10.");
  const Converted refused = slip.Slip("  -1    0.    0.").Convert();
  EXPECT_TRUE(refused.Has(fmt::format("deck.ain:{}:19-54: error[E0507]", slip.b5)))
      << refused.All();
}

// JTYPE 2 and -2: ATB's unpinned lockable joint (UPDATE_JOINTS: "unpinned", locked at -2),
// a ball joint that locks and unlocks by the size of its torque vector: sled's ball with
// `locked` and the B.5.a levels, in lb*in.
TEST(LegacyJointLock, JtypeMinusTwoIsALockedBallWithB5sLevels) {
  HipDeck deck;
  deck.Line(deck.hip).replace(10, 4, "  -2");
  deck.Line(deck.b5).replace(18, 12, "   50.   10.");
  const Converted converted = deck.Convert();
  deck_testing::ExpectLockedWithB5Levels(converted);
  EXPECT_TRUE(converted.Says(": ball(")) << converted.text;
  Compilation compiled = Compile(Source::Text(converted.text, "converted.sled"));
  ASSERT_TRUE(compiled.ok()) << compiled.Render() << converted.text;
  const runtime::Model& model = compiled.model();
  const std::size_t lowr = 1;
  const double lbf_in = 4.4482216152605 * 0.0254;
  EXPECT_EQ(model.joint_kind.at(lowr), runtime::JointKind::kBall);
  EXPECT_EQ(model.joint_locked.at(lowr), 7);
  EXPECT_NEAR(model.joint_unlock_above.at(lowr), 50 * lbf_in, 1e-12);
  EXPECT_NEAR(model.joint_lock_below.at(lowr), 10 * lbf_in, 1e-12);
}

TEST(LegacyJointLock, JtypeTwoIsABallThatLocksOnlyWithLevels) {
  // Without levels it never locks: JTYPE 0's ball, with its flexure and torsion springs.
  HipDeck plain;
  plain.Line(plain.hip).replace(10, 4, "   2");
  const Converted ball = plain.Convert();
  ASSERT_EQ(ball.errors, 0) << ball.All();
  EXPECT_NE(ball.text.find(": ball("), std::string::npos) << ball.text;
  EXPECT_NE(ball.text.find("twist ="), std::string::npos) << ball.text;
  EXPECT_EQ(ball.text.find("locked"), std::string::npos) << ball.text;
  EXPECT_EQ(ball.text.find("lock_below"), std::string::npos) << ball.text;
  // Locking below an angular velocity alone (VISC(6) without VISC(5)): refused, as for a pin.
  HipDeck by_rate;
  by_rate.Line(by_rate.hip).replace(10, 4, "   2");
  by_rate.Line(by_rate.b5).replace(48, 6, "    1.");
  EXPECT_TRUE(by_rate.Convert().Has(fmt::format("deck.ain:{}:49-54: error[E0507]", by_rate.b5)));
}

TEST(LegacyJointLock, TheGlobographicJointIsRefusedAtItsType) {
  for (const char* jtype : {"   3", "  -3"}) {
    HipDeck deck;
    deck.Line(deck.hip).replace(10, 4, jtype);
    const Converted converted = deck.Convert();
    EXPECT_TRUE(converted.Has(fmt::format("deck.ain:{}:11-14: error[E0507]", deck.hip)))
        << converted.All();
    EXPECT_NE(converted.All().find("GLOBAL"), std::string::npos) << converted.All();
  }
}

}  // namespace
}  // namespace sled::lang::legacy
