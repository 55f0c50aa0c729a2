#include "runtime/dynamics/vehicle.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "runtime/forces/row_search.h"

namespace sled::runtime {
namespace {

// The longest step of a turning vehicle's tabulated path [s]: with fourth-order steps the
// path's error stays far below any integrator tolerance at crash rates of turn.
constexpr double kPathStep = 1e-4;

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

// The velocity and the displacement that a piecewise-linear acceleration through `count` points
// (time_of(k), value_of(k)), zero before the first, has given by each point, exactly: gain(k,
// velocity, displacement) is called for every k in order.
template <typename Time, typename Value, typename Gains>
void IntegratePoints(std::size_t count, Time time_of, Value value_of, Gains gain) {
  double velocity = 0.0, displacement = 0.0;
  for (std::size_t k = 0; k < count; ++k) {
    if (k > 0) {
      const double t0 = time_of(k - 1), h = time_of(k) - t0;
      const double a0 = value_of(k - 1);
      const double slope = (value_of(k) - a0) / h;
      displacement += velocity * h + a0 * h * h / 2 + slope * h * h * h / 6;
      velocity += a0 * h + slope * h * h / 2;
    }
    gain(k, velocity, displacement);
  }
}

// The points of a piecewise-linear acceleration, read through accessors, with the velocity and
// displacement gained by each point (IntegratePoints).
template <typename Time, typename Value, typename Velocity, typename Displacement>
struct PiecewiseLinear {
  std::size_t count;
  Time time_of;
  Value value_of;
  Velocity velocity_of;
  Displacement displacement_of;
};
template <typename Time, typename Value, typename Velocity, typename Displacement>
PiecewiseLinear(std::size_t, Time, Value, Velocity, Displacement)
    -> PiecewiseLinear<Time, Value, Velocity, Displacement>;

// Exact acceleration, velocity and displacement at t of a piecewise-linear acceleration, zero
// before the first point and after the last, right-continuous at the points: the point before t
// by binary search, then its piece in closed form. No allocation.
template <typename Points>
Gain PiecewiseLinearGain(const Points& p, double t) {
  const std::size_t rows = RowsUpTo(p.count, p.time_of, t);
  if (rows == 0) return {};
  const std::size_t k = rows - 1;
  const double h = t - p.time_of(k);
  Gain gain;
  if (rows == p.count) {  // after the last point: no more acceleration
    gain.velocity = p.velocity_of(k);
    gain.displacement = p.displacement_of(k) + gain.velocity * h;
    return gain;
  }
  const double a0 = p.value_of(k);
  const double slope = (p.value_of(k + 1) - a0) / (p.time_of(k + 1) - p.time_of(k));
  gain.displacement =
      p.displacement_of(k) + (p.velocity_of(k) * h + a0 * h * h / 2 + slope * h * h * h / 6);
  gain.velocity = p.velocity_of(k) + (a0 * h + slope * h * h / 2);
  gain.acceleration = a0 + slope * h;
  return gain;
}

// The rows of a tabulated pulse or six-degree-of-freedom table (column 1 + axis) with their
// velocity and displacement gains.
template <std::size_t N>
auto TableAxis(const std::vector<std::array<double, N>>& rows,
               const std::vector<std::array<double, 6>>& row_gain, std::size_t axis) {
  return PiecewiseLinear{rows.size(), [&rows](std::size_t k) { return rows[k][0]; },
                         [&rows, axis](std::size_t k) { return rows[k][1 + axis]; },
                         [&row_gain, axis](std::size_t k) { return row_gain[k][axis]; },
                         [&row_gain, axis](std::size_t k) { return row_gain[k][3 + axis]; }};
}

std::array<std::array<double, 2>, 4> TrapezoidPoints(const VehicleMotion& m) {
  return {
      {{0.0, 0.0}, {m.rise, m.peak}, {m.rise + m.dwell, m.peak}, {m.rise + m.dwell + m.fall, 0.0}}};
}

Gain TrapezoidGain(const VehicleMotion& m, double t) {
  const std::array<std::array<double, 2>, 4> points = TrapezoidPoints(m);
  std::array<std::array<double, 6>, 4> gains{};
  IntegratePoints(
      points.size(), [&](std::size_t k) { return points[k][0]; },
      [&](std::size_t k) { return points[k][1]; },
      [&](std::size_t k, double velocity, double displacement) {
        gains[k][0] = velocity;
        gains[k][3] = displacement;
      });
  return PiecewiseLinearGain(
      PiecewiseLinear{points.size(), [&](std::size_t k) { return points[k][0]; },
                      [&](std::size_t k) { return points[k][1]; },
                      [&](std::size_t k) { return gains[k][0]; },
                      [&](std::size_t k) { return gains[k][3]; }},
      t);
}

// The rows of a table must have been integrated (IntegrateMotionRows) before it is evaluated.
void RequireRowGains(const VehicleMotion& m, std::size_t rows) {
  if (m.row_gain.size() != rows) {
    throw std::logic_error(
        "sled::runtime vehicle motion: a table's rows are evaluated before IntegrateMotionRows");
  }
}

Gain PulseGain(const VehicleMotion& m, double t) {
  switch (m.kind) {
    case VehicleMotion::Kind::kHalfSine:
      return HalfSineGain(m.delta_v, m.duration, t);
    case VehicleMotion::Kind::kTrapezoid:
      return TrapezoidGain(m, t);
    case VehicleMotion::Kind::kTable:
      RequireRowGains(m, m.table.size());
      return PiecewiseLinearGain(TableAxis(m.table, m.row_gain, 0), t);
    default:
      return {};
  }
}

// The row (of `count`, times from time_of) that starts the linear piece holding time `piece`,
// or `count` when none does (before the first row, from the last on). Choosing the piece by a
// time inside the step, not by the evaluation time itself, gives a step that starts or ends on
// a kink the one-sided limits it needs.
template <typename Time>
std::size_t PieceRow(std::size_t count, Time time_of, double piece) {
  const std::size_t rows = RowsUpTo(count, time_of, piece);
  return rows == 0 || rows == count ? count : rows - 1;
}

// The value at t of the linear piece through rows k and k + 1 (zero when k is no piece's row).
template <typename Time, typename Value>
double LinearPieceValue(std::size_t count, Time time_of, Value value_of, std::size_t k, double t) {
  if (k + 1 >= count) return 0.0;
  const double t0 = time_of(k), t1 = time_of(k + 1);
  return value_of(k) + (value_of(k + 1) - value_of(k)) * (t - t0) / (t1 - t0);
}

// The accelerations of a vehicle in vehicle axes at time `local` from its motion's start, on
// the smooth piece of the pulse that holds time `piece`.
struct BodyAcceleration {
  Vec3 linear = Vec3::Zero();
  Vec3 angular = Vec3::Zero();
};

BodyAcceleration BodyAccelerationAt(const VehicleMotion& m, double local, double piece) {
  BodyAcceleration out;
  switch (m.kind) {
    case VehicleMotion::Kind::kSixDof: {
      const std::size_t count = m.six_dof.size();
      auto time_of = [&](std::size_t i) { return m.six_dof[i][0]; };
      const std::size_t row = PieceRow(count, time_of, piece);
      for (std::size_t k = 0; k < 6; ++k) {
        const double value = LinearPieceValue(
            count, time_of, [&](std::size_t i) { return m.six_dof[i][1 + k]; }, row, local);
        (k < 3 ? out.linear : out.angular)[static_cast<Eigen::Index>(k % 3)] = value;
      }
      break;
    }
    case VehicleMotion::Kind::kHalfSine:
      if (piece >= 0 && piece < m.duration) {
        out.linear = m.axis * HalfSineGain(m.delta_v, m.duration, local).acceleration;
      }
      break;
    case VehicleMotion::Kind::kTrapezoid: {
      const std::array<std::array<double, 2>, 4> points = TrapezoidPoints(m);
      auto time_of = [&](std::size_t i) { return points[i][0]; };
      const std::size_t row = PieceRow(points.size(), time_of, piece);
      out.linear = m.axis * LinearPieceValue(
                                points.size(), time_of, [&](std::size_t i) { return points[i][1]; },
                                row, local);
      break;
    }
    case VehicleMotion::Kind::kTable: {
      auto time_of = [&](std::size_t i) { return m.table[i][0]; };
      const std::size_t row = PieceRow(m.table.size(), time_of, piece);
      out.linear = m.axis * LinearPieceValue(
                                m.table.size(), time_of,
                                [&](std::size_t i) { return m.table[i][1]; }, row, local);
      break;
    }
    case VehicleMotion::Kind::kNone:
      break;
  }
  return out;
}

}  // namespace

void IntegrateMotionRows(VehicleMotion& motion) {
  motion.row_gain.clear();
  auto integrate = [&](const auto& rows, std::size_t axes) {
    motion.row_gain.assign(rows.size(), {});
    for (std::size_t axis = 0; axis < axes; ++axis) {
      IntegratePoints(
          rows.size(), [&](std::size_t k) { return rows[k][0]; },
          [&](std::size_t k) { return rows[k][1 + axis]; },
          [&](std::size_t k, double velocity, double displacement) {
            motion.row_gain[k][axis] = velocity;
            motion.row_gain[k][3 + axis] = displacement;
          });
    }
  };
  if (motion.kind == VehicleMotion::Kind::kTable) integrate(motion.table, 1);
  if (motion.kind == VehicleMotion::Kind::kSixDof) integrate(motion.six_dof, 3);
}

std::vector<double> MotionBreakpoints(const VehicleMotion& m) {
  std::vector<double> times = {0.0};
  switch (m.kind) {
    case VehicleMotion::Kind::kHalfSine:
      times.push_back(m.duration);
      break;
    case VehicleMotion::Kind::kTrapezoid:
      times.insert(times.end(), {m.rise, m.rise + m.dwell, m.rise + m.dwell + m.fall});
      break;
    case VehicleMotion::Kind::kTable:
      for (const auto& row : m.table) times.push_back(row[0]);
      break;
    case VehicleMotion::Kind::kSixDof:
      for (const auto& row : m.six_dof) times.push_back(row[0]);
      break;
    case VehicleMotion::Kind::kNone:
      break;
  }
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end()), times.end());
  times.erase(std::remove_if(times.begin(), times.end(), [](double t) { return !(t >= 0); }),
              times.end());
  return times;
}

