// C.2.a MSEG and IVFLG/IVREF: a C card whose MSEG is body segment 1 converts to a vehicle of the
// card's motion and a weld of the segment to it, and the run moves the segment exactly along the
// half-sine's closed form; a further vehicle segment (MSEG = NSEG + 1) is a vehicle, given
// relative to the ground with IVFLG 2 and IVREF 0 as with IVFLG 0; what ATB rejects is E0512
// at its columns and what sled cannot express E0507. (The deck's .lin twin and its values are
// checked with the corpus, legacy_corpus_decks_test.cpp.)
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "legacy_test_deck.h"
#include "runtime/model/data.h"
#include "sled/compile.h"
#include "sled/simulate.h"

namespace sled::lang::legacy {
namespace {

using deck_testing::Converted;
using deck_testing::ConvertText;
using deck_testing::ReadDeckFile;

constexpr double kInch = 0.0254, kMph = 0.44704;

std::string Corpus() {
  return ReadDeckFile(std::string(SLED_SOURCE_ROOT) +
                      "/tests/legacy/corpus/prescribed_segment.ain");
}

// The corpus deck with its first C.2.a card (MSEG 1) replaced by `card`.
std::string WithSeatCard(const std::string& card) {
  std::string deck = Corpus();
  const std::string old_card =
      "    0.    0.    0.   20.   0.1    0.    0.  -10.     0    0.    0. 0 0 1";
  const std::size_t at = deck.find(old_card);
  EXPECT_NE(at, std::string::npos);
  if (at != std::string::npos) deck.replace(at, old_card.size(), card);
  return deck;
}

// UPPR's centre of mass at every output row.
class SeatSink : public RunSink {
 public:
  void OnRow(const runtime::Model& /*model*/, const runtime::Data& data) override {
    time.push_back(data.time);
    com.push_back(data.position[0]);
  }
  std::vector<double> time;
  std::vector<runtime::Vec3> com;
};

TEST(LegacyPrescribedSegment, MsegOneWeldsTheSegmentToAVehicleOfTheCardsMotion) {
  const Converted converted = ConvertText(Corpus());
  ASSERT_EQ(converted.errors, 0) << converted.All();
  EXPECT_NE(converted.text.find("constraint uppr_prescribed : welded(seat -> pair.uppr)"),
            std::string::npos)
      << converted.text;
  EXPECT_NE(converted.text.find("vehicle cart"), std::string::npos) << converted.text;
  EXPECT_TRUE(converted.Has("warning[W0501]: card C.2.a (vehicle 1), columns 71-72: MSEG is 1"))
      << converted.All();

  Compilation compiled = Compile(Source::Text(converted.text, "prescribed.sled"));
  ASSERT_TRUE(compiled.ok()) << compiled.Render() << converted.text;
  SeatSink sink;
  const RunResult run = Simulate(compiled.model(), {}, {&sink});
  ASSERT_FALSE(run.failed()) << run.summary.failure.cause;
  ASSERT_GT(sink.time.size(), 10u);
  // X0 = (0, 0, -10) in, 20 mph along x, a half-sine of 20 mph over 0.1 s along -x:
  // x(t) = v0 t - A/w (t - sin(w t) / w), A = pi dv / (2 T), w = pi / T.
  const double v0 = 20 * kMph, duration = 0.1, w = std::numbers::pi / duration;
  const double peak = std::numbers::pi * v0 / (2 * duration);
  for (std::size_t row = 0; row < sink.time.size(); ++row) {
    const double t = sink.time[row];
    const double x = v0 * t - peak / w * (t - std::sin(w * t) / w);
    EXPECT_NEAR(sink.com[row].x(), x, 1e-9) << "t = " << t;
    EXPECT_NEAR(sink.com[row].y(), 0.0, 1e-12);
    EXPECT_NEAR(sink.com[row].z(), -10 * kInch, 1e-12);
  }
}

TEST(LegacyPrescribedSegment, InvalidAndInexpressibleReferencesAreLocated) {
  // The seat card's last three fields (IVFLG, IVREF, MSEG in 67-72) and what each gives.
  const std::string fields = "    0.    0.    0.   20.   0.1    0.    0.  -10.     0    0.    0.";
  const std::vector<std::pair<std::string, std::string>> cases = {
      // ATB rejects: IVFLG outside -2 to 2 (STOP 263), IVREF without IVFLG (STOP 266), MSEG out
      // of order (STOP 6).
      {" 3 0 1", "error[E0512]: card C.2.a (vehicle 1), columns 67-68: IVFLG is 3"},
      {" 0 4 1", "error[E0512]: card C.2.a (vehicle 1), columns 69-70: IVREF is 4 with IVFLG 0"},
      {" 0 0 4",
       "columns 71-72: MSEG is 4 (help: a vehicle segment takes the next number, 3 "
       "(ATB: STOP 6))"},
      // Refused: motion relative to a segment, the ground seen from the vehicle, and a jointed
      // segment (LOWR hangs from the hip).
      {" 2 4 1", "error[E0507]: card C.2.a (vehicle 1), columns 67-70: IVFLG 2 with IVREF 4"},
      {"-1 0 1", "error[E0507]: card C.2.a (vehicle 1), columns 67-68: IVFLG -1"},
      {" 0 0 2",
       "error[E0507]: card C.2.a (vehicle 1), columns 71-72: MSEG is 2: segment 2 "
       "hangs from joint 1"},
  };
  // Segment 1 prescribed twice: the cart's card (line 28) given MSEG 1 too.
  {
    std::string deck = Corpus();
    const std::string cart = " 2 0 3\nSLED AT 20 MPH";
    ASSERT_NE(deck.find(cart), std::string::npos);
    deck.replace(deck.find(cart), cart.size(), " 0 0 1\nSLED AT 20 MPH");
    const Converted c = ConvertText(deck);
    EXPECT_TRUE(
        c.Has("error[E0507]: card C.2.a (vehicle 2), columns 71-72: MSEG is 1: segment 1 "
              "is prescribed by the C card of line 26 too"))
        << c.All();
  }
  for (const auto& [flags, expected] : cases) {
    const Converted c = ConvertText(WithSeatCard(fields + flags));
    EXPECT_TRUE(c.Has(expected)) << flags << "\n" << c.All();
  }
}

TEST(LegacyPrescribedSegment, AConstraintBetweenThePrescribedSegmentAndAVehicleIsRejected) {
  // D.1.a with NQ = 1, and a D.6 fixed point between segment 1 (prescribed by MSEG 1) and
  // segment 4 (SLED, the primary vehicle: NSEG 2 + the second vehicle segment).
  std::string deck = Corpus();
  const std::string d1 = "     1     0     0     0     0     1     0     0     0     0     0     0";
  const std::string p3 = "         50.        -50.         20.\n";
  ASSERT_NE(deck.find(d1), std::string::npos);
  ASSERT_NE(deck.find(p3), std::string::npos);
  deck.replace(deck.find(d1), d1.size(),
               "     1     0     0     0     1     1     0     0     0     0     0     0");
  deck.insert(deck.find(p3) + p3.size(),
              "     1     1     4    0.    0.    0.    0.    0.    0.\n");
  const Converted c = ConvertText(deck);
  EXPECT_TRUE(
      c.Has("error[E0512]: card D.6 (constraint 1), columns 7-18: both KQ1 and KQ2 have "
            "prescribed motion"))
      << c.All();
}

}  // namespace
}  // namespace sled::lang::legacy
