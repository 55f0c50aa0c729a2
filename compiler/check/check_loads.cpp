// Applied loads: `load NAME on SEGMENT { force = ...  direction = ... }` pushes a segment with a
// force (and a torque) that is a function of time; `load NAME on JOINT { torque = ... }` drives a
// joint, acting on its child and, opposite, on its parent: about a pin's axis, along a slip's,
// about a given axis for ball and Euler joints. A joint's own torque functions (flexure, ...)
// resist its angle; a motor is a load.
#include <fmt/format.h>

#include "compiler/check/checkers.h"

namespace sled::compiler::internal {
namespace {

std::string_view JointTypeName(JointType type) {
  switch (type) {
    case JointType::kBall:
      return "ball";
    case JointType::kPin:
      return "pin";
    case JointType::kEuler:
      return "euler";
    case JointType::kSlip:
      return "slip";
    case JointType::kNull:
      return "null";
  }
  return "?";
}

}  // namespace

void LoadChecker::CheckLoads() {
  for (const Pending& pending : loads_) {
    AppliedLoad& load = scenario_.loads[static_cast<std::size_t>(pending.index)];
    Scope& scope = *pending.scope;
    const ast::Statement& statement = *pending.statement;
    const BoundBlock bound = Bind(BlockKind::kLoad, statement.block.get(), statement.range);
    load.range = statement.range;
    const ast::Clause* on = statement.FindClause("on");
    if (!on) {
      Report(DiagnosticKind::kMalformedStatement, statement.range,
             "a load names what it acts on: `load NAME on SEGMENT { ... }` or `load NAME on "
             "JOINT { ... }`",
             "no `on`", "add `on` and a segment (a push) or a joint (a motor across it)");
      continue;
    }
    Entity* target = Resolve(scope, on->value, {EntityKind::kSegment, EntityKind::kJoint});
    const auto force = ReadFunction(scope, bound, BlockKind::kLoad, "force");
    const auto torque = ReadFunction(scope, bound, BlockKind::kLoad, "torque");
    RefuseUnloading(force, bound, "force", "a load");
    RefuseUnloading(torque, bound, "torque", "a load");
    if (!target) continue;
    load.across_joint = target->kind == EntityKind::kJoint;
    load.index = target->index;
    load.force = force.value_or(-1);
    load.torque = torque.value_or(-1);
    if (!One(bound, "force") && !One(bound, "torque")) {
      Report(DiagnosticKind::kMissingAttribute, statement.range,
             fmt::format("load `{}` has neither `force` nor `torque`", load.name), "no load",
             "give `force = ...` (with its `direction`) or `torque = ...` (with its `axis`), "
             "functions of time such as `table(time -> force) { 0 ms -> 0 N  10 ms -> 1 kN }`");
      continue;
    }
    // An attribute that has no meaning for this target is an error, never ignored.
    auto refuse = [&](AttributeKey name, const std::string& why, const std::string& help) {
      if (const ast::Statement* given = One(bound, name)) {
        Report(DiagnosticKind::kMisplacedStatement, given->keyword_range,
               fmt::format("`{}` does not apply here: {}", name.view(), why), "not for this load",
               help);
        return true;
      }
      return false;
    };
    auto require = [&](AttributeKey name, std::string_view with, const std::string& help) {
      if (One(bound, name)) return true;
      Report(DiagnosticKind::kMissingAttribute, statement.range,
             fmt::format("load `{}` has a `{}` but no `{}`", load.name, with, name.view()),
             fmt::format("no `{}`", name.view()), help);
      return false;
    };
    if (!load.across_joint) {
      if (const ast::Statement* frame = One(bound, "frame")) {
        const ast::Expr* word = SingleValue(*frame);
        if (word && word->kind == ast::ExprKind::kPath && word->path.size() == 1 &&
            (word->path[0] == "ground" || word->path[0] == "segment")) {
          load.in_segment = word->path[0] == "segment";
        } else if (word) {
          Report(DiagnosticKind::kInvalidEnumValue, word->range, "`frame` is `ground` or `segment`",
                 "not a frame word",
                 "`ground`: the direction stays fixed in the ground; `segment`: it turns with "
                 "the segment");
        }
      }
      if (One(bound, "force") &&
          require("direction", "force",
                  "give the force's direction: `direction = x` or (1, 0, 0)")) {
        load.direction = ExpectDirection(scope, *ValueOf(bound, "direction"), "direction")
                             .value_or(load.direction);
      } else {
        refuse("direction", "the load has no `force`", "remove it, or give the `force`");
      }
      if (One(bound, "torque") &&
          require("axis", "torque", "give the torque's axis: `axis = z` or (0, 0, 1)")) {
        load.axis = ReadVector(scope, bound, BlockKind::kLoad, "axis").value_or(load.axis);
      } else {
        refuse("axis", "the load has no `torque`", "remove it, or give the `torque`");
      }
      if (One(bound, "point")) {
        if (!One(bound, "force")) {
          refuse("point", "the load has no `force`", "remove it, or give the `force`");
        } else {
          load.point = ReadVector(scope, bound, BlockKind::kLoad, "point").value_or(Vec3{});
        }
      }
      continue;
    }
    // Across a joint.
    const Joint& joint = scenario_.joints[static_cast<std::size_t>(load.index)];
    const std::string type =
        fmt::format("`{}` is a {} joint", joint.name, JointTypeName(joint.type));
    refuse("direction", "a load across a joint acts along the joint's own axes",
           "remove it; a slip joint's load acts along its axis");
    refuse("point", "a load across a joint acts at the joint", "remove it");
    refuse("frame", "the axes of a load across a joint are the joint's",
           "remove it; give `axis` in the parent segment for a ball or Euler joint");
    switch (joint.type) {
      case JointType::kNull:
        Report(DiagnosticKind::kWrongKindOfName, on->value.range,
               fmt::format("{}: it joins nothing to drive", type), "a null joint",
               "a null joint only starts a new body; put the load on a segment");
        break;
      case JointType::kPin:
        refuse("force", type + ", which turns: its load is a torque about its axis",
               "write `torque = ...`");
        refuse("axis", type + ": its load turns it about its own axis", "remove it");
        break;
      case JointType::kSlip:
        refuse("torque", type + ", which slides: its load is a force along its axis",
               "write `force = ...`");
        refuse("axis", type + ": its load pushes along its own axis", "remove it");
        break;
      case JointType::kBall:
      case JointType::kEuler:
        refuse("force", type + ", which turns: its load is a torque", "write `torque = ...`");
        if (One(bound, "torque") &&
            require("axis", "torque",
                    "give the torque's axis in the parent segment: `axis = (0, 1, 0)`")) {
          load.axis = ReadVector(scope, bound, BlockKind::kLoad, "axis").value_or(load.axis);
        }
        break;
    }
  }
}

void LoadChecker::CheckLoadsInThePlane() {
  // Planar symmetry keeps the motion in the x-z plane: a load with a part out of it would lose
  // that part without a word.
  if (scenario_.run.symmetry != Symmetry::kPlanar) return;
  for (const AppliedLoad& load : scenario_.loads) {
    const bool pin_or_slip =
        load.across_joint &&
        (scenario_.joints[static_cast<std::size_t>(load.index)].type == JointType::kPin ||
         scenario_.joints[static_cast<std::size_t>(load.index)].type == JointType::kSlip);
    const bool force_out =
        !load.across_joint && load.force >= 0 && (load.direction[1] != 0.0 || load.point[1] != 0.0);
    const bool torque_out =
        load.torque >= 0 && !pin_or_slip && (load.axis[0] != 0.0 || load.axis[2] != 0.0);
    if (!force_out && !torque_out) continue;
    Report(DiagnosticKind::kValueOutOfRange, load.range,
           fmt::format("load `{}` acts out of the plane of `symmetry planar`", load.name),
           force_out ? "a force with a y part, or at a point off the plane"
                     : "a torque about an axis other than y",
           "under planar symmetry a force lies in the x-z plane (no y in `direction` or `point`) "
           "and a torque turns about y; drop the symmetry to load the scene in 3-D");
  }
}

}  // namespace sled::compiler::internal