namespace {

// d/dt of a path sample's state (rotation, angular velocity, displacement, velocity) in the
// axes of the vehicle at t = 0: q' = q (0, w)/2, w' = alpha, d' = u, u' = R(q) a.
struct PathRate {
  Eigen::Vector4d rotation;  // (w, x, y, z) of q'
  Vec3 angular_velocity;
  Vec3 displacement;
  Vec3 velocity;
};

PathRate RateOf(const VehicleMotion& m, double piece, const VehiclePathSample& x) {
  const BodyAcceleration a = BodyAccelerationAt(m, x.t - m.start, piece - m.start);
  const Eigen::Quaterniond spin =
      x.rotation *
      Eigen::Quaterniond(0, x.angular_velocity.x(), x.angular_velocity.y(), x.angular_velocity.z());
  return {0.5 * Eigen::Vector4d(spin.w(), spin.x(), spin.y(), spin.z()), a.angular, x.velocity,
          x.rotation * a.linear};
}

VehiclePathSample Advanced(const VehiclePathSample& x, const PathRate& rate, double h) {
  VehiclePathSample out = x;
  out.t = x.t + h;
  out.rotation.coeffs() +=
      h * Eigen::Vector4d(rate.rotation[1], rate.rotation[2], rate.rotation[3], rate.rotation[0]);
  out.angular_velocity += h * rate.angular_velocity;
  out.displacement += h * rate.displacement;
  out.velocity += h * rate.velocity;
  return out;
}

// One classical Runge–Kutta step of the path from x over h (inside one smooth piece of the
// accelerations, so the step's error is O(h^5)); the rotation is renormalised.
VehiclePathSample PathStep(const VehicleMotion& m, const VehiclePathSample& x, double h) {
  const double piece = x.t + h / 2;  // the steps never cross a kink
  const PathRate k1 = RateOf(m, piece, x);
  const PathRate k2 = RateOf(m, piece, Advanced(x, k1, h / 2));
  const PathRate k3 = RateOf(m, piece, Advanced(x, k2, h / 2));
  const PathRate k4 = RateOf(m, piece, Advanced(x, k3, h));
  PathRate sum;
  sum.rotation = (k1.rotation + 2 * k2.rotation + 2 * k3.rotation + k4.rotation) / 6;
  sum.angular_velocity = (k1.angular_velocity + 2 * k2.angular_velocity + 2 * k3.angular_velocity +
                          k4.angular_velocity) /
                         6;
  sum.displacement =
      (k1.displacement + 2 * k2.displacement + 2 * k3.displacement + k4.displacement) / 6;
  sum.velocity = (k1.velocity + 2 * k2.velocity + 2 * k3.velocity + k4.velocity) / 6;
  VehiclePathSample out = Advanced(x, sum, h);
  out.rotation.normalize();
  return out;
}

}  // namespace

