// The list-directed `.lin` reader (lang/legacy/list_reader): every `.lin` deck of examples/legacy
// converts to exactly the scenario of the `.ain` deck of the same name (both readers share the
// card declarations, so this checks the list-directed reading against the fixed-column one), the
// Fortran list-directed rules (separators, quotes, repeats, `/`, a READ over several lines, the
// ignored rest of a line), and mangled decks getting a diagnostic at the item's columns.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "lang/diagnostics/diagnostic.h"
#include "lang/diagnostics/render.h"
#include "lang/format/formatter.h"
#include "lang/legacy/convert.h"
#include "lang/source/source_manager.h"
#include "tests/legacy/legacy_test_deck.h"

namespace sled::lang::legacy {
namespace {

namespace fs = std::filesystem;
using namespace deck_testing;  // NOLINT(google-build-using-namespace): the deck helpers

const fs::path kLegacy = fs::path(SLED_SOURCE_ROOT) / "examples/legacy";

// The corpus's seated occupant has an airbag: converted as with --approximate-airbags.
Converted Convert(const std::string& text, DeckFormat format, const std::string& name) {
  ConvertOptions options;
  options.format = format;
  options.approximate_airbags = true;
  return ConvertText(text, options, name);
}

Converted ConvertLin(const std::string& text) {
  return Convert(text, DeckFormat::kList, "deck.lin");
}

std::string Read(const fs::path& path) { return ReadDeckFile(path.string()); }

std::string CorpusLin() { return Read(kLegacy / "seated_occupant.lin"); }

// The corpus deck with the line starting `prefix` replaced by `replacement`.
Converted Mangled(std::string_view prefix, const std::string& replacement, std::size_t* line) {
  std::vector<std::string> lines = Lines(CorpusLin());
  *line = LineStarting(lines, prefix);
  lines[*line - 1] = replacement;
  return ConvertLin(Join(lines, lines.size()));
}

TEST(LinDecks, EveryLinDeckConvertsToTheScenarioOfItsAinTwin) {
  int decks = 0;
  for (const auto& entry : fs::directory_iterator(kLegacy)) {
    if (entry.path().extension() != ".lin") continue;
    fs::path ain = entry.path();
    ain.replace_extension(".ain");
    ASSERT_TRUE(fs::exists(ain)) << entry.path() << " has no .ain of the same name";
    const Converted from_lin =
        Convert(Read(entry.path()), DeckFormat::kList, entry.path().filename().string());
    const Converted from_ain = Convert(Read(ain), DeckFormat::kFixed, ain.filename().string());
    ASSERT_EQ(from_lin.errors, 0) << entry.path() << "\n" << from_lin.All();
    ASSERT_EQ(from_ain.errors, 0) << ain << "\n" << from_ain.All();
    EXPECT_FALSE(from_lin.text.empty());
    EXPECT_EQ(from_lin.text, from_ain.text) << entry.path();
    ++decks;
  }
  EXPECT_GE(decks, 1);
}

TEST(LinDecks, FormatFollowsTheExtension) {
  EXPECT_EQ(DeckFormatOfPath("a/deck.ain"), DeckFormat::kFixed);
  EXPECT_EQ(DeckFormatOfPath("DECK.LIN"), DeckFormat::kList);
  EXPECT_EQ(DeckFormatOfPath("deck.dat"), std::nullopt);
  EXPECT_EQ(DeckFormatOfPath("decks.lin/deck"), std::nullopt);
}

TEST(LinReading, SeparatorsQuotesRepeatsAndSlashReadAsFortranDoes) {
  // The B.2.a card of segment 1 written five ways, each the same twelve items.
  const std::string forms[] = {
      R"( "LT" 26.6 1.1 0.9 1.2 4.5 6.5 4. 0. 0. 0. 0  Card B.2.a)",
      R"( 'LT',26.6, 1.1 ,0.9 1.2, 4.5 6.5 4. 3*0. 0)",
      R"( LT 26.6 1.1 0.9 1.2 4.5 6.5 4. /  the rest keeps its default)",
      R"( "LT" 26.6 1.1 0.9 1.2 4.5 6.5 4.,,,, 0)",
      R"( "LT" 26.6 1.1 0.9)",  // the READ goes on over the next line
  };
  const Converted reference = ConvertLin(CorpusLin());
  ASSERT_EQ(reference.errors, 0) << reference.All();
  for (const std::string& form : forms) {
    std::vector<std::string> lines = Lines(CorpusLin());
    const std::size_t line = LineStarting(lines, R"( "LT")");
    lines[line - 1] = form;
    if (form.back() == '9') lines.insert(lines.begin() + line, " 1.2 4.5 6.5 4. 4*0  Card B.2.a");
    const Converted converted = ConvertLin(Join(lines, lines.size()));
    ASSERT_EQ(converted.errors, 0) << form << "\n" << converted.All();
    // Line numbers in the comments move with the inserted line; the rest is the same scene.
    if (form.back() != '9') {
      EXPECT_EQ(converted.text, reference.text) << form;
    }
    EXPECT_NE(converted.text.find("segment lt {"), std::string::npos) << form;
    EXPECT_NE(converted.text.find("mass = 26.6 lbf / deck_g"), std::string::npos) << form;
  }
}

TEST(LinMangled, LettersInANumberNameTheItemsColumns) {
  std::size_t line = 0;
  const Converted converted =
      Mangled(R"( "UT")", R"( "UT" 39.5 2.2 1.7x 1.6 4.5 7. 6.5 0. 0. 0. 0  Card B.2.a)", &line);
  EXPECT_TRUE(converted.Has(fmt::format(
      "deck.lin:{}:16-19: error[E0502]: card B.2.a (segment 3), item 4 (PHI, the principal "
      "moments of inertia): `1.7x` is not a number",
      line)))
      << converted.All();
}

TEST(LinMangled, AMissingItemIsTakenFromTheNextLine) {
  // Without its LPMI, segment 1's READ takes the next line's first item, the name "CT".
  std::size_t line = 0;
  const Converted converted =
      Mangled(R"( "LT")", R"( "LT" 26.6 1.1 0.9 1.2 4.5 6.5 4. 0. 0. 0.)", &line);
  EXPECT_TRUE(converted.Has(
      fmt::format("deck.lin:{}:2-5: error[E0502]: card B.2.a (segment 1), item 12 (LPMI, "
                  "principal axes given): `\"CT\"` is not a whole number",
                  line + 1)))
      << converted.All();
}

TEST(LinMangled, AnUnclosedStringIsE0508) {
  std::size_t line = 0;
  const Converted converted = Mangled(" 15 14", R"( 15 14 "OCCUPANT 0  Card B.1)", &line);
  EXPECT_TRUE(converted.Has(fmt::format(
      "deck.lin:{}:8-28: error[E0508]: card B.1, item 3: the string is not closed on its line",
      line)))
      << converted.All();
}

TEST(LinMangled, BadRepeatCountsAreE0508) {
  std::size_t line = 0;
  const Converted zero = Mangled(" 36*0", " 0*0  Card A.5", &line);
  EXPECT_TRUE(
      zero.Has(fmt::format("deck.lin:{}:2-3: error[E0508]: card A.5, item 1: the repeat "
                           "count `0*` is not a positive number",
                           line)))
      << zero.All();
  const Converted extra = Mangled(" 36*0", " 37*0  Card A.5", &line);
  EXPECT_TRUE(extra.Has(fmt::format(
      "deck.lin:{}:2-5: error[E0508]: the repeat count gives 1 more value than its READ takes",
      line)))
      << extra.All();
}

TEST(LinMangled, AWordWhereANumberBelongs) {
  std::size_t line = 0;
  const Converted converted = Mangled(" 0 300", " 0 300 DT 0.0001 0.0005 0  Card A.4", &line);
  EXPECT_TRUE(converted.Has(fmt::format(
      "deck.lin:{}:8-9: error[E0502]: card A.4, item 3 (DT, the output step): `DT` is not a "
      "number",
      line)))
      << converted.All();
}

TEST(LinRobustness, EveryTruncationIsReportedNeverACrash) {
  ExpectEveryCutIsReported(CorpusLin(), ConvertLin, true);
  // Cut inside a line: the READ lacks items.
  const std::string text = CorpusLin();
  const Converted cut = ConvertLin(text.substr(0, text.find("\"OCCUPANT\"")));
  EXPECT_TRUE(cut.Has("error[E0501]: the deck ends before item 3 of card B.1")) << cut.All();
}

TEST(LinRobustness, CorruptedCharactersNeverCrash) {
  const std::string deck = CorpusLin();
  const char replacements[] = {'x', '9', ' ', '-', '.', ',', '/', '*', '"', '\'', '\n', '#'};
  std::uint32_t state = 54321;
  for (int trial = 0; trial < 2000; ++trial) {
    std::string copy = deck;
    for (int flips = 0; flips < 3; ++flips) {
      state = state * 1664525u + 1013904223u;
      const std::size_t at = state % copy.size();
      copy[at] = replacements[(state >> 16) % sizeof(replacements)];
    }
    const Converted converted = ConvertLin(copy);
    if (converted.errors == 0) {
      EXPECT_FALSE(converted.text.empty());
    }
  }
}

}  // namespace
}  // namespace sled::lang::legacy
