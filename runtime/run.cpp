#include "runtime/run.h"

#include <chrono>
#include <cmath>

#include <fmt/format.h>

#include "runtime/checkpoint.h"
#include "runtime/dynamics.h"
#include "runtime/energy.h"
#include "runtime/integrate/make_integrator.h"
#include "runtime/outputs.h"
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

std::string CheckpointFileName(double time) { return fmt::format("checkpoint_{:.6f}s.bin", time); }

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
  // Checkpoints fall on output rows: every `checkpoint_rows` rows.
  const auto checkpoint_rows = static_cast<std::size_t>(
      options.checkpoint_every > 0 ? std::llround(options.checkpoint_every / step) : 0);

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

  Failure failure;
  double initial_potential = 0.0;
  std::size_t first_row = 1;
  if (options.resume != nullptr) {
    // Continue where the checkpoint stopped: its integrator and Data, and its rows when the
    // channels are the same (otherwise the rows start again at the checkpoint).
    const Checkpoint& checkpoint = *options.resume;
    Archive archive = Archive::ForReading(checkpoint.state);
    SerializeRunState(archive, *integrator, data, initial_potential, summary.energy);
    if (!archive.ok() || !archive.at_end()) {
      summary.failed = true;
      summary.failure.cause = "the checkpoint's state does not fit this model";
      return summary;
    }
    first_row = static_cast<std::size_t>(checkpoint.next_row);
    if (checkpoint.series.names == series.names) {
      series.values.assign(checkpoint.series.values.begin(), checkpoint.series.values.end());
    } else if (Forward(model, data, &failure)) {
      summary.notes.push_back(fmt::format(
          "the output requests differ from the checkpoint's: the rows start at {} s", data.time));
      AppendRow(model, data, series);
    }
  } else if (Forward(model, data, &failure)) {
    // The first row: the initial state.
    initial_potential = PotentialEnergy(model, data);
    data.energy.initial = KineticEnergy(model, data) + initial_potential;
    UpdateEnergy(model, data, initial_potential, summary.energy);
    AppendRow(model, data, series);
  }
  if (!failure.cause.empty()) {
    summary.failed = true;
    summary.failure = failure;
    summary.failure.time = data.time;
  }

  for (std::size_t k = first_row; k < outputs && !summary.failed; ++k) {
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
    UpdateEnergy(model, data, initial_potential, summary.energy);
    AppendRow(model, data, series);
    if (checkpoint_rows > 0 && k % checkpoint_rows == 0 && k + 1 < outputs) {
      Checkpoint checkpoint;
      checkpoint.model = FingerprintOf(model);
      checkpoint.time = data.time;
      checkpoint.next_row = static_cast<std::int64_t>(k + 1);
      checkpoint.series = series;
      Archive archive = Archive::ForWriting();
      SerializeRunState(archive, *integrator, data, initial_potential, summary.energy);
      checkpoint.state = archive.bytes();
      const std::string path = options.checkpoint_directory + "/" + CheckpointFileName(data.time);
      std::string error;
      if (!WriteCheckpoint(path, checkpoint, &error)) {
        summary.failed = true;
        summary.failure.cause = error;
        summary.failure.time = data.time;
        break;
      }
      summary.checkpoints.push_back(path);
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