std::vector<VehiclePathSample> TabulateVehiclePath(const VehicleMotion& motion,
                                                   const Mat3& orientation,
                                                   const Vec3& angular_velocity) {
  const bool table_turns =
      motion.kind == VehicleMotion::Kind::kSixDof &&
      std::any_of(motion.six_dof.begin(), motion.six_dof.end(),
                  [](const auto& row) { return row[4] != 0 || row[5] != 0 || row[6] != 0; });
  const bool turns = table_turns || !angular_velocity.isZero();
  if (!turns) return {};
  VehiclePathSample x;
  x.angular_velocity = orientation.transpose() * angular_velocity;
  std::vector<VehiclePathSample> path = {x};
  // Before the motion starts the vehicle turns at its initial rate: one stretch from t = 0.
  std::vector<double> times = {0.0};
  for (double b : MotionBreakpoints(motion)) times.push_back(b + motion.start);
  std::sort(times.begin(), times.end());
  for (std::size_t k = 0; k + 1 < times.size(); ++k) {
    const double t0 = std::max(times[k], 0.0), t1 = times[k + 1];
    if (!(t1 > t0)) continue;
    const auto steps = static_cast<std::size_t>(std::ceil((t1 - t0) / kPathStep));
    for (std::size_t i = 1; i <= steps; ++i) {
      const double t =
          i == steps ? t1 : t0 + (t1 - t0) * static_cast<double>(i) / static_cast<double>(steps);
      path.push_back(PathStep(motion, path.back(), t - path.back().t));
    }
  }
  return path;
}

