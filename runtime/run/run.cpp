#include "runtime/run/run.h"

#include <chrono>
#include <cmath>

#include <fmt/format.h>

#include "runtime/dynamics/dynamics.h"
#include "runtime/forces/state_owner.h"
#include "runtime/integrate/make_integrator.h"
#include "runtime/run/checkpoint.h"
#include "runtime/run/energy.h"
#include "runtime/run/input_discontinuities.h"
#include "runtime/run/output_rows.h"
#include "runtime/run/outputs.h"
#include "runtime/run/system.h"

namespace sled::runtime {
namespace {

// Everything of a run that a checkpoint carries besides the rows, in one listing for both
// directions.
void SerializeRunState(Archive& archive, Integrator& integrator, Data& data,
                       double& initial_potential, EnergySummary& energy) {
  integrator.Serialize(archive);
  SerializeData(archive, data);
  archive.Field(initial_potential);
  archive.Field(energy);
}

// Why settling did not give the run a start: the pre-simulation failed, or its convergence test
// did not hold within the settling time (what did not hold, and by how much).
Failure SettleFailure(const Model& model, const SettleSummary& settle) {
  Failure failure;
  failure.time = model.start_time;
  const Model::Settle& want = model.settle;
  if (!settle.failure.empty()) {
    failure.cause = fmt::format("settling failed after {:.4g} s: {}", settle.time, settle.failure);
    return failure;
  }
  std::string what;
  if (settle.largest_velocity > want.velocity) {
    failure.where = settle.fastest_segment;
    what = fmt::format("a centre of mass still moves at {:.3g} m/s (at most {:.3g})",
                       settle.largest_velocity, want.velocity);
  } else if (settle.largest_angular_velocity > want.angular_velocity) {
    what = fmt::format("a segment still turns at {:.3g} rad/s (at most {:.3g})",
                       settle.largest_angular_velocity, want.angular_velocity);
  } else if (settle.largest_acceleration > want.velocity / want.check_every) {
    what = fmt::format("a centre of mass still accelerates at {:.3g} m/s^2 (at most {:.3g})",
                       settle.largest_acceleration, want.velocity / want.check_every);
  } else if (settle.largest_angular_acceleration > want.angular_velocity / want.check_every) {
    what =
        fmt::format("a segment's angular acceleration is still {:.3g} rad/s^2 (at most {:.3g})",
                    settle.largest_angular_acceleration, want.angular_velocity / want.check_every);
  } else {
    what = fmt::format(
        "a force still changed by {:.3g} of the largest, {:.4g} N, in {:.3g} s "
        "(at most {:.3g})",
        settle.largest_force_change, settle.largest_force, want.check_every, want.force_change);
  }
  failure.cause = fmt::format(
      "the scene did not settle in {:.4g} s: {}; give settling a longer `duration` or more "
      "`damping`",
      want.duration, what);
  return failure;
}

}  // namespace

IntegratorOptions IntegratorOptionsOf(const Model& model) {
  IntegratorOptions options;
  options.relative_tolerance = model.relative_tolerance;
  options.absolute_tolerance = model.absolute_tolerance;
  options.min_step = model.min_step;
  options.max_step = model.max_step;
  options.initial_step = model.initial_step;
  options.end_time = model.end_time;
  return options;
}

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
  CheckDataOf(model, data);
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
  auto row_time = [&](std::size_t k) {
    return std::min(model.start_time + static_cast<double>(k) * step, model.end_time);
  };

