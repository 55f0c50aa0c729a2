#include "runtime/airbag/airbag_forces.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "runtime/airbag/gas.h"
#include "runtime/contact/contact_forces.h"
#include "runtime/contact/contact_geometry.h"
#include "runtime/dynamics/frame_motion.h"
#include "runtime/forces/forces.h"
#include "runtime/forces/functions.h"

namespace sled::runtime {
namespace {

// Below this fraction of its full volume the gas of a full bag is taken to have no room left:
// the run fails there (the pressure would be unbounded), and the volume is held at it meanwhile.
constexpr double kMinimumVolumeFraction = 1e-3;
// The envelope's scale of an unfolding bag that segments push into is solved to this relative
// accuracy (far below the integrators' tolerances, so the rates stay smooth in the state).
constexpr double kScaleTolerance = 1e-13;
constexpr int kScaleIterations = 60;

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

// What the segments' ellipsoids take from bag b's envelope at `scale`: the volume, its rate
// from their motion, and its derivative with respect to the scale. Records each contact's area,
// volume, point and direction (the unit normal from the bag to the segment, in `force`).
struct Penetration {
  double volume = 0.0;
  double motion_rate = 0.0;  // d(volume)/dt from the motion of the segments and the bag's frame
  double per_scale = 0.0;    // d(volume)/d(scale)
};

Penetration Penetrate(const Model& model, Data& data, std::size_t b, const FrameMotion& frame,
                      double scale) {
  const AirbagTable& table = model.airbags;
  AirbagState& state = data.airbags;
  const Vec3& semi_axes = table.semi_axes[b];
  EllipsoidShape bag;
  bag.rotation = frame.rotation * table.axes[b];
  bag.semi_axes = scale * semi_axes;
  bag.center = frame.origin + frame.rotation * table.deploy_point[b] +
               scale * semi_axes.x() * bag.rotation.col(0);
  bag.radius = scale * semi_axes.maxCoeff();
  Penetration out;
  const auto first = static_cast<std::size_t>(table.first_contact[b]);
  const auto last = first + static_cast<std::size_t>(table.contact_count[b]);
  for (std::size_t c = first; c < last; ++c) {
    state.area[c] = 0.0;
    state.penetrated_volume[c] = 0.0;
    state.force[c].setZero();
    if (scale <= 0) continue;
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
    const EllipsoidCap bag_cap = CutEllipsoidCap(bag.semi_axes, bag.rotation, normal, g.deflection);
    const EllipsoidCap segment_cap =
        CutEllipsoidCap(segment.semi_axes, segment.rotation, normal, g.deflection);
    const EllipsoidCap& cap = bag_cap.volume < segment_cap.volume ? bag_cap : segment_cap;
    state.area[c] = cap.area;
    state.penetrated_volume[c] = cap.volume;
    state.point[c] = g.point;
    state.force[c] = normal;
    out.volume += cap.volume;
    // The deflection grows as the segment closes on the bag along the normal, and as the
    // envelope grows: its surface point along the normal moves out by its full-size extent plus
    // the centre's move along x, per unit of scale.
    const Vec3 closing =
        VelocityAt(frame, g.point) -
        VelocityAt(MotionOf(data, {FrameRef::Kind::kSegment, table.contact_segment[c]}), g.point);
    out.motion_rate += cap.area * normal.dot(closing);
    out.per_scale += cap.area * (Extent(semi_axes, bag.rotation, normal) +
                                 semi_axes.x() * normal.dot(bag.rotation.col(0)));
  }
  return out;
}

// The scale at which an unfolding bag's envelope, less what the segments take, holds
// `gas_volume`: the root of s^3 V_full - V_pen(s) = gas_volume, above the free bag's scale.
// Safeguarded Newton on a bracket that doubles until it holds the root.
double UnfoldedScale(const Model& model, Data& data, std::size_t b, const FrameMotion& frame,
                     double gas_volume, Penetration& penetration) {
  const double full = FullVolume(model.airbags, b);
  auto excess = [&](double s) {
    penetration = Penetrate(model, data, b, frame, s);
    return s * s * s * full - penetration.volume - gas_volume;
  };
  double low = std::cbrt(gas_volume / full);
  if (excess(low) >= 0) return low;  // nothing in the way
  double high = 2 * low;
  for (int k = 0; k < kScaleIterations && excess(high) < 0; ++k) high *= 2;
  double s = high;
  for (int k = 0; k < kScaleIterations && high - low > kScaleTolerance * high; ++k) {
    const double f = excess(s);
    if (f == 0) break;
    (f < 0 ? low : high) = s;
    const double slope = 3 * s * s * full - penetration.per_scale;
    const double newton = slope > 0 ? s - f / slope : -1.0;
    s = newton > low && newton < high ? newton : 0.5 * (low + high);
  }
  excess(s);  // leave the contacts recorded at the scale returned
  return s;
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

double AirbagFullnessEvent(const Model& model, const Data& data, std::size_t b) {
  const AirbagState& state = data.airbags;
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
    const double full_volume = FullVolume(table, b);
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
      for (std::size_t c = static_cast<std::size_t>(table.first_contact[b]);
           c < static_cast<std::size_t>(table.first_contact[b] + table.contact_count[b]); ++c) {
        state.force[c].setZero();
      }
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
    if (volume < kMinimumVolumeFraction * full_volume) {
      state.failed_bag = static_cast<int>(b);
      volume = kMinimumVolumeFraction * full_volume;
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