double PulseAcceleration(const VehicleMotion& motion, double t) {
  return PulseGain(motion, t - motion.start).acceleration;
}

namespace {

// The pose of a turning vehicle: one fourth-order step from the tabulated sample before t, or,
// after the last sample (no more acceleration), a steady turn at the final rate.
VehicleState TurningVehicleAt(const Model& model, std::size_t vehicle, double t) {
  const std::vector<VehiclePathSample>& path = model.vehicle_path[vehicle];
  const VehicleMotion& m = model.vehicle_motion[vehicle];
  const Mat3& R0 = model.vehicle_orientation[vehicle];
  VehiclePathSample x;
  if (t >= path.back().t) {
    const VehiclePathSample& last = path.back();
    const double h = t - last.t;
    x = last;
    x.t = t;
    const double angle = last.angular_velocity.norm() * h;
    if (angle > 0) {
      x.rotation = (last.rotation * Eigen::Quaterniond(Eigen::AngleAxisd(
                                        angle, last.angular_velocity.normalized())))
                       .normalized();
    }
    x.displacement += last.velocity * h;
  } else {
    const auto after = std::upper_bound(
        path.begin(), path.end(), t,
        [](double time, const VehiclePathSample& sample) { return time < sample.t; });
    const VehiclePathSample& before = after == path.begin() ? path.front() : *(after - 1);
    x = t > before.t ? PathStep(m, before, t - before.t) : before;
  }
  // The acceleration at t itself: the piece that starts at t (right-continuous).
  const BodyAcceleration a = BodyAccelerationAt(m, t - m.start, t - m.start);
  const Mat3 R = R0 * x.rotation.toRotationMatrix();
  VehicleState state;
  state.rotation = R;
  state.position =
      model.vehicle_position[vehicle] + model.vehicle_velocity[vehicle] * t + R0 * x.displacement;
  state.velocity = model.vehicle_velocity[vehicle] + R0 * x.velocity;
  state.acceleration = R * a.linear;
  state.angular_velocity = R * x.angular_velocity;
  state.angular_acceleration = R * a.angular;
  return state;
}

}  // namespace

VehicleState VehicleAt(const Model& model, std::size_t vehicle, double t) {
  if (vehicle < model.vehicle_path.size() && !model.vehicle_path[vehicle].empty()) {
    return TurningVehicleAt(model, vehicle, t);
  }
  const VehicleMotion& m = model.vehicle_motion[vehicle];
  VehicleState state;
  state.rotation = model.vehicle_orientation[vehicle];
  const Vec3 v0 = model.vehicle_velocity[vehicle];
  const double local = t - m.start;
  Vec3 velocity = Vec3::Zero(), displacement = Vec3::Zero(), acceleration = Vec3::Zero();
  if (m.kind == VehicleMotion::Kind::kSixDof) {
    // A table without angular acceleration: each vehicle axis in closed form.
    RequireRowGains(m, m.six_dof.size());
    for (int axis = 0; axis < 3; ++axis) {
      const Gain g = PiecewiseLinearGain(
          TableAxis(m.six_dof, m.row_gain, static_cast<std::size_t>(axis)), local);
      velocity[axis] = g.velocity;
      displacement[axis] = g.displacement;
      acceleration[axis] = g.acceleration;
    }
  } else {
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
