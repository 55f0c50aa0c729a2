// Physical checks of deck values where the deck gives them (E0512, E0507 at the card and
// columns): each of the seated occupant's cards with one value made impossible is refused at that
// card, not converted into a scenario that `sled check` then refuses (E0402, E0403, E0409, E0410,
// E0412, E0420, E0421). Two H.1 points on one segment, which ATB allows, become two columns; fields
// that were left out without a word (Euler stops, print controls) are refused or warned.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <string>
#include <vector>

#include "legacy_test_deck.h"
#include "sled/compile.h"

namespace sled::lang::legacy {
namespace {

using namespace deck_testing;  // NOLINT(google-build-using-namespace): the deck helpers

const std::string kDeck = kLegacyDir + "seated_occupant.ain";

// The seated occupant with the line starting `prefix` rewritten by `edit`, converted.
template <typename Edit>
Converted ConvertEdited(std::string_view prefix, Edit edit, std::size_t* line = nullptr) {
  std::vector<std::string> lines = Lines(ReadDeckFile(kDeck));
  const std::size_t at = LineStarting(lines, prefix);
  if (line) *line = at;
  edit(lines[at - 1]);
  ConvertOptions options;
  options.approximate_airbags = true;
  return ConvertText(Join(lines), options);
}

// The lines of tests/legacy/corpus/NAME.ain.
std::vector<std::string> CorpusDeck(const std::string& name) {
  return Lines(
      ReadDeckFile(std::string(SLED_SOURCE_ROOT) + "/tests/legacy/corpus/" + name + ".ain"));
}

// `text` right-aligned in columns first..last (1-based) of `line`.
void Put(std::string& line, int first, int last, const std::string& text) {
  const std::size_t width = static_cast<std::size_t>(last) - static_cast<std::size_t>(first) + 1;
  if (line.size() < static_cast<std::size_t>(last))
    line.resize(static_cast<std::size_t>(last), ' ');
  line.replace(static_cast<std::size_t>(first - 1), width,
               std::string(width - text.size(), ' ') + text);
}

TEST(LegacyPhysicalChecks, HminAboveHmaxIsRefusedAtA4) {
  std::size_t line = 0;
  const Converted c = ConvertEdited(
      "   0 300", [](std::string& s) { Put(s, 33, 40, "0.001"); }, &line);
  EXPECT_TRUE(
      c.Has(fmt::format("deck.ain:{}:25-40: error[E0512]: card A.4, columns 25-40: HMIN "
                        "(0.001) is larger than HMAX (0.0005)",
                        line)))
      << c.All();
}

TEST(LegacyPhysicalChecks, NegativeStepIsRefusedAtItsColumns) {
  std::size_t line = 0;
  const Converted c = ConvertEdited(
      "   0 300", [](std::string& s) { Put(s, 17, 24, "-1."); }, &line);
  EXPECT_TRUE(c.Has(
      fmt::format("deck.ain:{}:17-24: error[E0512]: card A.4, columns 17-24: H0 is -1", line)))
      << c.All();
}

TEST(LegacyPhysicalChecks, InertiasNoBodyCanHaveAreRefusedAtPhi) {
  std::size_t line = 0;
  // The head's PHI (0.16, 0.19, 0.13) with Iz = 1.: above Ix + Iy.
  Converted c = ConvertEdited(
      "H   ", [](std::string& s) { Put(s, 25, 30, "1."); }, &line);
  EXPECT_TRUE(c.Has(fmt::format("deck.ain:{}:13-30: error[E0512]", line))) << c.All();
  EXPECT_TRUE(c.Has("triangle inequality")) << c.All();
  c = ConvertEdited("H   ", [](std::string& s) { Put(s, 19, 24, "-0.19"); });
  EXPECT_TRUE(c.Has(fmt::format("deck.ain:{}:13-30: error[E0512]", line))) << c.All();
  // A weight with a zero moment: ATB's singular segment, which sled has only without mass.
  c = ConvertEdited("H   ", [](std::string& s) { Put(s, 19, 24, "0."); });
  EXPECT_TRUE(c.Has(fmt::format("deck.ain:{}:13-30: error[E0507]", line))) << c.All();
  // No weight: the moments are not used.
  c = ConvertEdited("H   ", [](std::string& s) { Put(s, 7, 12, "0."); });
  EXPECT_EQ(c.errors, 0) << c.All();
  EXPECT_TRUE(c.Has(fmt::format("deck.ain:{}:13-30: warning[W0503]", line))) << c.All();
}

TEST(LegacyPhysicalChecks, SemiAxesAreAllPositiveOrAllBlank) {
  std::size_t line = 0;
  Converted c = ConvertEdited(
      "H   ", [](std::string& s) { Put(s, 37, 42, "0."); }, &line);
  EXPECT_TRUE(
      c.Has(fmt::format("deck.ain:{}:31-48: error[E0512]: card B.2.a (segment 5), "
                        "columns 31-48: the semi-axes (3.9, 0, 4.4) are not all positive",
                        line)))
      << c.All();
  c = ConvertEdited("H   ", [](std::string& s) { Put(s, 31, 48, ""); });
  EXPECT_EQ(c.errors, 0) << c.All();
}

TEST(LegacyPhysicalChecks, PlaneCornersInLineAreRefusedAtD2) {
  std::size_t line = 0;
  // The seat pan's P3 on the line through P1 and P2.
  const Converted c = ConvertEdited(
      "         14.        -10.          0.",
      [](std::string& s) { s = "         -6.         20.          0."; }, &line);
  EXPECT_TRUE(c.Has(fmt::format("deck.ain:{}:1-36: error[E0512]: card D.2 (plane 1, P3)", line)))
      << c.All();
}

TEST(LegacyPhysicalChecks, AForceFunctionThatPullsIsRefusedAtItsE1Card) {
  std::size_t line = 0;
  // The seat foam's table: -150 lbf at 1 in.
  Converted c = ConvertEdited("          0.          0.          1.        150.",
                              [](std::string& s) { Put(s, 37, 48, "-150."); });
  const std::vector<std::string> lines = Lines(ReadDeckFile(kDeck));
  line = LineStarting(lines, "   1    SEAT FOAM");
  EXPECT_TRUE(
      c.Has(fmt::format("deck.ain:{}:1-4: error[E0512]: function 1 (E.1, line {}) pushes "
                        "the wrong way: its E.4.b table gives -150 at 1",
                        line, line)))
      << c.All();
  // A friction coefficient out of sled's range.
  c = ConvertEdited("          0.          0.         0.4",
                    [](std::string& s) { Put(s, 25, 36, "-0.4"); });
  EXPECT_TRUE(c.Has("error[E0512]: card F.1.b (plane 1, contact 1): friction function 2 is -0.4"))
      << c.All();
}

TEST(LegacyPhysicalChecks, NegativeJointDampingIsRefusedAtB5) {
  std::size_t line = 0;
  const Converted c = ConvertEdited(
      "   0.5    0.    1.", [](std::string& s) { Put(s, 1, 6, "-0.5"); }, &line);
  EXPECT_TRUE(c.Has(fmt::format("deck.ain:{}:1-6: error[E0512]", line))) << c.All();
}

TEST(LegacyPhysicalChecks, AJointedSegmentsG3aOrientationTurnsItsJoint) {
  // The 15 blank G.3.a cards follow the G.2 card; the third is segment 3's, below joint 2. A yaw
  // of 10 deg from the ground, its parent level: joint 2 turns by (10, 0, 0) deg
  // (legacy_posture_test.cpp checks the general case). With I3 = 0 (this deck) ATB ignores an
  // angular velocity of the card (W0503).
  std::vector<std::string> lines = Lines(ReadDeckFile(kDeck));
  const std::size_t g3 = LineStarting(lines, "# G.3.a") + 3;
  lines[g3 - 1] = "       10.";
  ConvertOptions options;
  options.approximate_airbags = true;
  const Converted turned = ConvertText(Join(lines), options);
  ASSERT_EQ(turned.errors, 0) << turned.All();
  EXPECT_NE(turned.text.find("angles = (10, 0, 0) deg"), std::string::npos) << turned.text;
  lines[g3 - 1] = "       10.        0.        0.        5.";
  const Converted spinning = ConvertText(Join(lines), options);
  EXPECT_EQ(spinning.errors, 0) << spinning.All();
  EXPECT_TRUE(spinning.Has(fmt::format("deck.ain:{}:31-40: warning[W0503]", g3))) << spinning.All();
}

TEST(LegacyPhysicalChecks, TwoPointsOnOneSegmentAreTwoColumnsAndCheckClean) {
  // H.1: the pelvis and the head; the head's request repeated at another point.
  std::vector<std::string> lines = Lines(ReadDeckFile(kDeck));
  const std::size_t h1 = LineStarting(lines, "     2  0  5");
  lines[h1 - 1] = "     3  0  5          0.          0.          0.     0";
  lines.insert(lines.begin() + static_cast<std::ptrdiff_t>(h1) + 1,
               "        0  5          0.          0.         -4.     0");
  ConvertOptions options;
  options.approximate_airbags = true;
  const Converted c = ConvertText(Join(lines), options);
  ASSERT_EQ(c.errors, 0) << c.All();
  EXPECT_NE(c.text.find("as h_acceleration_2"), std::string::npos) << c.text;
  const Compilation compiled = Compile(Source::Text(c.text, kLegacyDir + "converted.sled"));
  EXPECT_TRUE(compiled.ok()) << compiled.Render();
}

// An Euler joint's torsion and spin stops, which sled's one `stop` cannot hold, were left out
// without a word: they are refused at their columns.
TEST(LegacySilentlyDropped, EulerTorsionAndSpinStopsAreRefused) {
  std::vector<std::string> lines = CorpusDeck("head_and_ball");
  const std::size_t b4a = LineStarting(lines, "    2.    0.    0.   0.4         60.");
  lines[b4a - 1] += "         40.";
  lines[b4a] = "   0.5    0.    0.    0.         30.   10.    0.    0.";
  const Converted c = ConvertText(Join(lines));
  EXPECT_TRUE(
      c.Has(fmt::format("deck.ain:{}:61-72: error[E0507]: card B.4.a (joint 1), columns "
                        "61-72: a torsion stop angle (40 deg) of an Euler joint",
                        b4a)))
      << c.All();
  EXPECT_TRUE(c.Has(fmt::format("deck.ain:{}:25-36: error[E0507]: card B.4.b (joint 1)", b4a + 1)))
      << c.All();
}

// Each B.4 spring has its own energy-dissipation coefficient (INPUT_JOINTS reads five numbers
// per spring): the corpus's NECK gives 0.4, 0.2 and 0, which become each function's own
// `energy_loss`, not one joint `energy_loss` that the spin spring would take too. A ball joint
// whose flexure has one and whose twist has none: the twist keeps all its energy.
TEST(LegacyPhysicalChecks, EachJointSpringKeepsItsOwnEnergyCoefficient) {
  std::vector<std::string> lines = CorpusDeck("head_and_ball");
  Converted c = ConvertText(Join(lines));
  EXPECT_EQ(c.errors, 0) << c.All();
  EXPECT_NE(c.text.find("precession = polynomial(0, 2 N*m/deg) {\n        energy_loss = 0.4\n"),
            std::string::npos)
      << c.text;
  EXPECT_NE(c.text.find("nutation = polynomial(0, 1 N*m/deg) {\n        energy_loss = 0.2\n"),
            std::string::npos)
      << c.text;
  EXPECT_NE(c.text.find("spin = polynomial(0, 0.5 N*m/deg)\n"), std::string::npos) << c.text;
  EXPECT_EQ(c.text.find("\n      energy_loss"), std::string::npos) << c.text;
  const std::size_t b3a = LineStarting(lines, "NECK     1   4");
  lines[b3a - 1].replace(13, 1, "0");  // JTYPE 0: a ball joint, which has no B.4.b or B.5.b-c
  const std::size_t b4b = LineStarting(lines, "   0.5    0.    0.    0.          0.   10.");
  lines.erase(lines.begin() + static_cast<std::ptrdiff_t>(b4b - 1));
  const std::size_t b5b = LineStarting(lines, "  0.05   0.2    1.") + 1;
  lines.erase(lines.begin() + static_cast<std::ptrdiff_t>(b5b - 1),
              lines.begin() + static_cast<std::ptrdiff_t>(b5b + 1));
  const std::size_t b4a = LineStarting(lines, "    2.    0.    0.   0.4         60.");
  lines[b4a - 1].replace(54, 6, "    0.");
  c = ConvertText(Join(lines));
  EXPECT_EQ(c.errors, 0) << c.All();
  EXPECT_NE(c.text.find("flexure = polynomial(0, 2 N*m/deg) {\n        energy_loss = 0.4\n"),
            std::string::npos)
      << c.text;
  EXPECT_NE(c.text.find("twist = polynomial(0, 1 N*m/deg)\n"), std::string::npos) << c.text;
}

// G.2's IREF4 names a frame with prescribed motion (ATB stops otherwise, STOP 223).
TEST(LegacyPhysicalChecks, Iref4OfABodySegmentIsRefusedAtG2) {
  std::vector<std::string> lines = CorpusDeck("head_and_ball");
  const std::size_t g2 = LineStarting(lines, "       0.5        0.      -0.8");
  lines[g2 - 1].replace(63, 3, "  1");
  const Converted c = ConvertText(Join(lines));
  EXPECT_TRUE(
      c.Has(fmt::format("deck.ain:{}:64-66: error[E0512]: card G.2 (reference segment 3), "
                        "columns 64-66: IREF4 is 1, which has no prescribed motion",
                        g2)))
      << c.All();
}

// B.5.a's VISC(3), the rate of full Coulomb friction: ATB stops when it is not above zero for a
// joint with a proximal segment (STOP 294); with Coulomb friction it converts, approximated.
TEST(LegacyPhysicalChecks, FullCoulombRateIsRequiredAndItsRampApproximated) {
  const std::vector<std::string> deck = CorpusDeck("two_segments");
  std::vector<std::string> lines = deck;
  const std::size_t b5 = LineStarting(lines, "    2.    0.    1.");
  lines[b5 - 1].replace(12, 6, "    0.");
  Converted c = ConvertText(Join(lines));
  EXPECT_TRUE(
      c.Has(fmt::format("deck.ain:{}:13-18: error[E0512]: card B.5.a (joint 1), columns "
                        "13-18: the angular velocity of full Coulomb friction is 0",
                        b5)))
      << c.All();
  lines = deck;
  lines[b5 - 1].replace(6, 6, "   20.");
  c = ConvertText(Join(lines));
  EXPECT_EQ(c.errors, 0) << c.All();
  EXPECT_TRUE(c.Has(fmt::format("deck.ain:{}:7-18: warning[W0504]", b5))) << c.All();
  EXPECT_NE(c.text.find("coulomb = 20 lbf*in"), std::string::npos) << c.text;
}

// An Euler joint's B.5.b and B.5.c damp its second and third axes (INPUT_JOINTS): sled's one
// `viscous` holds them only when they equal B.5.a's.
TEST(LegacyPhysicalChecks, EulerAxesDampedUnlikeTheFirstAreRefused) {
  std::vector<std::string> lines = CorpusDeck("head_and_ball");
  const std::size_t b5a = LineStarting(lines, "  0.05   0.2    1.");
  lines[b5a].replace(0, 6, "   0.1");
  const Converted c = ConvertText(Join(lines));
  EXPECT_TRUE(c.Has(fmt::format("deck.ain:{}:1-60: error[E0507]: card B.5.b (joint 1)", b5a + 1)))
      << c.All();
}

// The rate of full Coulomb friction (VISC(3)) may differ per Euler axis: sled's `coulomb` ramp
// does not use it, so each axis whose rate differs is approximated at its own card (W0504) and
// the joint converts with the one friction torque the three cards share.
TEST(LegacyPhysicalChecks, EulerAxesWithAnotherFullCoulombRateConvertApproximated) {
  std::vector<std::string> lines = CorpusDeck("head_and_ball");
  const std::size_t b5a = LineStarting(lines, "  0.05   0.2    1.");
  for (std::size_t k = 0; k < 3; ++k) lines[b5a - 1 + k].replace(6, 6, "    2.");
  lines[b5a].replace(12, 6, "    5.");  // B.5.b: full friction at 5 deg/s, B.5.a and B.5.c at 1
  Converted c = ConvertText(Join(lines));
  EXPECT_EQ(c.errors, 0) << c.All();
  EXPECT_TRUE(c.Has(fmt::format("deck.ain:{}:7-18: warning[W0504]", b5a))) << c.All();
  EXPECT_TRUE(c.Has(fmt::format("deck.ain:{}:7-18: warning[W0504]", b5a + 1))) << c.All();
  EXPECT_FALSE(c.Has(fmt::format("deck.ain:{}:7-18: warning[W0504]", b5a + 2))) << c.All();
  EXPECT_NE(c.text.find("coulomb = 2 N*m\n"), std::string::npos) << c.text;
  lines[b5a + 1].replace(6, 6, "    3.");  // B.5.c: another friction torque
  c = ConvertText(Join(lines));
  EXPECT_TRUE(c.Has(fmt::format("deck.ain:{}:1-60: error[E0507]: card B.5.c (joint 1)", b5a + 2)))
      << c.All();
}

// A.5: NPRT(4) < 0 asks ATB for a post-processing run that simulates nothing (refused); the
// other print controls are left out with one warning at the card.
TEST(LegacySilentlyDropped, PrintControlsAreWarnedAndAPostProcessingRunRefused) {
  const std::vector<std::string> deck = CorpusDeck("two_segments");
  const std::size_t a5 = LineStarting(deck, "   0  20") + 1;
  std::vector<std::string> lines = deck;
  lines[a5 - 1] = " 1";
  Converted c = ConvertText(Join(lines));
  EXPECT_EQ(c.errors, 0) << c.All();
  EXPECT_TRUE(
      c.Has(fmt::format("deck.ain:{}:1-2: warning[W0503]: card A.5, columns 1-72: the "
                        "print and file controls",
                        a5)))
      << c.All();
  lines[a5 - 1] = "      -1";
  c = ConvertText(Join(lines));
  EXPECT_TRUE(
      c.Has(fmt::format("deck.ain:{}:7-8: error[E0507]: card A.5, columns 7-8: NPRT(4) "
                        "is -1",
                        a5)))
      << c.All();
}

}  // namespace
}  // namespace sled::lang::legacy
