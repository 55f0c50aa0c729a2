#include "runtime/forces/joint_hysteresis.h"

#include <array>
#include <cmath>

#include "runtime/dynamics/joint.h"
#include "runtime/forces/forces.h"
#include "runtime/forces/functions.h"
#include "runtime/model/data.h"

namespace sled::runtime {
namespace {

// Turns within this of the largest angle so far (rad, or m for a slip joint) are no events: the
// axis loads and unloads elastically over that span. Without it an axis resting at an angle
// (most often zero, between its two sides) turns at every step on the integrator's noise, and
// each turn stops the step.
constexpr double kTurnResolution = 1e-6;

// An axis's angle (a ball joint's flexure: its size) and its rate, for the histories.
struct AxisMotion {
  double angle = 0.0;
  double rate = 0.0;
  bool locked = false;
};

// The ball joint's flexure (k = 0) or twist (k = 1) and their rates. The quaternion turns the
// child joint frame into the parent's; its rate is q (0, w) / 2 with w in the child joint frame.
AxisMotion BallAxis(const Model& model, const Data& data, std::size_t s, std::size_t k) {
  const auto qa = static_cast<std::size_t>(model.q_address[s]);
  const auto va = static_cast<std::size_t>(model.v_address[s]);
  Eigen::Quaterniond q = QuaternionAt(data.q, qa).normalized();
  if (q.w() < 0) q.coeffs() = -q.coeffs();
  const Vec3 w_child(data.v[va], data.v[va + 1], data.v[va + 2]);
  const Vec3 w = model.joint_frame_in_child[s].transpose() * w_child;
  const SwingTwist angles = DecomposeSwingTwist(q);
  AxisMotion motion;
  motion.locked = data.locked[s] != 0;
  if (k == 0) {
    // cos(flexure) is R_zz (the swing turns z by the flexure angle), and dR/dt = R [w]x.
    motion.angle = angles.flexure;
    const double sine = std::sin(angles.flexure);
    const Mat3 rotation = q.toRotationMatrix();
    motion.rate =
        sine > 1e-9 ? -rotation.row(2).dot(w.cross(Vec3::UnitZ())) / sine : w.head<2>().norm();
    return motion;
  }
  // twist = 2 atan2(q_z, q_w).
  const Eigen::Quaterniond rate = q * Eigen::Quaterniond(0, 0.5 * w.x(), 0.5 * w.y(), 0.5 * w.z());
  const double norm = q.w() * q.w() + q.z() * q.z();
  motion.angle = angles.twist;
  motion.rate = norm > 1e-18 ? 2 * (q.w() * rate.z() - q.z() * rate.w()) / norm : 0.0;
  return motion;
}

AxisMotion MotionOfAxis(const Model& model, const Data& data, std::size_t s, std::size_t k) {
  const auto qa = static_cast<std::size_t>(model.q_address[s]);
  const auto va = static_cast<std::size_t>(model.v_address[s]);
  switch (model.joint_kind[s]) {
    case JointKind::kBall:
      return BallAxis(model, data, s, k);
    case JointKind::kEuler:
      return {data.q[qa + k], data.v[va + k], (data.locked[s] & (1u << k)) != 0};
    case JointKind::kPin:
    case JointKind::kSlip:
      return {data.q[qa], data.v[va], data.locked[s] != 0};
    case JointKind::kFree:
    case JointKind::kPlanar:
      break;
  }
  return {};
}

// The side of the angle (+1, -1), and how its function reads there
// (runtime/forces/force_deflection.h): mirrored on the negative side of a table that covers
// negative angles.
struct Side {
  double sign = 1.0;
  double mirror = 1.0;
};
Side SideOf(const FunctionTable& functions, std::int32_t id, double angle) {
  if (angle >= 0) return {};
  return {-1.0, CoversNegative(functions, id) ? -1.0 : 1.0};
}

}  // namespace

void SizeJointHistories(const Model& model, JointHistories& histories) {
  histories = JointHistories{};
  histories.of_axis.assign(model.nsegment(), {-1, -1, -1});
  for (std::size_t s = 0; s < model.nsegment(); ++s) {
    for (std::size_t k = 0; k < 3; ++k) {
      if (!HasHysteresis(model.functions, model.joint_function[s][k])) continue;
      histories.of_axis[s][k] = static_cast<std::int32_t>(histories.size());
      histories.segment.push_back(static_cast<std::uint32_t>(s));
      histories.axis.push_back(static_cast<std::uint8_t>(k));
    }
  }
  histories.positive.assign(histories.size(), LoadingHistory{});
  histories.negative.assign(histories.size(), LoadingHistory{});
}

void SetUpJointHistories(const Model& model, Data& data) {
  for (std::size_t h = 0; h < data.joint_histories.size(); ++h) TurnJointHistory(model, data, h);
}

double JointSpringTorque(const Model& model, const Data& data, std::size_t s, std::size_t k,
                         double angle) {
  const std::int32_t id = model.joint_function[s][k];
  const JointHistories& histories = data.joint_histories;
  const std::int32_t h = s < histories.of_axis.size() ? histories.of_axis[s][k] : -1;
  if (h < 0) return RestoringTorque(model.functions, id, angle);
  const Side side = SideOf(model.functions, id, angle);
  const auto at = static_cast<std::size_t>(h);
  const LoadingHistory& history = side.sign > 0 ? histories.positive[at] : histories.negative[at];
  return -side.sign *
         LoadingUnloadingForce(model.functions, id, std::abs(angle), history, side.mirror);
}

std::array<double, 3> JointAxisAngles(const Model& model, const Data& data, std::size_t s) {
  const auto qa = static_cast<std::size_t>(model.q_address[s]);
  switch (model.joint_kind[s]) {
    case JointKind::kBall: {
      // As BallAxis, without the rates: one decomposition for both axes.
      Eigen::Quaterniond q = QuaternionAt(data.q, qa).normalized();
      if (q.w() < 0) q.coeffs() = -q.coeffs();
      const SwingTwist angles = DecomposeSwingTwist(q);
      return {angles.flexure, angles.twist, 0.0};
    }
    case JointKind::kEuler:
      return {data.q[qa], data.q[qa + 1], data.q[qa + 2]};
    case JointKind::kPin:
    case JointKind::kSlip:
      return {data.q[qa], data.q[qa], data.q[qa]};
    case JointKind::kFree:
    case JointKind::kPlanar:
      break;
  }
  return {0.0, 0.0, 0.0};
}

double JointTurnFunction(const Model& model, const Data& data, std::size_t h) {
  const JointHistories& histories = data.joint_histories;
  const std::size_t s = histories.segment[h];
  const AxisMotion motion = MotionOfAxis(model, data, s, histories.axis[h]);
  const double largest = motion.angle >= 0 ? histories.positive[h].max_deflection
                                           : histories.negative[h].max_deflection;
  if (motion.locked || !(std::abs(motion.angle) > largest + kTurnResolution)) return 1.0;
  return motion.angle >= 0 ? motion.rate : -motion.rate;
}

void TurnJointHistory(const Model& model, Data& data, std::size_t h) {
  JointHistories& histories = data.joint_histories;
  const std::size_t s = histories.segment[h];
  const std::size_t k = histories.axis[h];
  const std::int32_t id = model.joint_function[s][k];
  const double angle = MotionOfAxis(model, data, s, k).angle;
  const Side side = SideOf(model.functions, id, angle);
  LoadingHistory& history = side.sign > 0 ? histories.positive[h] : histories.negative[h];
  UpdateLoadingHistory(model.functions, id, std::abs(angle), history, side.mirror);
}

}  // namespace sled::runtime
