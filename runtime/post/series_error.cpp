#include "runtime/post/series_error.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "runtime/outputs.h"

namespace sled::runtime::post {
namespace {

double Value(const TimeSeries& series, std::size_t row, std::size_t column) {
  return series.values[row * series.columns + column];
}

// The larger of a measure so far and a new value (-1 stands for "none yet").
void Raise(double& measure, double value) { measure = std::max(measure, value); }

}  // namespace

SeriesError CompareSeries(const Model& model, const TimeSeries& run,
                          const std::vector<CriterionValue>& run_criteria,
                          const TimeSeries& reference,
                          const std::vector<CriterionValue>& reference_criteria) {
  SeriesError error;
  error.rows = std::min(run.rows(), reference.rows());
  if (run.columns != reference.columns || error.rows == 0) {
    error.overall = std::numeric_limits<double>::quiet_NaN();
    return error;
  }
  std::size_t column = 1;  // after the time
  for (std::size_t group = 0; group < model.output_kind.size(); ++group) {
    const std::size_t count = ChannelCount(model, group);
    const Model::OutputKind kind = model.output_kind[group];
    for (std::size_t c = column; c < column + count && c < reference.columns; ++c) {
      double low = Value(reference, 0, c), high = low, deviation = 0.0;
      double run_peak = 0.0, reference_peak = 0.0;
      for (std::size_t row = 0; row < error.rows; ++row) {
        const double expected = Value(reference, row, c), got = Value(run, row, c);
        low = std::min(low, expected);
        high = std::max(high, expected);
        deviation = std::max(deviation, std::abs(got - expected));
        if (!std::isfinite(got)) deviation = std::numeric_limits<double>::infinity();
        run_peak = std::max(run_peak, std::abs(got));
        reference_peak = std::max(reference_peak, std::abs(expected));
      }
      // A constant channel: measured against its size, or absolutely when it is zero.
      const double range = high > low ? high - low : std::max(std::abs(high), 1.0);
      Raise(error.overall, deviation / range);
      if (kind == Model::OutputKind::kPosition) Raise(error.position, deviation / range);
      if (kind == Model::OutputKind::kAcceleration && reference_peak > 0) {
        Raise(error.peak_acceleration, std::abs(run_peak - reference_peak) / reference_peak);
      }
    }
    column += count;
  }
  for (std::size_t k = 0; k < std::min(run_criteria.size(), reference_criteria.size()); ++k) {
    const CriterionValue& got = run_criteria[k];
    const CriterionValue& expected = reference_criteria[k];
    if (!got.computed || !expected.computed || expected.value == 0) continue;
    Raise(error.criteria, std::abs(got.value - expected.value) / std::abs(expected.value));
  }
  return error;
}

}  // namespace sled::runtime::post
