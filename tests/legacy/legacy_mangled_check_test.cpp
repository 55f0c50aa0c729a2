// Mangled decks are judged where they are read: every numeric field of the example decks is
// replaced, in its own columns, by values a typing slip gives (zero, -1, its negative, a huge
// value), and each mangled deck must either convert to a scenario that compiles (checks and lowers)
// without an error, or be refused with errors that are all E05xx located at a line and columns
// of the deck. A deck that converts and then fails `sled check` is a deck value checked too late.
#include <gtest/gtest.h>

#include <cctype>
#include <string>
#include <vector>

#include "legacy_test_deck.h"
#include "sled/compile.h"

namespace sled::lang::legacy {
namespace {

// A number's span in a fixed-column line: a run of characters that can be part of a Fortran
// number, bounded by blanks.
struct Span {
  std::size_t first;
  std::size_t size;
};

std::vector<Span> NumberSpans(const std::string& line) {
  std::vector<Span> spans;
  std::size_t i = 0;
  while (i < line.size()) {
    if (line[i] == ' ') {
      ++i;
      continue;
    }
    const std::size_t start = i;
    bool numeric = true;
    while (i < line.size() && line[i] != ' ') {
      const char c = line[i];
      if (!std::isdigit(static_cast<unsigned char>(c)) && c != '.' && c != '-' && c != '+' &&
          c != 'E' && c != 'e')
        numeric = false;
      ++i;
    }
    if (numeric) spans.push_back({start, i - start});
  }
  return spans;
}

// `value` right-aligned in the span (widened to its left over blanks when it does not fit, so
// the field keeps its last column), or nothing when it cannot be placed.
bool Place(std::string& line, Span span, const std::string& value) {
  const std::size_t end = span.first + span.size;
  if (value.size() > end) return false;
  const std::size_t start = end - value.size();
  for (std::size_t i = start; i < span.first; ++i) {
    if (line[i] != ' ') return false;
  }
  line.replace(start, end - start, value);
  return true;
}

// Zero for every field, and in turn from field to field -1, a huge value or the field's own
// negative (all four for every field took twice as long).
std::vector<std::string> Manglings(const std::string& number, int field) {
  const bool real = number.find('.') != std::string::npos;
  std::vector<std::string> values = {real ? "0." : "0"};
  switch (field % 3) {
    case 0:
      values.emplace_back(real ? "-1." : "-1");
      break;
    case 1:
      values.emplace_back(real ? "9999." : "99");
      break;
    default:
      values.push_back(number[0] == '-' ? number.substr(1) : "-" + number);
      break;
  }
  return values;
}

// The errors of a refused deck: all E05xx at a deck line and columns.
void ExpectLocatedDeckErrors(const Converted& converted, const std::string& what) {
  for (const std::string& d : converted.diagnostics) {
    if (d.find("error[") == std::string::npos) continue;
    EXPECT_NE(d.find("error[E05"), std::string::npos) << what << "\n" << d;
    // "deck.ain:LINE:FIRST-LAST: error"
    EXPECT_EQ(d.rfind("deck.ain:", 0), 0u) << what << "\n" << d;
  }
}

void MangleEveryField(const std::string& name) {
  const std::vector<std::string> lines = Lines(ReadDeckFile(kLegacyDir + name));
  ConvertOptions options;
  options.approximate_airbags = true;
  int converted_clean = 0;
  int refused = 0;
  int field = 0;
  for (std::size_t l = 0; l < lines.size(); ++l) {
    if (lines[l].empty() || lines[l][0] == '#') continue;
    for (const Span span : NumberSpans(lines[l])) {
      for (const std::string& value : Manglings(lines[l].substr(span.first, span.size), field++)) {
        std::vector<std::string> copy = lines;
        if (!Place(copy[l], span, value)) continue;
        const std::string what = name + " line " + std::to_string(l + 1) + ": " + copy[l];
        const Converted converted = ConvertText(deck_testing::Join(copy), options);
        if (converted.errors > 0) {
          ++refused;
          ExpectLocatedDeckErrors(converted, what);
          continue;
        }
        CompileOptions compile;
        compile.lower = false;  // `sled check`: its errors, without the lints' warnings
        compile.lints = false;
        const Compilation compiled =
            Compile(Source::Text(converted.text, "converted.sled"), compile);
        EXPECT_TRUE(compiled.ok()) << what << "\n" << compiled.Render();
        ++converted_clean;
      }
    }
  }
  EXPECT_GT(converted_clean, 0);
  EXPECT_GT(refused, 0);
}

TEST(LegacyMangledDecks, SeatedOccupantFieldsCheckCleanOrAreRefusedAtTheirCard) {
  MangleEveryField("seated_occupant.ain");
}
TEST(LegacyMangledDecks, PedestrianFieldsCheckCleanOrAreRefusedAtTheirCard) {
  MangleEveryField("pedestrian.ain");
}
TEST(LegacyMangledDecks, EjectionSeatFieldsCheckCleanOrAreRefusedAtTheirCard) {
  MangleEveryField("ejection_seat.ain");
}

}  // namespace
}  // namespace sled::lang::legacy
