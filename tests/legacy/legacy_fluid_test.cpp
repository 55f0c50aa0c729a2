// E.6, F.7 and F.9 (wind and water, lang/legacy/fluid_readers.cpp and map_fluids.cpp): the corpus
// deck tests/legacy/corpus/wind_and_water.ain converts to `wind` and `water` blocks with the
// warnings of docs/legacy.md, and each card that sled cannot express is refused at its columns,
// without a cascade from the cards after it.
#include <gtest/gtest.h>

#include <map>
#include <string>

#include <fmt/format.h>

#include "legacy_test_deck.h"
#include "runtime/forces/fluid_forces.h"
#include "sled/compile.h"

namespace sled::lang::legacy {
namespace {

std::string Corpus() {
  return ReadDeckFile(std::string(SLED_SOURCE_ROOT) + "/tests/legacy/corpus/wind_and_water.ain");
}

// The corpus deck with the line that starts with `from` replaced by `to` (and its line number).
std::pair<std::string, std::size_t> Replaced(const std::string& from, const std::string& to) {
  std::vector<std::string> lines = Lines(Corpus());
  const std::size_t line = LineStarting(lines, from);
  lines[line - 1] = to;
  return {Join(lines), line};
}

TEST(LegacyFluids, TheCorpusDeckBecomesAWindAndAWaterBlock) {
  const Converted converted = ConvertText(Corpus());
  ASSERT_EQ(converted.errors, 0) << converted.All();
  EXPECT_NE(converted.text.find("wind {"), std::string::npos) << converted.text;
  EXPECT_NE(converted.text.find("pressure = blast"), std::string::npos) << converted.text;
  EXPECT_NE(converted.text.find("drag = 0.8"), std::string::npos) << converted.text;
  EXPECT_NE(converted.text.find("water {"), std::string::npos) << converted.text;
  EXPECT_NE(converted.text.find("level = 10 in"), std::string::npos) << converted.text;
  EXPECT_NE(converted.text.find("density = 0.0361 lbf/in^3 / deck_g"), std::string::npos)
      << converted.text;
  const std::size_t f7 = LineStarting(Lines(Corpus()), "   1   1   3   1");
  EXPECT_TRUE(converted.Has(fmt::format("deck.ain:{}:13-16: warning[W0504]", f7)))
      << converted.All();
  EXPECT_TRUE(converted.Has("the water's forces are read as buoyancy")) << converted.All();
}

TEST(LegacyFluids, CardsThatNameOtherFunctionsBecomeWindsOfTheirOwn) {
  // LOWR's F.7.b card without the drag table (MWSEG(6) = 0, ATB's Cd = 1): a second wind, the
  // same blast, on LOWR alone; UPPR keeps the first (Cd 0.8). The compiled Model has one row per
  // ellipsoid with its wind's drag coefficient.
  const auto [deck, line] = Replaced("   2   2   3   1", "   2   2   3   1   3   0   0");
  const Converted converted = ConvertText(deck);
  ASSERT_EQ(converted.errors, 0) << converted.All();
  const std::size_t first = converted.text.find("wind {");
  ASSERT_NE(first, std::string::npos) << converted.text;
  const std::size_t second = converted.text.find("wind {", first + 1);
  ASSERT_NE(second, std::string::npos) << converted.text;
  EXPECT_NE(converted.text.find("drag = 0.8\n    segments = pair.uppr\n", first), std::string::npos)
      << converted.text;
  EXPECT_NE(converted.text.find("direction = (1, 0, 0)\n    segments = pair.lowr\n", second),
            std::string::npos)
      << converted.text;
  Compilation compiled = Compile(Source::Text(converted.text, "winds.sled"));
  ASSERT_TRUE(compiled.ok()) << compiled.Render();
  const runtime::FluidTable& fluids = compiled.model().fluids;
  std::map<std::string, double> drag;
  for (std::size_t row = 0; row < fluids.size(); ++row) {
    if (fluids.medium[row] != runtime::FluidTable::Medium::kWind) continue;
    drag[compiled.model().segment_name.at(static_cast<std::size_t>(fluids.segment[row]))] =
        fluids.drag[row];
  }
  EXPECT_EQ(drag, (std::map<std::string, double>{{"pair.uppr", 0.8}, {"pair.lowr", 1.0}}));
}

TEST(LegacyFluids, AWindGivenInAVehiclesFrameIsCarriedByIt) {
  // NSR 3, the sled (NSEG 2 + vehicle 1): WINDY turns the table's (FX, FY, FZ) from NSR's axes
  // (and takes V relative to NSR's velocity): the air is carried by the sled. NSR 1, a body
  // segment: carried by UPPR. In the Model, each wind row's carrier is that frame.
  std::vector<std::string> lines = Lines(Corpus());
  const std::size_t e6b = LineStarting(lines, "   3    BLAST") + 1;
  for (const auto& [nsr, kind] : {std::pair{3, runtime::FrameRef::Kind::kVehicle},
                                  std::pair{1, runtime::FrameRef::Kind::kSegment}}) {
    lines[e6b - 1] = fmt::format("{:12}{:12}{:12}{:12}{:12}", "0.", "0.", "0.", 0, nsr);
    const Converted converted = ConvertText(Join(lines));
    ASSERT_EQ(converted.errors, 0) << converted.All();
    EXPECT_NE(converted.text.find(nsr == 3 ? "carried_by = sled" : "carried_by = pair.uppr"),
              std::string::npos)
        << converted.text;
    Compilation compiled = Compile(Source::Text(converted.text, "carried.sled"));
    ASSERT_TRUE(compiled.ok()) << compiled.Render();
    const runtime::FluidTable& fluids = compiled.model().fluids;
    for (std::size_t row = 0; row < fluids.size(); ++row) {
      if (fluids.medium[row] != runtime::FluidTable::Medium::kWind) continue;
      EXPECT_EQ(fluids.carrier[row].kind, kind) << nsr;
      EXPECT_EQ(fluids.carrier[row].index, 0) << nsr;
    }
  }
}

TEST(LegacyFluids, BlockingEllipsoidsAreRefusedWithoutACascade) {
  const auto [deck, line] = Replaced("   1   1   3   1", "   1   1   3   1   3   4   1 1 1");
  const Converted converted = ConvertText(deck);
  EXPECT_TRUE(converted.Has(fmt::format("deck.ain:{}:25-28: error[E0507]", line)))
      << converted.All();
  EXPECT_EQ(converted.errors, 1) << converted.All();
}

TEST(LegacyFluids, AVelocityWindGivesTheAirsDensityAndWarnsOfThePerAxisLaw) {
  // Function 3 with RK 1.4, C 13397 in/s, PR 14.7 psi, NSV 1 (and no table): rho = 1.4 * 14.7 /
  // 13397^2 lbf*s^2/in^4.
  std::vector<std::string> lines = Lines(Corpus());
  const std::size_t line = LineStarting(lines, "   3    BLAST") + 1;
  lines[line - 1] = "         1.4      13397.        14.7           1           0";
  lines.erase(lines.begin() + static_cast<std::ptrdiff_t>(line),
              lines.begin() + static_cast<std::ptrdiff_t>(line + 3));
  const Converted converted = ConvertText(Join(lines));
  ASSERT_EQ(converted.errors, 0) << converted.All();
  EXPECT_NE(converted.text.find("speed = 0 in/s"), std::string::npos) << converted.text;
  EXPECT_NE(converted.text.find("lbf*s^2/in^4"), std::string::npos) << converted.text;
  EXPECT_TRUE(converted.Has(fmt::format("deck.ain:{}:37-48: warning[W0504]", line)))
      << converted.All();
  EXPECT_TRUE(converted.Has("70.7 %")) << converted.All();
}

TEST(LegacyFluids, WhatStillWaterCannotHoldIsRefusedAtItsColumns) {
  {  // a flotation device: its cards' layout is not in the reference
    const auto [deck, line] = Replaced("    2    0  0.5", "    2    1  0.5   0.    0.");
    const Converted converted = ConvertText(deck);
    EXPECT_TRUE(converted.Has(fmt::format("deck.ain:{}:6-10: error[E0507]", line)))
        << converted.All();
  }
  {  // lift
    const auto [deck, line] = Replaced("    2    2  0.5", "    2    2  0.5   0.3    0.");
    const Converted converted = ConvertText(deck);
    EXPECT_TRUE(converted.Has(fmt::format("deck.ain:{}:17-22: error[E0507]", line)))
        << converted.All();
  }
  {  // NEBODY not among the ellipsoids in the water (ATB's STOP 597)
    const auto [deck, line] =
        Replaced("    1    1        0.", "    1    1        0.        0.        0.    7");
    const Converted converted = ConvertText(deck);
    EXPECT_TRUE(converted.Has(fmt::format("deck.ain:{}:41-45: error[E0512]", line)))
        << converted.All();
  }
  {  // a regular wave
    std::vector<std::string> lines = Lines(Corpus());
    const std::size_t b = LineStarting(lines, "    0        0.        0.");
    lines[b - 1] = "    1        0.        0.";
    lines.insert(lines.begin() + static_cast<std::ptrdiff_t>(b),
                 "      100.        2.        0.        0.");
    const Converted converted = ConvertText(Join(lines));
    EXPECT_TRUE(converted.Has(fmt::format("deck.ain:{}:1-40: error[E0507]", b + 1)))
        << converted.All();
  }
}

}  // namespace
}  // namespace sled::lang::legacy