  auto integrator = MakeIntegrator(model.integrator);
  if (!integrator) {
    summary.failed = true;
    summary.failure.cause = fmt::format("unknown integrator `{}`", model.integrator);
    return summary;
  }
  if (options.resume == nullptr && model.settle.duration > 0.0) {
    summary.settle = Settle(model, data);
    if (!summary.settle.converged) {
      summary.failed = true;
      summary.failure = SettleFailure(model, summary.settle);
      summary.end_time = data.time;
      return summary;
    }
  }
  MultibodySystem system(model, data);
  data.energy = EnergyBalance{};
  std::vector<double> y(system.size());
  system.Store(y);
  integrator->Reset(system, data.time, y, IntegratorOptionsOf(model));

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
  double initial_potential = 0.0;
  std::size_t next_row = 1;
  if (options.resume != nullptr) {
    // Continue where the checkpoint stopped: its integrator and Data, and its rows when the
    // channels are the same (otherwise the rows start again at the checkpoint's time, read from
    // the dense output of the step the checkpoint ended).
    const Checkpoint& checkpoint = *options.resume;
    Archive archive = Archive::ForReading(checkpoint.state);
    SerializeRunState(archive, *integrator, data, initial_potential, summary.energy);
    if (!archive.ok() || !archive.at_end()) {
      fail_because("the checkpoint's state does not fit this model", data.time);
      return summary;
    }
    next_row = static_cast<std::size_t>(checkpoint.next_row);
    // The rows so far belong to this run only when every channel is defined as it was (the
    // same names with a point moved are other channels).
    if (checkpoint.model.outputs == FingerprintOf(model).outputs &&
        checkpoint.series.names == series.names) {
      series.values.assign(checkpoint.series.values.begin(), checkpoint.series.values.end());
    } else {
      next_row = 0;
      while (next_row < outputs && row_time(next_row) < checkpoint.time) ++next_row;
      if (next_row < outputs) {
        summary.notes.push_back(fmt::format(
            "the output requests or criteria differ from the checkpoint's (added, removed, or a "
            "point, target or filter changed): every channel's rows start at the checkpoint's "
            "time, {} s, and the criteria see the run from there",
            row_time(next_row)));
      }
    }
  } else if (Failure failure; Forward(model, data, &failure)) {
    // The first row: the initial state.
    initial_potential = PotentialEnergy(model, data);
    data.energy.initial = KineticEnergy(model, data) + initial_potential;
    UpdateEnergy(model, data, initial_potential, summary.energy);
    WatchTablesAtRow(model, data);
    AppendRow(model, data, series);
    if (options.observer) {
      options.observer->OnRowValues(std::span<const double>(series.values).last(series.columns));
      options.observer->OnRow(model, data);
    }
  } else {
    fail(failure, data.time);
  }

  // The stop times at the start (a dump of the initial state).
  const std::vector<double>& stops = options.stop_times;
  auto same_time = [](double a, double b) {
    return std::abs(a - b) <= 1e-12 * std::max(1.0, std::abs(b));
  };
  std::size_t next_stop = 0;
  const double t_start = integrator->time();
  while (next_stop < stops.size() && stops[next_stop] < t_start &&
         !same_time(stops[next_stop], t_start)) {
    ++next_stop;  // before the start: never reached
  }
  if (!summary.failed && options.resume == nullptr) {
    for (; next_stop < stops.size() && same_time(stops[next_stop], t_start); ++next_stop) {
      if (options.observer) options.observer->OnStop(model, data);
    }
  }

  // Checkpoints: at the end of the first step at or after each multiple of checkpoint_every,
  // named by that multiple, so taking them changes no step.
  const double every = options.checkpoints != nullptr ? options.checkpoint_every : 0.0;
  auto checkpoint_time = [&](long m) { return model.start_time + static_cast<double>(m) * every; };
  long next_checkpoint = 0;
  if (every > 0) {
    while (checkpoint_time(next_checkpoint) <= integrator->time() + 1e-12 * every)
      ++next_checkpoint;
  }

