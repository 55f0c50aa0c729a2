// A D.6 fixed distance (KQTYPE 2) between two segments of one body, under a lap belt: the corpus
// deck belt_and_constraint.ain with its constraint moved from the sled to the upper segment.
// With the two points on one line with the hip joint the distance is the largest the joint
// allows, and the run used to fail at the minimum step at 1.76 ms, blaming the lower segment's
// velocity; it is now refused at the start, naming the constraint. Off that line the constraint
// is regular: it holds its distance through the run and the energy balance closes.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "legacy_test_deck.h"
#include "runtime/dynamics/constraints.h"
#include "sled/compile.h"
#include "sled/simulate.h"

namespace sled::lang::legacy {
namespace {

constexpr double kInch = 0.0254;

// The corpus deck with its D.6 card (KQTYPE 2, KQ1, KQ2, RK1, RK2) replaced by `d6`.
std::string DeckWithConstraint(const std::string& d6) {
  std::string deck =
      ReadDeckFile(std::string(SLED_SOURCE_ROOT) + "/tests/legacy/corpus/belt_and_constraint.ain");
  const std::string old_d6 = "     2     1     3    0.    0.    0.    0.    0.  -20.";
  const std::size_t at = deck.find(old_d6);
  EXPECT_NE(at, std::string::npos);
  if (at != std::string::npos) deck.replace(at, old_d6.size(), d6);
  return deck;
}

// The distance between the constraint's two points at every output row.
class DistanceSink : public RunSink {
 public:
  void OnRow(const runtime::Model& /*model*/, const runtime::Data& data) override {
    if (!data.constraints) return;
    const double d = (data.constraints->point_first[0] - data.constraints->point_second[0]).norm();
    smallest = std::min(smallest, d);
    largest = std::max(largest, d);
    ++rows;
  }
  double smallest = 1e300, largest = 0;
  int rows = 0;
};

RunResult RunDeck(const std::string& deck, DistanceSink* sink) {
  const Converted converted = ConvertText(deck);
  EXPECT_EQ(converted.errors, 0) << converted.All();
  Compilation compiled = Compile(Source::Text(converted.text, "constraint.sled"));
  EXPECT_TRUE(compiled.ok()) << compiled.Render() << converted.text;
  if (!compiled.ok()) return {};
  return Simulate(compiled.model(), {}, {sink});
}

TEST(LegacyConstraintRun, ADistanceOnTheJointsLineIsRefusedAtTheStartNamingTheConstraint) {
  // UPPR's centre and LOWR's centre: 6 in above and 8 in below the hip, on one line with it.
  DistanceSink sink;
  const RunResult run =
      RunDeck(DeckWithConstraint("     2     1     2    0.    0.    0.    0.    0.    0."), &sink);
  ASSERT_TRUE(run.failed());
  EXPECT_EQ(run.summary.end_time, 0.0);
  EXPECT_EQ(run.summary.failure.where, "constraint_1");
  EXPECT_NE(run.summary.failure.cause.find("one line with the centres of the joints"),
            std::string::npos)
      << run.summary.failure.cause;
}

TEST(LegacyConstraintRun, ADistanceOffTheJointsLineHoldsAndTheEnergyBalanceCloses) {
  // RK1 = (3, 0, 0) in on UPPR, RK2 = LOWR's centre: at the start (both segments upright, the
  // hip straight) the distance is sqrt(3^2 + (6 + 8)^2) in = sqrt(205) in, held through the
  // 20 ms while the belt pushes LOWR back.
  DistanceSink sink;
  const RunResult run =
      RunDeck(DeckWithConstraint("     2     1     2    3.    0.    0.    0.    0.    0."), &sink);
  ASSERT_FALSE(run.failed()) << run.summary.failure.cause;
  EXPECT_TRUE(run.summary.complete());
  const double distance = std::sqrt(205.0) * kInch;
  EXPECT_EQ(sink.rows, 21);
  EXPECT_NEAR(sink.smallest, distance, 1e-9);
  EXPECT_NEAR(sink.largest, distance, 1e-9);
  // The belt does work on the body: the balance is measured against a non-trivial scale.
  EXPECT_GT(run.summary.energy.scale, 1.0);
  EXPECT_LT(run.summary.energy.relative(), 1e-6) << run.summary.energy.largest_residual;
}

}  // namespace
}  // namespace sled::lang::legacy
