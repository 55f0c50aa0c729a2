#include "runtime/airbag/airbag_forces.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "runtime/airbag/gas.h"
#include "runtime/contact/contact_forces.h"
#include "runtime/contact/contact_geometry.h"
#include "runtime/forces.h"
#include "runtime/functions.h"

namespace sled::runtime {
namespace {

// Below this fraction of its envelope the gas of a bag is taken to have no room left: the run
// fails there (the pressure would be unbounded), and the volume is held at it meanwhile.
constexpr double kMinimumVolumeFraction = 1e-3;

Vec3 PointVelocity(const FrameMotion& frame, const Vec3& point) {
  return frame.velocity + frame.angular_velocity.cross(point - frame.origin);
}

// Support extent of an ellipsoid (semi-axes along the columns of `rotation`) along unit n.
double Extent(const Vec3& semi_axes, const Mat3& rotation, const Vec3& n) {
  return (rotation.transpose() * n).cwiseProduct(semi_axes).norm();
}

// The internal energy's state is U / (c_v T_in), a mass like the gas mass, so the integrators'
// absolute tolerance weighs both alike.
double EnergyScale(const AirbagTable& table, std::size_t b) {
  return table.gas_constant[b] / (table.gamma[b] - 1.0) * table.inflow_temperature[b];
}

double FullVolume(const AirbagTable& table, std::size_t b) {
  return 4.0 / 3.0 * std::numbers::pi * table.semi_axes[b].prod();
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
  const double energy =
      data.w[static_cast<std::size_t>(table.state_address[b]) + 1] * EnergyScale(table, b);
  return (table.gamma[b] - 1.0) * energy / (table.ambient_pressure[b] * FullVolume(table, b));
}

void ComputeAirbagForces(const Model& model, Data& data) {
  const AirbagTable& table = model.airbags;
  AirbagState& state = data.airbags;
  state.failed_bag = -1;
  for (std::size_t b = 0; b < table.size(); ++b) {
    const auto address = static_cast<std::size_t>(table.state_address[b]);
    const double gamma = table.gamma[b];
    const double cv = table.gas_constant[b] / (gamma - 1.0);
    const double energy_scale = EnergyScale(table, b);
    const double mass = std::max(data.w[address], 0.0);
    const double energy = std::max(data.w[address + 1], 0.0) * energy_scale;
    const double cp = gamma * cv;
    const double ambient = table.ambient_pressure[b];
    const Vec3& semi_axes = table.semi_axes[b];
    const double full_volume = FullVolume(table, b);

    // Deployment law: the envelope holds the gas at the ambient pressure until it is full, so
    // its volume is (gamma - 1) U / p_ambient, at most the full volume; it keeps the bag's shape
    // (scaled by `scale`) and grows from its back pole along its x axis.
    // The mode, not the state, says whether the envelope is full: it switches at an event, so
    // inside a step an unfolding envelope may pass its full size a little, or a full one hold
    // slightly less gas than fills it at the ambient pressure.
    const bool growing = !state.full[b];
    const double scale3 = growing ? (gamma - 1.0) * energy / (ambient * full_volume) : 1.0;
    const double scale = std::cbrt(scale3);
    const double temperature =
        mass > 0 && energy > 0 ? energy / (mass * cv) : table.inflow_temperature[b];

    const FrameMotion frame = MotionOf(data, table.frame[b]);
    EllipsoidShape bag;
    bag.rotation = frame.rotation * table.axes[b];
    bag.semi_axes = scale * semi_axes;
    bag.center = frame.origin + frame.rotation * table.deploy_point[b] +
                 scale * semi_axes.x() * bag.rotation.col(0);
    bag.radius = scale * semi_axes.maxCoeff();

    // The segments' ellipsoids in the envelope: the volume they take and how fast it changes
    // with their motion (motion_rate) and with the envelope's growth (growth_rate, per unit of
    // scale).
    double penetrated = 0.0;
    double motion_rate = 0.0;
    double growth_rate = 0.0;
    const auto first = static_cast<std::size_t>(table.first_contact[b]);
    const auto last = first + static_cast<std::size_t>(table.contact_count[b]);
    for (std::size_t c = first; c < last; ++c) {
      state.area[c] = 0.0;
      state.penetrated_volume[c] = 0.0;
      state.force[c].setZero();
      if (energy <= 0) continue;
      const auto s = static_cast<std::size_t>(table.contact_segment[c]);
      EllipsoidShape segment;
      segment.center = data.position[s] + data.rotation[s] * table.contact_center[c];
      segment.rotation = data.rotation[s] * table.contact_axes[c];
      segment.semi_axes = table.contact_semi_axes[c];
      segment.radius = table.contact_radius[c];
      if ((segment.center - bag.center).norm() > segment.radius + bag.radius) continue;
      const ContactGeometry g = EllipsoidEllipsoid(bag, segment, state.search_direction[c]);
      if (g.deflection <= 0) continue;
      const Vec3 normal = -g.normal;  // from the bag towards the segment
      // The volume lost is the smaller of the two caps the deflection cuts: a head pushed into a
      // large bag takes its own cap, a large body flattening a small bag the bag's.
      const EllipsoidCap bag_cap =
          CutEllipsoidCap(bag.semi_axes, bag.rotation, normal, g.deflection);
      const EllipsoidCap segment_cap =
          CutEllipsoidCap(segment.semi_axes, segment.rotation, normal, g.deflection);
      const EllipsoidCap& cap = bag_cap.volume < segment_cap.volume ? bag_cap : segment_cap;
      state.area[c] = cap.area;
      state.penetrated_volume[c] = cap.volume;
      state.point[c] = g.point;
      state.force[c] = normal;  // the direction, scaled by the pressure below
      penetrated += cap.volume;
      // The deflection grows as the segment closes on the bag along the normal ...
      const Vec3 closing =
          PointVelocity(frame, g.point) -
          PointVelocity(MotionOf(data, {FrameRef::Kind::kSegment, table.contact_segment[c]}),
                        g.point);
      motion_rate += cap.area * normal.dot(closing);
      // ... and as the envelope grows: its surface point along the normal moves out by its
      // full-size extent plus the centre's move along x, per unit of scale.
      if (growing) {
        growth_rate += cap.area * (Extent(semi_axes, bag.rotation, normal) +
                                   semi_axes.x() * normal.dot(bag.rotation.col(0)));
      }
    }

    const double envelope = scale3 * full_volume;
    double volume = envelope - penetrated;
    if (energy > 0 && volume < kMinimumVolumeFraction * envelope) {
      state.failed_bag = static_cast<int>(b);
      volume = kMinimumVolumeFraction * envelope;
    }
    // An unfolding bag nothing pushes into is at the ambient pressure by the deployment law;
    // set exactly, so rounding does not open the vent (whose flow has an infinite slope there).
    const bool at_ambient = energy <= 0 || (growing && penetrated <= 0);
    const double pressure = at_ambient ? ambient : (gamma - 1.0) * energy / volume;
    const double gauge = std::max(pressure - ambient, 0.0);
    for (std::size_t c = first; c < last; ++c) {
      if (state.area[c] <= 0) continue;
      const Vec3 force = gauge * state.area[c] * state.force[c];
      state.force[c] = force;
      AddPointForce(data, static_cast<std::size_t>(table.contact_segment[c]), state.point[c],
                    force);
      if (table.frame[b].kind == FrameRef::Kind::kSegment) {
        AddPointForce(data, static_cast<std::size_t>(table.frame[b].index), state.point[c], -force);
      }
    }

    // The inflator's flow (a function of the time since deployment) while it delivers: its
    // phase, too, switches at events.
    const double inflow = state.inflow_phase[b] == 1
                              ? std::max(EvaluateFunction(model.functions, table.inflow[b],
                                                          data.time - table.deploy_time[b]),
                                         0.0)
                              : 0.0;
    const double vent =
        OrificeMassFlow(table.discharge_coefficient[b] * table.vent_area[b], pressure, temperature,
                        ambient, gamma, table.gas_constant[b]);
    // Energy balance of the gas: dU = h_in dm_in - h dm_out - p dV, with V depending on U
    // through the envelope's growth; solved for dU/dt. Growth never takes volume away from the
    // gas: where the segments would take more of it than the envelope adds, the fabric is held.
    const double enthalpy_rate =
        inflow * cp * table.inflow_temperature[b] - vent * cp * temperature;
    double volume_per_energy = 0.0;  // dV/dU through the envelope's growth
    if (growing && energy > 0) {
      volume_per_energy =
          std::max((gamma - 1.0) / ambient - growth_rate * scale / (3.0 * energy), 0.0);
    }
    data.wdot[address] = inflow - vent;
    data.wdot[address + 1] = (enthalpy_rate + pressure * motion_rate) /
                             (1.0 + pressure * volume_per_energy) / energy_scale;

    state.pressure[b] = pressure;
    state.volume[b] = energy > 0 ? volume : 0.0;
    state.temperature[b] = temperature;
    state.vent_flow[b] = vent;
    state.inflow[b] = inflow;
    state.scale[b] = scale;
  }
}

}  // namespace sled::runtime
