#include "output/post/series_error.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "runtime/run/outputs.h"

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
  // Each channel's kind and its reference's range; a deviation counts against the largest range
  // among the channels of its kind (all contact forces, all accelerations, ...), so a contact
  // that barely touches in the reference does not make a tiny range the measure.
  std::vector<Model::OutputKind> kinds(reference.columns, Model::OutputKind::kPosition);
  std::vector<double> ranges(reference.columns, 0.0);
  std::map<Model::OutputKind, double> kind_range;
  std::size_t column = 1;  // after the time
  for (std::size_t group = 0; group < model.output_kind.size(); ++group) {
    const std::size_t count = ChannelCount(model, group);
    for (std::size_t c = column; c < column + count && c < reference.columns; ++c) {
      double low = Value(reference, 0, c), high = low;
      for (std::size_t row = 0; row < error.rows; ++row) {
        low = std::min(low, Value(reference, row, c));
        high = std::max(high, Value(reference, row, c));
      }
      kinds[c] = model.output_kind[group];
      ranges[c] = high - low;
      kind_range[kinds[c]] = std::max(kind_range[kinds[c]], ranges[c]);
    }
    column += count;
  }
  for (std::size_t c = 1; c < column && c < reference.columns; ++c) {
    // A contact point is zero while apart and jumps to where the surfaces meet: one row's shift
    // of the first touch moves it by its whole range. The contact's force and deflection, which
    // start from zero, carry its accuracy instead.
    if (kinds[c] == Model::OutputKind::kContactPoint) continue;
    double deviation = 0.0, run_peak = 0.0, reference_peak = 0.0;
    for (std::size_t row = 0; row < error.rows; ++row) {
      const double expected = Value(reference, row, c), got = Value(run, row, c);
      deviation = std::max(deviation, std::abs(got - expected));
      if (!std::isfinite(got)) deviation = std::numeric_limits<double>::infinity();
      run_peak = std::max(run_peak, std::abs(got));
      reference_peak = std::max(reference_peak, std::abs(expected));
    }
    // A kind whose channels are all constant: measured absolutely.
    const double range = kind_range[kinds[c]] > 0 ? kind_range[kinds[c]] : 1.0;
    Raise(error.overall, deviation / range);
    if (kinds[c] == Model::OutputKind::kPosition) Raise(error.position, deviation / range);
    if (kinds[c] == Model::OutputKind::kAcceleration && reference_peak > 0) {
      Raise(error.peak_acceleration, std::abs(run_peak - reference_peak) / reference_peak);
    }
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
