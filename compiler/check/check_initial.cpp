// Initial conditions: what each `initial` sets, and the refusals (E0421) of what the model could
// not take: the position, orientation or velocity of a segment that hangs from a joint (the
// joint's angles place it), the angles of a null joint, and a position or velocity of a root
// held at a point of the ground or a vehicle that the held point contradicts.
#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "compiler/check/checkers.h"
#include "compiler/check/initial_pose.h"

namespace sled::compiler::internal {
namespace {

// A given position agrees with the one the held point implies to within 1 % of the distance
// from the held point or 1 mm, whichever is larger (a position written with rounded sines and
// cosines agrees); a velocity to within 1 % of the implied one or 1 mm/s.
constexpr double kHeldRelative = 0.01;
constexpr double kHeldAbsolute = 1e-3;

double Norm(const Vec3& v) { return std::hypot(v[0], v[1], v[2]); }

double Distance(const Vec3& a, const Vec3& b) {
  return std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
}

std::string Millimetres(const Vec3& p) {
  return fmt::format("({:.6g}, {:.6g}, {:.6g}) mm", p[0] * 1e3, p[1] * 1e3, p[2] * 1e3);
}

std::string MetresPerSecond(const Vec3& v) {
  return fmt::format("({:.6g}, {:.6g}, {:.6g}) m/s", v[0], v[1], v[2]);
}

}  // namespace

void InitialChecker::CheckInitialConditions() {
  for (const Pending& pending : initials_) {
    const ast::Statement& statement = *pending.statement;
    Scope& scope = *pending.scope;
    const BoundBlock bound = Bind(BlockKind::kInitial, statement.block.get(), statement.range);
    if (!statement.target) {
      Report(DiagnosticKind::kMalformedStatement, statement.range,
             "`initial` names a body, segment, joint or vehicle: `initial occupant { ... }`",
             "no target", "name what the initial state is for after `initial`");
      continue;
    }
    Entity* entity = Resolve(
        scope, *statement.target,
        {EntityKind::kBody, EntityKind::kSegment, EntityKind::kJoint, EntityKind::kVehicle});
    if (!entity) continue;
    InitialCondition initial;
    initial.range = statement.range;
    initial.index = entity->index;
    const bool joint = entity->kind == EntityKind::kJoint;
    initial.kind = entity->kind == EntityKind::kBody      ? InitialCondition::Kind::kBody
                   : entity->kind == EntityKind::kSegment ? InitialCondition::Kind::kSegment
                   : joint                                ? InitialCondition::Kind::kJoint
                                                          : InitialCondition::Kind::kVehicle;
    for (const auto& [name, statements] : bound.attributes) {
      const bool for_joint = name == "angles";
      if (for_joint != joint) {
        Report(DiagnosticKind::kMisplacedStatement, statements[0]->keyword_range,
               joint ? fmt::format("a joint's initial state is its `angles`, not `{}`", name)
                     : "`angles` sets a joint; this `initial` names a body, segment or vehicle",
               "not for this target",
               joint ? "set the joint's `angles`"
                     : "name a joint in the `initial` that sets `angles`");
      }
    }
    initial.position = ReadVector(scope, bound, BlockKind::kInitial, "position");
    initial.orientation = ReadVector(scope, bound, BlockKind::kInitial, "orientation");
    initial.velocity = ReadVector(scope, bound, BlockKind::kInitial, "velocity");
    initial.angular_velocity = ReadVector(scope, bound, BlockKind::kInitial, "angular_velocity");
    initial.joint_angles = ReadVector(scope, bound, BlockKind::kInitial, "angles");
    if (const ast::Statement* at = One(bound, "position")) initial.position_range = at->range;
    if (const ast::Statement* at = One(bound, "velocity")) initial.velocity_range = at->range;
    if (const ast::Statement* h_statement = One(bound, "h_point")) {
      PlaceByHPoint(scope, bound, *h_statement, initial);
      if (initial.position) initial.position_range = h_statement->range;
    }
    RefuseUntakenInitial(initial, bound);
    scenario_.initial_conditions.push_back(initial);
  }
}

void InitialChecker::PlaceByHPoint(Scope& scope, const BoundBlock& bound,
                                   const ast::Statement& h_statement, InitialCondition& initial) {
  const SourceRange where = h_statement.keyword_range;
  if (initial.kind != InitialCondition::Kind::kBody) {
    Report(DiagnosticKind::kMisplacedStatement, where, "`h_point` places a body",
           "not for this target", "name the body after `initial`, or give `position`");
    return;
  }
  const Body& body = scenario_.bodies[static_cast<std::size_t>(initial.index)];
  if (!body.h_point) {
    Report(DiagnosticKind::kMissingAttribute, where,
           fmt::format("body `{}` declares no H-point", body.name), "no `h_point` in the body",
           "give the body `h_point = (x, y, z) mm` in its reference segment's frame, or place "
           "it by `position`");
    return;
  }
  if (initial.position) {
    Report(DiagnosticKind::kDuplicateAttribute, where,
           "`h_point` and `position` both place the body", "given with `position`",
           "keep one of the two");
    return;
  }
  const auto target = ReadVector(scope, bound, BlockKind::kInitial, "h_point");
  if (!target) return;
  const Mat3 rotation = RotationFromYawPitchRoll(initial.orientation.value_or(Vec3{}));
  Vec3 position{};
  for (std::size_t i = 0; i < 3; ++i) {
    double turned = 0.0;
    for (std::size_t j = 0; j < 3; ++j) turned += rotation[i][j] * (*body.h_point)[j];
    position[i] = (*target)[i] - turned;
  }
  initial.position = position;
}

// The dimension of a criterion's value: what its `limit` is given in.

// What a joint places cannot be given: a segment below a (non-null) joint takes its position,
// orientation and velocity from the joint's angles and rates (its angular velocity can be given:
// the rates are solved for it), and a null joint has no angles.
void InitialChecker::RefuseUntakenInitial(const InitialCondition& initial,
                                          const BoundBlock& bound) {
  if (initial.kind == InitialCondition::Kind::kJoint) {
    const Joint& joint = scenario_.joints[static_cast<std::size_t>(initial.index)];
    const ast::Statement* angles = One(bound, "angles");
    if (joint.type == JointType::kNull && angles) {
      Report(DiagnosticKind::kUntakenInitial, angles->range,
             fmt::format("`{}` is a null joint: it has no angles to set", joint.name), "no angles",
             "a null joint starts another tree; place its child with `initial SEGMENT { "
             "position = ...  orientation = ... }`");
    }
    return;
  }
  if (initial.kind != InitialCondition::Kind::kSegment) return;
  const Segment& segment = scenario_.segments[static_cast<std::size_t>(initial.index)];
  const auto above =
      std::find_if(scenario_.joints.begin(), scenario_.joints.end(), [&](const Joint& joint) {
        return joint.child == initial.index && joint.type != JointType::kNull;
      });
  if (above == scenario_.joints.end()) return;
  const std::pair<const ast::Statement*, std::string_view> placed[] = {
      {One(bound, "position"), "position"},
      {One(bound, "orientation"), "orientation"},
      {One(bound, "velocity"), "velocity"}};
  for (const auto& [given, what] : placed) {
    if (!given) continue;
    Report(
        DiagnosticKind::kUntakenInitial, given->range,
        fmt::format("the initial {} of `{}` cannot be given: it hangs from joint `{}`", what,
                    segment.name, above->name),
        "placed by its joint",
        what == "velocity"
            ? "it moves with the segment above it; give the body's `velocity`, or this "
              "segment's `angular_velocity` (the joint's rates are solved for it)"
            : fmt::format("set the joint's angles: `initial {} {{ angles = ... }}`", above->name));
  }
}

// A root held at a point of the ground or a vehicle by a fixed-point constraint is where that
// point and its orientation put it, and moves as that point and its angular velocity make it: a
// position or velocity given for it must agree.
void InitialChecker::CheckHeldInitialConditions() {
  const InitialPoses poses = ComputeInitialPoses(scenario_);
  auto root_of = [&](const InitialCondition& initial) {
    if (initial.kind == InitialCondition::Kind::kSegment) return initial.index;
    if (initial.kind != InitialCondition::Kind::kBody) return -1;
    const Body& body = scenario_.bodies[static_cast<std::size_t>(initial.index)];
    return body.reference_segments.empty() ? -1 : body.reference_segments.front();
  };
  for (const InitialCondition& initial : scenario_.initial_conditions) {
    const int root = root_of(initial);
    if (root < 0) continue;
    const std::string& name = scenario_.segments[static_cast<std::size_t>(root)].name;
    const int hold = HoldingConstraintOf(scenario_, root);
    if (hold < 0) continue;
    const std::string& held_by = scenario_.constraints[static_cast<std::size_t>(hold)].name;
    if (initial.position) {
      const Vec3 placed = *HeldRootPosition(scenario_, poses, root);
      const double lever = Distance(placed, *HeldPoint(scenario_, poses, root));
      if (Distance(*initial.position, placed) > std::max(kHeldAbsolute, kHeldRelative * lever)) {
        Report(DiagnosticKind::kUntakenInitial, initial.position_range,
               fmt::format("the initial position of `{}` is {:.5g} mm from where constraint `{}` "
                           "holds it",
                           name, Distance(*initial.position, placed) * 1e3, held_by),
               "not where it is held",
               fmt::format("with its orientation, the held point puts it at {}; give that, or "
                           "leave `position` out",
                           Millimetres(placed)));
      }
    }
    if (initial.velocity) {
      // A root given no angular velocity turns with its base.
      Vec3 angular{};
      const Constraint& constraint = scenario_.constraints[static_cast<std::size_t>(hold)];
      const FrameRef base =
          constraint.first.kind == FrameRef::Kind::kSegment ? constraint.second : constraint.first;
      if (base.kind == FrameRef::Kind::kVehicle) {
        angular = poses.vehicle_angular_velocities[static_cast<std::size_t>(base.index)];
      }
      // A welded root turns with its base whatever it is given (E0426 refuses another rate).
      for (const InitialCondition& other : scenario_.initial_conditions) {
        if (constraint.kind != Constraint::Kind::kWelded && root_of(other) == root &&
            other.angular_velocity) {
          angular = *other.angular_velocity;
        }
      }
      const Vec3 moving = *HeldRootVelocity(scenario_, poses, root, angular);
      if (Distance(*initial.velocity, moving) >
          std::max(kHeldAbsolute, kHeldRelative * Norm(moving))) {
        Report(DiagnosticKind::kUntakenInitial, initial.velocity_range,
               fmt::format("the initial velocity of `{}` contradicts constraint `{}`, which holds "
                           "it at a point",
                           name, held_by),
               "not how it is held",
               fmt::format("turning about the held point at its angular velocity, it moves at "
                           "{}; give `angular_velocity` instead, or leave `velocity` out",
                           MetresPerSecond(moving)));
      }
    }
  }
}

}  // namespace sled::compiler::internal
