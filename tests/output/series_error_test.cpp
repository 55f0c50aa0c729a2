// The measures `sled study` reports (output/post/series_error.h), on hand-made series whose
// deviations are known.
#include <gtest/gtest.h>

#include "output/post/series_error.h"

namespace sled::runtime::post {
namespace {

// Two output groups of three channels each: a position and an acceleration.
Model TwoGroups() {
  Model model;
  model.output_kind = {Model::OutputKind::kPosition, Model::OutputKind::kAcceleration};
  model.output_index = {0, 0};
  return model;
}

TimeSeries Series(const std::vector<std::vector<double>>& rows) {
  TimeSeries series;
  series.columns = rows.front().size();
  for (const auto& row : rows) series.values.insert(series.values.end(), row.begin(), row.end());
  return series;
}

TEST(SeriesError, DeviationsCountAgainstTheLargestRangeOfTheirKind) {
  const Model model = TwoGroups();
  // time, position x y z, acceleration x y z
  const TimeSeries reference = Series({{0, 0, 0, 0, 0, 0, 0},  //
                                       {1, 2, 0.1, 0, 10, 0, 0},
                                       {2, 4, 0.2, 0, 20, 0, 0}});
  const TimeSeries run = Series({{0, 0, 0, 0, 0, 0, 0},  //
                                 {1, 2, 0.2, 0, 10, 0, 0},
                                 {2, 4, 0.2, 0, 19, 0, 0}});
  std::vector<CriterionValue> got(1), expected(1);
  got[0].computed = expected[0].computed = true;
  got[0].value = 110;
  expected[0].value = 100;
  const SeriesError error = CompareSeries(model, run, got, reference, expected);
  EXPECT_EQ(error.rows, 3u);
  // Position y is off by 0.1 against the positions' largest range, 4 (x), not its own 0.2.
  EXPECT_DOUBLE_EQ(error.position, 0.1 / 4);
  // Acceleration x is off by 1 of 20, and its peak is 19 instead of 20.
  EXPECT_DOUBLE_EQ(error.overall, 1.0 / 20);
  EXPECT_DOUBLE_EQ(error.peak_acceleration, 1.0 / 20);
  EXPECT_DOUBLE_EQ(error.criteria, 0.1);
}

TEST(SeriesError, AShortRunIsComparedOnItsRowsAndNonFiniteValuesCountAsInfinite) {
  const Model model = TwoGroups();
  const TimeSeries reference = Series({{0, 0, 0, 0, 0, 0, 0}, {1, 1, 1, 1, 1, 1, 1}});
  const TimeSeries run = Series({{0, 0, 0, 0, std::nan(""), 0, 0}});
  const SeriesError error = CompareSeries(model, run, {}, reference, {});
  EXPECT_EQ(error.rows, 1u);
  EXPECT_TRUE(std::isinf(error.overall));
  EXPECT_EQ(error.criteria, -1.0);  // nothing to compare
}

}  // namespace
}  // namespace sled::runtime::post
