#include "runtime/dynamics.h"

#include <cmath>

#include <fmt/format.h>

#include "runtime/constraints.h"
#include "runtime/forces.h"
#include "runtime/joint.h"
#include "runtime/mirror.h"
#include "runtime/vehicle.h"

namespace sled::runtime {
namespace {

// The active joint velocities of a segment as a small vector.
SmallVector ActiveVelocities(const Model& model, const Data& data, std::size_t s) {
  int axes[6];
  const int count = ActiveAxes(model, s, data.locked[s], axes);
  SmallVector out(count);
  const auto va = static_cast<std::size_t>(model.v_address[s]);
  for (int c = 0; c < count; ++c) out[c] = data.v[va + static_cast<std::size_t>(axes[c])];
  return out;
}

// A frame's pose, spatial velocity and spatial acceleration (in its own coordinates).
struct Frame {
  Mat3 rotation = Mat3::Identity();
  Vec3 position = Vec3::Zero();
  Vec6 velocity = Vec6::Zero();
  Vec6 acceleration = Vec6::Zero();
};

Frame SegmentFrame(const Data& data, std::size_t s) {
  return {data.rotation[s], data.position[s], data.velocity[s], Vec6::Zero()};
}

Frame BaseFrame(const Model& model, const FrameRef& base, double t) {
  Frame frame;
  if (base.kind != FrameRef::Kind::kVehicle) return frame;
  const VehicleState vehicle = VehicleAt(model, static_cast<std::size_t>(base.index), t);
  frame.rotation = vehicle.rotation;
  frame.position = vehicle.position;
  const Vec3 w = vehicle.rotation.transpose() * vehicle.angular_velocity;
  frame.velocity << w, vehicle.rotation.transpose() * vehicle.velocity;
  // Spatial acceleration of a frame whose origin accelerates by a (classical): a - w x v.
  frame.acceleration << vehicle.rotation.transpose() * vehicle.angular_acceleration,
      vehicle.rotation.transpose() * vehicle.acceleration - w.cross(frame.velocity.tail<3>());
  return frame;
}

}  // namespace

Mat6 SpatialInertia(const Model& model, std::size_t segment) {
  Mat6 inertia = Mat6::Zero();
  inertia.topLeftCorner<3, 3>() = model.segment_inertia[segment];
  inertia.bottomRightCorner<3, 3>() = Mat3::Identity() * model.segment_mass[segment];
  return inertia;
}

void ComputeKinematics(const Model& model, Data& data) {
  JointMotion motion;
  for (std::size_t s = 0; s < model.nsegment(); ++s) {
    ComputeJointMotion(model, s, data.q, data.v, data.locked[s], motion);
    data.subspace[s] = motion.subspace;
    const SmallVector qdot = ActiveVelocities(model, data, s);
    const Vec6 joint_velocity = motion.subspace * qdot;
    const std::int32_t parent = model.segment_parent[s];
    Transform& x = data.parent_to_child[s];
    const Mat3& frame_parent = model.joint_frame_in_parent[s];
    const Mat3 rotation_parent_child =
        frame_parent * motion.rotation * model.joint_frame_in_child[s].transpose();
    x.E = rotation_parent_child.transpose();
    x.r = model.joint_point_in_parent[s] + frame_parent * motion.translation -
          rotation_parent_child * model.joint_point_in_child[s];
    // The parent: a segment, or for a root its base (the ground or a vehicle).
    const Frame base = parent >= 0 ? SegmentFrame(data, static_cast<std::size_t>(parent))
                                   : BaseFrame(model, model.segment_base[s], data.time);
    data.rotation[s] = base.rotation * rotation_parent_child;
    data.position[s] = base.position + base.rotation * x.r;
    data.velocity[s] = x.ApplyMotion(base.velocity) + joint_velocity;
    data.bias_acceleration[s] = CrossMotion(data.velocity[s], joint_velocity) + motion.bias;
    if (parent < 0) {
      // A moving base's acceleration enters as the root's parent acceleration.
      data.bias_acceleration[s] += x.ApplyMotion(base.acceleration);
    }
  }
}

bool ComputeAccelerations(const Model& model, Data& data, Failure* failure) {
  const std::size_t n = model.nsegment();
  // Bias forces: gyroscopic terms less the applied wrenches.
  for (std::size_t s = 0; s < n; ++s) {
    data.articulated_inertia[s] = SpatialInertia(model, s);
    data.articulated_bias[s] =
        CrossForce(data.velocity[s], data.articulated_inertia[s] * data.velocity[s]) -
        data.external[s];
  }
  // Leaves to roots: articulated inertias and biases, each handed to the parent.
  for (std::size_t i = n; i-- > 0;) {
    const MotionSubspace& S = data.subspace[i];
    const Mat6& IA = data.articulated_inertia[i];
    int axes[6];
    const int count = ActiveAxes(model, i, data.locked[i], axes);
    data.u_matrix[i] = IA * S;
    const SmallMatrix D = S.transpose() * data.u_matrix[i];
    SmallVector tau(count);
    const auto va = static_cast<std::size_t>(model.v_address[i]);
    for (int c = 0; c < count; ++c) {
      tau[c] = data.generalized_force[va + static_cast<std::size_t>(axes[c])];
    }
    data.u_vector[i] = tau - S.transpose() * data.articulated_bias[i];
    if (count > 0) {
      // D = S^T I^A S is symmetric positive definite for a physical segment; a closed-form
      // inverse for the common one- and three-axis joints, LU otherwise.
      if (count == 1) {
        data.d_inverse[i] = SmallMatrix::Constant(1, 1, 1.0 / D(0, 0));
      } else if (count == 3) {
        data.d_inverse[i] = Eigen::Matrix3d(D).inverse();
      } else {
        data.d_inverse[i] = D.inverse();
      }
      if (!data.d_inverse[i].allFinite()) {
        if (failure) {
          failure->where = model.segment_name[i];
          failure->cause =
              "the articulated inertia is singular (a massless segment without "
              "enough constraints?)";
        }
        return false;
      }
    } else {
      data.d_inverse[i].resize(0, 0);
    }
    const std::int32_t parent = model.segment_parent[i];
    if (parent < 0) continue;
    const auto p = static_cast<std::size_t>(parent);
    Mat6 Ia = IA;
    Vec6 pa = data.articulated_bias[i] + IA * data.bias_acceleration[i];
    if (count > 0) {
      Ia -= data.u_matrix[i] * data.d_inverse[i] * data.u_matrix[i].transpose();
      pa = data.articulated_bias[i] + Ia * data.bias_acceleration[i] +
           data.u_matrix[i] * (data.d_inverse[i] * data.u_vector[i]);
    }
    Mat6 inertia_to_parent = data.parent_to_child[i].TransposeApplyInertia(Ia);
    Vec6 bias_to_parent = data.parent_to_child[i].TransposeApplyForce(pa);
    if (i < model.segment_mirror_twin.size() && model.segment_mirror_twin[i]) {
      AddMirrorImage(model.mirror_normal[i], inertia_to_parent, bias_to_parent);
    }
    data.articulated_inertia[p] += inertia_to_parent;
    data.articulated_bias[p] += bias_to_parent;
  }
  // Roots to leaves: accelerations; then the wrench each joint transmits.
  for (std::size_t i = 0; i < n; ++i) {
    const std::int32_t parent = model.segment_parent[i];
    const Vec6 a_prime = parent < 0
                             ? Vec6(data.bias_acceleration[i])
                             : Vec6(data.parent_to_child[i].ApplyMotion(
                                        data.acceleration[static_cast<std::size_t>(parent)]) +
                                    data.bias_acceleration[i]);
    int axes[6];
    const int count = ActiveAxes(model, i, data.locked[i], axes);
    const auto va = static_cast<std::size_t>(model.v_address[i]);
    for (int k = 0; k < model.v_count[i]; ++k) data.vdot[va + static_cast<std::size_t>(k)] = 0.0;
    Vec6 a = a_prime;
    if (count > 0) {
      const SmallVector qdd =
          data.d_inverse[i] * (data.u_vector[i] - data.u_matrix[i].transpose() * a_prime);
      a += data.subspace[i] * qdd;
      for (int c = 0; c < count; ++c) data.vdot[va + static_cast<std::size_t>(axes[c])] = qdd[c];
    }
    data.acceleration[i] = a;
    data.joint_wrench[i] = data.articulated_inertia[i] * a + data.articulated_bias[i];
    if (!a.allFinite()) {
      if (failure) {
        failure->where = model.segment_name[i];
        failure->cause = "the acceleration is not finite";
      }
      return false;
    }
  }
  return true;
}

bool Forward(const Model& model, Data& data, Failure* failure) {
  ++data.evaluations;
  ComputeKinematics(model, data);
  ComputeForces(model, data);
  if (!ComputeAccelerations(model, data, failure)) {
    // A singular (massless) segment: the tree alone leaves its motion open; constraints on it
    // may settle it, solved together with the tree's equations.
    if (model.nconstraint() == 0) return false;
    Failure singular;
    if (failure) singular = *failure;
    if (ApplyConstraintsToSingularTree(model, data, failure)) return true;
    if (failure) {
      failure->cause = fmt::format("{}; with the constraints: {}", singular.cause, failure->cause);
    }
    return false;
  }
  if (model.nconstraint() > 0) return ApplyConstraints(model, data, failure);
  return true;
}

}  // namespace sled::runtime
