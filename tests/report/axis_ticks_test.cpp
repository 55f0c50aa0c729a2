// Axis ranges and ticks of the report's plots: round steps, ranges that start and end on a tick
// and hold the data, labels with the decimals the step needs.
#include "output/report/axis_ticks.h"

#include <cmath>
#include <limits>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace sled::report {
namespace {

using ::testing::ElementsAre;

TEST(NiceStep, RoundsUpToOneTwoOrFiveTimesAPowerOfTen) {
  EXPECT_DOUBLE_EQ(NiceStep(0.3), 0.5);
  EXPECT_DOUBLE_EQ(NiceStep(1.0), 1.0);
  EXPECT_DOUBLE_EQ(NiceStep(1.7), 2.0);
  EXPECT_DOUBLE_EQ(NiceStep(2.0), 2.0);
  EXPECT_DOUBLE_EQ(NiceStep(3.75), 5.0);
  EXPECT_DOUBLE_EQ(NiceStep(7.0), 10.0);
  EXPECT_DOUBLE_EQ(NiceStep(0.002), 0.002);
  EXPECT_DOUBLE_EQ(NiceStep(4200.0), 5000.0);
}

TEST(ChooseTicks, ThirtyMillisecondsInFives) {
  const AxisTicks ticks = ChooseTicks(0.0, 30.0, 8);
  EXPECT_DOUBLE_EQ(ticks.step, 5.0);
  EXPECT_DOUBLE_EQ(ticks.low, 0.0);
  EXPECT_DOUBLE_EQ(ticks.high, 30.0);
  EXPECT_THAT(ticks.values, ElementsAre(0, 5, 10, 15, 20, 25, 30));
  EXPECT_EQ(ticks.decimals, 0);
}

TEST(ChooseTicks, RangeGrowsOutwardToTicksAroundNegativeData) {
  // A head acceleration from -6.2 g to 0.47 g: (6.67 / 5) rounds up to a step of 2.
  const AxisTicks ticks = ChooseTicks(-6.2, 0.47, 5);
  EXPECT_DOUBLE_EQ(ticks.step, 2.0);
  EXPECT_DOUBLE_EQ(ticks.low, -8.0);
  EXPECT_DOUBLE_EQ(ticks.high, 2.0);
  EXPECT_THAT(ticks.values, ElementsAre(-8, -6, -4, -2, 0, 2));
}

TEST(ChooseTicks, SmallValuesGetTheDecimalsTheirStepNeeds) {
  const AxisTicks ticks = ChooseTicks(0.0012, 0.0087, 5);
  EXPECT_DOUBLE_EQ(ticks.step, 0.002);
  EXPECT_DOUBLE_EQ(ticks.low, 0.0);
  EXPECT_NEAR(ticks.high, 0.01, 1e-15);
  EXPECT_EQ(ticks.decimals, 3);
  ASSERT_EQ(ticks.values.size(), 6u);
  EXPECT_EQ(TickLabel(ticks.values[3], ticks.decimals), "0.006");
  // 0.1 + 0.2 is no multiple of 0.1 in binary; the ticks are.
  const AxisTicks tenths = ChooseTicks(0.0, 0.3, 3);
  EXPECT_EQ(tenths.values[3], 0.3);
}

TEST(ChooseTicks, EveryValueLiesInsideTheRange) {
  for (const auto& [low, high] : {std::pair{-1234.5, 98.7}, {3.3e-7, 9.1e-6}, {17.0, 17.5}}) {
    const AxisTicks ticks = ChooseTicks(low, high, 5);
    EXPECT_LE(ticks.low, low);
    EXPECT_GE(ticks.high, high);
    EXPECT_LE(ticks.values.size(), 12u) << low << " " << high;
    EXPECT_GE(ticks.values.size(), 3u) << low << " " << high;
  }
}

TEST(ChooseTicks, ConstantAndMissingDataStillGiveAnAxis) {
  const AxisTicks constant = ChooseTicks(3.0, 3.0, 5);
  EXPECT_LT(constant.low, 3.0);
  EXPECT_GT(constant.high, 3.0);
  const AxisTicks zero = ChooseTicks(0.0, 0.0, 5);
  EXPECT_LT(zero.low, 0.0);
  EXPECT_GT(zero.high, 0.0);
  const AxisTicks none = ChooseTicks(std::numeric_limits<double>::quiet_NaN(), 1.0, 5);
  EXPECT_DOUBLE_EQ(none.low, 0.0);
  EXPECT_DOUBLE_EQ(none.high, 1.0);
}

TEST(ValueRange, SkipsValuesThatAreNotFinite) {
  ValueRange range;
  EXPECT_TRUE(range.empty());
  const double values[] = {std::numeric_limits<double>::quiet_NaN(), 2.0, -1.0,
                           std::numeric_limits<double>::infinity()};
  range.Include(values);
  EXPECT_DOUBLE_EQ(range.low, -1.0);
  EXPECT_DOUBLE_EQ(range.high, 2.0);
}

TEST(TickLabel, NegativeZeroReadsZero) {
  EXPECT_EQ(TickLabel(-1e-17, 1), "0");
  EXPECT_EQ(TickLabel(-2.5, 1), "-2.5");
  EXPECT_EQ(TickLabel(10.0, 0), "10");
}

}  // namespace
}  // namespace sled::report
