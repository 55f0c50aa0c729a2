#include "runtime/airbag/airbag_forces.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "runtime/airbag/airbag_envelope.h"
#include "runtime/airbag/free_bag.h"
#include "runtime/airbag/gas.h"
#include "runtime/dynamics/frame_motion.h"
#include "runtime/forces/forces.h"
#include "runtime/forces/functions.h"

namespace sled::runtime {
namespace {

// The internal energy's state is U / (c_v T_in), a mass like the gas mass, so the integrators'
// absolute tolerance weighs both alike.
double EnergyScale(const AirbagTable& table, std::size_t b) {
  return table.gas_constant[b] / (table.gamma[b] - 1.0) * table.inflow_temperature[b];
}

}  // namespace

double AirbagInflowEnd(const Model& model, std::size_t b) {
  const FunctionTable& functions = model.functions;
  const std::int32_t id = model.airbags.inflow[b];
  if (id < 0) return model.airbags.deploy_time[b];
  const auto f = static_cast<std::size_t>(id);
  if (functions.kind[f] != FunctionTable::Kind::kTable) {
    return std::numeric_limits<double>::infinity();
  }
  const auto last = static_cast<std::size_t>(functions.first[f] + functions.count[f] - 1);
  return model.airbags.deploy_time[b] + functions.points_x[last];
}

std::uint8_t AirbagInflowPhase(const Model& model, std::size_t b, double t) {
  if (t < model.airbags.deploy_time[b]) return 0;
  return t < AirbagInflowEnd(model, b) ? 1 : 2;
}

double AirbagUnfoldedFraction(const Model& model, const Data& data, std::size_t b) {
  const AirbagTable& table = model.airbags;
  if (table.free_bag[b]) {
    const double mass = data.w[static_cast<std::size_t>(table.state_address[b])];
    return FreeBagAmbientVolume(table, b, mass) / FullAirbagVolume(table, b);
  }
  const double energy =
      data.w[static_cast<std::size_t>(table.state_address[b]) + 1] * EnergyScale(table, b);
  return (table.gamma[b] - 1.0) * energy / (table.ambient_pressure[b] * FullAirbagVolume(table, b));
}

double AirbagFullnessEvent(const Model& model, const Data& data, std::size_t b) {
  const AirbagState& state = data.airbags;
  // ATB's free bag, once full, stays full (its motion has started).
  if (model.airbags.free_bag[b] && state.full[b]) return 1.0;
  return state.full[b] ? state.pressure[b] / model.airbags.ambient_pressure[b] - 1.0
                       : state.scale[b] - 1.0;
}

void ComputeAirbagForces(const Model& model, Data& data) {
  const AirbagTable& table = model.airbags;
  AirbagState& state = data.airbags;
  state.failed_bag = -1;
  for (std::size_t b = 0; b < table.size(); ++b) {
    const auto address = static_cast<std::size_t>(table.state_address[b]);
    const double gamma = table.gamma[b];
    const double cv = table.gas_constant[b] / (gamma - 1.0);
    const double cp = gamma * cv;
    const double energy_scale = EnergyScale(table, b);
    const double mass = std::max(data.w[address], 0.0);
    const double energy = std::max(data.w[address + 1], 0.0) * energy_scale;
    const double ambient = table.ambient_pressure[b];
    const double full_volume = FullAirbagVolume(table, b);
    const double temperature =
        mass > 0 && energy > 0 ? energy / (mass * cv) : table.inflow_temperature[b];
    const FrameMotion frame = MotionOf(data, table.frame[b]);
    // The inflator's flow (a function of the time since deployment) while it delivers; its
    // phase switches at events.
    const double inflow = state.inflow_phase[b] == 1
                              ? std::max(EvaluateFunction(model.functions, table.inflow[b],
                                                          data.time - table.deploy_time[b]),
                                         0.0)
                              : 0.0;
    if (table.free_bag[b]) {
      ComputeFreeBagForces(model, data, b, frame, inflow);
      continue;
    }
    state.inflow[b] = inflow;
    state.temperature[b] = temperature;

    // The mode, switched at events only, says whether the envelope is full, so inside a step
    // an unfolding envelope may pass its full size a little, or a full bag dip a little below
    // the ambient pressure.
    if (!state.full[b]) {
      // Unfolding: the slack envelope holds the gas at the ambient pressure, (gamma - 1) U / p_a
      // of it, growing around whatever the segments take; it pushes on nothing and nothing
      // vents. With dU = h_in dm - p_a dV, the gas keeps the inflator's c_v T_in per kilogram.
      const double gas_volume = (gamma - 1.0) * energy / ambient;
      Penetration penetration;
      state.scale[b] =
          energy > 0 ? UnfoldedScale(model, data, b, frame, gas_volume, penetration) : 0.0;
      const auto first = static_cast<std::size_t>(table.first_contact[b]);
      const auto count = static_cast<std::size_t>(table.contact_count[b]);
      for (std::size_t c = first; c < first + count; ++c) state.force[c].setZero();
      state.pressure[b] = ambient;
      state.volume[b] = gas_volume;
      state.vent_flow[b] = 0.0;
      data.wdot[address] = inflow;
      data.wdot[address + 1] = inflow * cp * table.inflow_temperature[b] / gamma / energy_scale;
      continue;
    }

    // Full: the envelope keeps its full size; the gas fills it less what the segments take, at
    // p = (gamma - 1) U / V.
    state.scale[b] = 1.0;
    const Penetration penetration = Penetrate(model, data, b, frame, 1.0);
    double volume = full_volume - penetration.volume;
    if (volume < kMinimumAirbagVolumeFraction * full_volume) {
      state.failed_bag = static_cast<int>(b);
      volume = kMinimumAirbagVolumeFraction * full_volume;
    }
    const double pressure = (gamma - 1.0) * energy / volume;
    const double gauge = std::max(pressure - ambient, 0.0);
    const auto first = static_cast<std::size_t>(table.first_contact[b]);
    for (std::size_t c = first; c < first + static_cast<std::size_t>(table.contact_count[b]); ++c) {
      if (state.area[c] <= 0) continue;
      // The gauge pressure on the contact area, along the normal, on the segment; the reaction
      // on the bag's frame (a segment, or a vehicle whose motion does work on the gas).
      const Vec3 force = gauge * state.area[c] * state.force[c];
      state.force[c] = force;
      AddPointForce(data, static_cast<std::size_t>(table.contact_segment[c]), state.point[c],
                    force);
      AddFrameForce(data, table.frame[b], state.point[c], -force);
    }
    const double vent =
        OrificeMassFlow(table.discharge_coefficient[b] * table.vent_area[b], pressure, temperature,
                        ambient, gamma, table.gas_constant[b]);
    // dU = h_in dm_in - h dm_out - p dV, the volume changing only as the segments move.
    data.wdot[address] = inflow - vent;
    data.wdot[address + 1] = (inflow * cp * table.inflow_temperature[b] - vent * cp * temperature +
                              pressure * penetration.motion_rate) /
                             energy_scale;
    state.pressure[b] = pressure;
    state.volume[b] = volume;
    state.vent_flow[b] = vent;
  }
}

}  // namespace sled::runtime
