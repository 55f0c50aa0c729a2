#include "runtime/airbag/free_bag.h"

#include <algorithm>
#include <cmath>

#include "runtime/airbag/airbag_envelope.h"
#include "runtime/airbag/gas.h"
#include "runtime/forces/forces.h"

namespace sled::runtime {
namespace {

// Offsets of the states after the gas mass.
constexpr std::size_t kVented = 1;
constexpr std::size_t kCentre = 2;
constexpr std::size_t kVelocity = 5;

Vec3 StateVector(const Data& data, std::size_t at) {
  return {data.w[at], data.w[at + 1], data.w[at + 2]};
}

// The full envelope's centre, from its back pole at the deployment point, in `frame`'s pose.
Vec3 AttachedCentre(const AirbagTable& table, std::size_t b, const FrameMotion& frame) {
  const Mat3 axes = frame.rotation * table.axes[b];
  return frame.origin + frame.rotation * table.deploy_point[b] +
         table.semi_axes[b].x() * axes.col(0);
}

// A body that carries the envelope as the bag's frame would, but with the full envelope centred
// at `centre` and moving with `velocity`, turning with the frame.
FrameMotion FreeCarrier(const AirbagTable& table, std::size_t b, const FrameMotion& frame,
                        const Vec3& centre, const Vec3& velocity) {
  FrameMotion carrier = frame;
  carrier.origin = centre - (AttachedCentre(table, b, frame) - frame.origin);
  carrier.velocity = velocity + frame.angular_velocity.cross(carrier.origin - centre);
  return carrier;
}

}  // namespace

double FreeBagAmbientVolume(const AirbagTable& table, std::size_t b, double mass) {
  return mass * table.gas_constant[b] * table.inflow_temperature[b] / table.ambient_pressure[b];
}

void StartFreeBag(const Model& model, Data& data, std::size_t b) {
  const AirbagTable& table = model.airbags;
  const auto address = static_cast<std::size_t>(table.state_address[b]);
  const FrameMotion frame = MotionOf(data, table.frame[b]);
  const Vec3 centre = AttachedCentre(table, b, frame);
  const Vec3 velocity = VelocityAt(frame, centre);
  for (int i = 0; i < 3; ++i) {
    data.w[address + kCentre + static_cast<std::size_t>(i)] = centre[i];
    data.w[address + kVelocity + static_cast<std::size_t>(i)] = velocity[i];
  }
}

void ComputeFreeBagForces(const Model& model, Data& data, std::size_t b, const FrameMotion& frame,
                          double inflow) {
  const AirbagTable& table = model.airbags;
  AirbagState& state = data.airbags;
  const auto address = static_cast<std::size_t>(table.state_address[b]);
  const double ambient = table.ambient_pressure[b];
  const double gamma = table.gamma[b];
  const double mass = std::max(data.w[address], 0.0);
  const double ambient_volume = FreeBagAmbientVolume(table, b, mass);
  const auto first = static_cast<std::size_t>(table.first_contact[b]);
  const auto last = first + static_cast<std::size_t>(table.contact_count[b]);
  state.inflow[b] = inflow;
  data.wdot[address] = inflow;
  for (std::size_t k = kVented; k < static_cast<std::size_t>(AirbagTable::kFreeBagStates); ++k) {
    data.wdot[address + k] = 0.0;
  }

  if (!state.full[b]) {
    // Unfolding, as in ATB: the envelope grows with its frame around the volume the gas takes at
    // the ambient pressure and whatever the segments take; it pushes on nothing, nothing vents.
    Penetration penetration;
    state.scale[b] =
        mass > 0 ? UnfoldedScale(model, data, b, frame, ambient_volume, penetration) : 0.0;
    for (std::size_t c = first; c < last; ++c) state.force[c].setZero();
    state.pressure[b] = ambient;
    state.volume[b] = ambient_volume;
    state.vent_flow[b] = 0.0;
    state.temperature[b] = table.inflow_temperature[b];
    return;
  }

  // Full: the envelope keeps its full size and moves with the bag's own states.
  const Vec3 centre = StateVector(data, address + kCentre);
  const Vec3 velocity = StateVector(data, address + kVelocity);
  const FrameMotion carrier = FreeCarrier(table, b, frame, centre, velocity);
  state.scale[b] = 1.0;
  const double full_volume = FullAirbagVolume(table, b);
  const Penetration penetration = Penetrate(model, data, b, carrier, 1.0);
  double volume = full_volume - penetration.volume;
  if (volume < kMinimumAirbagVolumeFraction * full_volume) {
    state.failed_bag = static_cast<int>(b);
    volume = kMinimumAirbagVolumeFraction * full_volume;
  }
  const double pressure = PolytropicPressure(ambient, ambient_volume, volume, gamma);
  // As ATB, a gauge pressure below zero pushes nothing (the fabric cannot pull).
  const double gauge = std::max(pressure - ambient, 0.0);
  Vec3 on_bag = Vec3::Zero();
  for (std::size_t c = first; c < last; ++c) {
    if (state.area[c] <= 0) continue;
    const Vec3 force = gauge * state.area[c] * state.force[c];
    state.force[c] = force;
    AddPointForce(data, static_cast<std::size_t>(table.contact_segment[c]), state.point[c], force);
    on_bag -= force;
  }
  // The spring from the bag's back pole to the deployment point; its reaction on the frame.
  const Vec3 pole = centre - table.semi_axes[b].x() * (frame.rotation * table.axes[b]).col(0);
  const Vec3 anchor = frame.origin + frame.rotation * table.deploy_point[b];
  const Vec3 tether = table.tether_stiffness[b] * (anchor - pole);
  on_bag += tether;
  AddFrameForce(data, table.frame[b], anchor, -tether);

  // The vent: incompressible orifice flow of the gas at its density at the ambient pressure.
  const double density = ambient / (table.gas_constant[b] * table.inflow_temperature[b]);
  const double vent = SquareRootVentFlow(table.discharge_coefficient[b] * table.vent_area[b],
                                         density, gauge, table.vent_opening_pressure[b]);
  const double moving_mass = table.mass_factor[b] * (mass + table.bag_mass[b]);
  data.wdot[address] = inflow - vent;
  data.wdot[address + kVented] = vent;
  for (int i = 0; i < 3; ++i) {
    const auto k = static_cast<std::size_t>(i);
    data.wdot[address + kCentre + k] = velocity[i];
    data.wdot[address + kVelocity + k] = on_bag[i] / moving_mass + model.gravity[i];
  }
  state.pressure[b] = pressure;
  state.volume[b] = volume;
  state.vent_flow[b] = vent;
  // Along the polytrope from the reference state (the ambient pressure, the inflator's
  // temperature): T = T_ref (p / p_a)^((gamma - 1) / gamma).
  state.temperature[b] =
      table.inflow_temperature[b] * std::pow(pressure / ambient, (gamma - 1.0) / gamma);
}

}  // namespace sled::runtime
