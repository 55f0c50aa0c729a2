#include "runtime/run.h"

#include <chrono>
#include <cmath>

#include <fmt/format.h>

#include "runtime/dynamics.h"
#include "runtime/integrate/make_integrator.h"
#include "runtime/outputs.h"
#include "runtime/system.h"

namespace sled::runtime {
namespace {

void AppendRow(const Model& model, Data& data, TimeSeries& series) {
  const std::size_t start = series.values.size();
  series.values.resize(start + series.columns);  // reserved in advance: no reallocation
  series.values[start] = data.time;
  EvaluateChannels(model, data,
                   std::span<double>(series.values).subspan(start + 1, series.columns - 1));
}

}  // namespace

RunSummary Run(const Model& model, Data& data, TimeSeries& series, const RunOptions& options) {
  const auto wall_start = std::chrono::steady_clock::now();
  RunSummary summary;
  summary.integrator = model.integrator;
  series.names = ChannelNames(model);
  series.columns = 1 + series.names.size();
  const double step =
      model.output_every > 0 ? model.output_every : model.end_time - model.start_time;
  const auto outputs =
      static_cast<std::size_t>(std::floor((model.end_time - model.start_time) / step + 1e-9)) + 1;
  series.values.clear();
  series.values.reserve(outputs * series.columns);

  auto integrator = MakeIntegrator(model.integrator);
  if (!integrator) {
    summary.failed = true;
    summary.failure.cause = fmt::format("unknown integrator `{}`", model.integrator);
    return summary;
  }
  MultibodySystem system(model, data);
  std::vector<double> y(system.size());
  system.Store(y);
  IntegratorOptions integrator_options;
  integrator_options.relative_tolerance = model.relative_tolerance;
  integrator_options.absolute_tolerance = model.absolute_tolerance;
  integrator_options.min_step = model.min_step;
  integrator_options.max_step = model.max_step;
  integrator_options.initial_step = model.initial_step;
  integrator->Reset(system, data.time, y, integrator_options);

  // The first row: the initial state.
  Failure failure;
  if (!Forward(model, data, &failure)) {
    summary.failed = true;
    summary.failure = failure;
    summary.failure.time = data.time;
  } else {
    AppendRow(model, data, series);
  }
  for (std::size_t k = 1; k < outputs && !summary.failed; ++k) {
    const double target = model.start_time + static_cast<double>(k) * step;
    const AdvanceResult result = integrator->Advance(std::min(target, model.end_time));
    system.Load(integrator->time(), integrator->state());
    if (result.status != IntegratorStatus::kOk) {
      summary.failed = true;
      summary.failure = system.failure();
      summary.failure.time = result.t;
      if (summary.failure.cause.empty()) summary.failure.cause = result.reason;
      break;
    }
    if (!Forward(model, data, &failure)) {
      summary.failed = true;
      summary.failure = failure;
      summary.failure.time = data.time;
      break;
    }
    AppendRow(model, data, series);
    if (options.progress)
      options.progress(static_cast<double>(k) / static_cast<double>(outputs - 1),
                       options.progress_context);
  }
  summary.stats = integrator->stats();
  summary.end_time = data.time;
  summary.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  return summary;
}

}  // namespace sled::runtime
