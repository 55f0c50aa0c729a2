#include "runtime/forces/applied_loads.h"

#include "runtime/dynamics/frame_motion.h"
#include "runtime/forces/functions.h"
#include "runtime/model/data.h"
#include "runtime/model/model.h"

namespace sled::runtime {
namespace {

// The rotation of the frame the joint above segment s hangs from: its parent segment, or the
// ground or vehicle a root is attached to.
Mat3 ParentRotation(const Model& model, const Data& data, std::size_t s) {
  const std::int32_t parent = model.segment_parent[s];
  if (parent >= 0) return data.rotation[static_cast<std::size_t>(parent)];
  return MotionOf(data, model.segment_base[s]).rotation;
}

}  // namespace

void AddAppliedForce(Data& data, std::size_t s, const Vec3& point_world, const Vec3& force_world,
                     const Vec3& torque_world) {
  const Mat3& R = data.rotation[s];
  Vec6 wrench;  // about the centre of mass, in the segment frame
  wrench.head<3>() =
      R.transpose() * (torque_world + (point_world - data.position[s]).cross(force_world));
  wrench.tail<3>() = R.transpose() * force_world;
  data.external[s] += wrench;
  data.applied_power += wrench.dot(data.velocity[s]);
}

void AddAppliedLoads(const Model& model, Data& data) {
  const LoadTable& loads = model.loads;
  const double t = data.time;
  for (std::size_t k = 0; k < loads.size(); ++k) {
    const auto s = static_cast<std::size_t>(loads.segment[k]);
    const double f = loads.force[k] >= 0 ? EvaluateFunction(model.functions, loads.force[k], t) : 0;
    const double m =
        loads.torque[k] >= 0 ? EvaluateFunction(model.functions, loads.torque[k], t) : 0;
    if (loads.kind[k] == LoadTable::Kind::kSegment) {
      const Mat3& R = data.rotation[s];
      const Vec3 direction =
          loads.in_segment[k] ? Vec3(R * loads.direction[k]) : loads.direction[k];
      const Vec3 axis = loads.in_segment[k] ? Vec3(R * loads.axis[k]) : loads.axis[k];
      AddAppliedForce(data, s, data.position[s] + R * loads.point[k], f * direction, m * axis);
      continue;
    }
    // Across a joint: on the child, and the opposite on the parent, at the joint point.
    const Vec3 axis = ParentRotation(model, data, s) * loads.axis[k];
    const Vec3 joint_point = data.position[s] + data.rotation[s] * model.joint_point_in_child[s];
    const Vec3 force =
        loads.kind[k] == LoadTable::Kind::kJointForce ? Vec3(f * axis) : Vec3::Zero();
    const Vec3 torque =
        loads.kind[k] == LoadTable::Kind::kJointTorque ? Vec3(m * axis) : Vec3::Zero();
    AddAppliedForce(data, s, joint_point, force, torque);
    const std::int32_t parent = model.segment_parent[s];
    if (parent >= 0)
      AddAppliedForce(data, static_cast<std::size_t>(parent), joint_point, -force, -torque);
  }
}

}  // namespace sled::runtime
