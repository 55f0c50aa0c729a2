// F.8 harnesses through `sled convert`: the ejection-seat deck's harness (a lap belt and two
// straps that end at the lap belt's anchors, ATB tie points 1 and 2 on the seat) becomes one
// `harness` with its tie-point friction, and every harness field sled cannot express gets a
// located E0507 naming it, a value ATB would stop on an E0512, a value ATB ignores a W0503.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <string>
#include <vector>

#include "tests/legacy/legacy_test_deck.h"

namespace sled::lang::legacy {
namespace {

using namespace deck_testing;  // NOLINT(google-build-using-namespace): the deck helpers

const std::string kDeck = kLegacyDir + "ejection_seat.ain";

// The harness's cards in the deck: the F.8.c card of each belt and its points' F.8.d.1 cards.
struct HarnessLines {
  std::size_t head = 0;  // F.8.a
  std::size_t belt[3] = {};
  std::size_t point(int belt_index, int point_index) const {
    return belt[belt_index] + 1 + 2 * static_cast<std::size_t>(point_index);
  }
};

HarnessLines Locate(const std::vector<std::string>& lines) {
  HarnessLines at;
  at.head = LineStarting(lines, "   3   0   0   0   0   ");
  std::size_t line = at.head + 2;
  for (int b = 0; b < 3; ++b) {
    while (line <= lines.size() && lines[line - 1].rfind("   4   0   0   0   0", 0) != 0) ++line;
    at.belt[b] = line++;
  }
  return at;
}

class LegacyHarness : public ::testing::Test {
 protected:
  void SetUp() override {
    lines_ = Lines(ReadDeckFile(kDeck));
    at_ = Locate(lines_);
  }
  // Columns first..first+size-1 of 1-based `line` replaced by `text`.
  void Put(std::size_t line, int first, const std::string& text) {
    std::string& s = lines_[line - 1];
    if (s.size() < static_cast<std::size_t>(first - 1) + text.size()) {
      s.resize(static_cast<std::size_t>(first - 1) + text.size(), ' ');
    }
    s.replace(static_cast<std::size_t>(first - 1), text.size(), text);
  }
  Converted Convert() const { return ConvertText(Join(lines_)); }
  // Converts without errors and requires `fragment` in the scenario.
  void ExpectScenarioHas(const std::string& fragment) const {
    const Converted converted = Convert();
    ASSERT_EQ(converted.errors, 0) << converted.All();
    EXPECT_NE(converted.text.find(fragment), std::string::npos) << converted.text;
  }

