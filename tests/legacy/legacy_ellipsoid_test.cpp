// D.5 ellipsoids beyond the body's (a vehicle's own, NSEG < M <= NVEH, and extra ones, M at or
// above NGRND) and the F.3.b contacts that place them: MS_SEG(1) and MS_SEG(3) name the
// ellipsoids of the card's segment and of the other frame, which may be a vehicle segment. The
// deck is the corpus pedestrian (15 segments, the car 16, NGRND 17) with cards added.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <string>
#include <vector>

#include "tests/legacy/legacy_test_deck.h"

namespace sled::lang::legacy {
namespace {

using namespace deck_testing;  // NOLINT: the deck helpers

// The pedestrian with NELP ellipsoids `d5` after its planes, and `f3` added to the F.3.b cards of
// segments 6 and 7 (one each).
std::string Pedestrian(int nelp, const std::vector<std::string>& d5,
                       const std::vector<std::string>& f3) {
  std::vector<std::string> lines = Lines(ReadDeckFile(kLegacyDir + "pedestrian.ain"));
  const std::size_t d1 = LineStarting(lines, "# ---- D cards");  // 1-based: D.1 is next
  lines[d1].replace(18, 6, fmt::format("{:6}", nelp));
  const std::size_t d7 = LineStarting(lines, "# D.7");
  lines.insert(lines.begin() + static_cast<std::ptrdiff_t>(d7 - 1), d5.begin(), d5.end());
  const std::size_t f3a = LineStarting(lines, "   0   0   0   0   0   1   1");
  lines[f3a - 1] = "   0   0   0   0   0   2   2   0   0   0   0   0   0   0   0";
  lines.insert(lines.begin() + static_cast<std::ptrdiff_t>(f3a + 1), f3[1]);
  lines.insert(lines.begin() + static_cast<std::ptrdiff_t>(f3a), f3[0]);
  return Join(lines);
}

TEST(LegacyEllipsoids, ContactsWithAVehiclesOwnAndExtraEllipsoidsConvert) {
  const std::string deck =
      Pedestrian(2,
                 {"    16    4.    4.    4.  -30.    0.  -30.",
                  "    17    3.    3.    3.  -40.    0.  -20.    0.    0.    0.  4.  4.  4."},
                 {"   6   0  16   0   6   0   0   0   8       0",
                  "   7   0  16  17   6   0   0   0   8       1"});
  const Converted converted = ConvertText(deck);
  ASSERT_EQ(converted.errors, 0) << converted.All();
  const std::string& t = converted.text;
  for (const char* expected :
       {"ellipsoid car_ellipsoid on car", "ellipsoid car_ellipsoid_17 on car",
        "with car_ellipsoid {", "with car_ellipsoid_17 {", "degree = 4"}) {
    EXPECT_NE(t.find(expected), std::string::npos) << expected << "\n" << t;
  }
  EXPECT_NE(t.find("contact_force"), std::string::npos);
}

TEST(LegacyEllipsoids, UnplacedExtrasWarnAndBadNumbersAreLocated) {
  // 17 is named by no F.3.b card; the segment-6 card names vehicle 16, which has no ellipsoid,
  // and the segment-7 card an ellipsoid 30 that no D.5 card defines.
  const std::string deck = Pedestrian(1, {"    17    3.    3.    3.    0.    0.    0."},
                                      {"   6   0  16   0   6   0   0   0   8       0",
                                       "   7   0   9  30   6   0   0   0   8       0"});
  const std::vector<std::string> lines = Lines(deck);
  const std::size_t d5 = LineStarting(lines, "    17");
  const Converted converted = ConvertText(deck);
  EXPECT_TRUE(converted.Has(fmt::format("deck.ain:{}:1-6: warning[W0503]", d5))) << converted.All();
  EXPECT_TRUE(converted.Has("vehicle segment 16 has no ellipsoid")) << converted.All();
  EXPECT_TRUE(converted.Has("ellipsoid 30 is neither segment 9's own")) << converted.All();
  // An airbag's number on D.5 is what ATB stops on: E0512 at M.
  const Converted airbag_range =
      ConvertText(Pedestrian(1, {"    81    3.    3.    3."},
                             {"   6   0   9   0   6   0   0   0   8       0",
                              "   7   0  10   0   6   0   0   0   8       0"}));
  EXPECT_TRUE(airbag_range.Has("error[E0512]")) << airbag_range.All();
  EXPECT_TRUE(airbag_range.Has("STOP 63")) << airbag_range.All();
}

}  // namespace
}  // namespace sled::lang::legacy
