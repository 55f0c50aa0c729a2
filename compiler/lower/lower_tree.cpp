// Segments in tree order and the joints above them: for each body, its reference segments first,
// then each tree depth first with children in the order their joints were declared.
#include <algorithm>
#include <stdexcept>
#include <vector>

#include <fmt/format.h>

#include "compiler/lower/lowering.h"
#include "runtime/model/dummy_types.h"

namespace sled::compiler::lowering {
namespace {

using runtime::JointKind;

JointKind KindOf(JointType type) {
  switch (type) {
    case JointType::kBall:
      return JointKind::kBall;
    case JointType::kPin:
      return JointKind::kPin;
    case JointType::kEuler:
      return JointKind::kEuler;
    case JointType::kSlip:
      return JointKind::kSlip;
    case JointType::kNull:
      break;
  }
  return JointKind::kFree;
}

// The order: fills new_index, old_index and joint_above.
void OrderSegments(Lowering& lowering) {
  const CheckedScenario& scenario = lowering.scenario();
  const std::size_t count = scenario.segments.size();
  std::vector<std::vector<int>> child_joints(count);
  for (const Body& body : scenario.bodies) {
    for (int j : body.joints) {
      const Joint& joint = lowering.joint(j);
      lowering.segment(joint.parent);
      lowering.segment(joint.child);
      if (joint.type != JointType::kNull) {
        child_joints[static_cast<std::size_t>(joint.parent)].push_back(j);
      }
    }
  }
  lowering.new_index.assign(count, -1);
  lowering.old_index.clear();
  lowering.joint_above.clear();
  auto place = [&](int old, int joint) {
    if (lowering.new_index[static_cast<std::size_t>(old)] >= 0) {
      throw std::logic_error(fmt::format("compiler::Lower: segment `{}` is reached twice",
                                         lowering.segment(old).name));
    }
    lowering.new_index[static_cast<std::size_t>(old)] = static_cast<int>(lowering.old_index.size());
    lowering.old_index.push_back(old);
    lowering.joint_above.push_back(joint);
  };
  for (const Body& body : scenario.bodies) {
    for (int root : body.reference_segments) {
      lowering.segment(root);  // checks the index
      if (!lowering.Dropped(root)) place(root, -1);
    }
    for (int root : body.reference_segments) {
      if (lowering.Dropped(root)) continue;  // a right twin and all that hangs from it
      // Depth first, preorder: a stack of joints still to visit, last child on top.
      std::vector<int> stack(child_joints[static_cast<std::size_t>(root)].rbegin(),
                             child_joints[static_cast<std::size_t>(root)].rend());
      while (!stack.empty()) {
        const int j = stack.back();
        stack.pop_back();
        const Joint& joint = lowering.joint(j);
        if (lowering.Dropped(joint.child)) continue;
        place(joint.child, j);
        const auto& next = child_joints[static_cast<std::size_t>(joint.child)];
        stack.insert(stack.end(), next.rbegin(), next.rend());
      }
    }
  }
  for (std::size_t s = 0; s < count; ++s) {
    if (lowering.new_index[s] < 0 && !lowering.Dropped(static_cast<int>(s))) {
      throw std::logic_error(fmt::format(
          "compiler::Lower: segment `{}` is in no joint tree (was the scenario checked?)",
          scenario.segments[s].name));
    }
  }
}

// Each segment's ISO/TS 13499 dummy type, its body's (runtime::kNoDummyCode when the body names
// none); left empty when no body names one.
void LowerDummyTypes(Lowering& lowering) {
  const CheckedScenario& scenario = lowering.scenario();
  const auto named = [](const Body& body) { return !body.dummy.empty(); };
  if (std::none_of(scenario.bodies.begin(), scenario.bodies.end(), named)) return;
  runtime::Model& model = lowering.model();
  for (const int old : lowering.old_index) {
    const int body = lowering.segment(old).body;
    const std::string& dummy =
        body >= 0 ? scenario.bodies[static_cast<std::size_t>(body)].dummy : std::string();
    model.segment_dummy.push_back(dummy.empty() ? std::string(runtime::kNoDummyCode) : dummy);
  }
}

}  // namespace

void LowerTree(Lowering& lowering) {
  lowering.constraint_is_base_joint.assign(lowering.scenario().constraints.size(), false);
  PlanMirrorSymmetry(lowering);
  OrderSegments(lowering);
  runtime::Model& model = lowering.model();
  const std::size_t n = lowering.old_index.size();
  model.segment_name.reserve(n);
  std::int32_t nq = 0;
  std::int32_t nv = 0;
  for (std::size_t s = 0; s < n; ++s) {
    const int old = lowering.old_index[s];
    const Segment& segment = lowering.segment(old);
    const int j = lowering.joint_above[s];
    model.segment_name.push_back(segment.name);
    model.segment_mass.push_back(segment.mass);
    const runtime::Mat3 axes = RotationMatrix(segment.principal_axes);
    model.segment_inertia.push_back(axes * ToEigen(segment.inertia).asDiagonal() *
                                    axes.transpose());
    model.segment_source.push_back(lowering.Position(segment.range));

    if (j < 0) {
      // A root floats (a free joint to the ground) unless a fixed-point constraint or a weld
      // holds it at a point of the ground or a vehicle: then that constraint is its ball joint to
      // that base (locked for a weld), solved in the tree rather than as a loop.
      const int held = HoldingConstraintOf(lowering.scenario(), old);
      lowering.base_constraint.push_back(held);
      model.segment_parent.push_back(-1);
      if (held < 0) {
        model.segment_base.push_back({});
        model.joint_kind.push_back(JointKind::kFree);
        model.joint_name.emplace_back();
        model.joint_point_in_parent.push_back(runtime::Vec3::Zero());
        model.joint_point_in_child.push_back(runtime::Vec3::Zero());
      } else {
        const Constraint& constraint =
            lowering.scenario().constraints[static_cast<std::size_t>(held)];
        const bool segment_first = constraint.first.kind == FrameRef::Kind::kSegment;
        model.segment_base.push_back(
            lowering.Frame(segment_first ? constraint.second : constraint.first));
        model.joint_kind.push_back(JointKind::kBall);
        model.joint_name.push_back(constraint.name);
        model.joint_point_in_parent.push_back(
            ToEigen(segment_first ? constraint.point_in_second : constraint.point_in_first));
        model.joint_point_in_child.push_back(
            ToEigen(segment_first ? constraint.point_in_first : constraint.point_in_second));
        lowering.constraint_is_base_joint[static_cast<std::size_t>(held)] = true;
      }
      model.joint_frame_in_parent.push_back(runtime::Mat3::Identity());
      model.joint_frame_in_child.push_back(runtime::Mat3::Identity());
      model.joint_axis.push_back(runtime::Vec3::Zero());
      runtime::AppendPlainJointCharacteristics(model);
      if (held >= 0 && lowering.scenario().constraints[static_cast<std::size_t>(held)].kind ==
                           Constraint::Kind::kWelded) {
        // A weld: the joint to the base locked for good (no unlock level), so the segment moves
        // rigidly with its base at its initial relative orientation.
        model.joint_locked.back() = 7;
      }
      model.joint_source.emplace_back();
    } else {
      const Joint& joint = lowering.joint(j);
      const JointKind kind = KindOf(joint.type);
      lowering.base_constraint.push_back(-1);
      model.segment_base.push_back({});
      model.segment_parent.push_back(lowering.new_index[static_cast<std::size_t>(joint.parent)]);
      model.joint_kind.push_back(kind);
      model.joint_name.push_back(joint.name);
      const runtime::Mat3 frame_in_parent = RotationMatrix(joint.axes_in_parent);
      model.joint_point_in_parent.push_back(ToEigen(joint.location_in_parent));
      model.joint_frame_in_parent.push_back(frame_in_parent);
      model.joint_point_in_child.push_back(ToEigen(joint.location_in_child));
      model.joint_frame_in_child.push_back(RotationMatrix(joint.axes_in_child));
      runtime::Vec3 axis = runtime::Vec3::Zero();
      if (kind == JointKind::kPin || kind == JointKind::kSlip) {
        // Given in the parent segment; the runtime wants it in the joint frame.
        axis = (frame_in_parent.transpose() * ToEigen(joint.axis)).normalized();
      }
      model.joint_axis.push_back(axis);
      // The joint's energy loss unloads each torque function that has no unloading of its own.
      auto torque = [&](FunctionId id) { return lowering.TorqueFunction(id, joint.energy_loss); };
      if (kind == JointKind::kEuler) {
        model.joint_function.push_back(
            {torque(joint.precession), torque(joint.nutation), torque(joint.spin)});
      } else {
        model.joint_function.push_back({torque(joint.flexure), torque(joint.twist), -1});
      }
      model.joint_viscous.push_back(joint.viscous);
      model.joint_coulomb.push_back(joint.coulomb);
      model.joint_stop.push_back(joint.stop.value_or(0.0));
      model.joint_twist_stop.push_back(joint.twist_stop.value_or(0.0));
      model.joint_stop_impulse.push_back(joint.stop_impulse ? 1 : 0);
      model.joint_restitution.push_back(joint.restitution);
      model.joint_locked.push_back(static_cast<std::uint8_t>(joint.locked_axes & 7u));
      model.joint_lock_below.push_back(joint.lock_below.value_or(-1.0));
      model.joint_unlock_above.push_back(joint.unlock_above.value_or(-1.0));
      model.joint_source.push_back(lowering.Position(joint.range));
    }
    if (lowering.scenario().run.symmetry == Symmetry::kPlanar) RestrictToPlane(lowering, s);
    ApplyMirrorSymmetry(lowering, s);
    const JointKind kind = model.joint_kind.back();
    model.q_address.push_back(nq);
    model.v_address.push_back(nv);
    model.q_count.push_back(runtime::PositionCount(kind));
    model.v_count.push_back(runtime::VelocityCount(kind));
    nq += runtime::PositionCount(kind);
    nv += runtime::VelocityCount(kind);
  }
  model.nq = nq;
  model.nv = nv;
  LowerDummyTypes(lowering);
}

}  // namespace sled::compiler::lowering
