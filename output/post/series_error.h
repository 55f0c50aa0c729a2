// How far a run's outputs are from a reference run of the same scene (the same output times):
// the measures `sled study` puts against run time (docs/numerics.md). Each is relative, so
// channels of different units compare: a channel's largest deviation over the largest range of
// the reference's channels of its kind, a peak against the reference's peak, a criterion against
// the reference's value. Contact points are left out: they jump from zero to where the surfaces
// meet, so a first touch one row earlier moves them by their whole range.
#pragma once

#include <vector>

#include "output/post/criterion_value.h"
#include "runtime/model/model.h"
#include "runtime/run/time_series.h"

namespace sled::runtime::post {

struct SeriesError {
  double overall = 0.0;             // largest deviation of any channel over its range
  double position = -1.0;           // the same over position channels; -1: the scene has none
  double peak_acceleration = -1.0;  // largest relative error of an acceleration channel's peak
  double criteria = -1.0;           // largest relative error of a computed criterion
  std::size_t rows = 0;             // rows compared (fewer than the reference's after a failure)
};

SeriesError CompareSeries(const Model& model, const TimeSeries& run,
                          const std::vector<CriterionValue>& run_criteria,
                          const TimeSeries& reference,
                          const std::vector<CriterionValue>& reference_criteria);

}  // namespace sled::runtime::post
