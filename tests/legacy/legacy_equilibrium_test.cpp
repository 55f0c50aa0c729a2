// G.1.a I1 = 15, ATB's equilibrium run (EQUILB), solved at conversion for G.5 position
// variables with given forces: the corpus deck equilibrium.ain moves a 100 lb block's z until
// its floor force 500 d + 1000 d^2 lb is 100 lb (corpus .expect: the position from the quadratic's
// root). Here the converted run is checked against that hand computation from the other side:
// at the start the runtime's contact force is the block's weight and the block stays at rest.
// What the conversion cannot solve is refused at its card.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include <fmt/format.h>

#include "legacy_test_deck.h"
#include "sled/compile.h"
#include "sled/simulate.h"

namespace sled::lang::legacy {
namespace {

using deck_testing::Converted;
using deck_testing::ConvertText;
using deck_testing::Join;
using deck_testing::Lines;
using deck_testing::LineStarting;
using deck_testing::ReadDeckFile;

constexpr double kPound = 4.4482216152605;  // lbf in N
constexpr double kInch = 0.0254;

std::vector<std::string> CorpusDeck() {
  return Lines(
      ReadDeckFile(std::string(SLED_SOURCE_ROOT) + "/tests/legacy/corpus/equilibrium.ain"));
}

// The floor's normal force on the block and the block's height at every output row.
class FloorSink : public RunSink {
 public:
  void OnRow(const runtime::Model& model, const runtime::Data& data) override {
    force.push_back(data.contacts.normal_force.at(0));
    height.push_back(data.q.at(static_cast<std::size_t>(model.q_address.at(0)) + 2));
  }
  std::vector<double> force, height;
};

TEST(LegacyEquilibrium, TheSolvedBlockStartsWithItsWeightOnTheFloorAndStaysThere) {
  const Converted converted = ConvertText(Join(CorpusDeck()), {}, "equilibrium.ain");
  ASSERT_EQ(converted.errors, 0) << converted.All();
  EXPECT_NE(converted.text.find("G.1.a I1 = 15 (EQUILB)"), std::string::npos) << converted.text;
  Compilation compiled = Compile(Source::Text(converted.text, "equilibrium.sled"));
  ASSERT_TRUE(compiled.ok()) << compiled.Render() << converted.text;
  FloorSink sink;
  const RunResult result = Simulate(compiled.model(), {}, {&sink});
  ASSERT_FALSE(result.summary.failed) << converted.text;
  ASSERT_GT(sink.force.size(), 10u);
  // The weight: 100 lb, as A.3's G and the block's weight make it (m g = W).
  const double weight = 100 * kPound;
  EXPECT_NEAR(sink.force.front(), weight, 1e-9 * weight);
  const double z = (15 + (-500 + std::sqrt(650000.0)) / 2000) * kInch;
  for (std::size_t row = 0; row < sink.height.size(); ++row) {
    EXPECT_NEAR(sink.height[row], z, 1e-9) << row;  // at rest: no sinking, no bounce
    EXPECT_NEAR(sink.force[row], weight, 1e-6 * weight) << row;
  }
}

// NTV 2: the block's sphere 10 in along its x from its centre of gravity, pitched (G.3.a,
// about y) until the floor's force is its weight. Pitching by a turns the sphere's centre to
// z = 10 in - 10 in sin(a) (the G.2 z is 10 in), so d = z - 15 in = -5 in - 10 in sin(a) and
// a = asin(-(5 in + d) / 10 in), d the penetration of 100 lb (the corpus deck's).
TEST(LegacyEquilibrium, APitchVariableTurnsTheSegmentUntilItsForceIsGx) {
  std::vector<std::string> lines = CorpusDeck();
  const std::size_t blok = LineStarting(lines, "BLOK");
  lines[blok - 1].replace(48, 6, "   10.");
  const std::size_t g5 = LineStarting(lines, "   1   3   1");
  lines[g5 - 1] = "   2   2   1    100.      1.   1   1   0";
  const Converted converted = ConvertText(Join(lines), {}, "deck.ain");
  ASSERT_EQ(converted.errors, 0) << converted.All();
  EXPECT_NE(converted.text.find("turned its G.3.a pitch by"), std::string::npos) << converted.text;
  Compilation compiled = Compile(Source::Text(converted.text, "pitch.sled"));
  ASSERT_TRUE(compiled.ok()) << compiled.Render() << converted.text;
  const runtime::Model& model = compiled.model();
  const double d = (-500 + std::sqrt(650000.0)) / 2000;
  const double pitch = std::asin(-(5 + d) / 10);
  const auto q = static_cast<std::size_t>(model.q_address.at(0));
  EXPECT_NEAR(model.q0.at(q + 3), std::cos(pitch / 2), 1e-9);  // (w, x, y, z)
  EXPECT_NEAR(model.q0.at(q + 5), std::sin(pitch / 2), 1e-9);
  FloorSink sink;
  Simulate(model, {}, {&sink});
  ASSERT_FALSE(sink.force.empty());
  EXPECT_NEAR(sink.force.front(), 100 * kPound, 1e-9 * 100 * kPound);
}

// The corpus deck with `erase` cards from `line` (found by its start) replaced by `cards`.
Converted WithCard(const std::string& start, const std::vector<std::string>& cards,
                   std::size_t* line, std::ptrdiff_t erase = 1) {
  std::vector<std::string> lines = CorpusDeck();
  *line = LineStarting(lines, start);
  lines.erase(lines.begin() + static_cast<std::ptrdiff_t>(*line) - 1,
              lines.begin() + static_cast<std::ptrdiff_t>(*line) - 1 + erase);
  lines.insert(lines.begin() + static_cast<std::ptrdiff_t>(*line) - 1, cards.begin(), cards.end());
  return ConvertText(Join(lines), {}, "deck.ain");
}
Converted WithCard(const std::string& start, const std::string& card, std::size_t* line) {
  return WithCard(start, std::vector<std::string>{card}, line);
}

TEST(LegacyEquilibrium, WhatTheConversionCannotSolveIsRefusedAtItsCard) {
  std::size_t line = 0;
  // G.6 constraints, whose forces EQUILB takes for GX: refused at NCON. The G.6 card (plane 1,
  // segment 1, a rolling constraint, setting variable 1) follows the G.5 card.
  const Converted constraint = WithCard(
      "   1   0", {"   1   1", "   1   3   1    100.      1.   1   1   0", "   1   1   3   1"},
      &line, 2);
  EXPECT_EQ(constraint.errors, 1) << constraint.All();
  EXPECT_TRUE(constraint.Has(fmt::format("deck.ain:{}:5-8: error[E0507]", line)))
      << constraint.All();
  // A pitch (NTV 2) of the centred sphere, which does not change its reach: no solve.
  const Converted turn =
      WithCard("   1   3   1", "   2   2   1    100.      1.   1   1   0", &line);
  EXPECT_TRUE(turn.Has("error[E0507]: card G.4")) << turn.All();
  // 2000 lb: past the 1500 lb the function reaches at the end of its first part (|D1| = 1 in).
  const Converted heavy =
      WithCard("   1   3   1", "   1   3   1   2000.      1.   1   1   0", &line);
  EXPECT_TRUE(heavy.Has(fmt::format("deck.ain:{}:13-20: error[E0507]", line))) << heavy.All();
  // Moving x, along the floor: the force does not depend on it.
  const Converted along =
      WithCard("   1   3   1", "   1   1   1    100.      1.   1   1   0", &line);
  EXPECT_TRUE(along.Has("error[E0507]: card G.4")) << along.All();
  // The block 48 in along x: its footprint reaches the floor's edge at 50 in.
  const Converted edge =
      WithCard("        0.        0.       10.",
               "       48.        0.       10.        0.        0.        0.  0  0", &line);
  EXPECT_TRUE(edge.Has(":29-32: error[E0507]: card G.5")) << edge.All();
}

}  // namespace
}  // namespace sled::lang::legacy
