#include "runtime/run/energy.h"

#include <cmath>

#include "runtime/dynamics/constraints.h"

namespace sled::runtime {
double MirrorWeight(const Model& model, std::size_t segment) {
  return model.segment_mirror_count.empty() ? 1.0 : model.segment_mirror_count[segment];
}

double KineticEnergy(const Model& model, const Data& data) {
  double sum = 0.0;
  for (std::size_t s = 0; s < model.nsegment(); ++s) {
    const Vec3 w = data.velocity[s].head<3>();
    const Vec3 v = data.velocity[s].tail<3>();
    sum += MirrorWeight(model, s) * 0.5 *
           (model.segment_mass[s] * v.squaredNorm() + w.dot(model.segment_inertia[s] * w));
  }
  return sum;
}

double PotentialEnergy(const Model& model, const Data& data) {
  double sum = 0.0;
  for (std::size_t s = 0; s < model.nsegment(); ++s) {
    sum -= MirrorWeight(model, s) * model.segment_mass[s] * model.gravity.dot(data.position[s]);
  }
  return sum;
}

SegmentPower PowerIntoSegments(const Model& model, const Data& data) {
  SegmentPower power;
  for (std::size_t s = 0; s < model.nsegment(); ++s) {
    // data.external holds gravity too: take it out, the potential energy accounts for it.
    Vec6 applied = data.external[s];
    applied.tail<3>() -= model.segment_mass[s] * (data.rotation[s].transpose() * model.gravity);
    double joint = 0.0;
    const auto va = static_cast<std::size_t>(model.v_address[s]);
    const auto dof = static_cast<std::size_t>(model.v_count[s]);
    for (std::size_t k = va; k < va + dof; ++k) joint += data.generalized_force[k] * data.v[k];
    const double before = power.elements + power.constraints;
    power.elements += MirrorWeight(model, s) * (applied.dot(data.velocity[s]) + joint);
    // A root jointed to a moving vehicle: the joint's reaction (the wrench the vehicle transmits)
    // works on the vehicle's motion at the segment; its part along the joint's free axes is the
    // joint torque, counted above.
    if (model.segment_parent[s] < 0 && model.segment_base[s].kind == FrameRef::Kind::kVehicle &&
        model.joint_kind[s] != JointKind::kFree) {
      const VehicleState& vehicle =
          data.vehicle[static_cast<std::size_t>(model.segment_base[s].index)];
      const Mat3& R = data.rotation[s];
      Vec6 base_velocity;
      base_velocity.head<3>() = R.transpose() * vehicle.angular_velocity;
      base_velocity.tail<3>() =
          R.transpose() *
          (vehicle.velocity + vehicle.angular_velocity.cross(data.position[s] - vehicle.position));
      power.constraints += MirrorWeight(model, s) * data.joint_wrench[s].dot(base_velocity);
    }
    if (data.constraints) {
      power.constraints +=
          MirrorWeight(model, s) * data.constraints->segment_wrench[s].dot(data.velocity[s]);
    }
    if (power.not_finite < 0 && std::isfinite(before) &&
        !std::isfinite(power.elements + power.constraints)) {
      power.not_finite = static_cast<std::ptrdiff_t>(s);
    }
  }
  return power;
}

}  // namespace sled::runtime
