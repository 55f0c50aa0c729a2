#include "runtime/vehicle.h"

#include <array>
#include <cmath>
#include <numbers>

namespace sled::runtime {
namespace {

// What a pulse alone adds at time t (measured from its start): acceleration, and the velocity
// and displacement gained, by exact integration.
struct Gain {
  double acceleration = 0.0;
  double velocity = 0.0;
  double displacement = 0.0;
};

Gain HalfSineGain(double delta_v, double duration, double t) {
  // a = A sin(pi t / T) on [0, T] with A = pi dv / (2 T), so that the velocity change is dv.
  const double T = duration;
  if (!(T > 0) || t <= 0) return {};
  const double A = std::numbers::pi * delta_v / (2 * T);
  const double w = std::numbers::pi / T;
  const double tc = std::min(t, T);
  Gain gain;
  gain.acceleration = t <= T ? A * std::sin(w * t) : 0.0;
  gain.velocity = A / w * (1 - std::cos(w * tc));
  gain.displacement = A / w * (tc - std::sin(w * tc) / w);
  if (t > T) gain.displacement += gain.velocity * (t - T);
  return gain;
}

// Piecewise-linear acceleration through `count` points (time_of(k), value_of(k)), zero before
// the first and after the last: exact velocity and displacement. No allocation.
template <typename Time, typename Value>
Gain PiecewiseLinearGain(std::size_t count, Time time_of, Value value_of, double t) {
  Gain gain;
  for (std::size_t k = 0; k + 1 < count; ++k) {
    const double t0 = time_of(k), t1 = time_of(k + 1);
    if (t <= t0) break;
    const double a0 = value_of(k);
    const double slope = (value_of(k + 1) - a0) / (t1 - t0);
    const double h = std::min(t, t1) - t0;
    gain.displacement += gain.velocity * h + a0 * h * h / 2 + slope * h * h * h / 6;
    gain.velocity += a0 * h + slope * h * h / 2;
    if (t < t1) gain.acceleration = a0 + slope * h;
  }
  if (count > 0 && t > time_of(count - 1)) {
    gain.displacement += gain.velocity * (t - time_of(count - 1));
  }
  return gain;
}

Gain PulseGain(const VehicleMotion& m, double t) {
  switch (m.kind) {
    case VehicleMotion::Kind::kHalfSine:
      return HalfSineGain(m.delta_v, m.duration, t);
    case VehicleMotion::Kind::kTrapezoid: {
      const std::array<std::array<double, 2>, 4> points = {{{0.0, 0.0},
                                                            {m.rise, m.peak},
                                                            {m.rise + m.dwell, m.peak},
                                                            {m.rise + m.dwell + m.fall, 0.0}}};
      return PiecewiseLinearGain(
          points.size(), [&](std::size_t k) { return points[k][0]; },
          [&](std::size_t k) { return points[k][1]; }, t);
    }
    case VehicleMotion::Kind::kTable:
      return PiecewiseLinearGain(
          m.table.size(), [&](std::size_t k) { return m.table[k][0]; },
          [&](std::size_t k) { return m.table[k][1]; }, t);
    default:
      return {};
  }
}

}  // namespace

double PulseAcceleration(const VehicleMotion& motion, double t) {
  return PulseGain(motion, t - motion.start).acceleration;
}

VehicleState VehicleAt(const Model& model, std::size_t vehicle, double t) {
  const VehicleMotion& m = model.vehicle_motion[vehicle];
  VehicleState state;
  state.rotation = model.vehicle_orientation[vehicle];
  const Vec3 v0 = model.vehicle_velocity[vehicle];
  const double local = t - m.start;
  Vec3 velocity = Vec3::Zero(), displacement = Vec3::Zero(), acceleration = Vec3::Zero();
  if (m.kind == VehicleMotion::Kind::kSixDof) {
    // The linear part, per axis of the vehicle frame. The angular part is not integrated yet: a
    // six-degree-of-freedom table moves the vehicle without turning it.
    for (int axis = 0; axis < 3; ++axis) {
      const Gain g = PiecewiseLinearGain(
          m.six_dof.size(), [&](std::size_t k) { return m.six_dof[k][0]; },
          [&](std::size_t k) { return m.six_dof[k][1 + static_cast<std::size_t>(axis)]; }, local);
      velocity[axis] = g.velocity;
      displacement[axis] = g.displacement;
      acceleration[axis] = g.acceleration;
    }
  } else if (m.kind != VehicleMotion::Kind::kNone) {
    const Gain g = PulseGain(m, local);
    velocity = m.axis * g.velocity;
    displacement = m.axis * g.displacement;
    acceleration = m.axis * g.acceleration;
  }
  state.position = model.vehicle_position[vehicle] + v0 * t + state.rotation * displacement;
  state.velocity = v0 + state.rotation * velocity;
  state.acceleration = state.rotation * acceleration;
  return state;
}

}  // namespace sled::runtime