  // The rows from here on, on a Data of their own (output_rows.h), from the states and
  // histories each step hands over.
  OutputRows rows(model, series, options, next_row, outputs, initial_potential, summary.energy,
                  options.row_thread && !summary.failed);
  const std::size_t state_size = system.size();
  double last_entry_time = -1.0;  // of the last step's last row or stop (-1: it had none)
  const std::vector<double> kinks = InputDiscontinuities(model);
  std::size_t next_kink = 0;
  while (!summary.failed && integrator->time() < model.end_time && !rows.halted()) {
    const double t_now = integrator->time();
    while (next_kink < kinks.size() && kinks[next_kink] <= t_now) ++next_kink;
    const double t_stop =
        next_kink < kinks.size() ? std::min(kinks[next_kink], model.end_time) : model.end_time;
    const AdvanceResult result = integrator->Step(t_stop);
    if (result.status != IntegratorStatus::kOk) {
      system.Load(integrator->time(), integrator->state());
      fail(system.failure(), result.t);
      if (summary.failure.cause.empty()) summary.failure.cause = result.reason;
      if (result.component >= 0) {
        NameStateOwner(model, static_cast<std::size_t>(result.component), summary.failure);
      }
      break;
    }
    const double t_end = integrator->time();
    // Rows and stop times on the step, in time order, from its dense output, with the
    // histories the step ended with.
    OutputRows::Job& job = rows.NextJob();
    while (true) {
      const bool row_next = next_row < outputs && row_time(next_row) <= t_end;
      const bool stop_next = next_stop < stops.size() && stops[next_stop] <= t_end;
      if (!row_next && !stop_next) break;
      if (row_next && (!stop_next || row_time(next_row) <= stops[next_stop])) {
        const double t = row_time(next_row++);
        integrator->Interpolate(t, job.Add({true, true, t}, state_size));
        // A stop at the row's time sees the same state.
        for (; next_stop < stops.size() && same_time(stops[next_stop], t); ++next_stop) {
          job.Add({false, false, t}, state_size);
        }
      } else {
        const double t = stops[next_stop++];
        integrator->Interpolate(t, job.Add({false, true, t}, state_size));
      }
    }
    last_entry_time = job.entries.empty() ? -1.0 : job.entries.back().time;
    if (!job.entries.empty()) {
      job.histories.Take(data);
      job.stats = integrator->stats();
      rows.Submit();
    }
    if (every > 0 && t_end >= checkpoint_time(next_checkpoint) - 1e-12 * every &&
        t_end < model.end_time) {
      rows.Drain();  // the checkpoint carries the rows so far
      if (rows.halted()) break;
      MergeTableWatch(model, rows.data().table_watch, data.table_watch);
      Checkpoint checkpoint;
      checkpoint.model = FingerprintOf(model);
      checkpoint.time = checkpoint_time(next_checkpoint);
      checkpoint.next_row = static_cast<std::int64_t>(next_row);
      checkpoint.series = series;
      Archive archive = Archive::ForWriting();
      EnergySummary energy = rows.energy();
      SerializeRunState(archive, *integrator, data, initial_potential, energy);
      checkpoint.state = archive.bytes();
      std::string where;
      std::string error;
      if (!options.checkpoints->Keep(checkpoint, &where, &error)) {
        summary.output_error = error;  // not the numerics' fault: the run stops, its rows kept
        break;
      }
      summary.checkpoints.push_back(where);
      while (checkpoint_time(next_checkpoint) <= t_end + 1e-12 * every) ++next_checkpoint;
    }
  }
  rows.Finish();
  summary.output_evaluations = rows.evaluations();
  summary.energy = rows.energy();
  MergeTableWatch(model, rows.data().table_watch, data.table_watch);
  summary.stats = integrator->stats();
  summary.end_time = last_entry_time >= 0 && !summary.failed ? last_entry_time : data.time;
  if (rows.halted()) {
    // A row that could not be evaluated, or the stop request, ends the run there: the steps
    // taken past it (by the integration running ahead of the rows) are not the run's.
    summary.failed = rows.failed();
    summary.failure = rows.failed() ? rows.failure() : Failure{};
    summary.interrupted = rows.interrupted();
    summary.stats = rows.halt_stats();
    summary.end_time = rows.halt_time();
  }
  summary.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  return summary;
}

}  // namespace sled::runtime
