// Planar (2-D) symmetry removes the degrees of freedom that would leave the xz plane: a floating
// reference segment gets a planar joint (x, z and a turn about y), ball and Euler joints become
// pins about the axis that points along the ground's y in the initial posture, and a pin or
// slip joint whose axis would take its segment out of the plane is locked. The initial posture
// must itself lie in the plane; LowerInitialState keeps only its in-plane part and says so.
#include <algorithm>
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
      lowering.AddNote(lang::DiagnosticKind::kReducedBySymmetry, range,
                       fmt::format("planar symmetry: {} joint `{}` turns only about the "
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
        lowering.AddNote(lang::DiagnosticKind::kReducedBySymmetry, range,
                         fmt::format("planar symmetry: pin joint `{}` of `{}` turns "
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
        lowering.AddNote(lang::DiagnosticKind::kReducedBySymmetry, range,
                         fmt::format("planar symmetry: slip joint `{}` of `{}` slides out "
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

namespace sled::compiler::lowering {
namespace {

// The checked segment a non-null joint hangs `old` from, or -1 for a root.
int ParentOf(const CheckedScenario& scenario, int old) {
  for (const Joint& joint : scenario.joints) {
    if (joint.type != JointType::kNull && joint.child == old) return joint.parent;
  }
  return -1;
}

}  // namespace

void PlanMirrorSymmetry(Lowering& lowering) {
  const CheckedScenario& scenario = lowering.scenario();
  const RunSettings& run = scenario.run;
  if (run.symmetry != Symmetry::kMirror) return;
  const std::size_t count = scenario.segments.size();
  std::vector<int> twin(count, -1);      // right -> left
  std::vector<int> right_of(count, -1);  // left -> right
  for (const auto& [left, right] : run.mirror_pairs) {
    twin[static_cast<std::size_t>(right)] = left;
    right_of[static_cast<std::size_t>(left)] = right;
  }
  auto refuse = [&](const std::string& why) {
    lowering.AddNote(lang::DiagnosticKind::kReducedBySymmetry, {},
                     fmt::format("mirror symmetry is not applied: {}; every segment keeps "
                                 "all its degrees of freedom",
                                 why));
  };
  auto name = [&](int old) { return scenario.segments[static_cast<std::size_t>(old)].name; };
  for (const auto& [left, right] : run.mirror_pairs) {
    const int left_parent = ParentOf(scenario, left), right_parent = ParentOf(scenario, right);
    const bool same_centre =
        left_parent == right_parent &&
        (left_parent < 0 || (twin[static_cast<std::size_t>(left_parent)] < 0 &&
                             right_of[static_cast<std::size_t>(left_parent)] < 0));
    const bool twin_parents = left_parent >= 0 && right_parent >= 0 &&
                              right_of[static_cast<std::size_t>(left_parent)] == right_parent;
    if (!same_centre && !twin_parents) {
      return refuse(
          fmt::format("`{}` and `{}` do not hang from the same segment in the plane "
                      "or from two twins",
                      name(left), name(right)));
    }
  }
  for (const Joint& joint : scenario.joints) {
    if (joint.type == JointType::kNull) continue;
    if (twin[static_cast<std::size_t>(joint.parent)] >= 0 &&
        twin[static_cast<std::size_t>(joint.child)] < 0) {
      return refuse(
          fmt::format("`{}` hangs from the right segment `{}` but is not the right "
                      "one of a pair",
                      name(joint.child), name(joint.parent)));
    }
    // A left segment stands for its twin's whole subtree: a child without a pair would be
    // restricted to the plane as if it were on the centre line.
    if (right_of[static_cast<std::size_t>(joint.parent)] >= 0 &&
        right_of[static_cast<std::size_t>(joint.child)] < 0) {
      return refuse(
          fmt::format("`{}` hangs from the left segment `{}` but is not the left "
                      "one of a pair",
                      name(joint.child), name(joint.parent)));
    }
  }
  auto on_right = [&](const FrameRef& frame) {
    return frame.kind == FrameRef::Kind::kSegment &&
           twin[static_cast<std::size_t>(frame.index)] >= 0;
  };
  for (const SpringDamper& spring : scenario.springs) {
    if (on_right(spring.first) || on_right(spring.second)) {
      return refuse(fmt::format("spring `{}` acts on a right segment", spring.name));
    }
  }
  // A load acts on one segment: the left one would stand for both, a centre one be pulled
  // sideways with nothing to balance it.
  if (!scenario.loads.empty()) {
    return refuse(fmt::format("load `{}` acts on one side only", scenario.loads.front().name));
  }
  if (!scenario.actuators.empty()) {
    return refuse(
        fmt::format("actuator `{}` drives one side only", scenario.actuators.front().name));
  }
  for (const Belt& belt : scenario.belts) {
    for (const BeltPoint& point : belt.path) {
      const bool right = point.kind == BeltPoint::Kind::kSegment
                             ? twin[static_cast<std::size_t>(point.segment)] >= 0
                             : on_right(point.frame);
      if (right) return refuse(fmt::format("belt `{}` runs over a right segment", belt.name));
    }
  }
  for (std::size_t c = 0; c < scenario.constraints.size(); ++c) {
    const Constraint& constraint = scenario.constraints[c];
    const bool holds_a_root = (constraint.kind == Constraint::Kind::kFixedPoint ||
                               constraint.kind == Constraint::Kind::kWelded) &&
                              ((constraint.first.kind == FrameRef::Kind::kSegment &&
                                constraint.second.kind != FrameRef::Kind::kSegment &&
                                HoldingConstraintOf(lowering.scenario(), constraint.first.index) ==
                                    static_cast<int>(c)) ||
                               (constraint.second.kind == FrameRef::Kind::kSegment &&
                                constraint.first.kind != FrameRef::Kind::kSegment &&
                                HoldingConstraintOf(lowering.scenario(), constraint.second.index) ==
                                    static_cast<int>(c)));
    if (!holds_a_root) {
      return refuse(
          fmt::format("constraint `{}` closes a loop (loops are solved with the full "
                      "mass matrix, which knows no mirror images)",
                      constraint.name));
    }
  }
  lowering.mirror_twin = std::move(twin);
  // The plane: y of the first segment in it (a reference segment), else y = 0.
  for (std::size_t old = 0; old < count; ++old) {
    if (lowering.mirror_twin[old] < 0 && right_of[old] < 0 &&
        ParentOf(scenario, static_cast<int>(old)) < 0) {
      lowering.model().mirror_plane_y = lowering.poses.segments[old].position[1];
      break;
    }
  }
}

void ApplyMirrorSymmetry(Lowering& lowering, std::size_t s) {
  if (lowering.mirror_twin.empty()) return;
  runtime::Model& model = lowering.model();
  const int old = lowering.old_index[s];
  const CheckedScenario& scenario = lowering.scenario();
  const bool left = std::find(lowering.mirror_twin.begin(), lowering.mirror_twin.end(), old) !=
                    lowering.mirror_twin.end();
  model.segment_mirror_twin.push_back(0);
  model.mirror_normal.push_back(runtime::Vec3::Zero());
  // A left segment stands for its right twin, and so does all that hangs from it (the twin's
  // subtree is left out whole), however deep below the plane.
  const std::int32_t model_parent = model.segment_parent[s];
  const bool below_left =
      model_parent >= 0 && model.segment_mirror_count[static_cast<std::size_t>(model_parent)] == 2;
  model.segment_mirror_count.push_back(left || below_left ? 2 : 1);
  if (!left) {
    RestrictToPlane(lowering, s);
    return;
  }
  const int parent = ParentOf(scenario, old);
  const bool parent_in_plane =
      parent >= 0 && std::find(lowering.mirror_twin.begin(), lowering.mirror_twin.end(), parent) ==
                         lowering.mirror_twin.end();
  if (!parent_in_plane) return;
  model.segment_mirror_twin.back() = 1;
  model.mirror_normal.back() =
      ToEigen(lowering.poses.segments[static_cast<std::size_t>(parent)].rotation).transpose() *
      runtime::Vec3::UnitY();
}

}  // namespace sled::compiler::lowering
