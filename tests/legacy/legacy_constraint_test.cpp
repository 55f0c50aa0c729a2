// D.6 constraints through `sled convert`: KQTYPE 1 and 2 become `fixed_point` and
// `fixed_distance` constraints between segments, vehicles and the ground; the kinds that need a
// contact, the tension element and the switched kinds are refused at KQTYPE; frames outside the
// deck get E0505, an airbag E0507.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <string>
#include <vector>

#include "tests/legacy/legacy_test_deck.h"

namespace sled::lang::legacy {
namespace {

using namespace deck_testing;  // NOLINT(google-build-using-namespace): the deck helpers

// The seated-occupant deck with D.1.a's NQ set and `cards` as its D.6 cards; `*first` is the line
// of the first of them.
Converted WithConstraints(const std::vector<std::string>& cards, std::size_t* first = nullptr) {
  std::vector<std::string> lines = Lines(ReadDeckFile(kLegacyDir + "seated_occupant.ain"));
  const std::size_t d1 = LineStarting(lines, "     4     2     1");
  lines[d1 - 1].replace(24, 6, fmt::format("{:6}", cards.size()));
  const std::size_t d7 = LineStarting(lines, "# D.7");
  lines.insert(lines.begin() + static_cast<std::ptrdiff_t>(d7 - 1), cards.begin(), cards.end());
  if (first != nullptr) *first = d7;
  ConvertOptions options;
  options.approximate_airbags = true;  // the deck's airbag is segment 17; the ground is 18
  return ConvertText(Join(lines), options);
}

TEST(LegacyConstraints, FixedPointsAndDistancesConvert) {
  std::size_t line = 0;
  const Converted converted = WithConstraints(
      {"     1    13    16    0.    0.   -6.   20.    8.  -10.",   // right hand on the sled
       "     2    13    15    0.    0.   -6.    0.    0.   -6.",   // the hands a span apart
       "     1    18     1   10.    0.    5.    0.    0.    0."},  // the ground to the pelvis
      &line);
  ASSERT_EQ(converted.errors, 0) << converted.All();
  const std::string& text = converted.text;
  EXPECT_NE(text.find(fmt::format("  // card D.6, line {}\n  constraint constraint_1 : "
                                  "fixed_point(occupant.rla -> sled) {{\n"
                                  "    at occupant.rla = (0, 0, -6) in\n"
                                  "    at sled = (20, 8, -10) in\n  }}",
                                  line)),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("constraint constraint_2 : fixed_distance(occupant.rla -> occupant.lla) {"),
            std::string::npos);
  EXPECT_NE(text.find("constraint constraint_3 : fixed_point(ground -> occupant.lt) {\n"
                      "    at ground = (10, 0, 5) in"),
            std::string::npos);
}

TEST(LegacyConstraints, WhatSledCannotExpressIsRefusedAtKqtype) {
  for (const char* type : {"     3", "     4", "     5", "     6", "    -1"}) {
    std::size_t line = 0;
    const Converted converted = WithConstraints(
        {std::string(type) + "    13    16    0.    0.   -6.    0.    0.    0."}, &line);
    EXPECT_TRUE(
        converted.Has(fmt::format("deck.ain:{}:1-6: error[E0507]: card D.6 "
                                  "(constraint 1), columns 1-6: KQTYPE",
                                  line)))
        << type << "\n"
        << converted.All();
  }
  std::size_t line = 0;
  EXPECT_TRUE(WithConstraints({"     7    13    16"}, &line)
                  .Has(fmt::format("deck.ain:{}:1-6: error[E0512]", line)));
}

TEST(LegacyConstraints, FramesMustExistAndDiffer) {
  std::size_t line = 0;
  EXPECT_TRUE(WithConstraints({"     1    13    19"}, &line)
                  .Has(fmt::format("deck.ain:{}:13-18: error[E0505]", line)));
  EXPECT_TRUE(WithConstraints({"     1    13    17"}, &line)
                  .Has(fmt::format("deck.ain:{}:13-18: error[E0507]: card D.6 (constraint 1), "
                                   "columns 13-18: KQ2, the second segment is 17: an airbag",
                                   line)));
  EXPECT_TRUE(WithConstraints({"     1    16    18"}, &line)
                  .Has(fmt::format("deck.ain:{}:7-18: error[E0512]", line)));
  EXPECT_TRUE(WithConstraints({"     2     4     4"}, &line)
                  .Has(fmt::format("deck.ain:{}:7-18: error[E0512]", line)));
  EXPECT_FALSE(WithConstraints({"     1    13    16", "     1    13    16"})
                   .Has("error[E0505]: card D.1.a, columns 25-30"));
  std::vector<std::string> many(13, "     1    13    16");
  EXPECT_TRUE(WithConstraints(many).Has("error[E0505]: card D.1.a, columns 25-30"));
}

}  // namespace
}  // namespace sled::lang::legacy
