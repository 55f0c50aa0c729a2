// The legacy deck reader and translator (lang/legacy): Fortran field reading, the diagnostics of
// mangled decks (file, line, card and columns), the corpus deck's conversion and its stability
// under the formatter, and robustness against truncated and corrupted decks.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "lang/diagnostics/diagnostic.h"
#include "lang/diagnostics/render.h"
#include "lang/format/formatter.h"
#include "lang/legacy/convert.h"
#include "lang/legacy/fortran_field.h"
#include "lang/source/source_manager.h"
#include "lang/syntax/parser.h"
#include "tests/legacy/legacy_test_deck.h"

namespace sled::lang::legacy {
namespace {

using namespace deck_testing;  // NOLINT(google-build-using-namespace): the deck helpers

const std::string kDeck = kLegacyDir + "seated_occupant.ain";

// The corpus deck has an airbag: converted as `sled convert --approximate-airbags` does.
Converted Convert(const std::string& text, BlankMode blanks = BlankMode::kIgnore) {
  ConvertOptions options;
  options.blanks = blanks;
  options.approximate_airbags = true;
  return ConvertText(text, options);
}

std::string CorpusDeck() { return ReadDeckFile(kDeck); }

TEST(FortranField, ReadsRealsAsFormattedReadsDo) {
  EXPECT_EQ(ReadRealField("  26.6", BlankMode::kIgnore).number, 26.6);
  EXPECT_EQ(ReadRealField("   386", BlankMode::kIgnore).number, 386.0);  // Fw.0: a whole number
  EXPECT_EQ(ReadRealField("1.5E-3", BlankMode::kIgnore).number, 1.5e-3);
  EXPECT_EQ(ReadRealField("1.5D+2", BlankMode::kIgnore).number, 150.0);
  EXPECT_EQ(ReadRealField(" 1.5-3", BlankMode::kIgnore).number, 1.5e-3);
  EXPECT_EQ(ReadRealField("      ", BlankMode::kIgnore).number, 0.0);
  EXPECT_TRUE(ReadRealField("      ", BlankMode::kIgnore).blank);
  EXPECT_EQ(ReadRealField("1 2. ", BlankMode::kIgnore).number, 12.0);  // BN: blanks vanish
  EXPECT_EQ(ReadRealField(" 1 2. ", BlankMode::kZero).number, 102.0);  // BZ: embedded blank is 0
  EXPECT_EQ(ReadRealField("12a", BlankMode::kIgnore).problem, FieldProblem::kNotANumber);
  EXPECT_EQ(ReadRealField("-", BlankMode::kIgnore).problem, FieldProblem::kNotANumber);
  EXPECT_EQ(ReadRealField("1e999", BlankMode::kIgnore).problem, FieldProblem::kOutOfRange);
}

TEST(FortranField, ReadsIntegersAndBlankZeroMode) {
  EXPECT_EQ(ReadIntegerField("  15", BlankMode::kIgnore).number, 15.0);
  EXPECT_EQ(ReadIntegerField(" -3 ", BlankMode::kIgnore).number, -3.0);
  EXPECT_EQ(ReadIntegerField(" 1  ", BlankMode::kIgnore).number, 1.0);
  EXPECT_EQ(ReadIntegerField(" 1  ", BlankMode::kZero).number, 100.0);  // left-justified in CVS-III
  EXPECT_EQ(ReadIntegerField("15. ", BlankMode::kIgnore).problem, FieldProblem::kNotAnInteger);
  EXPECT_EQ(ReadIntegerField("1x", BlankMode::kIgnore).problem, FieldProblem::kNotANumber);
  EXPECT_EQ(ReadIntegerField("99999999999", BlankMode::kIgnore).problem, FieldProblem::kOutOfRange);
}

TEST(LegacyConvert, CorpusDeckConvertsAndFormatsStably) {
  const Converted converted = Convert(CorpusDeck());
  ASSERT_EQ(converted.errors, 0) << converted.diagnostics.front();
  ASSERT_FALSE(converted.text.empty());
  // The printed scenario parses back without errors, and formatting it again changes nothing.
  SourceManager sources;
  DiagnosticCollector collector;
  const FileId id = sources.Add("converted.sled", converted.text);
  ParseOptions parse;
  parse.diagnostics = &collector;
  const ast::File reparsed = Parse(sources, id, parse);
  EXPECT_FALSE(collector.has_errors());
  EXPECT_EQ(Format(reparsed), converted.text);
  // Names and units come from the deck; each declaration names its card.
  EXPECT_NE(converted.text.find("segment lt {"), std::string::npos);
  EXPECT_NE(converted.text.find("mass = 26.6 lbf / deck_g"), std::string::npos);
  EXPECT_NE(converted.text.find("joint lumb : ball(lt -> ct)"), std::string::npos);
  EXPECT_NE(converted.text.find("// card B.2.a, line"), std::string::npos);
  EXPECT_NE(converted.text.find("function seat_foam = table(deflection -> force) {"),
            std::string::npos);
  EXPECT_NE(converted.text.find("1 in -> 150 lbf"), std::string::npos);
  // The unverified fields the deck uses are reported as warnings, and only those.
  EXPECT_TRUE(converted.Has("warning[W0501]")) << converted.diagnostics.size();
}

TEST(LegacyConvert, LettersInANumericFieldNameLineCardAndColumns) {
  std::vector<std::string> lines = Lines(CorpusDeck());
  const std::size_t line = LineStarting(lines, "UT  ");
  lines[line - 1].replace(26, 4, "1.7x");  // columns 27-30 hold PHI(y)
  const Converted converted = Convert(Join(lines, lines.size()));
  EXPECT_TRUE(
      converted.Has(fmt::format("deck.ain:{}:25-30: error[E0502]: card B.2.a (segment 3), "
                                "columns 25-30",
                                line)))
      << converted.diagnostics.front();
}

TEST(LegacyConvert, EachManglingGetsItsCode) {
  const std::vector<std::string> lines = Lines(CorpusDeck());
  auto mangled = [&](std::string_view prefix, auto edit) {
    std::vector<std::string> copy = lines;
    edit(copy[LineStarting(copy, prefix) - 1]);
    return Convert(Join(copy, copy.size()));
  };
  EXPECT_TRUE(mangled("    15    14", [](std::string& s) {
                s.replace(0, 6, "   15.");
              }).Has("error[E0503]"));
  EXPECT_TRUE(mangled("    15    14", [](std::string& s) {
                s.replace(0, 6, "    75");
              }).Has("error[E0505]"));
  EXPECT_TRUE(mangled("LT  ", [](std::string& s) { s[3] = '\t'; }).Has("error[E0504]"));
  EXPECT_TRUE(
      mangled("IN  LB", [](std::string& s) { s.replace(0, 4, "FURL"); }).Has("error[E0506]"));
  EXPECT_TRUE(mangled("LUMB", [](std::string& s) {
                s.replace(54, 6, " 5000.");
              }).Has("55-66: warning[W0503]: card B.3.a (joint 1), columns 55-66: TENS_MAX 5000"));
  // Shifting a card's fields one column to the right puts digits where blanks belong.
  EXPECT_GT(mangled("H    ", [](std::string& s) { s.insert(6, " "); }).errors, 0);
  // Extra cards after H.3.
  const Converted extra = Convert(Join(lines, lines.size()) + "     1  0  5\n");
  EXPECT_TRUE(extra.Has("error[E0510]"));
}

TEST(LegacyConvert, BlankCardsAreDataNotSkipped) {
  // Removing one of the 15 blank G.3.a cards leaves the deck one card short at the end.
  std::vector<std::string> lines = Lines(CorpusDeck());
  const std::size_t g3 = LineStarting(lines, "# G.3.a");
  lines.erase(lines.begin() + static_cast<std::ptrdiff_t>(g3));
  const Converted converted = Convert(Join(lines, lines.size()));
  EXPECT_GT(converted.errors, 0);
}

TEST(LegacyConvert, UndefinedFunctionIsReportedAtItsField) {
  std::vector<std::string> lines = Lines(CorpusDeck());
  // The first F.1.b card names function 1 in columns 17-20; make it 7.
  const std::size_t line = LineStarting(lines, "   1   1   0   0   1");
  lines[line - 1].replace(16, 4, "   7");
  const Converted converted = Convert(Join(lines, lines.size()));
  EXPECT_TRUE(converted.Has(fmt::format("deck.ain:{}:17-20: error[E0509]", line)));
}

// The scenario's `initial BODY { ... }` block, empty when there is none.
std::string InitialBlock(const std::string& scenario, std::string_view body) {
  const std::size_t start = scenario.find(fmt::format("initial {} {{", body));
  if (start == std::string::npos) return {};
  return scenario.substr(start, scenario.find("\n  }", start) - start);
}

TEST(LegacyConvert, G1aI3ChoosesTheVehiclesVelocityOrTheGCards) {
  const std::vector<std::string> lines = Lines(CorpusDeck());
  const std::size_t g1 = LineStarting(lines, "# ---- G cards") + 1;  // G.1.a, then G.2, G.3.a
  auto convert = [&](const std::string& i3, const std::string& g2_velocity,
                     const std::string& g3_rate) {
    std::vector<std::string> copy = lines;
    copy[g1 - 1] = std::string(46, ' ') + i3;
    copy[g1].replace(30, 30, g2_velocity);
    copy[g1 + 2] = std::string(30, ' ') + g3_rate;
    return Convert(Join(copy, copy.size()));
  };
  const std::string blank(30, ' ');
  const std::string rate = "        0.       10.        0.";
  // I3 = 0 (blank): the sled's 30 mph (C.2.a's VIPS), whatever G.2 and G.3.a say; what they say is
  // W0503.
  const Converted vehicle = convert("    ", blank, blank);
  EXPECT_EQ(vehicle.errors, 0);
  EXPECT_FALSE(vehicle.Has("W0503"));
  EXPECT_NE(InitialBlock(vehicle.text, "occupant").find("velocity = (30, 0, 0) mph"),
            std::string::npos)
      << vehicle.text;
  const Converted ignored = convert("   0", "      100.        0.        0.", rate);
  EXPECT_TRUE(ignored.Has(fmt::format("deck.ain:{}:31-60: warning[W0503]: card G.2", g1 + 1)));
  EXPECT_TRUE(ignored.Has(fmt::format("deck.ain:{}:31-60: warning[W0503]: card G.3.a", g1 + 3)));
  EXPECT_EQ(InitialBlock(ignored.text, "occupant"), InitialBlock(vehicle.text, "occupant"));
  EXPECT_EQ(ignored.text.find("angular_velocity"), std::string::npos);
  // I3 = 1 and 2: the G cards, blank or not.
  for (const char* i3 : {"   1", "   2"}) {
    const Converted cards = convert(i3, "      100.        0.        0.", rate);
    EXPECT_EQ(cards.warnings, vehicle.warnings) << i3;
    EXPECT_NE(InitialBlock(cards.text, "occupant").find("velocity = (100, 0, 0) in/s"),
              std::string::npos)
        << cards.text;
    EXPECT_NE(cards.text.find("angular_velocity = (0, 10, 0) deg/s"), std::string::npos);
  }
  const Converted at_rest = convert("   1", blank, blank);
  EXPECT_EQ(InitialBlock(at_rest.text, "occupant").find("velocity"), std::string::npos);
  EXPECT_TRUE(convert("   3", blank, blank)
                  .Has(fmt::format("deck.ain:{}:47-50: error[E0512]: card G.1.a", g1)));
}

TEST(LegacyConvert, VehicleVelocityLiesAlongTheVehiclesXAxis) {
  const std::vector<std::string> lines = Lines(CorpusDeck());
  const std::size_t c2 = LineStarting(lines, "SLED 30 MPH") + 1;
  auto convert = [&](const std::string& yaw_pitch_roll) {
    std::vector<std::string> copy = lines;
    copy[c2 - 1].replace(0, 18, yaw_pitch_roll);
    return Convert(Join(copy, copy.size()));
  };
  // Pitched -90 degrees, x points down (+z); yawed 90, along +y; the roll turns about x itself.
  const Converted pitched = convert("    0.  -90.   30.");
  EXPECT_NE(pitched.text.find("velocity = (0, 0, 30) mph"), std::string::npos) << pitched.text;
  EXPECT_NE(InitialBlock(pitched.text, "occupant").find("velocity = (0, 0, 30) mph"),
            std::string::npos);
  EXPECT_NE(convert("   90.    0.    0.").text.find("velocity = (0, 30, 0) mph"),
            std::string::npos);
  const Converted yawed = convert("   60.    0.    0.");
  const double yaw = 60 * (std::numbers::pi / 180);
  EXPECT_NE(yawed.text.find(
                fmt::format("velocity = ({}, {}, 0) mph", 30 * std::cos(yaw), 30 * std::sin(yaw))),
            std::string::npos)
      << yawed.text;
}

TEST(LegacyConvert, ObsoleteJointFunctionCardsAreRefusedWithoutACascade) {
  // A CVS-III deck: NJNTF = 2 on D.1.a and two F.5 cards of unknown layout after the E cards.
  std::vector<std::string> lines = Lines(CorpusDeck());
  const std::size_t d1 = LineStarting(lines, "     4     2     1");
  lines[d1 - 1].replace(48, 6, "     2");
  const std::size_t f_cards = LineStarting(lines, "# ---- F cards");
  lines.insert(lines.begin() + static_cast<std::ptrdiff_t>(f_cards - 1),
               {"    1    1   -1    0.5", "    2    2   -2    0.5"});
  for (const BlankMode blanks : {BlankMode::kIgnore, BlankMode::kZero}) {
    const Converted converted = Convert(Join(lines), blanks);
    EXPECT_EQ(converted.errors, 1) << converted.All();
    EXPECT_TRUE(
        converted.Has(fmt::format("deck.ain:{}:49-54: error[E0507]: card D.1.a, columns "
                                  "49-54: NJNTF is 2: the deck has the obsolete "
                                  "joint-function cards (F.5)",
                                  d1)))
        << converted.All();
  }
}

TEST(LegacyConvertRobustness, EveryTruncationIsReportedNeverACrash) {
  ExpectEveryCutIsReported(
      CorpusDeck(), [](const std::string& text) { return Convert(text); }, false);
}

TEST(LegacyConvertRobustness, CorruptedCharactersNeverCrash) {
  const std::string deck = CorpusDeck();
  const char replacements[] = {'x', '9', ' ', '-', '.', '\t', '\n', '#', 'E'};
  std::uint32_t state = 12345;
  for (int trial = 0; trial < 2000; ++trial) {
    std::string copy = deck;
    for (int flips = 0; flips < 3; ++flips) {
      state = state * 1664525u + 1013904223u;
      const std::size_t at = state % copy.size();
      copy[at] = replacements[(state >> 16) % sizeof(replacements)];
    }
    const Converted converted = Convert(copy, trial % 2 ? BlankMode::kZero : BlankMode::kIgnore);
    if (converted.errors == 0) {
      EXPECT_FALSE(converted.text.empty());
    }
  }
}

}  // namespace
}  // namespace sled::lang::legacy
