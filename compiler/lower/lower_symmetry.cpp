// Planar (2-D) symmetry removes the degrees of freedom that would leave the xz plane: a floating
// reference segment gets a planar joint (x, z and a turn about y), ball and Euler joints become
// pins about the axis that points along the ground's y in the initial posture, and a pin or
// slip joint whose axis would take its segment out of the plane is locked. The initial posture
// must itself lie in the plane; LowerInitialState keeps only its in-plane part and says so.
#include <cmath>

#include <fmt/format.h>

#include "compiler/lower/lowering.h"

namespace sled::compiler::lowering {
namespace {

using runtime::JointKind;

// How far from parallel two unit vectors may be and still count as parallel (or perpendicular).
constexpr double kAlignment = 1e-9;

// The torque function a ball or Euler joint keeps as a pin about `normal` (joint frame): a ball's
// twist function when the normal is its z axis, else its flexure function; for an Euler joint
// the function of the axis along the normal in the neutral posture (precession z, nutation y,
// spin x), or none.
std::int32_t PinFunction(const runtime::Model& model, std::size_t s, const runtime::Vec3& normal) {
  const auto& functions = model.joint_function[s];
  if (model.joint_kind[s] == JointKind::kBall) {
    return std::abs(normal.z()) > 1.0 - kAlignment ? functions[1] : functions[0];
  }
  const runtime::Vec3 axes[3] = {runtime::Vec3::UnitZ(), runtime::Vec3::UnitY(),
                                 runtime::Vec3::UnitX()};
  for (std::size_t k = 0; k < 3; ++k) {
    if (std::abs(normal.dot(axes[k])) > 1.0 - kAlignment) return functions[k];
  }
  return -1;
}

}  // namespace

void RestrictToPlane(Lowering& lowering, std::size_t s) {
  runtime::Model& model = lowering.model();
  JointKind& kind = model.joint_kind[s];
  const int j = lowering.joint_above[s];
  const std::string& name = model.segment_name[s];
  if (kind == JointKind::kFree) {
    // The plane of motion is the ground's xz plane through the segment's starting point.
    kind = JointKind::kPlanar;
    const Pose& pose = lowering.poses.segments[static_cast<std::size_t>(lowering.old_index[s])];
    model.joint_point_in_parent[s] = runtime::Vec3(0.0, pose.position[1], 0.0);
    return;
  }
  // The joint frame of the parent side (for a held root: its base frame), in world axes.
  runtime::Mat3 parent_joint_frame;
  if (j < 0) {
    const Constraint& held =
        lowering.scenario().constraints[static_cast<std::size_t>(lowering.base_constraint[s])];
    const bool segment_first = held.first.kind == FrameRef::Kind::kSegment;
    parent_joint_frame =
        ToEigen(lowering.poses.Of(segment_first ? held.second : held.first).rotation);
  } else {
    const int parent_old = lowering.joint(j).parent;
    parent_joint_frame =
        ToEigen(lowering.poses.segments[static_cast<std::size_t>(parent_old)].rotation) *
        model.joint_frame_in_parent[s];
  }
  // The plane's normal in the parent joint frame.
  const runtime::Vec3 normal = parent_joint_frame.transpose() * runtime::Vec3::UnitY();
  const std::string joint_name = j < 0 ? model.joint_name[s] : lowering.joint(j).name;
  const SourceRange range = j < 0 ? SourceRange{} : lowering.joint(j).range;
  switch (kind) {
    case JointKind::kBall:
    case JointKind::kEuler:
      lowering.AddNote(range, fmt::format("planar symmetry: {} joint `{}` turns only about the "
                                          "plane's normal (a pin)",
                                          runtime::JointKindName(kind), joint_name));
      model.joint_function[s] = {PinFunction(model, s, normal), -1, -1};
      if (kind == JointKind::kBall && std::abs(normal.z()) > 1.0 - kAlignment) {
        model.joint_stop[s] = model.joint_twist_stop[s];  // the pin turns as the ball's twist
      }
      kind = JointKind::kPin;
      model.joint_axis[s] = normal;
      model.joint_locked[s] = model.joint_locked[s] != 0 ? 1 : 0;
      model.joint_twist_stop[s] = 0.0;
      return;
    case JointKind::kPin:
      if (std::abs(std::abs(model.joint_axis[s].dot(normal)) - 1.0) > kAlignment &&
          model.joint_locked[s] == 0) {
        model.joint_locked[s] = 1;
        model.joint_lock_below[s] = -1.0;
        model.joint_unlock_above[s] = -1.0;
        lowering.AddNote(range, fmt::format("planar symmetry: pin joint `{}` of `{}` turns "
                                            "about an axis out of the plane's normal; it is "
                                            "locked",
                                            joint_name, name));
      }
      return;
    case JointKind::kSlip:
      if (std::abs(model.joint_axis[s].dot(normal)) > kAlignment && model.joint_locked[s] == 0) {
        model.joint_locked[s] = 1;
        model.joint_lock_below[s] = -1.0;
        model.joint_unlock_above[s] = -1.0;
        lowering.AddNote(range, fmt::format("planar symmetry: slip joint `{}` of `{}` slides out "
                                            "of the plane; it is locked",
                                            joint_name, name));
      }
      return;
    case JointKind::kFree:
    case JointKind::kPlanar:
      return;
  }
}

}  // namespace sled::compiler::lowering
