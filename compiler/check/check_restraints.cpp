// Contacts, belts, harnesses, airbags, spring–dampers, tension elements and constraints.
#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "compiler/check/checkers.h"

namespace sled::compiler::internal {
namespace {

// The range of semi-axes whose squares (and the products of two) are normal doubles.
constexpr double kSmallestSemiAxis = 1e-150;
constexpr double kLargestSemiAxis = 1e150;

}  // namespace

void CheckContext::ReadEllipsoid(Scope& scope, const BoundBlock& bound, BlockKind kind,
                                 Ellipsoid& ellipsoid) {
  if (auto semi_axes = ReadVector(scope, bound, kind, "semi_axes")) {
    ellipsoid.semi_axes = *semi_axes;
    for (double axis : *semi_axes) {
      if (!(axis > 0.0)) {
        Report(DiagnosticKind::kNonPositiveSemiAxis, One(bound, "semi_axes")->values[0].range,
               fmt::format("ellipsoid `{}` has a semi-axis of {:g} m", ellipsoid.name, axis),
               "not positive", "every semi-axis must be greater than zero");
        break;
      }
      // Contacts and belts compute with the squares of the semi-axes: a square that underflows
      // to zero or overflows made the surface silently untouchable.
      if (!(axis >= kSmallestSemiAxis && axis <= kLargestSemiAxis)) {
        Report(DiagnosticKind::kValueOutOfRange, One(bound, "semi_axes")->values[0].range,
               fmt::format("ellipsoid `{}` has a semi-axis of {:g} m, but it must be between "
                           "{:g} m and {:g} m",
                           ellipsoid.name, axis, kSmallestSemiAxis, kLargestSemiAxis),
               "out of range", "the squares of semi-axes outside that range do not fit a double");
        break;
      }
    }
  }
  ellipsoid.center = ReadVector(scope, bound, kind, "center").value_or(Vec3{});
  ellipsoid.orientation = ReadVector(scope, bound, kind, "orientation").value_or(Vec3{});
  if (const ast::Statement* degree = One(bound, "degree")) {
    if (const ast::Expr* expr = SingleValue(*degree)) {
      if (auto value = ExpectQuantity(scope, *expr, dim::kDimensionless, "degree")) {
        if (!(*value >= 2.0) || *value > 32.0) {
          Report(DiagnosticKind::kInvalidHyperDegree, expr->range,
                 fmt::format("ellipsoid degree {:g} is outside 2 to 32", *value), "invalid degree",
                 "2 is an ellipsoid; a larger degree makes a boxier hyper-ellipsoid");
        } else {
          ellipsoid.degree = *value;
        }
      }
    }
  }
}

std::optional<std::array<FrameRef, 2>> CheckContext::ReadConnection(Scope& scope,
                                                                    const ast::Statement& statement,
                                                                    const ast::Expr& arrow) {
  if (arrow.kind != ast::ExprKind::kArrow || arrow.operands.size() != 2) {
    Report(DiagnosticKind::kMalformedStatement, arrow.range,
           fmt::format("`{}` connects two frames: `A -> B`", statement.keyword), "expected A -> B",
           "name the two frames joined by `->`, as in `ground -> occupant.pelvis`");
    return std::nullopt;
  }
  auto first = ResolveFrame(scope, arrow.operands[0]);
  auto second = ResolveFrame(scope, arrow.operands[1]);
  if (!first || !second) return std::nullopt;
  if (*first == *second) {
    Report(DiagnosticKind::kJointToItself, arrow.range,
           fmt::format("`{}` connects `{}` to itself", statement.keyword,
                       arrow.operands[0].PathText()),
           "the same frame twice", "connect two different segments or frames");
    return std::nullopt;
  }
  return std::array<FrameRef, 2>{*first, *second};
}

std::array<std::optional<Vec3>, 2> CheckContext::ReadAtPoints(Scope& scope, const BoundBlock& bound,
                                                              std::string_view keyword,
                                                              const std::array<FrameRef, 2>& frames,
                                                              SourceRange owner, bool required,
                                                              bool local_names) {
  // Inside a body, segments are written by their own name: `at pelvis`, not `at occupant.pelvis`.
  auto written = [&](const FrameRef& frame) {
    std::string name = FrameName(frame);
    if (local_names && name.rfind('.') != std::string::npos)
      name = name.substr(name.rfind('.') + 1);
    return name;
  };
  std::array<std::optional<Vec3>, 2> points;
  auto it = bound.attributes.find(std::string(keyword));
  if (it != bound.attributes.end()) {
    for (const ast::Statement* statement : it->second) {
      auto frame = ResolveFrame(scope, *statement->target);
      if (!frame) continue;
      const int side = *frame == frames[0] ? 0 : *frame == frames[1] ? 1 : -1;
      if (side < 0) {
        Report(
            DiagnosticKind::kMalformedStatement, statement->target->range,
            fmt::format("`{}` is not one of the two connected frames `{}` and `{}`",
                        statement->target->PathText(), FrameName(frames[0]), FrameName(frames[1])),
            "not connected here",
            fmt::format("use `{}` or `{}`", FrameName(frames[0]), FrameName(frames[1])));
        continue;
      }
      if (points[static_cast<std::size_t>(side)]) {
        Report(DiagnosticKind::kDuplicateAttribute, statement->keyword_range,
               fmt::format("`{} {}` is given twice", keyword, statement->target->PathText()),
               "given again", "remove one of the two");
        continue;
      }
      const ast::Expr* value = SingleValue(*statement);
      if (!value) continue;
      const Dimension dimension = keyword == "axes" ? dim::kAngle : dim::kLength;
      points[static_cast<std::size_t>(side)] = ExpectVector(scope, *value, dimension, keyword);
      if (!points[static_cast<std::size_t>(side)]) points[static_cast<std::size_t>(side)] = Vec3{};
    }
  }
  if (required) {
    for (std::size_t side = 0; side < 2; ++side) {
      if (!points[side]) {
        Report(DiagnosticKind::kMissingAttribute, owner,
               fmt::format("the location in `{}` is missing", FrameName(frames[side])),
               fmt::format("no `{} {}`", keyword, written(frames[side])),
               fmt::format("add `{} {} = (x, y, z) mm`", keyword, written(frames[side])));
      }
    }
  }
  return points;
}

void RestraintChecker::CheckContacts() {
  for (const Pending& pending : contacts_) {
    const ast::Statement& statement = *pending.statement;
    Scope& scope = *pending.scope;
    const BoundBlock bound = Bind(BlockKind::kContact, statement.block.get(), statement.range);
    const ast::Clause* with = statement.FindClause("with");
    if (!statement.target || !with) {
      Report(DiagnosticKind::kMalformedStatement, statement.range,
             "a contact names two surfaces: `contact occupant.head with windshield { ... }`",
             "expected `contact A with B`",
             "name a segment, then `with` and a plane, an ellipsoid or another segment");
      continue;
    }
    // Each side: a segment (all its ellipsoids), an ellipsoid or a plane.
    auto surfaces = [&](const ast::Expr& expr, bool allow_plane) -> std::vector<SurfaceRef> {
      std::vector<EntityKind> kinds = {EntityKind::kSegment, EntityKind::kEllipsoid};
      if (allow_plane) kinds.push_back(EntityKind::kPlane);
      Entity* entity = Resolve(scope, expr, kinds);
      if (!entity) return {};
      if (entity->kind == EntityKind::kPlane) return {{SurfaceRef::Kind::kPlane, entity->index}};
      if (entity->kind == EntityKind::kEllipsoid) {
        return {{SurfaceRef::Kind::kEllipsoid, entity->index}};
      }
      const Segment& segment = scenario_.segments[static_cast<std::size_t>(entity->index)];
      if (segment.ellipsoids.empty()) {
        Report(DiagnosticKind::kWrongKindOfName, expr.range,
               fmt::format("segment `{}` has no contact ellipsoid", segment.name),
               "nothing to touch with",
               "give the segment an `ellipsoid { semi_axes = ... }` block");
      }
      std::vector<SurfaceRef> refs;
      for (int ellipsoid : segment.ellipsoids) {
        refs.push_back({SurfaceRef::Kind::kEllipsoid, ellipsoid});
      }
      return refs;
    };
    const std::vector<SurfaceRef> firsts = surfaces(*statement.target, false);
    const std::vector<SurfaceRef> seconds = surfaces(with->value, true);
    Contact contact;
    contact.range = statement.range;
    const auto force = ReadFunction(scope, bound, BlockKind::kContact, "force");
    contact.damping = ReadQuantity(scope, bound, BlockKind::kContact, "damping").value_or(0.0);
    contact.friction = ReadQuantity(scope, bound, BlockKind::kContact, "friction").value_or(0.0);
    contact.impulse = ReadBool(bound, "impulse").value_or(false);
    contact.restitution =
        ReadQuantity(scope, bound, BlockKind::kContact, "restitution").value_or(0.0);
    if (!force || !ReadRateTerms(scope, bound, statement, contact)) continue;
    contact.force = *force;
    if (!firsts.empty() && firsts == seconds) {
      Report(DiagnosticKind::kJointToItself, statement.range,
             fmt::format("`{}` is in contact with itself", statement.target->PathText()),
             "the same surface twice", "a contact acts between two different surfaces");
      continue;
    }
    for (const SurfaceRef& first : firsts) {
      for (const SurfaceRef& second : seconds) {
        if (first == second) continue;
        contact.first = first;
        contact.second = second;
        scenario_.contacts.push_back(contact);
      }
    }
  }
}

bool RestraintChecker::ReadRateTerms(Scope& scope, const BoundBlock& bound,
                                     const ast::Statement& statement, Contact& contact) {
  const auto scaled = ReadFunction(scope, bound, BlockKind::kContact, "rate_scaled_force");
  const auto scale = ReadFunction(scope, bound, BlockKind::kContact, "rate_scale");
  const auto rate_force = ReadFunction(scope, bound, BlockKind::kContact, "rate_force");
  RefuseUnloading(scaled, bound, "rate_scaled_force", "a contact's rate term");
  RefuseUnloading(scale, bound, "rate_scale", "a contact's rate term");
  RefuseUnloading(rate_force, bound, "rate_force", "a contact's rate term");
  if (scaled.has_value() != scale.has_value()) {
    Report(DiagnosticKind::kMissingAttribute, statement.range,
           fmt::format("`{}` without `{}`", scaled ? "rate_scaled_force" : "rate_scale",
                       scaled ? "rate_scale" : "rate_scaled_force"),
           "half of a rate term",
           "the force adds rate_scaled_force(deflection) * rate_scale(deflection rate): give "
           "both, or neither");
    return false;
  }
  contact.rate_scaled_force = scaled.value_or(-1);
  contact.rate_scale = scale.value_or(-1);
  contact.rate_force = rate_force.value_or(-1);
  return true;
}

void RestraintChecker::CheckRestraints() {
  auto read_frame = [&](const Pending& pending) -> FrameRef {
    if (const ast::Clause* on = pending.statement->FindClause("on")) {
      if (auto frame = ResolveFrame(*pending.scope, on->value)) return *frame;
    }
    return FrameRef{};
  };
  // Belts, also those inside harnesses.
  auto check_belt = [&](const ast::Statement& statement, Scope& scope, Belt& belt) {
    const BoundBlock bound = Bind(BlockKind::kBelt, statement.block.get(), statement.range);
    if (auto force = ReadFunction(scope, bound, BlockKind::kBelt, "force")) belt.force = *force;
    belt.slack = ReadQuantity(scope, bound, BlockKind::kBelt, "slack").value_or(0.0);
    belt.pretension = ReadQuantity(scope, bound, BlockKind::kBelt, "pretension").value_or(0.0);
    belt.friction = ReadQuantity(scope, bound, BlockKind::kBelt, "friction").value_or(0.0);
    const ast::Statement* path = One(bound, "path");
    if (!path) return;
    const ast::Expr* chain = SingleValue(*path);
    if (!chain) return;
    if (chain->kind != ast::ExprKind::kArrow) {
      Report(
          DiagnosticKind::kInvalidBeltPath, chain->range,
          "a belt path runs anchor -> segment -> ... -> anchor", "not a path",
          "start and end the path at anchors, with the segments the belt passes over between them");
      return;
    }
    for (const ast::Expr& element : chain->operands) {
      BeltPoint point;
      if (element.kind == ast::ExprKind::kPath) {
        Entity* segment = Resolve(scope, element, {EntityKind::kSegment});
        if (!segment) continue;
        point.kind = BeltPoint::Kind::kSegment;
        point.segment = segment->index;
      } else {
        auto anchor = ExpectVector(scope, element, dim::kLength, "belt anchor");
        if (!anchor) continue;
        point.frame = belt.frame;
        point.point = *anchor;
      }
      belt.path.push_back(point);
    }
    if (belt.path.size() != chain->operands.size()) return;
    const bool anchored = belt.path.front().kind == BeltPoint::Kind::kAnchor &&
                          belt.path.back().kind == BeltPoint::Kind::kAnchor;
    const bool wraps = std::any_of(belt.path.begin(), belt.path.end(), [](const BeltPoint& p) {
      return p.kind == BeltPoint::Kind::kSegment;
    });
    if (!anchored || !wraps) {
      Report(DiagnosticKind::kInvalidBeltPath, chain->range,
             !anchored ? "a belt path must start and end at an anchor point"
                       : "a belt path must pass over at least one segment",
             "invalid path", "write `path = (x, y, z) mm -> occupant.pelvis -> (x, y, z) mm`");
    }
  };
  for (const Pending& pending : belts_) {
    Belt& belt = scenario_.belts[static_cast<std::size_t>(pending.index)];
    belt.frame = read_frame(pending);
    check_belt(*pending.statement, *pending.scope, belt);
  }
  for (const Pending& pending : harnesses_) {
    const BoundBlock bound =
        Bind(BlockKind::kHarness, pending.statement->block.get(), pending.statement->range);
    Harness& harness = scenario_.harnesses[static_cast<std::size_t>(pending.index)];
    harness.frame = read_frame(pending);
    harness.friction =
        ReadQuantity(*pending.scope, bound, BlockKind::kHarness, "friction").value_or(0.0);
    // The harness's belts are named `harness.belt`.
    Scope* belts_scope = NewScope(nullptr, harness.name + ".", pending.scope->directory);
    auto harness_entity = pending.scope->names.find(pending.statement->target->path[0]);
    if (harness_entity != pending.scope->names.end()) harness_entity->second.inner = belts_scope;
    for (const ast::Statement* child : bound.declarations) {
      if (!child->target || child->target->kind != ast::ExprKind::kPath ||
          child->target->path.size() != 1) {
        Report(DiagnosticKind::kMalformedStatement, child->range,
               "a harness belt needs a plain name: `belt NAME { ... }`", "no plain name",
               "name the belt with one word, such as `belt lap { ... }`");
        continue;
      }
      if (const ast::Clause* on = child->FindClause("on")) {
        Report(DiagnosticKind::kMalformedStatement, on->word_range,
               "the belts of a harness are anchored in the harness's frame", "`on` not allowed",
               "move `on` to the harness: `harness NAME on FRAME { belt ... }`");
      }
      Declare(*belts_scope, child->target->path[0],
              Entity{EntityKind::kBelt, static_cast<int>(scenario_.belts.size()),
                     child->target->range});
      Belt belt;
      belt.name = harness.name + "." + child->target->PathText();
      belt.harness = pending.index;
      belt.frame = harness.frame;
      belt.range = child->target->range;
      check_belt(*child, *pending.scope, belt);
      harness.belts.push_back(static_cast<int>(scenario_.belts.size()));
      scenario_.belts.push_back(std::move(belt));
    }
    if (harness.belts.empty()) {
      Report(DiagnosticKind::kMissingAttribute, pending.statement->range,
             fmt::format("harness `{}` has no belts", harness.name), "empty harness",
             "add `belt NAME { path = ... force = ... }` blocks");
    }
  }
  for (const Pending& pending : airbags_) {
    Airbag& bag = scenario_.airbags[static_cast<std::size_t>(pending.index)];
    bag.frame = read_frame(pending);
    Scope& scope = *pending.scope;
    const BoundBlock bound =
        Bind(BlockKind::kAirbag, pending.statement->block.get(), pending.statement->range);
    bag.position = ReadVector(scope, bound, BlockKind::kAirbag, "position").value_or(Vec3{});
    bag.orientation = ReadVector(scope, bound, BlockKind::kAirbag, "orientation").value_or(Vec3{});
    if (auto semi_axes = ReadVector(scope, bound, BlockKind::kAirbag, "semi_axes")) {
      bag.semi_axes = *semi_axes;
      if (!std::all_of(semi_axes->begin(), semi_axes->end(), [](double a) { return a > 0; })) {
        Report(DiagnosticKind::kNonPositiveSemiAxis, One(bound, "semi_axes")->values[0].range,
               fmt::format("airbag `{}` has a semi-axis that is not positive", bag.name),
               "not positive", "give each semi-axis a positive length");
      }
    }
    bag.deploy_time = ReadQuantity(scope, bound, BlockKind::kAirbag, "deploy_at").value_or(0.0);
    if (auto inflow = ReadFunction(scope, bound, BlockKind::kAirbag, "inflow")) {
      bag.inflow = *inflow;
      RefuseUnloading(inflow, bound, "inflow", "an airbag");
    }
    bag.vent_area = ReadQuantity(scope, bound, BlockKind::kAirbag, "vent_area").value_or(0.0);
    bag.ambient_pressure =
        ReadQuantity(scope, bound, BlockKind::kAirbag, "ambient_pressure").value_or(101325.0);
    bag.gas_temperature =
        ReadQuantity(scope, bound, BlockKind::kAirbag, "gas_temperature").value_or(300.0);
    bag.gamma = ReadQuantity(scope, bound, BlockKind::kAirbag, "gamma").value_or(1.4);
    bag.gas_constant =
        ReadQuantity(scope, bound, BlockKind::kAirbag, "gas_constant").value_or(287.0);
    bag.discharge_coefficient =
        ReadQuantity(scope, bound, BlockKind::kAirbag, "discharge_coefficient").value_or(0.6);
    if (const ast::Statement* contacts = One(bound, "contacts")) {
      for (const ast::Expr& value : contacts->values) {
        if (Entity* segment = Resolve(scope, value, {EntityKind::kSegment})) {
          bag.contact_segments.push_back(segment->index);
        }
      }
    }
    CheckAirbagModel(scope, bound, bag);
  }
  for (const Pending& pending : springs_) {
    SpringDamper& spring = scenario_.springs[static_cast<std::size_t>(pending.index)];
    Scope& scope = *pending.scope;
    const BoundBlock bound =
        Bind(BlockKind::kSpring, pending.statement->block.get(), pending.statement->range);
    const ast::Clause* colon = pending.statement->FindClause(":");
    if (!colon) {
      Report(DiagnosticKind::kMalformedStatement, pending.statement->range,
             fmt::format("write `{} NAME : A -> B {{ ... }}`", pending.statement->keyword),
             "the two frames are missing", "add the two frames after `:`, joined by `->`");
      continue;
    }
    auto frames = ReadConnection(scope, *pending.statement, colon->value);
    if (!frames) continue;
    spring.first = (*frames)[0];
    spring.second = (*frames)[1];
    auto points = ReadAtPoints(scope, bound, "at", *frames, pending.statement->range, true);
    spring.point_in_first = points[0].value_or(Vec3{});
    spring.point_in_second = points[1].value_or(Vec3{});
    if (auto stiffness = ReadFunction(scope, bound, BlockKind::kSpring, "stiffness")) {
      spring.stiffness = *stiffness;
      RefuseUnloading(stiffness, bound, "stiffness", "a spring-damper");
    }
    spring.damping = ReadQuantity(scope, bound, BlockKind::kSpring, "damping").value_or(0.0);
    spring.free_length = ReadQuantity(scope, bound, BlockKind::kSpring, "free_length");
  }
  for (const Pending& pending : constraints_) {
    Constraint& constraint = scenario_.constraints[static_cast<std::size_t>(pending.index)];
    Scope& scope = *pending.scope;
    const BoundBlock bound =
        Bind(BlockKind::kConstraint, pending.statement->block.get(), pending.statement->range);
    const ast::Clause* colon = pending.statement->FindClause(":");
    const ast::Expr* call = colon ? &colon->value : nullptr;
    // `rolling` is read to be refused (E0422) with its reason; the others are the kinds.
    static const std::vector<std::string> kKinds = {"fixed_point", "fixed_distance", "rolling",
                                                    "sliding", "welded"};
    if (!call || call->kind != ast::ExprKind::kCall || call->arguments.size() != 1 ||
        !call->arguments[0].name.empty()) {
      Report(DiagnosticKind::kMalformedStatement, call ? call->range : pending.statement->range,
             "write `constraint NAME : fixed_point(A -> B) { ... }` (or fixed_distance, sliding, "
             "welded)",
             "not a constraint kind",
             "constraint kinds: fixed_point, fixed_distance, sliding, welded");
      continue;
    }
    const std::string kind = call->PathText();
    const auto found = std::find(kKinds.begin(), kKinds.end(), kind);
    if (found == kKinds.end()) {
      Report(DiagnosticKind::kInvalidEnumValue, call->range,
             fmt::format("unknown constraint kind `{}`", kind), "not a constraint kind",
             lang::DidYouMean(kind, kKinds));
      continue;
    }
    constraint.kind = static_cast<Constraint::Kind>(found - kKinds.begin());
    if (constraint.kind == Constraint::Kind::kRolling) {
      // Two points cannot roll on each other: rolling without slipping needs the shape that
      // rolls (where the contact point is on it), which a constraint's `at` points do not give.
      Report(DiagnosticKind::kRollingConstraint, call->range,
             fmt::format("constraint `{}`: a point cannot roll; rolling needs the surface that "
                         "rolls and the one it rolls on",
                         constraint.name),
             "rolling of two points",
             "for a wheel or a foot on a floor, give its ellipsoid a `contact` with `friction` "
             "(it rolls where friction holds it); `sliding` keeps a point on a line, "
             "`fixed_point` pins it");
    }
    auto frames = ReadConnection(scope, *pending.statement, *call->arguments[0].value);
    if (!frames) continue;
    constraint.first = (*frames)[0];
    constraint.second = (*frames)[1];
    auto points = ReadAtPoints(scope, bound, "at", *frames, pending.statement->range, true);
    constraint.point_in_first = points[0].value_or(Vec3{});
    constraint.point_in_second = points[1].value_or(Vec3{});
    constraint.distance = ReadQuantity(scope, bound, BlockKind::kConstraint, "distance");
    if (auto axis = ReadVector(scope, bound, BlockKind::kConstraint, "axis")) {
      constraint.axis = *axis;
    }
  }
}

}  // namespace sled::compiler::internal
