// Sweep designs: the samplers against their defining properties and an independent
// implementation, and BuildDesign's grids, lists, units and combinations.
#include <algorithm>
#include <set>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "compiler/check/check.h"
#include "compiler/sweep/design.h"
#include "compiler/sweep/sampling.h"
#include "lang/diagnostics/render.h"

namespace sled::compiler {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;

// In every dimension, the n points fall one in each of the n strata [k/n, (k+1)/n).
void ExpectStratified(const std::vector<std::vector<double>>& points, int n, int d) {
  for (int j = 0; j < d; ++j) {
    std::set<int> strata;
    for (const auto& point : points) {
      const double u = point[static_cast<std::size_t>(j)];
      ASSERT_GE(u, 0.0);
      ASSERT_LT(u, 1.0);
      strata.insert(static_cast<int>(u * n));
    }
    EXPECT_EQ(static_cast<int>(strata.size()), n) << "dimension " << j;
  }
}

TEST(LatinHypercube, PutsOnePointInEachStratumOfEachDimension) {
  const auto points = LatinHypercube(37, 5, 7);
  ASSERT_EQ(points.size(), 37u);
  ExpectStratified(points, 37, 5);
}

TEST(LatinHypercube, TheSeedReproducesTheDesignAndAnotherSeedChangesIt) {
  EXPECT_EQ(LatinHypercube(16, 3, 42), LatinHypercube(16, 3, 42));
  EXPECT_NE(LatinHypercube(16, 3, 42), LatinHypercube(16, 3, 43));
}

TEST(SplitMix64, MatchesTheReferenceSequenceOfItsAuthors) {
  // The first outputs for seed 0 (Vigna's splitmix64.c).
  SplitMix64 random(0);
  EXPECT_EQ(random.Next(), 0xe220a8397b1dcdafULL);
  EXPECT_EQ(random.Next(), 0x6e789e6aa1b965f4ULL);
}

TEST(Sobol, MatchesAnIndependentImplementationInAllTwentyOneDimensions) {
  // scipy 1.10.1, qmc.Sobol(d=21, scramble=False).random(1024), rows 100 and 1023: the same
  // Joe–Kuo direction numbers, computed by other code.
  const std::vector<double> row100 = {
      0.4140625, 0.2578125, 0.7734375, 0.7265625, 0.8828125, 0.7421875, 0.0234375,
      0.4765625, 0.6328125, 0.6953125, 0.4609375, 0.6796875, 0.4765625, 0.8515625,
      0.3203125, 0.4921875, 0.6796875, 0.7421875, 0.8359375, 0.3359375, 0.7578125};
  const std::vector<double> row1023 = {
      0.0009765625, 0.7529296875, 0.6123046875, 0.1455078125, 0.1865234375, 0.4384765625,
      0.1396484375, 0.6181640625, 0.3447265625, 0.8505859375, 0.6787109375, 0.0361328125,
      0.1298828125, 0.6650390625, 0.3623046875, 0.4638671875, 0.3134765625, 0.8759765625,
      0.5849609375, 0.3193359375, 0.8662109375};
  const auto points = Sobol(1024, kMaxSobolDimensions, 0);
  EXPECT_EQ(points[100], row100);
  EXPECT_EQ(points[1023], row1023);
  EXPECT_EQ(points[0], std::vector<double>(21, 0.0));
}

TEST(Sobol, TheFirstPowerOfTwoPointsAreStratifiedWithOrWithoutAShift) {
  for (const std::uint64_t seed : {0ULL, 1ULL, 99ULL}) {
    const auto points = Sobol(64, 8, seed);
    ExpectStratified(points, 64, 8);
    // The first two dimensions form a (0, 6, 2)-net: one point in each 8 x 8 box.
    std::set<int> boxes;
    for (const auto& p : points)
      boxes.insert(static_cast<int>(p[0] * 8) * 8 + static_cast<int>(p[1] * 8));
    EXPECT_EQ(boxes.size(), 64u) << "seed " << seed;
  }
  EXPECT_NE(Sobol(8, 2, 1), Sobol(8, 2, 0));
}

// The scene the design tests vary.
constexpr const char* kScene = R"(scenario "design" {
  param speed = 56 km/h
  param slack = 5 mm
  param friction = 0.4
  param offset = (0, 0, 10) mm
  time { end = 100 ms  output_every = 1 ms }
  vehicle sled {
    motion = half_sine(delta_v = speed, duration = 100 ms, axis = -x)
  }
  let used = slack * friction
}
)";

struct Built {
  std::optional<Design> design;
  std::string diagnostics;
};

Built Build(const std::vector<std::string>& vary, Sampling sampling = Sampling::kNone,
            int samples = 0) {
  lang::SourceManager sources;
  lang::DiagnosticCollector collector;
  const lang::FileId file = sources.Add("scene.sled", kScene);
  CheckOptions options;
  options.diagnostics = &collector;
  options.lints = false;
  const CheckedScenario scene = ParseAndCheck(sources, file, options);
  EXPECT_FALSE(collector.has_errors());
  DesignRequest request;
  for (const std::string& text : vary) request.vary.push_back(sources.Add("--vary", text));
  request.sampling = sampling;
  request.samples = samples;
  Built built;
  built.design = BuildDesign(sources, request, scene, collector);
  for (const auto& d : collector.diagnostics())
    built.diagnostics += lang::RenderCompact(sources, d) + "\n";
  return built;
}

std::vector<double> Column(const Design& design, std::size_t variable) {
  std::vector<double> values;
  for (const auto& point : design.points) values.push_back(point[variable]);
  return values;
}

