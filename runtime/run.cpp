#include "runtime/run.h"

#include <chrono>
#include <cmath>

#include <fmt/format.h>

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

  // The first row: the initial state.
  Failure failure;
  double initial_potential = 0.0;
  if (!Forward(model, data, &failure)) {
    summary.failed = true;
    summary.failure = failure;
    summary.failure.time = data.time;
  } else {
    initial_potential = PotentialEnergy(model, data);
    data.energy.initial = KineticEnergy(model, data) + initial_potential;
    UpdateEnergy(model, data, initial_potential, summary.energy);
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
    UpdateEnergy(model, data, initial_potential, summary.energy);
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