  std::vector<std::string> lines_;
  HarnessLines at_;
};

TEST_F(LegacyHarness, TheEjectionSeatHarnessConverts) {
  const Converted converted = Convert();
  ASSERT_EQ(converted.errors, 0) << converted.All();
  const std::string& text = converted.text;
  EXPECT_NE(text.find("harness harness_1 on seat {\n    friction = 0.2\n"), std::string::npos)
      << text;
  EXPECT_NE(text.find("path = (1.5, -9, 3) in -> pilot.lt -> (1.5, 9, 3) in"), std::string::npos);
  EXPECT_NE(text.find("path = (-26, 3, 7) in -> pilot.ut -> (1.5, 9, 3) in"), std::string::npos);
  EXPECT_NE(text.find("path = (-26, -3, 7) in -> pilot.ut -> (1.5, -9, 3) in"), std::string::npos);
  EXPECT_NE(text.find("function harness_webbing = table(strain -> force)"), std::string::npos);
  // Each wrapped point: sled lays the webbing over the ellipsoid (W0504); nothing else is said of
  // the harness.
  for (int b = 0; b < 3; ++b) {
    EXPECT_TRUE(
        converted.Has(fmt::format("deck.ain:{}:37-72: warning[W0504]: card F.8.d.1 "
                                  "(harness 1, belt {}, point 2)",
                                  at_.point(b, 1), b + 1)))
        << converted.All();
  }
  EXPECT_FALSE(converted.Has("F.8.d.1 (harness 1, belt 1, point 1)"));
}

TEST_F(LegacyHarness, EndsMustBeAnchorsInOneFrame) {
  Put(at_.point(0, 0), 1, "   1");  // the lap belt from body segment 1
  EXPECT_TRUE(
      Convert().Has(fmt::format("deck.ain:{}:1-4: error[E0507]: card F.8.d.1 (harness "
                                "1, belt 1, point 1), columns 1-4: KS is 1: the belt ends "
                                "on body segment 1",
                                at_.point(0, 0))));
  SetUp();
  Put(at_.point(1, 0), 1, "  17");  // the right strap from the ground, the rest on the seat
  EXPECT_TRUE(Convert().Has(fmt::format("deck.ain:{}:1-4: error[E0507]", at_.point(1, 0))));
  SetUp();
  Put(at_.point(1, 0), 1, "  18");  // no such segment
  EXPECT_TRUE(Convert().Has(fmt::format("deck.ain:{}:1-4: error[E0505]", at_.point(1, 0))));
  SetUp();
  Put(at_.point(1, 0), 5, "   3");  // an end on an ellipsoid
  EXPECT_TRUE(Convert().Has(fmt::format("deck.ain:{}:5-8: error[E0507]", at_.point(1, 0))));
  SetUp();
  Put(at_.point(1, 0), 9, "   0");  // ATB stops without NPD at an end (STOP 60)
  EXPECT_TRUE(Convert().Has(fmt::format("deck.ain:{}:9-12: error[E0512]", at_.point(1, 0))));
  SetUp();
  Put(at_.point(1, 0), 33, "   7");  // friction where the webbing is held
  EXPECT_TRUE(Convert().Has(fmt::format("deck.ain:{}:33-36: error[E0507]", at_.point(1, 0))));
}

TEST_F(LegacyHarness, PointsBetweenTheEndsMustWrapABodySegment) {
  const std::size_t pelvis = at_.point(0, 1);
  Put(pelvis, 1, "  16");  // a guide ring on the seat
  EXPECT_TRUE(Convert().Has(fmt::format("deck.ain:{}:1-4: error[E0507]", pelvis)));
  SetUp();
  Put(pelvis, 1, " 101");  // a tie point between the ends
  EXPECT_TRUE(Convert().Has(fmt::format("deck.ain:{}:1-4: error[E0507]", pelvis)));
  SetUp();
  Put(pelvis, 5, "   0");  // fixed on the segment, off its surface
  EXPECT_TRUE(Convert().Has(fmt::format("deck.ain:{}:5-8: error[E0507]", pelvis)));
  SetUp();
  Put(pelvis, 9, "   1");  // a preferred friction direction
  EXPECT_TRUE(Convert().Has(fmt::format("deck.ain:{}:9-12: error[E0507]", pelvis)));
  SetUp();
  Put(pelvis, 17, "   2");  // a point's force function
  EXPECT_TRUE(Convert().Has(fmt::format("deck.ain:{}:17-20: error[E0507]", pelvis)));
  SetUp();
  Put(pelvis, 33, "  -7");  // a ring the webbing may not leave
  EXPECT_TRUE(Convert().Has(fmt::format("deck.ain:{}:33-36: error[E0507]", pelvis)));
  SetUp();
  Put(pelvis, 33, "   6");  // the lap belt's friction on the pelvis: 0.4
  ExpectScenarioHas(
      "-> pilot.lt -> (1.5, 9, 3) in\n      force = harness_webbing\n"
      "      slack = 0.1 in\n      friction = 0.4");
  SetUp();
  // ATB ignores an offset on an ellipsoid and a preferred direction without NPD.
  Put(pelvis + 1, 1, "          1.");
  Put(pelvis + 1, 61, "          1.");
  const Converted ignored = Convert();
  EXPECT_EQ(ignored.errors, 0) << ignored.All();
  EXPECT_TRUE(ignored.Has(fmt::format("deck.ain:{}:1-36: warning[W0503]", pelvis + 1)));
  EXPECT_TRUE(ignored.Has(fmt::format("deck.ain:{}:37-72: warning[W0503]", pelvis + 1)));
}

TEST_F(LegacyHarness, TiePointsAreWhereSledJoinsBelts) {
  // The left strap's end moved off tie point 1.
  Put(at_.point(2, 2), 49, "        -8.5");
  EXPECT_TRUE(
      Convert().Has(fmt::format("deck.ain:{}:1-4: error[E0512]: card F.8.d.1 (harness "
                                "1, belt 3, point 3): tie point 1 is at",
                                at_.point(2, 2))));
  // The right strap ends at the lap belt's right anchor without tying to it: sled would join them.
  SetUp();
  Put(at_.point(1, 2), 1, "  16");
  Put(at_.point(1, 2), 33, "   0");
  EXPECT_TRUE(Convert().Has(fmt::format("deck.ain:{}:1-4: error[E0507]", at_.point(1, 2))));
  // Tie points with two frictions.
  SetUp();
  Put(at_.point(2, 2), 33, "   6");
  EXPECT_TRUE(Convert().Has(fmt::format("deck.ain:{}:33-36: error[E0507]", at_.point(2, 2))));
}

TEST_F(LegacyHarness, BeltAndHarnessCards) {
  // The webbing's own friction function: stored by ATB, read by none of its harness routines.
  Put(at_.belt[1], 17, "   7");
  const Converted own_friction = Convert();
  EXPECT_EQ(own_friction.errors, 0) << own_friction.All();
  EXPECT_TRUE(own_friction.Has(fmt::format("deck.ain:{}:17-20: warning[W0503]", at_.belt[1])))
      << own_friction.All();
  SetUp();
  Put(at_.belt[1], 21, "   -0.100000");  // webbing shorter than its path
  EXPECT_TRUE(Convert().Has(fmt::format("deck.ain:{}:21-32: error[E0507]", at_.belt[1])));
  SetUp();
  Put(at_.belt[1], 1, "   0");  // no webbing function
  EXPECT_TRUE(Convert().Has(fmt::format("deck.ain:{}:1-4: error[E0507]", at_.belt[1])));
  SetUp();
  Put(at_.belt[1], 21, "    0.000000");  // no slack: none is written
  ExpectScenarioHas(
      "-> pilot.ut -> (1.5, 9, 3) in\n      force = harness_webbing\n      "
      "friction = 0.2");
  SetUp();
  Put(at_.head + 1, 5, "   2");  // the right strap with two points: nothing on the body
  EXPECT_GT(Convert().errors, 0);
  SetUp();
  Put(at_.head, 5, "   2");  // belts of a second harness that D.1.a does not announce
  EXPECT_TRUE(Convert().Has(fmt::format("deck.ain:{}:5-8: warning[W0503]", at_.head)));
  SetUp();
  Put(LineStarting(lines_, "     3     0     0     0     0     0     1"), 37, "     6");
  EXPECT_TRUE(Convert().Has("error[E0505]: card D.1.a, columns 37-42 (NHRNSS"));
}

TEST_F(LegacyHarness, EveryTruncationInTheHarnessIsReported) {
  const std::size_t g_cards = LineStarting(lines_, "# ---- G cards");
  for (std::size_t keep = at_.head - 1; keep < g_cards; ++keep) {
    EXPECT_GT(ConvertText(Join(lines_, keep)).errors, 0) << "cut after line " << keep;
  }
}

}  // namespace
}  // namespace sled::lang::legacy
