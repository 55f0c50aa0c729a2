#include "runtime/run.h"

#include <chrono>
#include <cmath>

#include <fmt/format.h>

#include "runtime/checkpoint.h"
#include "runtime/dynamics.h"
#include "runtime/energy.h"
#include "runtime/integrate/make_integrator.h"
#include "runtime/outputs.h"
#include "runtime/state_owner.h"
#include "runtime/system.h"

namespace sled::runtime {
namespace {

// The balance at data's state (after Forward): the terms, the residual, and the largest of each.
void UpdateEnergy(const Model& model, const Data& data, double initial_potential,
                  EnergySummary& energy) {
  const EnergyBalance& balance = data.energy;
  energy.kinetic = KineticEnergy(model, data);
  energy.potential = PotentialEnergy(model, data);
  energy.absorbed = balance.Absorbed();
  energy.prescribed_work = balance.PrescribedWork();
  energy.impulses = balance.impulses;
  energy.residual = balance.Residual(energy.kinetic, energy.potential);
  energy.largest_residual = std::max(energy.largest_residual, std::abs(energy.residual));
  for (double term : {energy.kinetic, energy.potential - initial_potential, energy.absorbed,
                      energy.prescribed_work, energy.impulses}) {
    energy.scale = std::max(energy.scale, std::abs(term));
  }
}

void AppendRow(const Model& model, Data& data, TimeSeries& series) {
  const std::size_t start = series.values.size();
  series.values.resize(start + series.columns);  // reserved in advance: no reallocation
  series.values[start] = data.time;
  EvaluateChannels(model, data,
                   std::span<double>(series.values).subspan(start + 1, series.columns - 1));
}

// Everything of a run that a checkpoint carries besides the rows, in one listing for both
// directions.
void SerializeRunState(Archive& archive, Integrator& integrator, Data& data,
                       double& initial_potential, EnergySummary& energy) {
  integrator.Serialize(archive);
  SerializeData(archive, data);
  archive.Field(initial_potential);
  archive.Field(energy);
}

}  // namespace

std::size_t OutputRowCount(const Model& model) {
  const double step =
      model.output_every > 0 ? model.output_every : model.end_time - model.start_time;
  // An end within 1e-5 of a step of a row time gets that row (its time clamped to the end):
  // end - start loses up to about 2e-6 of a step to rounding when the run starts late, since
  // the checker (E0412) allows an output step down to 1e-10 of the end time.
  return static_cast<std::size_t>(std::floor((model.end_time - model.start_time) / step + 1e-5)) +
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
  // Checkpoints fall on output rows: every `checkpoint_rows` rows.
  const auto checkpoint_rows =
      static_cast<std::size_t>(options.checkpoint_every > 0 && options.checkpoints != nullptr
                                   ? std::llround(options.checkpoint_every / step)
                                   : 0);

  auto integrator = MakeIntegrator(model.integrator);
  if (!integrator) {
    summary.failed = true;
    summary.failure.cause = fmt::format("unknown integrator `{}`", model.integrator);
    return summary;
  }
  MultibodySystem system(model, data);
  data.energy = EnergyBalance{};
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
  auto fail = [&](const Failure& why, double t) {
    summary.failed = true;
    summary.failure = why;
    summary.failure.time = t;
  };
  auto fail_because = [&](std::string cause, double t) {
    Failure why;
    why.cause = std::move(cause);
    fail(why, t);
  };
  auto advance_to = [&](double t) {
    const AdvanceResult result = integrator->Advance(t);
    system.Load(integrator->time(), integrator->state());
    if (result.status != IntegratorStatus::kOk) {
      fail(system.failure(), result.t);
      if (summary.failure.cause.empty()) summary.failure.cause = result.reason;
      if (result.component >= 0) {
        NameStateOwner(model, static_cast<std::size_t>(result.component), summary.failure);
      }
      return false;
    }
    if (!Forward(model, data, &failure)) {
      fail(failure, data.time);
      return false;
    }
    return true;
  };

  double initial_potential = 0.0;
  std::size_t first_row = 1;
  if (options.resume != nullptr) {
    // Continue where the checkpoint stopped: its integrator and Data, and its rows when the
    // channels are the same (otherwise the rows start again at the checkpoint).
    const Checkpoint& checkpoint = *options.resume;
    Archive archive = Archive::ForReading(checkpoint.state);
    SerializeRunState(archive, *integrator, data, initial_potential, summary.energy);
    if (!archive.ok() || !archive.at_end()) {
      fail_because("the checkpoint's state does not fit this model", data.time);
      return summary;
    }
    first_row = static_cast<std::size_t>(checkpoint.next_row);
    if (checkpoint.series.names == series.names) {
      series.values.assign(checkpoint.series.values.begin(), checkpoint.series.values.end());
    } else if (Forward(model, data, &failure)) {
      summary.notes.push_back(fmt::format(
          "the output requests differ from the checkpoint's: the rows start at {} s", data.time));
      AppendRow(model, data, series);
    } else {
      fail(failure, data.time);
    }
  } else if (Forward(model, data, &failure)) {
    // The first row: the initial state.
    initial_potential = PotentialEnergy(model, data);
    data.energy.initial = KineticEnergy(model, data) + initial_potential;
    UpdateEnergy(model, data, initial_potential, summary.energy);
    AppendRow(model, data, series);
    if (options.observer) options.observer->OnRow(model, data);
  } else {
    fail(failure, data.time);
  }

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
  if (!summary.failed && options.resume == nullptr) observe_stops_here();

  for (std::size_t k = first_row; k < outputs && !summary.failed; ++k) {
    const double target =
        std::min(model.start_time + static_cast<double>(k) * step, model.end_time);
    // Stop times before this row: the integrator lands on each of them.
    while (next_stop < stops.size() && stops[next_stop] < target && !at_stop(target)) {
      if (!advance_to(stops[next_stop])) break;
      observe_stops_here();
    }
    if (summary.failed || !advance_to(target)) break;
    UpdateEnergy(model, data, initial_potential, summary.energy);
    AppendRow(model, data, series);
    if (options.observer) options.observer->OnRow(model, data);
    observe_stops_here();
    if (checkpoint_rows > 0 && k % checkpoint_rows == 0 && k + 1 < outputs) {
      Checkpoint checkpoint;
      checkpoint.model = FingerprintOf(model);
      checkpoint.time = data.time;
      checkpoint.next_row = static_cast<std::int64_t>(k + 1);
      checkpoint.series = series;
      Archive archive = Archive::ForWriting();
      SerializeRunState(archive, *integrator, data, initial_potential, summary.energy);
      checkpoint.state = archive.bytes();
      std::string where;
      std::string error;
      if (!options.checkpoints->Keep(checkpoint, &where, &error)) {
        fail_because(error, data.time);
        break;
      }
      summary.checkpoints.push_back(where);
    }
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
