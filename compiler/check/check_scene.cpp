// Scene-level declarations: what a scenario or module block declares, and the checking of
// vehicles, surfaces, contacts, restraints, springs and constraints once every name is known.
#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "compiler/check/checkers.h"
#include "compiler/check/displacement_history.h"

namespace sled::compiler::internal {
namespace {

Vec3 Subtract(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec3 Cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double Norm(const Vec3& a) { return std::hypot(a[0], a[1], a[2]); }

// The name a declaration gives, or empty after reporting that it has none.
std::string NameOf(CheckContext& checker, const ast::Statement& statement) {
  if (statement.target && statement.target->kind == ast::ExprKind::kPath &&
      statement.target->path.size() == 1) {
    return statement.target->path[0];
  }
  checker.Report(
      DiagnosticKind::kMalformedStatement,
      statement.target ? statement.target->range : statement.keyword_range,
      fmt::format("`{}` needs a plain name: `{} NAME ...`", statement.keyword, statement.keyword),
      statement.target ? "not a plain name" : "name missing",
      "a name is one word of letters, digits and `_`");
  return {};
}

}  // namespace

std::optional<FrameRef> CheckContext::ResolveFrame(Scope& scope, const ast::Expr& expr) {
  Entity* entity =
      Resolve(scope, expr, {EntityKind::kGround, EntityKind::kVehicle, EntityKind::kSegment});
  if (!entity) return std::nullopt;
  switch (entity->kind) {
    case EntityKind::kVehicle:
      return FrameRef{FrameRef::Kind::kVehicle, entity->index};
    case EntityKind::kSegment:
      return FrameRef{FrameRef::Kind::kSegment, entity->index};
    default:
      return FrameRef{};
  }
}

std::string CheckContext::FrameName(const FrameRef& frame) const {
  switch (frame.kind) {
    case FrameRef::Kind::kVehicle:
      return scenario_.vehicles.at(static_cast<std::size_t>(frame.index)).name;
    case FrameRef::Kind::kSegment:
      return scenario_.segments.at(static_cast<std::size_t>(frame.index)).name;
    case FrameRef::Kind::kGround:
      break;
  }
  return "ground";
}

CheckContext::BoundBlock SceneChecker::DeclareFileContents(Scope& scope, const ast::Block& block,
                                                           BlockKind kind) {
  BoundBlock bound = Bind(kind, &block, block.range);
  if (kind == BlockKind::kScenario) scenario_bound_ = bound;
  auto declare = [&](const ast::Statement& statement, EntityKind entity_kind, int index,
                     std::vector<Pending>& pending) {
    const std::string name = NameOf(*this, statement);
    if (name.empty()) return false;
    if (!Declare(scope, name, Entity{entity_kind, index, statement.target->range})) return false;
    pending.push_back({&statement, &scope, index});
    return true;
  };
  // Reserves the next element of a scenario list for a named declaration, with its qualified
  // name and range, and queues it for checking once every name is known.
  auto declare_named = [&](auto& list, const ast::Statement& statement, EntityKind entity_kind,
                           std::vector<Pending>& pending) {
    const int index = static_cast<int>(list.size());
    list.emplace_back();
    if (!declare(statement, entity_kind, index, pending)) return false;
    list.back().name = scope.prefix + statement.target->path[0];
    list.back().range = statement.target->range;
    return true;
  };
  for (const ast::Statement* statement : bound.declarations) {
    const std::string& keyword = statement->keyword;
    if (keyword == "scenario") {
      if (scenario_statement_) {
        auto diagnostic =
            lang::MakeDiagnostic(DiagnosticKind::kMultipleScenarios, statement->keyword_range,
                                 "a file holds one scenario; this is a second", "second scenario");
        diagnostic.labels.push_back({scenario_statement_->keyword_range, "first here", false});
        diagnostic.help = "split the scenarios into files of their own";
        diagnostics_.Consume(std::move(diagnostic));
        continue;
      }
      scenario_statement_ = statement;
      if (statement->target && statement->target->kind == ast::ExprKind::kString) {
        scenario_.title = statement->target->text;
      }
      if (!statement->block) {
        Report(DiagnosticKind::kMalformedStatement, statement->range,
               "a scenario has a block: `scenario \"title\" { ... }`", "no block",
               "add `{ ... }` after the title");
        continue;
      }
      DeclareFileContents(scope, *statement->block, BlockKind::kScenario);
    } else if (keyword == "import") {
      Import(scope, *statement);
    } else if (keyword == "param" || keyword == "let") {
      const std::string name = NameOf(*this, *statement);
      if (name.empty()) continue;
      if (statement->values.size() != 1 || !statement->clauses.empty() || statement->block) {
        Report(DiagnosticKind::kMalformedStatement, statement->range,
               fmt::format("write `{} {} = value`", keyword, name), "not a single value",
               fmt::format("a `{}` names one value; declare several with one `{}` each", keyword,
                           keyword));
        continue;
      }
      auto parameter = std::make_unique<Parameter>();
      parameter->name = scope.prefix + name;
      parameter->expr = &statement->values[0];
      parameter->scope = &scope;
      parameter->is_param = keyword == "param";
      parameter->range = statement->target->range;
      if (parameter->is_param && &scope == scene_scope_) {
        for (Override& entry : overrides_) {
          if (entry.name == name && entry.value) {
            parameter->override_expr = *entry.value;
            entry.used = true;
          }
        }
      }
      const int index = static_cast<int>(parameters_.size());
      parameters_.push_back(std::move(parameter));
      Declare(scope, name, Entity{EntityKind::kParameter, index, statement->target->range});
    } else if (keyword == "body") {
      if (kind == BlockKind::kModule) continue;  // instanced when imported
      const std::string name = NameOf(*this, *statement);
      if (name.empty()) continue;
      const int index = static_cast<int>(scenario_.bodies.size());
      CheckBodyDeclarations(scope, *statement, scope.prefix + name, statement->target->range);
      Declare(scope, name,
              Entity{EntityKind::kBody, index, statement->target->range, bodies_.back().scope});
    } else if (keyword == "function") {
      const int index = static_cast<int>(scenario_.functions.size());
      scenario_.functions.emplace_back();
      function_valid_.push_back(false);
      declare(*statement, EntityKind::kFunction, index, functions_);
    } else if (keyword == "vehicle") {
      declare_named(scenario_.vehicles, *statement, EntityKind::kVehicle, vehicles_);
    } else if (kind == BlockKind::kModule && (keyword == "plane" || keyword == "ellipsoid")) {
      continue;  // instanced when imported, in the frame the import gives
    } else if (keyword == "plane") {
      declare_named(scenario_.planes, *statement, EntityKind::kPlane, planes_);
    } else if (keyword == "ellipsoid") {
      declare_named(scenario_.ellipsoids, *statement, EntityKind::kEllipsoid, ellipsoids_);
    } else if (keyword == "belt") {
      declare_named(scenario_.belts, *statement, EntityKind::kBelt, belts_);
    } else if (keyword == "harness") {
      declare_named(scenario_.harnesses, *statement, EntityKind::kHarness, harnesses_);
    } else if (keyword == "airbag") {
      declare_named(scenario_.airbags, *statement, EntityKind::kAirbag, airbags_);
    } else if (keyword == "spring" || keyword == "tension") {
      if (declare_named(scenario_.springs, *statement, EntityKind::kSpring, springs_)) {
        scenario_.springs.back().tension_only = keyword == "tension";
      }
    } else if (keyword == "constraint") {
      declare_named(scenario_.constraints, *statement, EntityKind::kConstraint, constraints_);
    } else if (keyword == "load") {
      declare_named(scenario_.loads, *statement, EntityKind::kLoad, loads_);
    } else if (keyword == "actuator") {
      declare_named(scenario_.actuators, *statement, EntityKind::kActuator, actuators_);
    } else if (keyword == "segment") {
      if (declare_named(scenario_.segments, *statement, EntityKind::kSegment, segments_)) {
        const int index = static_cast<int>(scenario_.segments.size()) - 1;
        scenario_.segments.back().body = current_body_;
        scenario_.bodies[static_cast<std::size_t>(current_body_)].segments.push_back(index);
      }
    } else if (keyword == "joint") {
      if (declare_named(scenario_.joints, *statement, EntityKind::kJoint, joints_)) {
        const int index = static_cast<int>(scenario_.joints.size()) - 1;
        scenario_.bodies[static_cast<std::size_t>(current_body_)].joints.push_back(index);
      }
    } else if (keyword == "contact") {
      contacts_.push_back({statement, &scope, -1});
    } else if (keyword == "override") {
      joint_overrides_.push_back({statement, &scope, -1});
    } else if (keyword == "initial") {
      initials_.push_back({statement, &scope, -1});
    } else if (keyword == "output") {
      outputs_.push_back({statement, &scope, -1});
    } else {
      // time, integrator, restart, settle, symmetry, water: at most one of each; several winds
      // (airs of their own speeds on their own segments, as ATB's F.7.b cards name functions).
      for (const ast::Statement* earlier : run_blocks_) {
        if (earlier->keyword == keyword && keyword != "wind") {
          auto diagnostic =
              lang::MakeDiagnostic(DiagnosticKind::kDuplicateAttribute, statement->keyword_range,
                                   fmt::format("`{}` is given twice", keyword), "given again here");
          diagnostic.labels.push_back({earlier->keyword_range, "first given here", false});
          diagnostics_.Consume(std::move(diagnostic));
        }
      }
      run_blocks_.push_back(statement);
    }
  }
  return bound;
}

void SceneChecker::DeclareModuleSurfaces(Scope& instance, const ast::Block& module,
                                         const ast::Expr* frame, Scope& frame_scope) {
  // The surfaces' own scope: their names live in the instance, their frame here.
  Scope* surfaces = NewScope(&instance, instance.prefix, instance.directory);
  surfaces->surface_frame = frame;
  surfaces->surface_frame_scope = &frame_scope;
  for (const ast::Statement& statement : module.statements) {
    const bool plane = statement.keyword == "plane";
    if (!(plane || statement.keyword == "ellipsoid") ||
        statement.kind != ast::StatementKind::kHeader) {
      continue;
    }
    if (const ast::Clause* on = statement.FindClause("on")) {
      Report(
          DiagnosticKind::kMalformedStatement, on->word_range,
          fmt::format("a {} of a module is fixed in the frame its import gives", statement.keyword),
          "no `on` here", "write `import MODULE as NAME on FRAME` in the scene");
      continue;
    }
    const std::string name = NameOf(*this, statement);
    if (name.empty()) continue;
    const EntityKind kind = plane ? EntityKind::kPlane : EntityKind::kEllipsoid;
    const int index =
        static_cast<int>(plane ? scenario_.planes.size() : scenario_.ellipsoids.size());
    if (!Declare(instance, name, Entity{kind, index, statement.target->range})) continue;
    if (plane) {
      scenario_.planes.emplace_back();
      scenario_.planes.back().name = instance.prefix + name;
      scenario_.planes.back().range = statement.target->range;
      planes_.push_back({&statement, surfaces, index});
    } else {
      scenario_.ellipsoids.emplace_back();
      scenario_.ellipsoids.back().name = instance.prefix + name;
      scenario_.ellipsoids.back().range = statement.target->range;
      ellipsoids_.push_back({&statement, surfaces, index});
    }
  }
}

std::optional<FrameRef> CheckContext::SurfaceFrame(const ast::Statement& statement, Scope& scope) {
  if (const ast::Clause* on = statement.FindClause("on")) return ResolveFrame(scope, on->value);
  if (scope.surface_frame) return ResolveFrame(*scope.surface_frame_scope, *scope.surface_frame);
  return FrameRef{};
}

namespace {

// Reads the named arguments of a call against a list of allowed names; reports unknown and
// missing ones.
struct CallArguments {
  std::map<std::string, const ast::Expr*> named;
  bool ok = true;
};

CallArguments ReadArguments(CheckContext& checker, const ast::Expr& call,
                            const std::vector<std::string>& allowed,
                            const std::vector<std::string>& required) {
  CallArguments result;
  for (const ast::Argument& argument : call.arguments) {
    if (argument.name.empty()) {
      checker.Report(DiagnosticKind::kUnknownArgument, argument.value->range,
                     fmt::format("`{}` takes named arguments only", call.PathText()),
                     "name this argument",
                     fmt::format("write `{}(...)` with `name = value` for each of: {}",
                                 call.PathText(), fmt::join(allowed, ", ")));
      result.ok = false;
      continue;
    }
    if (std::find(allowed.begin(), allowed.end(), argument.name) == allowed.end()) {
      checker.Report(DiagnosticKind::kUnknownArgument, argument.name_range,
                     fmt::format("`{}` takes no argument `{}`", call.PathText(), argument.name),
                     "unknown argument", lang::DidYouMean(argument.name, allowed));
      result.ok = false;
      continue;
    }
    result.named[argument.name] = argument.value.get();
  }
  for (const std::string& name : required) {
    if (!result.named.count(name)) {
      checker.Report(DiagnosticKind::kMissingArgument, call.range,
                     fmt::format("`{}` needs the argument `{}`", call.PathText(), name),
                     fmt::format("`{}` missing", name),
                     fmt::format("add `{} = ...` to the call", name));
      result.ok = false;
    }
  }
  return result;
}

}  // namespace

void SceneChecker::CheckSceneElements() {
  for (const Pending& pending : vehicles_) {
    Vehicle& vehicle = scenario_.vehicles[static_cast<std::size_t>(pending.index)];
    const BoundBlock bound =
        Bind(BlockKind::kVehicle, pending.statement->block.get(), pending.statement->range);
    vehicle.position =
        ReadVector(*pending.scope, bound, BlockKind::kVehicle, "position").value_or(Vec3{});
    vehicle.orientation =
        ReadVector(*pending.scope, bound, BlockKind::kVehicle, "orientation").value_or(Vec3{});
    vehicle.velocity =
        ReadVector(*pending.scope, bound, BlockKind::kVehicle, "velocity").value_or(Vec3{});
    const ast::Statement* motion = One(bound, "motion");
    if (!motion) continue;
    const ast::Expr* call = SingleValue(*motion);
    if (!call) continue;
    if (call->kind != ast::ExprKind::kCall) {
      Report(DiagnosticKind::kWrongValueKind, call->range,
             "`motion` is half_sine(...), trapezoid(...) or table(time -> acceleration)",
             "not a motion",
             "for example `half_sine(delta_v = 56 km/h, duration = 100 ms, axis = -x)`");
      continue;
    }
    const std::string form = call->PathText();
    Motion& m = vehicle.motion;
    Scope& scope = *pending.scope;
    auto read_axis = [&](const CallArguments& arguments) {
      auto it = arguments.named.find("axis");
      if (it != arguments.named.end()) {
        if (auto axis = ExpectDirection(scope, *it->second, "axis")) m.axis = *axis;
      }
      auto start = arguments.named.find("start");
      if (start != arguments.named.end()) {
        m.start = ExpectQuantity(scope, *start->second, dim::kTime, "start").value_or(0.0);
      }
    };
    if (form == "half_sine") {
      auto arguments = ReadArguments(*this, *call, {"delta_v", "duration", "axis", "start"},
                                     {"delta_v", "duration"});
      if (!arguments.ok) continue;
      m.kind = Motion::Kind::kHalfSine;
      m.delta_v = ExpectQuantity(scope, *arguments.named["delta_v"], dim::kVelocity, "delta_v")
                      .value_or(0.0);
      const auto duration =
          ExpectQuantity(scope, *arguments.named["duration"], dim::kTime, "duration");
      m.duration = duration.value_or(0.0);
      if (duration && !(m.duration > 0.0)) {  // a value in error is reported already
        Report(DiagnosticKind::kValueOutOfRange, arguments.named["duration"]->range,
               "a pulse duration must be positive", "not positive",
               "give the pulse a positive duration, such as `duration = 100 ms`");
      }
      read_axis(arguments);
    } else if (form == "trapezoid") {
      // By its shape (peak, rise, dwell, fall), or by the test's delta-v and pulse duration
      // with the rise and fall: then dwell = duration - rise - fall and the peak gives the
      // delta-v, peak = delta_v / (duration - (rise + fall) / 2).
      const bool by_delta_v = std::any_of(
          call->arguments.begin(), call->arguments.end(),
          [](const ast::Argument& a) { return a.name == "delta_v" || a.name == "duration"; });
      auto arguments =
          by_delta_v
              ? ReadArguments(*this, *call,
                              {"delta_v", "duration", "rise", "fall", "axis", "start"},
                              {"delta_v", "duration", "rise", "fall"})
              : ReadArguments(*this, *call, {"peak", "rise", "dwell", "fall", "axis", "start"},
                              {"peak", "rise", "dwell", "fall"});
      if (!arguments.ok) continue;
      m.kind = Motion::Kind::kTrapezoid;
      m.rise = ExpectQuantity(scope, *arguments.named["rise"], dim::kTime, "rise").value_or(0.0);
      m.fall = ExpectQuantity(scope, *arguments.named["fall"], dim::kTime, "fall").value_or(0.0);
      if (by_delta_v) {
        const double delta_v =
            ExpectQuantity(scope, *arguments.named["delta_v"], dim::kVelocity, "delta_v")
                .value_or(0.0);
        const auto duration =
            ExpectQuantity(scope, *arguments.named["duration"], dim::kTime, "duration");
        m.dwell = duration.value_or(0.0) - m.rise - m.fall;
        if (duration && m.dwell < 0.0) {
          Report(DiagnosticKind::kValueOutOfRange, arguments.named["duration"]->range,
                 fmt::format("the pulse lasts {:g} ms, less than its rise and fall ({:g} ms)",
                             *duration * 1e3, (m.rise + m.fall) * 1e3),
                 "shorter than rise + fall",
                 "a trapezoid's duration is rise + dwell + fall: make it at least rise + fall");
          continue;
        }
        const double effective = m.dwell + 0.5 * (m.rise + m.fall);
        m.peak = effective > 0.0 ? delta_v / effective : 0.0;
      } else {
        m.peak = ExpectQuantity(scope, *arguments.named["peak"], dim::kAcceleration, "peak")
                     .value_or(0.0);
        m.dwell =
            ExpectQuantity(scope, *arguments.named["dwell"], dim::kTime, "dwell").value_or(0.0);
      }
      for (const auto& [name, value] :
           {std::pair{"rise", m.rise}, std::pair{"dwell", m.dwell}, std::pair{"fall", m.fall}}) {
        if (value < 0.0 && arguments.named.count(name) != 0) {
          Report(DiagnosticKind::kValueOutOfRange, arguments.named[name]->range,
                 fmt::format("the pulse's `{}` is negative", name), "negative",
                 "a trapezoid's rise, dwell and fall are durations: zero or more");
        }
      }
      read_axis(arguments);
    } else if (form == "table") {
      // table(time -> acceleration [-> angular_acceleration], axis = -x) { rows }, or
      // table(PULSE, axis = -x) with PULSE a named table function of time -> acceleration (the
      // pulses of the standard library).
      const ast::Expr* signature = nullptr;
      const ast::Expr* pulse = nullptr;
      CallArguments arguments;
      for (const ast::Argument& argument : call->arguments) {
        if (argument.name.empty() && argument.value->kind == ast::ExprKind::kArrow) {
          signature = argument.value.get();
        } else if (argument.name.empty() && argument.value->kind == ast::ExprKind::kPath &&
                   !pulse) {
          pulse = argument.value.get();
        } else if (argument.name == "axis" || argument.name == "start") {
          arguments.named[argument.name] = argument.value.get();
        } else {
          Report(DiagnosticKind::kUnknownArgument,
                 argument.name.empty() ? argument.value->range : argument.name_range,
                 "a motion table takes its signature and `axis`, `start`", "unexpected argument",
                 "remove it; the rows go in the block after the table");
        }
      }
      if (pulse && !signature) {
        read_axis(arguments);
        m.kind = Motion::Kind::kTable;
        if (motion->block) {
          Report(DiagnosticKind::kMalformedStatement, motion->block->range,
                 "a motion table that names its pulse takes no rows", "rows not allowed here",
                 "write the rows in the named function, or drop the name and keep the rows");
        }
        Entity* entity = Resolve(scope, *pulse, {EntityKind::kFunction});
        if (!entity ||
            !MatchSignature(entity->index, dim::kTime, dim::kAcceleration, pulse->range)) {
          continue;
        }
        const Function& function = scenario_.functions[static_cast<std::size_t>(entity->index)];
        if (function.kind != Function::Kind::kTable) {
          Report(
              DiagnosticKind::kWrongValueKind, pulse->range,
              fmt::format("a motion pulse is a table; `{}` is a {}", pulse->PathText(),
                          function.kind == Function::Kind::kConstant ? "constant" : "polynomial"),
              "not a table", "declare it as `function NAME = table(time -> acceleration) { ... }`");
          continue;
        }
        m.table = function.points;
        continue;
      }
      const bool six_dof = signature && signature->operands.size() == 3;
      // table(time -> displacement): the vehicle's travel along the axis, as recorded.
      const bool displacement = signature && signature->operands.size() == 2 &&
                                signature->operands[1].PathText() == "displacement";
      if (!signature || signature->operands.size() < 2 ||
          signature->operands[0].PathText() != "time" ||
          (signature->operands[1].PathText() != "acceleration" && !displacement) ||
          (six_dof && signature->operands[2].PathText() != "angular_acceleration")) {
        Report(DiagnosticKind::kMissingArgument, call->range,
               "a motion table is `table(time -> acceleration)`, `table(time -> displacement)` "
               "or `table(time -> acceleration -> angular_acceleration)`",
               "signature missing or wrong", "write `table(time -> acceleration) { rows }`");
        continue;
      }
      read_axis(arguments);
      m.kind = six_dof ? Motion::Kind::kSixDof : Motion::Kind::kTable;
      const BoundBlock rows = Bind(BlockKind::kTable, motion->block.get(), motion->range);
      double previous = -std::numeric_limits<double>::infinity();
      for (const ast::Statement* row : rows.rows) {
        const ast::Expr& arrow = row->values.at(0);
        if (arrow.operands.size() != (six_dof ? 3u : 2u)) {
          Report(DiagnosticKind::kMalformedStatement, arrow.range,
                 fmt::format("a row of this table has {} values", six_dof ? 3 : 2),
                 "wrong number of values",
                 six_dof ? "write rows `time -> acceleration -> angular_acceleration`"
                         : "write rows `time -> acceleration`");
          continue;
        }
        auto t = ExpectQuantity(scope, arrow.operands[0], dim::kTime, "time");
        if (!t) continue;
        if (!(*t > previous)) {
          Report(DiagnosticKind::kTableNotMonotone, arrow.operands[0].range,
                 "table time does not increase", "not after the previous row",
                 "order the rows by increasing time, each time once");
          continue;
        }
        if (displacement && m.table.empty() && *t != 0.0) {
          Report(DiagnosticKind::kValueOutOfRange, arrow.operands[0].range,
                 "a displacement history starts at 0 ms", "not 0",
                 "give the travel at the motion's start first; `start` delays the whole history");
        }
        previous = *t;
        if (six_dof) {
          auto linear = ExpectVector(scope, arrow.operands[1], dim::kAcceleration, "acceleration");
          auto angular = ExpectVector(scope, arrow.operands[2], dim::kAngularAcceleration,
                                      "angular_acceleration");
          if (linear && angular) {
            m.six_dof.push_back({*t, (*linear)[0], (*linear)[1], (*linear)[2], (*angular)[0],
                                 (*angular)[1], (*angular)[2]});
          }
        } else if (auto a = ExpectQuantity(scope, arrow.operands[1],
                                           displacement ? dim::kLength : dim::kAcceleration,
                                           displacement ? "displacement" : "acceleration")) {
          m.table.push_back({*t, *a});
        }
      }
      if (displacement && m.table.size() >= 2) {
        // The natural cubic spline through the samples, as its acceleration table; the vehicle
        // starts where the history starts, at its rate there (before the motion's `start`, it
        // moves steadily at that rate).
        const AccelerationHistory history = AccelerationFromDisplacement(m.table);
        m.table = history.table;
        for (std::size_t k = 0; k < 3; ++k) {
          vehicle.velocity[k] += m.axis[k] * history.velocity;
          vehicle.position[k] += m.axis[k] * (history.position - history.velocity * m.start);
        }
      }
      if ((six_dof ? m.six_dof.size() : m.table.size()) < 2 && !rows.rows.empty()) {
        Report(DiagnosticKind::kTableTooShort, call->range, "a motion table needs two rows",
               "too few rows", "add a second row");
      } else if (rows.rows.empty()) {
        Report(DiagnosticKind::kTableTooShort, call->range,
               "a motion table needs rows: `{ 0 ms -> 0 g  10 ms -> 20 g }`", "no rows",
               "give the rows in a block after the table");
      }
    } else {
      Report(DiagnosticKind::kInvalidEnumValue, call->range,
             fmt::format("unknown motion `{}`", form), "not a motion",
             lang::DidYouMean(form, {"half_sine", "trapezoid", "table"}));
    }
  }

  for (const Pending& pending : planes_) {
    Plane& plane = scenario_.planes[static_cast<std::size_t>(pending.index)];
    if (auto frame = SurfaceFrame(*pending.statement, *pending.scope)) plane.frame = *frame;
    const BoundBlock bound =
        Bind(BlockKind::kPlane, pending.statement->block.get(), pending.statement->range);
    const ast::Statement* corners = One(bound, "corners");
    if (!corners) continue;
    if (corners->values.size() != 3) {
      Report(DiagnosticKind::kWrongValueKind, corners->range,
             fmt::format("a plane has three corners P1, P2, P3, found {}", corners->values.size()),
             "not three points", "give three corner points, P1, P2, P3, separated by commas");
      continue;
    }
    bool ok = true;
    for (std::size_t i = 0; i < 3; ++i) {
      auto point = ExpectVector(*pending.scope, corners->values[i], dim::kLength, "corners");
      if (point) plane.corners[i] = *point;
      ok = ok && point.has_value();
    }
    if (ok) {
      const Vec3 normal = Cross(Subtract(plane.corners[1], plane.corners[0]),
                                Subtract(plane.corners[2], plane.corners[0]));
      if (!std::isfinite(Norm(normal))) {
        // The contact computes with the edges' squares and the area: beyond about 1e154 m
        // they overflow, and a plane with an infinite normal would never be touched.
        Report(DiagnosticKind::kValueOutOfRange, corners->range,
               fmt::format("the corners of plane `{}` are so far apart that its area ({:g} by "
                           "{:g} m) cannot be computed",
                           plane.name, Norm(Subtract(plane.corners[1], plane.corners[0])),
                           Norm(Subtract(plane.corners[2], plane.corners[0]))),
               "too far apart", "give corners a realistic distance apart");
      } else if (!(Norm(normal) > 1e-12)) {
        Report(DiagnosticKind::kZeroVector, corners->range,
               fmt::format("the corners of plane `{}` lie on one line", plane.name), "no normal",
               "P1, P2 and P3 must span a parallelogram");
      }
    }
  }

  for (const Pending& pending : ellipsoids_) {
    Ellipsoid& ellipsoid = scenario_.ellipsoids[static_cast<std::size_t>(pending.index)];
    const bool in_module = pending.scope->surface_frame_scope != nullptr;
    if (!in_module && !pending.statement->FindClause("on")) {
      Report(DiagnosticKind::kMalformedStatement, pending.statement->range,
             "an ellipsoid is fixed in a frame: `ellipsoid NAME on FRAME { ... }`", "no `on`",
             "add `on FRAME` after the name: ground, a vehicle or a segment");
    } else if (auto frame = SurfaceFrame(*pending.statement, *pending.scope)) {
      ellipsoid.frame = *frame;
      if (frame->kind == FrameRef::Kind::kSegment) {
        scenario_.segments[static_cast<std::size_t>(frame->index)].ellipsoids.push_back(
            pending.index);
      }
    }
    const BoundBlock bound =
        Bind(BlockKind::kEllipsoid, pending.statement->block.get(), pending.statement->range);
    ReadEllipsoid(*pending.scope, bound, BlockKind::kEllipsoid, ellipsoid);
  }
}

}  // namespace sled::compiler::internal
