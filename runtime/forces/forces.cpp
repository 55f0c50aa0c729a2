#include "runtime/forces/forces.h"

#include <cmath>

#include "runtime/airbag/airbag_forces.h"
#include "runtime/contact/contact_forces.h"
#include "runtime/dynamics/frame_motion.h"
#include "runtime/dynamics/joint.h"
#include "runtime/dynamics/vehicle.h"
#include "runtime/forces/actuators.h"
#include "runtime/forces/fluid_forces.h"
#include "runtime/forces/functions.h"
#include "runtime/forces/joint_hysteresis.h"
#include "runtime/restraint/belts.h"

namespace sled::runtime {
namespace {

// Coulomb friction as a smooth function of the rate: full torque above this rate [rad/s], so
// the equations stay Lipschitz for the integrators.
constexpr double kCoulombRate = 1e-2;

double SmoothSign(double x) { return std::tanh(x / kCoulombRate); }

void JointTorques(const Model& model, Data& data, std::size_t s) {
  const auto qa = static_cast<std::size_t>(model.q_address[s]);
  const auto va = static_cast<std::size_t>(model.v_address[s]);
  const auto& f = model.joint_function[s];
  const double viscous = model.joint_viscous[s];
  const double coulomb = model.joint_coulomb[s];
  double* tau = data.generalized_force.data() + va;
  switch (model.joint_kind[s]) {
    case JointKind::kFree:
    case JointKind::kPlanar:
      return;
    case JointKind::kPin:
    case JointKind::kSlip: {
      const double angle = data.q[qa], rate = data.v[va];
      tau[0] =
          JointSpringTorque(model, data, s, 0, angle) - viscous * rate - coulomb * SmoothSign(rate);
      return;
    }
    case JointKind::kEuler:
      for (std::size_t k = 0; k < 3; ++k) {
        const double angle = data.q[qa + k], rate = data.v[va + k];
        tau[k] = JointSpringTorque(model, data, s, k, angle) - viscous * rate -
                 coulomb * SmoothSign(rate);
      }
      return;
    case JointKind::kBall: {
      // A ball joint without characteristics applies nothing: skip the decomposition (the
      // generalized forces were zeroed before the joints were visited).
      if (f[0] < 0 && f[1] < 0 && viscous == 0 && coulomb == 0) return;
      const SwingTwist angles = DecomposeSwingTwist(QuaternionAt(data.q, qa).normalized());
      const Mat3& frame_child = model.joint_frame_in_child[s];
      const Mat3 rotation = QuaternionAt(data.q, qa).normalized().toRotationMatrix();
      // Flexure acts about the swing axis (parent joint frame), twist about the child's z.
      const Vec3 flexure_torque =
          angles.flexure_axis * JointSpringTorque(model, data, s, 0, angles.flexure);
      const Vec3 twist_torque = Vec3::UnitZ() * JointSpringTorque(model, data, s, 1, angles.twist);
      const Vec3 w(data.v[va], data.v[va + 1], data.v[va + 2]);
      const double speed = w.norm();
      Vec3 torque =
          frame_child * (rotation.transpose() * flexure_torque + twist_torque) - viscous * w;
      if (coulomb > 0 && speed > 0) torque -= coulomb * SmoothSign(speed) * w / speed;
      for (int k = 0; k < 3; ++k) tau[k] = torque[k];
      return;
    }
  }
}

}  // namespace

void AddPointForce(Data& data, std::size_t segment, const Vec3& point_world,
                   const Vec3& force_world) {
  const Mat3& R = data.rotation[segment];
  const Vec3 force = R.transpose() * force_world;
  const Vec3 arm = R.transpose() * (point_world - data.position[segment]);
  data.external[segment].head<3>() += arm.cross(force);
  data.external[segment].tail<3>() += force;
}

void AddFrameForce(Data& data, const FrameRef& frame, const Vec3& point_world,
                   const Vec3& force_world, double weight) {
  switch (frame.kind) {
    case FrameRef::Kind::kSegment:
      AddPointForce(data, static_cast<std::size_t>(frame.index), point_world, force_world);
      return;
    case FrameRef::Kind::kVehicle: {
      const VehicleState& vehicle = data.vehicle[static_cast<std::size_t>(frame.index)];
      const Vec3 velocity =
          vehicle.velocity + vehicle.angular_velocity.cross(point_world - vehicle.position);
      data.vehicle_power += weight * force_world.dot(velocity);
      return;
    }
    case FrameRef::Kind::kGround:
      return;
  }
}

SwingTwist DecomposeSwingTwist(const Eigen::Quaterniond& rotation) {
  Eigen::Quaterniond q = rotation;
  if (q.w() < 0) q.coeffs() = -q.coeffs();
  SwingTwist out;
  const double twist_norm = std::hypot(q.w(), q.z());
  Eigen::Quaterniond twist(1, 0, 0, 0);
  if (twist_norm > 1e-12) twist = Eigen::Quaterniond(q.w() / twist_norm, 0, 0, q.z() / twist_norm);
  out.twist = 2 * std::atan2(twist.z(), twist.w());
  const Eigen::Quaterniond swing = q * twist.conjugate();
  const double sin_half = swing.vec().norm();
  out.flexure = 2 * std::atan2(sin_half, std::abs(swing.w()));
  if (sin_half > 1e-12) out.flexure_axis = swing.vec() / sin_half * (swing.w() < 0 ? -1 : 1);
  return out;
}

PointState PointInFrame(const Data& data, const FrameRef& frame, const Vec3& point) {
  const FrameMotion motion = MotionOf(data, frame);
  const Vec3 position = motion.origin + motion.rotation * point;
  return {position, VelocityAt(motion, position)};
}

void ComputeJointTorques(const Model& model, Data& data) {
  std::fill(data.generalized_force.begin(), data.generalized_force.end(), 0.0);
  for (std::size_t s = 0; s < model.nsegment(); ++s) JointTorques(model, data, s);
}

void ComputeForces(const Model& model, Data& data) {
  ComputeJointTorques(model, data);
  ComputeElementForces(model, data);
}

void ComputeElementForces(const Model& model, Data& data) {
  for (std::size_t s = 0; s < model.nsegment(); ++s) {
    data.external[s].setZero();
    data.external[s].tail<3>() =
        model.segment_mass[s] * (data.rotation[s].transpose() * model.gravity);
  }
  data.vehicle_power = 0.0;
  data.applied_power = 0.0;
  if (model.contacts.npair() > 0) AccumulateContactForces(model, data);

  for (std::size_t k = 0; k < model.nspring(); ++k) {
    const PointState a = PointInFrame(data, model.spring_first[k], model.spring_point_first[k]);
    const PointState b = PointInFrame(data, model.spring_second[k], model.spring_point_second[k]);
    const Vec3 gap = b.position - a.position;
    const double length = gap.norm();
    data.spring_length[k] = length;
    const Vec3 direction = length > 1e-12 ? Vec3(gap / length) : Vec3::UnitX();
    const double elongation = length - model.spring_free_length[k];
    const double rate = direction.dot(b.velocity - a.velocity);
    double force = EvaluateFunction(model.functions, model.spring_function[k], elongation) +
                   model.spring_damping[k] * rate;
    if (model.spring_tension_only[k] && (elongation <= 0 || force < 0)) force = 0.0;
    data.spring_force[k] = force;
    // Tension pulls the first point toward the second and the second toward the first.
    AddFrameForce(data, model.spring_first[k], a.position, force * direction);
    AddFrameForce(data, model.spring_second[k], b.position, -force * direction);
  }
  ComputeBeltForces(model, data);
  if (model.airbags.size() > 0) ComputeAirbagForces(model, data);
  if (model.loads.size() > 0) AddAppliedLoads(model, data);
  if (model.actuators.size() > 0) AddActuatorTorques(model, data);
  if (model.fluids.size() > 0) AddFluidForces(model, data);
}

}  // namespace sled::runtime
