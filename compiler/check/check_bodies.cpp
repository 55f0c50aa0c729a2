// Bodies: segments (mass, inertia, ellipsoids), joints (type, locations, torque functions,
// stops, locks) and the joint tree of each body.
#include <algorithm>
#include <cmath>
#include <functional>
#include <map>

#include <fmt/format.h>

#include "compiler/check/checkers.h"
#include "runtime/model/dummy_types.h"

namespace sled::compiler::internal {
namespace {

const std::vector<std::string> kJointTypes = {"ball", "pin", "euler", "slip", "null"};

std::string_view JointTypeName(JointType type) {
  return kJointTypes[static_cast<std::size_t>(type)];
}

}  // namespace

void BodyChecker::CheckBodyDeclarations(Scope& scope, const ast::Statement& body_statement,
                                        const std::string& instance_name,
                                        SourceRange instance_range) {
  const int index = static_cast<int>(scenario_.bodies.size());
  Body body;
  body.name = instance_name;
  body.range = instance_range;
  scenario_.bodies.push_back(std::move(body));
  Scope* body_scope = NewScope(&scope, instance_name + ".", scope.directory);
  PendingBody pending{&body_statement, body_scope, index, nullptr};
  if (!body_statement.block) {
    Report(DiagnosticKind::kMalformedStatement, body_statement.range,
           "a body has a block of segments and joints: `body NAME { ... }`", "no block",
           "add `{ segment ... joint ... }` after the body's name");
  } else {
    const int saved = current_body_;
    current_body_ = index;
    const BoundBlock bound =
        DeclareFileContents(*body_scope, *body_statement.block, BlockKind::kBody);
    current_body_ = saved;
    pending.reference = One(bound, "reference");
    pending.h_point = One(bound, "h_point");
    pending.dummy = One(bound, "dummy");
  }
  bodies_.push_back(pending);
}

void BodyChecker::CheckBodyDetails() {
  for (const Pending& pending : segments_) {
    Segment& segment = scenario_.segments[static_cast<std::size_t>(pending.index)];
    Scope& scope = *pending.scope;
    const BoundBlock bound =
        Bind(BlockKind::kSegment, pending.statement->block.get(), pending.statement->range);
    segment.singular = ReadBool(bound, "singular").value_or(false);
    if (const ast::Statement* mass = One(bound, "mass")) {
      if (const ast::Expr* expr = SingleValue(*mass)) {
        if (auto value = ExpectQuantity(scope, *expr, dim::kMass, "mass")) {
          segment.mass = *value;
          if (segment.singular ? *value != 0.0 : !(*value > 0.0)) {
            Report(DiagnosticKind::kNonPositiveMass, expr->range,
                   segment.singular
                       ? fmt::format("singular segment `{}` has a mass of {:g} kg", segment.name,
                                     *value)
                       : fmt::format("segment `{}` has a mass of {:g} kg", segment.name, *value),
                   segment.singular ? "must be zero" : "not positive",
                   segment.singular
                       ? "a singular segment is massless: give `mass = 0 kg` or drop `singular`"
                       : "mass must be greater than zero; a massless segment held by "
                         "constraints is declared with `singular = true`");
          }
        }
      }
    }
    const ast::Statement* inertia_statement = One(bound, "inertia");
    if (!inertia_statement && !segment.singular &&
        (!pending.statement->block || !pending.statement->block->had_syntax_errors)) {
      Report(DiagnosticKind::kMissingAttribute, pending.statement->range,
             fmt::format("segment `{}` needs `inertia`", segment.name), "no `inertia` given",
             "add `inertia = (Ix, Iy, Iz) kg*m^2`: the principal moments of inertia");
    }
    if (auto inertia = ReadVector(scope, bound, BlockKind::kSegment, "inertia")) {
      segment.inertia = *inertia;
      const auto& I = *inertia;
      const SourceRange range = inertia_statement->values[0].range;
      const bool positive = I[0] > 0 && I[1] > 0 && I[2] > 0;
      // Principal moments of a rigid body obey the triangle inequality: each is at most the sum
      // of the other two (equality only for a flat body).
      const double slack = 1e-9 * (I[0] + I[1] + I[2]);
      const bool triangle =
          I[0] <= I[1] + I[2] + slack && I[1] <= I[0] + I[2] + slack && I[2] <= I[0] + I[1] + slack;
      if (segment.singular && (I[0] != 0 || I[1] != 0 || I[2] != 0)) {
        Report(DiagnosticKind::kInvalidInertia, range,
               fmt::format("singular segment `{}` has inertia", segment.name), "must be zero",
               "a segment without mass has no inertia: remove `inertia`, or give it a mass");
      } else if (!segment.singular && !positive) {
        Report(DiagnosticKind::kInvalidInertia, range,
               fmt::format("segment `{}` has a principal moment of inertia that is not positive",
                           segment.name),
               "not positive", "every principal moment must be greater than zero");
      } else if (!segment.singular && !triangle) {
        const int largest = static_cast<int>(std::max_element(I.begin(), I.end()) - I.begin());
        Report(DiagnosticKind::kInvalidInertia, range,
               fmt::format("the principal moments of `{}` break the triangle inequality: "
                           "I{} = {:g} kg*m^2 exceeds the sum of the other two ({:g} kg*m^2)",
                           segment.name, "xyz"[largest], I[static_cast<std::size_t>(largest)],
                           I[0] + I[1] + I[2] - I[static_cast<std::size_t>(largest)]),
               "no rigid body has these moments",
               "each principal moment must be at most the sum of the other two; check the "
               "units and the order of the axes");
      }
    }
    segment.principal_axes =
        ReadVector(scope, bound, BlockKind::kSegment, "principal_axes").value_or(Vec3{});
    // The segment's own contact ellipsoids; named ones are `segment.name`.
    Scope* ellipsoid_scope = nullptr;
    for (const ast::Statement* child : bound.declarations) {
      Ellipsoid ellipsoid;
      ellipsoid.name = segment.name;
      if (child->target) {
        if (child->target->kind == ast::ExprKind::kPath && child->target->path.size() == 1) {
          ellipsoid.name += "." + child->target->path[0];
          if (!ellipsoid_scope) {
            ellipsoid_scope = NewScope(nullptr, segment.name + ".", scope.directory);
            auto entity = scope.names.find(pending.statement->target->path[0]);
            if (entity != scope.names.end()) entity->second.inner = ellipsoid_scope;
          }
          Declare(*ellipsoid_scope, child->target->path[0],
                  Entity{EntityKind::kEllipsoid, static_cast<int>(scenario_.ellipsoids.size()),
                         child->target->range});
        } else {
          Report(DiagnosticKind::kMalformedStatement, child->target->range,
                 "an ellipsoid's name is a plain name", "not a plain name",
                 "name it with one word, such as `ellipsoid chin { ... }`");
        }
      }
      ellipsoid.frame = {FrameRef::Kind::kSegment, pending.index};
      ellipsoid.range = child->range;
      const BoundBlock ellipsoid_bound =
          Bind(BlockKind::kSegmentEllipsoid, child->block.get(), child->range);
      ReadEllipsoid(scope, ellipsoid_bound, BlockKind::kSegmentEllipsoid, ellipsoid);
      segment.ellipsoids.push_back(static_cast<int>(scenario_.ellipsoids.size()));
      scenario_.ellipsoids.push_back(std::move(ellipsoid));
    }
  }

  for (const Pending& pending : joints_) {
    Joint& joint = scenario_.joints[static_cast<std::size_t>(pending.index)];
    Scope& scope = *pending.scope;
    const ast::Statement& statement = *pending.statement;
    const BoundBlock bound = Bind(BlockKind::kJoint, statement.block.get(), statement.range);
    const ast::Clause* colon = statement.FindClause(":");
    const ast::Expr* call = colon ? &colon->value : nullptr;
    if (!call || call->kind != ast::ExprKind::kCall || call->arguments.size() != 1 ||
        !call->arguments[0].name.empty()) {
      Report(DiagnosticKind::kMalformedStatement, call ? call->range : statement.range,
             "write `joint NAME : ball(parent -> child) { ... }` (or pin, euler, slip, null)",
             "not a joint type", "joint types: ball, pin, euler, slip, null");
      joint.parent = joint.child = -1;
      continue;
    }
    const std::string type = call->PathText();
    const auto found = std::find(kJointTypes.begin(), kJointTypes.end(), type);
    if (found == kJointTypes.end()) {
      Report(DiagnosticKind::kInvalidEnumValue, call->range,
             fmt::format("unknown joint type `{}`", type), "not a joint type",
             lang::DidYouMean(type, kJointTypes));
      joint.parent = joint.child = -1;
      continue;
    }
    joint.type = static_cast<JointType>(found - kJointTypes.begin());
    const ast::Expr& arrow = *call->arguments[0].value;
    joint.parent = joint.child = -1;
    if (arrow.kind != ast::ExprKind::kArrow || arrow.operands.size() != 2) {
      Report(DiagnosticKind::kMalformedStatement, arrow.range,
             "a joint connects a parent to a child: `ball(pelvis -> abdomen)`", "not A -> B",
             "name the parent segment, then the child, joined by `->`");
      continue;
    }
    Entity* parent = Resolve(scope, arrow.operands[0], {EntityKind::kSegment});
    Entity* child = Resolve(scope, arrow.operands[1], {EntityKind::kSegment});
    if (!parent || !child) continue;
    const int body = scenario_.segments[static_cast<std::size_t>(parent->index)].body;
    const int own_body = [&] {
      for (const PendingBody& b : bodies_) {
        if (b.scope == &scope) return b.index;
      }
      return body;
    }();
    for (const auto* side : {&arrow.operands[0], &arrow.operands[1]}) {
      Entity* entity = side == &arrow.operands[0] ? parent : child;
      if (scenario_.segments[static_cast<std::size_t>(entity->index)].body != own_body) {
        Report(DiagnosticKind::kJointAcrossBodies, side->range,
               fmt::format("joint `{}` connects `{}`, a segment of another body", joint.name,
                           side->PathText()),
               "another body's segment",
               "join bodies with a constraint, or declare the segments in one body");
        parent = nullptr;
      }
    }
    if (!parent) continue;
    if (parent->index == child->index) {
      Report(DiagnosticKind::kJointToItself, arrow.range,
             fmt::format("joint `{}` connects `{}` to itself", joint.name,
                         arrow.operands[0].PathText()),
             "the same segment twice",
             "a joint connects a parent to another segment: (parent -> child)");
      continue;
    }
    joint.parent = parent->index;
    joint.child = child->index;
    const std::array<FrameRef, 2> frames = {FrameRef{FrameRef::Kind::kSegment, joint.parent},
                                            FrameRef{FrameRef::Kind::kSegment, joint.child}};
    const bool is_null = joint.type == JointType::kNull;
    auto locations = ReadAtPoints(scope, bound, "at", frames, statement.range, !is_null, true);
    joint.location_in_parent = locations[0].value_or(Vec3{});
    joint.location_in_child = locations[1].value_or(Vec3{});
    auto axes = ReadAtPoints(scope, bound, "axes", frames, statement.range, false, true);
    joint.axes_in_parent = axes[0].value_or(Vec3{});
    joint.axes_in_child = axes[1].value_or(Vec3{});

    ReadJointCharacteristics(scope, bound, BlockKind::kJoint, joint);
    if (is_null) {
      for (const auto& [name, statements] : bound.attributes) {
        if (name != "at" && name != "axes") {
          Report(DiagnosticKind::kMisplacedStatement, statements[0]->keyword_range,
                 fmt::format("`{}` has no meaning for a null joint", name),
                 "a null joint starts a new body and carries no torque",
                 "remove it, or make the joint a ball, pin, euler or slip joint");
        }
      }
    }
  }

  // `override JOINT { ... }`: the scene changes a joint's characteristics (an imported body's,
  // usually), in the order the overrides are written; every value is checked as in a joint.
  for (const Pending& pending : joint_overrides_) {
    const ast::Statement& statement = *pending.statement;
    const BoundBlock bound = Bind(BlockKind::kOverride, statement.block.get(), statement.range);
    if (!statement.target) {
      Report(DiagnosticKind::kMalformedStatement, statement.range,
             "an override names the joint it changes", "no joint named",
             "write `override occupant.neck_upper { viscous = 2 N*m*s/rad }`");
      continue;
    }
    Entity* target = Resolve(*pending.scope, *statement.target, {EntityKind::kJoint});
    if (!target) continue;
    Joint& joint = scenario_.joints[static_cast<std::size_t>(target->index)];
    if (joint.parent < 0) continue;  // its own declaration did not check
    if (joint.type == JointType::kNull && !bound.attributes.empty()) {
      Report(DiagnosticKind::kMisplacedStatement, statement.target->range,
             fmt::format("`{}` is a null joint, which has no characteristics", joint.name),
             "a null joint", "override a ball, pin, euler or slip joint");
      continue;
    }
    ReadJointCharacteristics(*pending.scope, bound, BlockKind::kOverride, joint);
  }

  for (const PendingBody& pending : bodies_) {
    Body& body = scenario_.bodies[static_cast<std::size_t>(pending.index)];
    if (pending.reference) {
      if (const ast::Expr* value = SingleValue(*pending.reference)) {
        if (Entity* reference = Resolve(*pending.scope, *value, {EntityKind::kSegment})) {
          body.reference_segments.push_back(reference->index);
        }
      }
    }
    if (pending.h_point) {
      if (const ast::Expr* value = SingleValue(*pending.h_point)) {
        body.h_point = ExpectVector(*pending.scope, *value, dim::kLength, "h_point");
      }
    }
    if (pending.dummy) body.dummy = ReadDummy(*pending.dummy);
    CheckTopology(body, pending.index);
  }
}

// `dummy = WORD` of a body: the ISO/TS 13499 dummy type of the word (runtime/model/dummy_types.h);
// empty when the word is none of them (reported).
std::string CheckContext::ReadDummy(const ast::Statement& statement) {
  const ast::Expr* value = SingleValue(statement);
  if (!value) return {};
  const std::string word = value->kind == ast::ExprKind::kPath ? value->PathText() : "";
  std::vector<std::string> words;
  std::string listed;
  for (const runtime::DummyType& type : runtime::kDummyTypes) {
    if (type.word == word) return std::string(type.iso_code);
    words.emplace_back(type.word);
    listed += (listed.empty() ? "`" : ", `") + words.back() + "`";
  }
  Report(DiagnosticKind::kInvalidEnumValue, value->range,
         fmt::format("`dummy` names a crash-test dummy: {}", listed), "not a dummy type",
         lang::DidYouMean(word, words));
  return {};
}

// The characteristics a joint's block (or an `override` of it) gives: only what the block
// states changes, so an override keeps the imported body's other values.
void BodyChecker::ReadJointCharacteristics(Scope& scope, const BoundBlock& bound, BlockKind kind,
                                           Joint& joint) {
  const bool euler = joint.type == JointType::kEuler;
  auto only_for = [&](AttributeKey name, bool allowed, std::string_view types) {
    const ast::Statement* attribute = One(bound, name);
    if (attribute && !allowed) {
      Report(DiagnosticKind::kMisplacedStatement, attribute->keyword_range,
             fmt::format("`{}` applies to {} joints; `{}` is a {} joint", name.view(), types,
                         joint.name, JointTypeName(joint.type)),
             "not for this joint type", "remove it, or change the joint's type");
      return false;
    }
    return attribute != nullptr;
  };
  if (only_for("axis", joint.type == JointType::kPin || joint.type == JointType::kSlip,
               "pin and slip")) {
    joint.axis = ReadVector(scope, bound, kind, "axis").value_or(Vec3{0, 0, 1});
  }
  const bool bending = joint.type == JointType::kBall || joint.type == JointType::kPin ||
                       joint.type == JointType::kSlip;
  // A slip joint slides: its generalized coordinate is a displacement and its generalized force a
  // force, so its flexure is a force against the displacement, its stop a displacement and its
  // damping, friction and lock levels are forces; the other joints turn, and theirs are torques
  // against angles.
  const bool slip = joint.type == JointType::kSlip;
  const Dimension effort = slip ? dim::kForce : dim::kTorque;
  if (only_for("flexure", bending, "ball, pin and slip")) {
    joint.flexure = (slip ? ReadFunction(scope, bound, kind, "flexure", dim::kLength, dim::kForce)
                          : ReadFunction(scope, bound, kind, "flexure"))
                        .value_or(joint.flexure);
  }
  if (only_for("twist", joint.type == JointType::kBall, "ball")) {
    joint.twist = ReadFunction(scope, bound, kind, "twist").value_or(joint.twist);
  }
  if (only_for("precession", euler, "euler")) {
    joint.precession = ReadFunction(scope, bound, kind, "precession").value_or(joint.precession);
  }
  if (only_for("nutation", euler, "euler")) {
    joint.nutation = ReadFunction(scope, bound, kind, "nutation").value_or(joint.nutation);
  }
  if (only_for("spin", euler, "euler")) {
    joint.spin = ReadFunction(scope, bound, kind, "spin").value_or(joint.spin);
  }
  RefuseAtbUnloading(joint.flexure, bound, "flexure", "a joint");
  RefuseAtbUnloading(joint.twist, bound, "twist", "a joint");
  RefuseAtbUnloading(joint.precession, bound, "precession", "a joint");
  RefuseAtbUnloading(joint.nutation, bound, "nutation", "a joint");
  RefuseAtbUnloading(joint.spin, bound, "spin", "a joint");
  joint.viscous =
      ReadQuantity(scope, bound, kind, "viscous", slip ? dim::kDamping : dim::kRotationalDamping)
          .value_or(joint.viscous);
  joint.coulomb = ReadQuantity(scope, bound, kind, "coulomb", effort).value_or(joint.coulomb);
  joint.energy_loss = ReadQuantity(scope, bound, kind, "energy_loss").value_or(joint.energy_loss);
  if (auto stop = ReadQuantity(scope, bound, kind, "stop", slip ? dim::kLength : dim::kAngle)) {
    joint.stop = stop;
  }
  if (auto stop = ReadQuantity(scope, bound, kind, "twist_stop")) joint.twist_stop = stop;
  joint.stop_impulse = ReadBool(bound, "stop_impulse").value_or(joint.stop_impulse);
  joint.restitution = ReadQuantity(scope, bound, kind, "restitution").value_or(joint.restitution);
  if (auto level = ReadQuantity(scope, bound, kind, "lock_below", effort)) joint.lock_below = level;
  if (auto level = ReadQuantity(scope, bound, kind, "unlock_above", effort)) {
    joint.unlock_above = level;
  }
  if (const ast::Statement* locked = One(bound, "locked")) {
    joint.locked_axes = 0;
    static const std::vector<std::string> kAxes = {"precession", "nutation", "spin"};
    for (const ast::Expr& value : locked->values) {
      if (value.kind == ast::ExprKind::kBool) {
        if (locked->values.size() == 1 && value.text == "true") joint.locked_axes = 7;
        continue;
      }
      const auto axis = value.kind == ast::ExprKind::kPath && value.path.size() == 1
                            ? std::find(kAxes.begin(), kAxes.end(), value.path[0])
                            : kAxes.end();
      if (axis == kAxes.end()) {
        Report(DiagnosticKind::kInvalidEnumValue, value.range,
               "`locked` is true, false, or a list of Euler axes", "not an axis",
               value.kind == ast::ExprKind::kPath ? lang::DidYouMean(value.PathText(), kAxes)
                                                  : std::string());
        continue;
      }
      if (!euler) {
        Report(DiagnosticKind::kInvalidLockAxes, value.range,
               fmt::format("`{}` is a {} joint; only Euler joints lock single axes", joint.name,
                           JointTypeName(joint.type)),
               "no such axis", "write `locked = true` to lock the whole joint");
        continue;
      }
      joint.locked_axes |= 1u << static_cast<unsigned>(axis - kAxes.begin());
    }
  }
  const ast::Statement* level = One(bound, "lock_below");
  if (!level) level = One(bound, "unlock_above");
  if (level && !level->values.empty() && joint.lock_below && joint.unlock_above &&
      *joint.lock_below > *joint.unlock_above) {
    Report(
        DiagnosticKind::kValueOutOfRange, level->values[0].range,
        fmt::format("joint `{}` locks below {:g} {} but unlocks above {:g} {}", joint.name,
                    *joint.lock_below, slip ? "N" : "N*m", *joint.unlock_above, slip ? "N" : "N*m"),
        "lock level above unlock level",
        "the lock level must not exceed the unlock level, or the joint would chatter");
  }
}

void BodyChecker::CheckTopology(Body& body, int body_index) {
  (void)body_index;
  // Parent of each segment through a (non-null) joint; a segment may have only one.
  std::map<int, int> parent_joint;
  // Union–find over the body's segments to find closed loops.
  std::map<int, int> root;
  std::function<int(int)> find = [&](int x) {
    auto it = root.find(x);
    if (it == root.end() || it->second == x) return x;
    return it->second = find(it->second);
  };
  for (int joint_index : body.joints) {
    const Joint& joint = scenario_.joints[static_cast<std::size_t>(joint_index)];
    if (joint.parent < 0 || joint.child < 0) continue;
    auto [it, inserted] = parent_joint.emplace(joint.child, joint_index);
    if (!inserted) {
      const Joint& first = scenario_.joints[static_cast<std::size_t>(it->second)];
      auto diagnostic = lang::MakeDiagnostic(
          DiagnosticKind::kSegmentReachedTwice, joint.range,
          fmt::format("segment `{}` is the child of two joints, `{}` and `{}`",
                      scenario_.segments[static_cast<std::size_t>(joint.child)].name, first.name,
                      joint.name),
          "second parent joint");
      diagnostic.labels.push_back({first.range, "first parent joint", false});
      diagnostic.help =
          "each segment hangs from one joint; check the direction `parent -> child`, or close "
          "the loop with a constraint";
      diagnostics_.Consume(std::move(diagnostic));
      continue;
    }
    if (joint.type == JointType::kNull) continue;
    const int a = find(joint.parent);
    const int b = find(joint.child);
    if (a == b) {
      Report(DiagnosticKind::kJointCycle, joint.range,
             fmt::format("joint `{}` closes a loop of joints", joint.name), "closes a loop",
             "a joint structure is a tree; close loops with `constraint ... : fixed_point(A -> "
             "B)`");
      continue;
    }
    root[a] = b;
  }
  // Roots: segments with no parent joint; children of null joints start further bodies.
  std::vector<int> roots;
  std::vector<int> null_children;
  bool unresolved_joint = false;
  for (int joint_index : body.joints) {
    const Joint& joint = scenario_.joints[static_cast<std::size_t>(joint_index)];
    unresolved_joint |= joint.parent < 0 || joint.child < 0;
  }
  for (int segment : body.segments) {
    auto it = parent_joint.find(segment);
    if (it == parent_joint.end()) {
      roots.push_back(segment);
    } else if (scenario_.joints[static_cast<std::size_t>(it->second)].type == JointType::kNull) {
      null_children.push_back(segment);
    }
  }
  int reference = body.reference_segments.empty() ? -1 : body.reference_segments.front();
  if (reference >= 0 && parent_joint.count(reference) &&
      scenario_.joints[static_cast<std::size_t>(parent_joint[reference])].type !=
          JointType::kNull) {
    Report(DiagnosticKind::kSegmentNotReached,
           scenario_.segments[static_cast<std::size_t>(reference)].range,
           fmt::format("reference segment `{}` is the child of a joint",
                       scenario_.segments[static_cast<std::size_t>(reference)].name),
           "not a root", "the reference segment is the root of the joint tree");
  }
  if (reference < 0 && !roots.empty()) {
    reference = roots.front();
    body.reference_segments.insert(body.reference_segments.begin(), reference);
  }
  body.reference_segments.insert(body.reference_segments.end(), null_children.begin(),
                                 null_children.end());
  // A joint whose segments could not be resolved was reported already; what it would have
  // reached is unknown, so "not reached" would only repeat that error.
  if (unresolved_joint) return;
  for (int segment : roots) {
    if (segment == reference) continue;
    const Segment& s = scenario_.segments[static_cast<std::size_t>(segment)];
    Report(DiagnosticKind::kSegmentNotReached, s.range,
           fmt::format("segment `{}` is not reached from the reference segment `{}`", s.name,
                       scenario_.segments[static_cast<std::size_t>(reference)].name),
           "no joint leads here",
           "connect it with a joint, or start another body from it with a `null` joint");
  }
}

}  // namespace sled::compiler::internal
