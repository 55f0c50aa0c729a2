// The H cards (lang/legacy/output_reader.cpp): ATB V.3's output requests H.1 to H.10 with zero
// and non-zero counts, KREF's frames, the continuation cards of H.4 to H.9, the dummy cards and a
// deck that ends early. The decks are the corpus's seated occupant with its H cards rewritten from
// the READ statements' layouts.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <string>
#include <vector>

#include "tests/legacy/legacy_test_deck.h"

namespace sled::lang::legacy {
namespace {

using namespace deck_testing;  // NOLINT: the deck helpers

Converted Convert(const std::string& text, const std::string& name = "deck.ain") {
  ConvertOptions options;
  options.approximate_airbags = true;
  if (name.ends_with(".lin")) options.format = DeckFormat::kList;
  return ConvertText(text, options, name);
}

// The corpus deck up to and including its "# ---- H cards" line, then `h_cards`.
std::string WithHCards(const std::string& h_cards,
                       const std::string& file = "seated_occupant.ain") {
  const std::vector<std::string> lines = Lines(ReadDeckFile(kLegacyDir + file));
  return Join(lines, LineStarting(lines, "# ---- H cards")) + h_cards;
}

// H.1 to H.3 as the corpus deck has them (so its H.4 cards start on the deck's line `h4`).
const std::string kPointCards =
    "     2  0  5          0.          0.          0.     0\n"
    "        0  3          0.          0.          0.     0\n"
    "     0\n"
    " 0\n"
    "     1  0  1          0.          0.          0.     0\n"
    " 0\n";

TEST(LegacyOutputs, ZeroCountsRequestNothingAndWarnNothing) {
  const Converted converted =
      Convert(WithHCards(kPointCards + "     0\n     0\n     0\n     0\n     0\n     0\n     0\n"));
  EXPECT_EQ(converted.errors, 0) << converted.All();
  EXPECT_FALSE(converted.Has("W0503")) << converted.All();
  EXPECT_FALSE(converted.Has("W0505")) << converted.All();
  // KREF 0 on H.3: relative to the primary vehicle, as ATB's OUTPUT_HCARDS takes NVEH.
  EXPECT_NE(converted.text.find("position occupant.lt at (0, 0, 0) in relative_to sled"),
            std::string::npos)
      << converted.text;
  EXPECT_NE(converted.text.find("acceleration occupant.h at (0, 0, 0) in\n"), std::string::npos);
}

TEST(LegacyOutputs, SegmentRequestsTakeKrefsFrame) {
  // H.1 in the head's axes of the thorax (KREF 3), H.2 relative to the thorax, H.4 of the head
  // plain and in the vehicle's axes (KREF 16, the sled), H.5 relative to the sled (KREF 0), H.6
  // relative to the ground (18: the bag is 17), H.7 joints 1 and 4, H.9 joint 4.
  const std::string h =
      "     1  3  5          0.          0.         10.     0\n"
      " 0\n"
      "     1  3  5          0.          0.         10.     0\n"
      " 0\n"
      "     0\n"
      " 0\n"
      "     2  0  5 16  5\n"
      "     1  0  5\n"
      "     1 18  5\n"
      "     2     1     4\n"
      "     0\n"
      "     1  0  4\n"
      "     0\n";
  const Converted converted = Convert(WithHCards(h));
  ASSERT_EQ(converted.errors, 0) << converted.All();
  const std::string& t = converted.text;
  for (const char* expected : {
           "acceleration occupant.h at (0, 0, 10) in expressed_in occupant.ut",
           "velocity occupant.h at (0, 0, 10) in relative_to occupant.ut",
           "angular_acceleration occupant.h\n",
           "angular_acceleration occupant.h expressed_in sled",
           "angular_velocity occupant.h relative_to sled",
           "orientation occupant.h relative_to ground",
           "joint_angle occupant.",
           "joint_force occupant.",
       }) {
    EXPECT_NE(t.find(expected), std::string::npos) << expected << "\n" << t;
  }
  // H.2 relative to a turning segment differs from ATB's difference of velocities: W0504 at KREF.
  const std::size_t h2 = LineStarting(Lines(WithHCards(h)), "# ---- H cards") + 3;
  EXPECT_TRUE(converted.Has(fmt::format("deck.ain:{}:7-9: warning[W0504]", h2))) << converted.All();
}

TEST(LegacyOutputs, PairsContinueOnASecondCardAfterEleven) {
  // H.5 with 12 requests: eleven pairs on the first card (columns 7-72), the twelfth on the next
  // in columns 1-9 (KREF) and 10-12 (MSG).
  std::string first = "    12";
  for (int i = 1; i <= 11; ++i) first += fmt::format("{:3}{:3}", 0, i);
  const std::string h = kPointCards + "     0\n" + first + "\n" +
                        fmt::format("{:9}{:3}\n", 18, 12) +
                        "     0\n     0\n     0\n     0\n     0\n";
  const Converted converted = Convert(WithHCards(h));
  ASSERT_EQ(converted.errors, 0) << converted.All();
  EXPECT_NE(converted.text.find("angular_velocity occupant.rll relative_to sled"),
            std::string::npos);
  EXPECT_NE(converted.text.find("angular_velocity occupant.lf relative_to sled"),
            std::string::npos);
  EXPECT_NE(converted.text.find("angular_velocity occupant.rua relative_to ground"),
            std::string::npos)
      << converted.text;
}

// H.8's wind forces and H.10's total-body centres of gravity are read and not written (W0504:
// sled has neither channel; an output changes no value of the run), the cards after them in place.
TEST(LegacyOutputs, WindForcesAndTotalBodiesAreReadAndNotWritten) {
  auto deck_with_set = [](const std::string& set) {
    return Lines(WithHCards(kPointCards +
                            "     0\n     0\n     0\n"
                            "     0\n     1  0  5\n     0\n"
                            "     1\n" +
                            set + "\n        0.        0.        0.\n"));
  };
  const std::vector<std::string> deck = deck_with_set("  1  2  1  2");
  const std::size_t h8 = LineStarting(deck, "# ---- H cards") + 11;
  const Converted converted = Convert(Join(deck));
  EXPECT_EQ(converted.errors, 0) << converted.All();
  EXPECT_TRUE(converted.Has(fmt::format("deck.ain:{}:1-6: warning[W0504]", h8))) << converted.All();
  EXPECT_TRUE(
      converted.Has(fmt::format("deck.ain:{}:1-12: warning[W0504]: card H.10.b (set 1), "
                                "columns 1-12: the centre of gravity of segments 1, 2",
                                h8 + 3)))
      << converted.All();
  EXPECT_FALSE(converted.Has("E0510")) << converted.All();  // the H.10 cards are read
  // A set member that is not a body segment is an error at its columns.
  const Converted bad = Convert(Join(deck_with_set("  1  2  1 99")));
  EXPECT_TRUE(bad.Has(fmt::format("deck.ain:{}:10-12: error[E0512]", h8 + 3))) << bad.All();
}

TEST(LegacyOutputs, ADeckEndingEarlyOrWithoutItsDummyCardIsWarned) {
  const Converted early = Convert(WithHCards(kPointCards));
  EXPECT_EQ(early.errors, 0) << early.All();
  EXPECT_TRUE(early.Has("warning[W0505]")) << early.All();
  EXPECT_TRUE(early.Has("the deck ends before card H.4")) << early.All();
  // Ending within H.4 to H.10 is a deck cut short, as ATB's end of file.
  const Converted cut = Convert(WithHCards(kPointCards + "     0\n     0\n     0\n"));
  EXPECT_TRUE(cut.Has("error[E0501]")) << cut.All();
  // H.2's dummy card left out: ATB takes H.3.a as the dummy, and the request it held is lost.
  const std::vector<std::string> deck =
      Lines(WithHCards("     2  0  5          0.          0.          0.     0\n"
                       "        0  3          0.          0.          0.     0\n"
                       "     0\n"
                       "     1  0  1          0.          0.          0.     0\n"
                       " 0\n"));
  const std::size_t h3 = LineStarting(deck, "# ---- H cards") + 4;
  const Converted lost = Convert(Join(deck));
  EXPECT_TRUE(lost.Has(fmt::format("deck.ain:{}:1-2: warning[W0503]", h3))) << lost.All();
}

TEST(LegacyOutputs, ListDirectedTwinReadsTheSameRequests) {
  const std::string h =
      " 0 0 0 0. 0. 0. 0 Card H.1.a\n 0 Card H.1.b\n 0 0 0 0. 0. 0. 0 Card H.2.a\n 0 Card H.2.b\n"
      " 0 0 0 0. 0. 0. 0 Card H.3.a\n 0 Card H.3.b\n"
      " 2 0 5 16 5 Card H.4.a\n 1 0 5 Card H.5.a\n 0 Card H.6.a\n 1 4 Card H.7.a\n 0 Card H.8.a\n"
      " 0 Card H.9.a\n 0 Card H.10.a\n";
  const Converted converted = Convert(WithHCards(h, "seated_occupant.lin"), "deck.lin");
  ASSERT_EQ(converted.errors, 0) << converted.All();
  EXPECT_NE(converted.text.find("angular_acceleration occupant.h expressed_in sled"),
            std::string::npos)
      << converted.text;
  EXPECT_NE(converted.text.find("angular_velocity occupant.h relative_to sled"), std::string::npos);
  EXPECT_NE(converted.text.find("joint_angle occupant."), std::string::npos);
}

}  // namespace
}  // namespace sled::lang::legacy
