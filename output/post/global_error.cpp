#include "output/post/global_error.h"

#include <cmath>

#include <fmt/format.h>

#include "output/post/injury_criteria.h"
#include "output/post/series_error.h"
#include "runtime/integrate/ode.h"

namespace sled::runtime::post {

double ErrorFromCompanion(const Model& model, const TimeSeries& run,
                          const std::vector<CriterionValue>& run_criteria,
                          const TimeSeries& companion,
                          const std::vector<CriterionValue>& companion_criteria) {
  const SeriesError difference =
      CompareSeries(model, run, run_criteria, companion, companion_criteria);
  if (!(difference.overall >= 0) || difference.rows != run.rows()) return -1.0;
  return difference.overall / (1.0 - 1.0 / kCompanionRatio);
}

GlobalErrorEstimate EstimateGlobalError(const Model& model, const TimeSeries& run,
                                        const std::vector<CriterionValue>& criteria) {
  GlobalErrorEstimate estimate;
  Model companion_model = model;
  companion_model.relative_tolerance = model.relative_tolerance / kCompanionRatio;
  companion_model.absolute_tolerance = model.absolute_tolerance / kCompanionRatio;
  if (companion_model.relative_tolerance < kMinRelativeTolerance) {
    estimate.reason = fmt::format(
        "the companion run would need a tolerance of {:.1e}, below the {:.1e} doubles can meet",
        companion_model.relative_tolerance, kMinRelativeTolerance);
    return estimate;
  }
  Data data = MakeData(companion_model);
  TimeSeries companion;
  const RunSummary summary = Run(companion_model, data, companion);
  estimate.wall_seconds = summary.wall_seconds;
  if (summary.failed) {
    estimate.reason = fmt::format("the companion run at a tolerance of {:.1e} failed at t = {} s",
                                  companion_model.relative_tolerance, summary.failure.time);
    return estimate;
  }
  const double value = ErrorFromCompanion(model, run, criteria, companion,
                                          EvaluateCriteria(companion_model, companion));
  if (value < 0) {
    estimate.reason = "the run and its companion have different rows";
    return estimate;
  }
  estimate.computed = true;
  estimate.overall = value;
  return estimate;
}

}  // namespace sled::runtime::post
