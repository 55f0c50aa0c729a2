// A run's global error, estimated rather than bounded: the same scene is run again with the same
// method at a tenth of its tolerances (the companion), and the estimate is the largest deviation
// of the run's channels from the companion's, over the largest range of their kind (the `all`
// measure of `sled study`, output/post/series_error.h), divided by 1 - 1/10. When the error is
// proportional to the tolerance, as the error control aims for, the companion's error is a tenth
// of the run's and this is the run's error; when it falls faster, the estimate is still within
// 1/0.9 of it. It is not a bound: an error the error control cannot see (a history that changes
// between steps) does not fall with the tolerance, and the estimate misses it.
#pragma once

#include <string>
#include <vector>

#include "output/post/criterion_value.h"
#include "runtime/run/run.h"

namespace sled::runtime::post {

// The companion's tolerances are the run's divided by this.
inline constexpr double kCompanionRatio = 10.0;

// The estimate from a companion run already at hand (same model and method, tolerances divided
// by kCompanionRatio); -1 when the runs cannot be compared.
double ErrorFromCompanion(const Model& model, const TimeSeries& run,
                          const std::vector<CriterionValue>& run_criteria,
                          const TimeSeries& companion,
                          const std::vector<CriterionValue>& companion_criteria);

struct GlobalErrorEstimate {
  bool computed = false;
  double overall = 0.0;       // of the channels' ranges, as SeriesError::overall
  std::string reason;         // why it was not computed
  double wall_seconds = 0.0;  // the companion run's
};

// Runs the companion of `model`'s run (which gave `run` and `criteria`) and compares.
GlobalErrorEstimate EstimateGlobalError(const Model& model, const TimeSeries& run,
                                        const std::vector<CriterionValue>& criteria);

}  // namespace sled::runtime::post
