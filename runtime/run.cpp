#include "runtime/run.h"

#include <algorithm>
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

std::size_t OutputRowCount(const Model& model) {
  const double step =
      model.output_every > 0 ? model.output_every : model.end_time - model.start_time;
  return static_cast<std::size_t>(std::floor((model.end_time - model.start_time) / step + 1e-9)) +
         1;
}

RunSummary Run(const Model& model, Data& data, TimeSeries& series, const RunOptions& options) {
  const auto wall_start = std::chrono::steady_clock::now();
  RunSummary summary;
  summary.integrator = model.integrator;
  series.names = ChannelNames(model);
  series.columns = 1 + series.names.size();
  const double step =
      model.output_every > 0 ? model.output_every : model.end_time - model.start_time;
  const std::size_t outputs = OutputRowCount(model);
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

  // Integrates to t and evaluates the state there; false (and the summary says why) on failure.
  Failure failure;
  auto advance_to = [&](double t) {
    const AdvanceResult result = integrator->Advance(t);
    system.Load(integrator->time(), integrator->state());
    if (result.status != IntegratorStatus::kOk) {
      summary.failed = true;
      summary.failure = system.failure();
      summary.failure.time = result.t;
      if (summary.failure.cause.empty()) summary.failure.cause = result.reason;
      return false;
    }
    if (!Forward(model, data, &failure)) {
      summary.failed = true;
      summary.failure = failure;
      summary.failure.time = data.time;
      return false;
    }
    return true;
  };
  // The stop times at the current time (they coincide with an output row or the start).
  const std::vector<double>& stops = options.stop_times;
  auto same_time = [](double a, double b) {
    return std::abs(a - b) <= 1e-12 * std::max(1.0, std::abs(b));
  };
  std::size_t next_stop = 0;
  while (next_stop < stops.size() && stops[next_stop] < data.time &&
         !same_time(stops[next_stop], data.time)) {
    ++next_stop;  // before the start: never reached
  }
  auto at_stop = [&](double t) {
    return next_stop < stops.size() && same_time(stops[next_stop], t);
  };
  auto observe_stops_here = [&] {
    for (; at_stop(data.time); ++next_stop) {
      if (options.observer) options.observer->OnStop(model, data);
    }
  };

  // The first row: the initial state.
  if (!Forward(model, data, &failure)) {
    summary.failed = true;
    summary.failure = failure;
    summary.failure.time = data.time;
  } else {
    AppendRow(model, data, series);
    if (options.observer) options.observer->OnRow(model, data);
    observe_stops_here();
  }
  for (std::size_t k = 1; k < outputs && !summary.failed; ++k) {
    const double target =
        std::min(model.start_time + static_cast<double>(k) * step, model.end_time);
    // Stop times before this row: the integrator lands on each of them.
    while (next_stop < stops.size() && stops[next_stop] < target && !at_stop(target)) {
      if (!advance_to(stops[next_stop])) break;
      observe_stops_here();
    }
    if (summary.failed || !advance_to(target)) break;
    AppendRow(model, data, series);
    if (options.observer) options.observer->OnRow(model, data);
    observe_stops_here();
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