TEST(BuildDesign, AStepGridIncludesBothEnds) {
  const Built built = Build({"speed=40..64 km/h step 8"});
  ASSERT_TRUE(built.design) << built.diagnostics;
  EXPECT_THAT(Column(*built.design, 0), ElementsAre(40, 48, 56, 64));
  EXPECT_EQ(built.design->ValueText(1, 0), "48 km/h");
  EXPECT_EQ(built.design->variables[0].unit, "km/h");
}

TEST(BuildDesign, DecimalStepsGiveTheValuesAsWritten) {
  const Built built = Build({"friction=0..1 step 0.1"});
  ASSERT_TRUE(built.design) << built.diagnostics;
  ASSERT_EQ(built.design->points.size(), 11u);
  EXPECT_EQ(built.design->points[3][0], 0.3);  // not 0.30000000000000004
  EXPECT_EQ(built.design->points[10][0], 1.0);
}

TEST(BuildDesign, CountSpreadsEvenly) {
  const Built built = Build({"slack=0..10 mm count 5"});
  ASSERT_TRUE(built.design) << built.diagnostics;
  EXPECT_THAT(Column(*built.design, 0), ElementsAre(0, 2.5, 5, 7.5, 10));
}

TEST(BuildDesign, AListTakesTheLastUnitAndConvertsOthers) {
  const Built built = Build({"slack=0.002 m, 5, 8 mm"});
  ASSERT_TRUE(built.design) << built.diagnostics;
  EXPECT_THAT(Column(*built.design, 0), ElementsAre(2, 5, 8));
  EXPECT_EQ(built.design->variables[0].unit, "mm");
}

TEST(BuildDesign, SeveralVariesMakeEveryCombinationTheFirstSlowest) {
  const Built built = Build({"speed=40,50 km/h", "slack=0,5,10 mm"});
  ASSERT_TRUE(built.design) << built.diagnostics;
  ASSERT_EQ(built.design->points.size(), 6u);
  EXPECT_THAT(built.design->points[0], ElementsAre(40, 0));
  EXPECT_THAT(built.design->points[1], ElementsAre(40, 5));
  EXPECT_THAT(built.design->points[3], ElementsAre(50, 0));
}

TEST(BuildDesign, SampledRangesCombineWithTheGridInVaryOrder) {
  const Built built = Build({"speed=40..64 km/h", "slack=0,10 mm"}, Sampling::kLatinHypercube, 4);
  ASSERT_TRUE(built.design) << built.diagnostics;
  ASSERT_EQ(built.design->points.size(), 8u);
  for (const auto& point : built.design->points) {
    EXPECT_GE(point[0], 40);
    EXPECT_LT(point[0], 64);
  }
  EXPECT_EQ(built.design->points[0][1], 0);
  EXPECT_EQ(built.design->points[4][1], 10);
  EXPECT_EQ(built.design->method, "lhs");
}

TEST(BuildDesign, ValueTextReadsBackToTheSameNumber) {
  const Built built = Build({"speed=40..64 km/h"}, Sampling::kSobol, 8);
  ASSERT_TRUE(built.design) << built.diagnostics;
  for (std::size_t r = 0; r < built.design->points.size(); ++r) {
    const std::string text = built.design->ValueText(r, 0);
    EXPECT_EQ(std::stod(text), built.design->points[r][0]) << text;
  }
}

TEST(BuildDesign, ReportsEachKindOfBadDesign) {
  EXPECT_THAT(Build({"speed=40..64 km/h step -8"}).diagnostics, HasSubstr("E0604"));
  EXPECT_THAT(Build({"speed=40..64 km/h step 30"}).diagnostics, HasSubstr("E0604"));
  EXPECT_THAT(Build({"speed=40..40 km/h"}, Sampling::kLatinHypercube, 4).diagnostics,
              HasSubstr("E0604"));
  EXPECT_THAT(Build({"speed=40..64 km/h count 1"}).diagnostics, HasSubstr("E0604"));
  EXPECT_THAT(Build({"speed=40,48"}).diagnostics, HasSubstr("has no unit"));
  EXPECT_THAT(Build({"friction=0.1,0.2 mm"}).diagnostics, HasSubstr("E0603"));
  EXPECT_THAT(Build({"speed=40 km/h, 2 s"}).diagnostics, HasSubstr("E0603"));
  EXPECT_THAT(Build({"speed=40 kph"}).diagnostics, HasSubstr("E0301"));
  EXPECT_THAT(Build({"used=1,2 mm"}).diagnostics, HasSubstr("E0602"));
  EXPECT_THAT(Build({"offset=1,2 mm"}).diagnostics, HasSubstr("is a vector"));
  EXPECT_THAT(Build({"speed=40 km/h", "speed=50 km/h"}).diagnostics, HasSubstr("varied twice"));
  EXPECT_THAT(Build({"speed=40,48 km/h"}, Sampling::kSobol, 4).diagnostics, HasSubstr("E0605"));
  EXPECT_THAT(Build({"speed=0..1000 km/h step 0.001"}).diagnostics, HasSubstr("E0605"));
  EXPECT_THAT(Build({"speed 40 km/h"}).diagnostics, HasSubstr("E0601"));
  EXPECT_THAT(Build({"speed=40..64 km/h count 2.5"}).diagnostics, HasSubstr("E0601"));
  EXPECT_THAT(Build({"speed=40,"}).diagnostics, HasSubstr("E0601"));
}

}  // namespace
}  // namespace sled::compiler
