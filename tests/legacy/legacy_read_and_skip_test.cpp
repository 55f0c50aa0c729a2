// Cards read so that the deck stays aligned: the F.4 globalgraphic-joint cards (their functions
// act only in a JTYPE 3 joint, which B.3.a refuses: left out with a warning at their line) and
// the G.4 to G.6 cards of ATB's equilibrium run (with no cascade). What ATB would stop on is an
// error at its columns.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "tests/legacy/legacy_test_deck.h"

namespace sled::lang::legacy {
namespace {

// seated_occupant has a D.4 airbag, converted only with --approximate-airbags.
Converted ConvertLines(const std::vector<std::string>& lines) {
  ConvertOptions options;
  options.approximate_airbags = true;
  return deck_testing::ConvertText(Join(lines, lines.size()), options);
}

std::vector<std::string> SeatedOccupant() {
  return Lines(ReadDeckFile(deck_testing::kLegacyDir + "seated_occupant.ain"));
}

// The 1-based line of seated_occupant's F.4.a card (14 joints: one card of zeros), the line
// before the F.6 comment.
std::size_t GlobalCountLine(const std::vector<std::string>& lines) {
  return LineStarting(lines, "# F.6") - 1;
}

TEST(LegacyGlobalGraphic, FunctionsOfAJointThatIsNotJtype3AreReadAndLeftOut) {
  std::vector<std::string> lines = SeatedOccupant();
  const std::size_t f4a = GlobalCountLine(lines);
  ASSERT_EQ(lines[f4a - 1].substr(0, 8), "   0   0");
  // Joint 2 gets two F.4.b cards (NJ, MS_SEG(3), NF(5), NX, NOUT).
  lines[f4a - 1].replace(4, 4, "   2");
  const std::vector<std::string> cards = {"   2   0   3   0  11   0   0   0   2   0   0",
                                          "   2   0   4   0  11   0   0   0   2   0   0"};
  lines.insert(lines.begin() + static_cast<std::ptrdiff_t>(f4a), cards.begin(), cards.end());
  const Converted converted = ConvertLines(lines);
  EXPECT_EQ(converted.errors, 0) << converted.All();
  // One W0503 per card, at its line; the F.6 and G cards after them are still read in place.
  for (std::size_t k = 1; k <= 2; ++k) {
    EXPECT_TRUE(
        converted.Has(fmt::format("deck.ain:{}:1-44: warning[W0503]: card F.4.b (joint 2, "
                                  "contact {})",
                                  f4a + k, k)))
        << converted.All();
  }
  EXPECT_FALSE(converted.text.empty());
}

TEST(LegacyGlobalGraphic, WhatAtbStopsOnIsAnErrorAndARollingConstraintIsRefused) {
  std::vector<std::string> lines = SeatedOccupant();
  const std::size_t f4a = GlobalCountLine(lines);
  lines[f4a - 1].replace(0, 4, "   3");
  const std::vector<std::string> cards = {
      "   2   0   3   0  11   0   0   0   2   0   0",   // NJ 2 on joint 1's card: STOP 14
      "   1   0   3   0  11   0   0   0   0   0   0",   // NF(5) 0: STOP 105
      "   1   0   3   0   0   0   0   0   2   0   0"};  // NF(1) 0: a rolling constraint
  lines.insert(lines.begin() + static_cast<std::ptrdiff_t>(f4a), cards.begin(), cards.end());
  const Converted converted = ConvertLines(lines);
  EXPECT_TRUE(converted.Has(fmt::format("deck.ain:{}:1-4: error[E0512]", f4a + 1)))
      << converted.All();
  EXPECT_TRUE(converted.Has(fmt::format("deck.ain:{}:33-36: error[E0512]", f4a + 2)))
      << converted.All();
  EXPECT_TRUE(converted.Has(fmt::format("deck.ain:{}:17-20: error[E0507]", f4a + 3)))
      << converted.All();
}

TEST(LegacyGlobalGraphic, ADeckWithoutJointsHasNoF4Card) {
  // INPUT_FCARDS reads F.4 only when NJNT > 0: a one-segment deck goes from F.3.a to G.1.a (it
  // read one more card before, the G.1.a, so the deck came out a card short).
  const std::string deck = R"(# One segment on a floor: no joints, so no F.4.a card.
# ---- A cards ----
11/28/2026
ONE SEGMENT ON A FLOOR
CORPUS DECK 1
IN  LB  SEC           0.          0.386.08800000386.08800000
   0  200.001000  1.0E-4  0.5E-30.000001

# ---- B cards ----
     1     0        ONE                     0
UPPR  20.000    1.   0.8   0.5    4.    3.    6.    0.    0.    0.   0

# ---- C cards ----
SLED AT 20 MPH
    0.    0.    0.   20.   0.1    0.    0.    0.     0    0.    0. 0 0 0
# ---- D cards ----
     1     0     0     0     0     0     0     0     0     0     0     0
   1    FLOOR
        -50.        -50.         20.
        -50.         50.         20.
         50.        -50.         20.

# ---- E cards ----
   1    FLOOR FORCE
          0.         -1.          0.          0.          0.
     3
          0.          0.          1.        500.          2.       2000.
   2    FRICTION 0.3
          0.          0.         0.3          0.          0.
  99
# ---- F cards ----
   1
   1   1   0   0   1   0   0   0   2       0

# ---- G cards ----
                                 0   0           1
        0.        0.      -10.      100.        0.        0.  0  0

# ---- H cards ----
     1  0  1          0.          0.          2.     0

     0

     0

     0
     0
     0
     0
     0
     0
     0
)";
  const Converted converted = deck_testing::ConvertText(deck);
  EXPECT_EQ(converted.errors, 0) << converted.All();
  EXPECT_FALSE(converted.Has("W0503")) << converted.All();
  EXPECT_NE(converted.text.find("segment uppr"), std::string::npos) << converted.text;
}

// G.1.a I1 = 15: the G.4 to G.6 cards read (no error in the H cards after them), INPUT_EQUILB's
// checks at their columns, and a G.6 constraint (whose force EQUILB takes as GX) refused at
// NCON; legacy_equilibrium_test.cpp has the solve.
TEST(LegacyEquilibrium, TheEquilibriumCardsAreReadAndAConstraintIsRefusedAtNcon) {
  auto with_equilibrium = [](const std::vector<std::string>& cards) {
    std::vector<std::string> lines = SeatedOccupant();
    const std::size_t g1 = LineStarting(lines, "# ---- G cards") + 1;
    lines[g1 - 1].resize(std::max<std::size_t>(lines[g1 - 1].size(), 34), ' ');  // a blank card
    lines[g1 - 1].replace(30, 4, "  15");
    const std::size_t h = LineStarting(lines, "# ---- H cards");
    lines.insert(lines.begin() + static_cast<std::ptrdiff_t>(h) - 1, cards.begin(), cards.end());
    return std::make_pair(ConvertLines(lines), h);
  };
  // One variable (the z of segment 1's position, until its force on plane 1 is 150 lbf, moving
  // segment 2 along) and one constraint of segment 1 on plane 1 (LTYPE 3) setting it.
  const auto [refused, g4] = with_equilibrium(
      {"   1   1", "   1   3   1    150.     2.0   1   1   1   2", "   1   1   3   1"});
  EXPECT_TRUE(refused.Has(fmt::format("deck.ain:{}:5-8: error[E0507]: card G.4", g4)))
      << refused.All();
  EXPECT_FALSE(refused.Has("card H.")) << refused.All();
  const auto [bad, line] = with_equilibrium(
      {"  11   6", "   3   1   1    150.     2.0   1   1   0", "   1   1   5   1"});
  EXPECT_TRUE(bad.Has(fmt::format("deck.ain:{}:1-4: error[E0512]: card G.4, columns 1-4", line)))
      << bad.All();
  EXPECT_TRUE(bad.Has(fmt::format("deck.ain:{}:5-8: error[E0512]", line))) << bad.All();
  const Converted bad_cards =
      with_equilibrium({"   1   1", "   3   4   0    150.     2.0   9   1   6", "   1   1   5   2"})
          .first;
  EXPECT_EQ(bad_cards.errors, 7) << bad_cards.All();  // the seven G.5 and G.6 fields
  for (const char* field : {"1-4: error[E0512]: card G.5", "5-8: error[E0512]: card G.5",
                            "9-12: error[E0512]: card G.5", "29-32: error[E0512]: card G.5",
                            "37-40: error[E0512]: card G.5", "9-12: error[E0512]: card G.6",
                            "13-16: error[E0512]: card G.6"}) {
    EXPECT_TRUE(bad_cards.Has(field)) << field << "\n" << bad_cards.All();
  }
}

// F.8.d.1 guide rings: corpus guide_ring converts to harness.ain's two tied belts (the corpus
// test compares its values); a ring that cannot be converted is refused at its columns.
TEST(LegacyGuideRing, ARingWithoutASegmentBesideItOrOnASurfaceIsRefused) {
  const std::vector<std::string> ring =
      Lines(ReadDeckFile(std::string(SLED_SOURCE_ROOT) + "/tests/legacy/corpus/guide_ring.ain"));
  const std::size_t at = LineStarting(ring, "   3   0   0   0   0   0   0   0  -2");
  // The ring right after the first anchor: no body segment between them.
  std::vector<std::string> beside = ring;
  std::swap(beside[at - 1], beside[at - 3]);
  std::swap(beside[at], beside[at - 2]);
  const Converted no_segment = deck_testing::ConvertText(Join(beside, beside.size()));
  EXPECT_TRUE(no_segment.Has(fmt::format("deck.ain:{}:1-4: error[E0507]", at - 2)))
      << no_segment.All();
  // KE not 0 (a point on the vehicle's contact surface), and NPD at the ring.
  std::vector<std::string> surface = ring;
  surface[at - 1].replace(4, 4, "   3");
  surface[at - 1].replace(8, 4, "   1");
  const Converted on_surface = deck_testing::ConvertText(Join(surface, surface.size()));
  EXPECT_TRUE(on_surface.Has(fmt::format("deck.ain:{}:5-8: error[E0507]", at))) << on_surface.All();
  EXPECT_TRUE(on_surface.Has(fmt::format("deck.ain:{}:9-12: error[E0507]", at)))
      << on_surface.All();
  // The unchanged deck converts, its belt in two parts.
  const Converted converted = deck_testing::ConvertText(Join(ring, ring.size()));
  EXPECT_EQ(converted.errors, 0) << converted.All();
  EXPECT_NE(converted.text.find("belt belt_1_2 {"), std::string::npos) << converted.text;
}

// The same cards list-directed (.lin): F.4.b one READ of 11 items, G.5 one READ of 8 + NAV.
TEST(LegacyReadAndSkip, ListDirectedDecksReadTheSameCards) {
  std::vector<std::string> lines =
      Lines(ReadDeckFile(std::string(SLED_SOURCE_ROOT) + "/tests/legacy/corpus/two_segments.lin"));
  ConvertOptions options;
  options.format = DeckFormat::kList;
  const std::size_t f4a = LineStarting(lines, " 0  Card F.4.a");
  lines[f4a - 1] = " 1  Card F.4.a";
  lines.insert(lines.begin() + static_cast<std::ptrdiff_t>(f4a),
               " 1 0 2 0 2 0 0 0 2 0 0  Card F.4.b");
  const Converted global = deck_testing::ConvertText(Join(lines, lines.size()), options, "d.lin");
  EXPECT_EQ(global.errors, 0) << global.All();
  EXPECT_TRUE(global.Has(fmt::format("d.lin:{}:", f4a + 1))) << global.All();
  EXPECT_TRUE(global.Has("warning[W0503]: card F.4.b (joint 1, contact 1)")) << global.All();
  // I1 = 15 with one variable for segment 2's contact (a jointed segment) and one constraint:
  // refused at NCON and JSG, the cards read as the .ain deck's.
  const std::size_t g1 = LineStarting(lines, " 0 1  Card G.1.a");
  lines[g1 - 1] = " 15 1  Card G.1.a";
  const std::size_t h = LineStarting(lines, "# ---- H cards");
  const std::vector<std::string> cards = {" 1 1  Card G.4", " 1 3 1 150. 2. 1 2 1 1  Card G.5",
                                          " 1 2 3 1  Card G.6"};
  lines.insert(lines.begin() + static_cast<std::ptrdiff_t>(h) - 1, cards.begin(), cards.end());
  const Converted equilibrium =
      deck_testing::ConvertText(Join(lines, lines.size()), options, "d.lin");
  EXPECT_EQ(equilibrium.errors, 2) << equilibrium.All();
  EXPECT_TRUE(equilibrium.Has("error[E0507]: card G.4")) << equilibrium.All();
  EXPECT_TRUE(equilibrium.Has("error[E0507]: card G.5")) << equilibrium.All();
}

}  // namespace
}  // namespace sled::lang::legacy
