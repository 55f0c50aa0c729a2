// The output requests and injury criteria of a scenario: what each measures, in which frame,
// filtered how (OutputChecker, checkers.h).
#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "compiler/check/checkers.h"

namespace sled::compiler::internal {

static Dimension CriterionDimension(Criterion::Kind kind) {
  switch (kind) {
    case Criterion::Kind::kHead3ms:
    case Criterion::Kind::kChest3ms:
      return dim::kAcceleration;
    case Criterion::Kind::kNeckTension:
    case Criterion::Kind::kNeckCompression:
    case Criterion::Kind::kFemurLoad:
      return dim::kForce;
    case Criterion::Kind::kViscousCriterion:
      return dim::kVelocity;
    case Criterion::Kind::kTti:
      return dim::kAcceleration;
    case Criterion::Kind::kNic:
      return dim::kVelocity * dim::kVelocity;
    case Criterion::Kind::kTibiaIndex:
    case Criterion::Kind::kHic15:
    case Criterion::Kind::kHic36:
    case Criterion::Kind::kGaddHead:
    case Criterion::Kind::kGaddChest:
    case Criterion::Kind::kNij:
    case Criterion::Kind::kNkm:
      return dim::kDimensionless;
  }
  return dim::kDimensionless;
}

// A criterion's arguments after its target: the second input of NIC and TTI
// (`nic(occupant.head, t1 = occupant.neck_lower)`), and its own limit
// (`hic15(pedestrian.head, limit = 1000, standard = "GTR 9")`), in the criterion's dimension,
// always with the standard it comes from. False after reporting.
bool OutputChecker::ReadCriterionArguments(Scope& scope, const ast::Expr& call,
                                           const CriterionSpec& spec, Criterion& criterion) {
  const ast::Expr* limit = nullptr;
  const ast::Expr* standard = nullptr;
  const ast::Expr* second = nullptr;
  bool ok = true;
  for (std::size_t i = 1; i < call.arguments.size(); ++i) {
    const ast::Argument& argument = call.arguments[i];
    if (argument.name == "limit" && !limit) {
      limit = argument.value.get();
    } else if (argument.name == "standard" && !standard) {
      standard = argument.value.get();
    } else if (!spec.second_name.empty() && argument.name == spec.second_name && !second) {
      second = argument.value.get();
    } else {
      Report(DiagnosticKind::kUnknownArgument,
             argument.name.empty() ? argument.value->range : argument.name_range,
             spec.second_name.empty()
                 ? std::string("a criterion takes its target, then `limit` and `standard`")
                 : fmt::format("`{}` takes its target, then `{}`, `limit` and `standard`",
                               spec.name, spec.second_name),
             "unexpected argument",
             "write `hic15(pedestrian.head, limit = 1000, standard = \"GTR 9\")`");
      ok = false;
    }
  }
  if (!spec.second_name.empty()) {
    if (!second) {
      Report(DiagnosticKind::kMissingArgument, call.range,
             fmt::format("`{}` needs its {} `{}` as well as its target", spec.name,
                         spec.second_kind, spec.second_name),
             fmt::format("no `{}`", spec.second_name),
             spec.name == "nic" ? "write `nic(occupant.head, t1 = occupant.neck_lower)`"
                                : "write `tti(occupant.thorax, spine = occupant.abdomen)`");
      return false;
    }
    Entity* input = Resolve(scope, *second, {*EntityKindFromName(spec.second_kind)});
    if (!input) return false;
    criterion.second = input->index;
  }
  if (!limit && !standard) return ok;
  if (!limit || !standard) {
    Report(DiagnosticKind::kMissingArgument, call.range,
           limit ? "a criterion's own limit names the standard it comes from"
                 : "a criterion's `standard` comes with the `limit` it sets",
           limit ? "no `standard`" : "no `limit`",
           "give both: `limit = 1000, standard = \"GTR 9\"`");
    return false;
  }
  if (standard->kind != ast::ExprKind::kString || standard->text.empty()) {
    Report(DiagnosticKind::kWrongValueKind, standard->range,
           "a criterion's `standard` is its name in quotes", "not a string",
           "write the standard's name in double quotes, such as `standard = \"Euro NCAP\"`");
    return false;
  }
  const auto value = ExpectQuantity(scope, *limit, CriterionDimension(criterion.kind), "limit");
  if (!value) return false;
  if (!(*value > 0.0)) {
    Report(DiagnosticKind::kValueOutOfRange, limit->range, "a criterion's limit must be positive",
           "not positive", "give the largest value the standard allows");
    return false;
  }
  criterion.limit = *value;
  criterion.standard = standard->text;
  return ok;
}

// `filter cfc1000` on an output request: the class in Hz, 0 for `none`, -1 when invalid
// (reported) so the request keeps its kind's default.
int OutputChecker::ReadFilterClass(const ast::Expr& value) {
  static const std::vector<std::string> kClasses = {"cfc60", "cfc180", "cfc600", "cfc1000", "none"};
  static constexpr int kHertz[] = {60, 180, 600, 1000, 0};
  const std::string word = value.kind == ast::ExprKind::kPath ? value.PathText() : "";
  for (std::size_t i = 0; i < kClasses.size(); ++i) {
    if (word == kClasses[i]) return kHertz[i];
  }
  Report(DiagnosticKind::kInvalidEnumValue, value.range,
         "a channel's filter is a SAE J211 class, `cfc60`, `cfc180`, `cfc600` or `cfc1000`, or "
         "`none`",
         "not a filter class", lang::DidYouMean(word, kClasses));
  return -1;
}

// `filter_standard = sae_j211 | iso_6487` of an output block: true for ISO 6487.
bool OutputChecker::ReadFilterStandard(const BoundBlock& bound) {
  const ast::Statement* statement = One(bound, "filter_standard");
  if (!statement) return false;
  const ast::Expr* value = SingleValue(*statement);
  if (!value) return false;
  static const std::vector<std::string> kStandards = {"sae_j211", "iso_6487"};
  const std::string word = value->kind == ast::ExprKind::kPath ? value->PathText() : "";
  if (word == "iso_6487") return true;
  if (word != "sae_j211") {
    Report(DiagnosticKind::kInvalidEnumValue, value->range,
           "`filter_standard` is `sae_j211` or `iso_6487`", "not a filter standard",
           lang::DidYouMean(word, kStandards));
  }
  return false;
}

// `relative_to FRAME` or `expressed_in FRAME` on a segment request: the frame and how the
// quantity is taken in it. The frame names the channels unless `as` does
// (`occupant.head.relative_to.sled`). False when the frame is reported.
bool OutputChecker::ReadOutputFrame(Scope& scope, const ast::Statement& request,
                                    const OutputSpec& spec, OutputRequest& output) {
  if (spec.target_kind != "segment") return true;
  const ast::Clause* relative = request.FindClause("relative_to");
  const ast::Clause* expressed = request.FindClause("expressed_in");
  if (relative && expressed) {
    Report(DiagnosticKind::kMalformedStatement, expressed->word_range,
           fmt::format("`{}` takes `relative_to` or `expressed_in`, not both", request.keyword),
           "second frame",
           "`relative_to F` is the motion seen from F; `expressed_in F` the motion relative to the "
           "ground in F's axes");
    return false;
  }
  const ast::Clause* clause = relative ? relative : expressed;
  if (!clause ||
      (expressed && (request.keyword == "position" || request.keyword == "orientation"))) {
    return true;  // none, or reported as not allowed
  }
  output.relative_to = ResolveFrame(scope, clause->value);
  if (!output.relative_to) return false;
  output.expressed_in = expressed != nullptr;
  if (!request.FindClause("as")) {
    output.label =
        fmt::format("{}.{}.{}", output.label, clause->word, FrameName(*output.relative_to));
  }
  return true;
}

void OutputChecker::CheckOutputs() {
  for (const Pending& pending : outputs_) {
    const ast::Statement& statement = *pending.statement;
    Scope& scope = *pending.scope;
    const BoundBlock bound = Bind(BlockKind::kOutput, statement.block.get(), statement.range);
    const bool iso_filter = ReadFilterStandard(bound);
    for (const ast::Statement* request : bound.declarations) {
      const OutputSpec* spec = FindOutput(request->keyword);
      if (!request->target || request->has_value || request->block) {
        Report(DiagnosticKind::kMalformedStatement, request->range,
               fmt::format("write `{} {}{}`", request->keyword,
                           spec->target_kind == "contact" ? "A with B" : "NAME",
                           spec->takes_point ? " [at (x, y, z) mm]" : ""),
               "not an output request", "the output requests are listed in docs/language.md §17");
        continue;
      }
      OutputRequest output;
      output.range = request->range;
      output.kind = static_cast<OutputRequest::Kind>(spec - AllOutputSpecs().data());
      output.label = request->target->PathText();
      output.iso_filter = iso_filter;
      for (const ast::Clause& clause : request->clauses) {
        const bool allowed = (clause.word == "at" && spec->takes_point) || clause.word == "as" ||
                             clause.word == "filter" ||
                             (clause.word == "with" && spec->target_kind == "contact") ||
                             (clause.word == "relative_to" && spec->target_kind == "segment") ||
                             (clause.word == "expressed_in" && spec->target_kind == "segment" &&
                              request->keyword != "position" && request->keyword != "orientation");
        if (!allowed) {
          Report(DiagnosticKind::kMalformedStatement, clause.word_range,
                 fmt::format("`{}` takes no `{}` clause", request->keyword, clause.word),
                 "not allowed here", "remove the clause");
        }
      }
      if (const ast::Clause* as = request->FindClause("as")) {
        if (as->value.kind == ast::ExprKind::kPath && as->value.path.size() == 1) {
          output.label = as->value.path[0];
        } else {
          Report(DiagnosticKind::kMalformedStatement, as->value.range, "`as` takes one plain name",
                 "not a plain name", "the column name is one word, such as `head_x`");
        }
      }
      if (const ast::Clause* filter = request->FindClause("filter")) {
        output.filter_class = ReadFilterClass(filter->value);
      }
      if (const ast::Clause* at = request->FindClause("at"); at && spec->takes_point) {
        output.point = ExpectVector(scope, at->value, dim::kLength, "at").value_or(Vec3{});
      }
      if (!ReadOutputFrame(scope, *request, *spec, output)) continue;  // reported
      if (spec->target_kind == "contact") {
        const ast::Clause* with = request->FindClause("with");
        if (!with) {
          Report(DiagnosticKind::kMalformedStatement, request->range,
                 "write `contact_force A with B`", "no `with`",
                 "name the two surfaces: `contact_force occupant.head with windscreen`");
          continue;
        }
        // The request names the same two surfaces as a declared contact.
        Entity* first =
            Resolve(scope, *request->target, {EntityKind::kSegment, EntityKind::kEllipsoid});
        Entity* second = Resolve(
            scope, with->value, {EntityKind::kSegment, EntityKind::kEllipsoid, EntityKind::kPlane});
        if (!first || !second) continue;
        auto matches = [&](const SurfaceRef& surface, Entity* entity) {
          if (entity->kind == EntityKind::kPlane) {
            return surface.kind == SurfaceRef::Kind::kPlane && surface.index == entity->index;
          }
          if (surface.kind != SurfaceRef::Kind::kEllipsoid) return false;
          if (entity->kind == EntityKind::kEllipsoid) return surface.index == entity->index;
          const Ellipsoid& e = scenario_.ellipsoids[static_cast<std::size_t>(surface.index)];
          return e.frame.kind == FrameRef::Kind::kSegment && e.frame.index == entity->index;
        };
        for (std::size_t i = 0; i < scenario_.contacts.size(); ++i) {
          const Contact& contact = scenario_.contacts[i];
          if (matches(contact.first, first) && matches(contact.second, second)) {
            if (output.index < 0) output.index = static_cast<int>(i);
            output.contacts.push_back(static_cast<int>(i));
          }
        }
        if (output.index < 0) {
          Report(DiagnosticKind::kOutputNeverComputed, request->range,
                 fmt::format("no contact between `{}` and `{}` is declared, so its force is "
                             "never computed",
                             request->target->PathText(), with->value.PathText()),
                 "nothing to output",
                 fmt::format("declare `contact {} with {} {{ force = ... }}`",
                             request->target->PathText(), with->value.PathText()));
          continue;
        }
        if (!request->FindClause("as")) {
          output.label = fmt::format("{}.{}", output.label, with->value.PathText());
        }
        scenario_.outputs.push_back(std::move(output));
        continue;
      }
      const EntityKind kind = *EntityKindFromName(spec->target_kind);
      Entity* target = Resolve(scope, *request->target, {kind});
      if (!target) continue;
      output.index = target->index;
      if (kind == EntityKind::kJoint &&
          (request->keyword == "joint_torque" || request->keyword == "joint_angle")) {
        const Joint& joint = scenario_.joints[static_cast<std::size_t>(target->index)];
        if (joint.type == JointType::kNull) {
          Report(DiagnosticKind::kOutputNeverComputed, request->range,
                 fmt::format("`{}` is a null joint: it has no {}", joint.name,
                             request->keyword == "joint_torque" ? "torque" : "angle"),
                 "never computed", "null joints only start a new body");
          continue;
        }
      }
      scenario_.outputs.push_back(std::move(output));
    }
    if (const ast::Statement* criteria = One(bound, "criteria")) {
      for (const ast::Expr& value : criteria->values) {
        if (value.kind != ast::ExprKind::kCall || value.arguments.empty() ||
            !value.arguments[0].name.empty()) {
          Report(DiagnosticKind::kWrongValueKind, value.range,
                 "a criterion is written `name(target)`, as in `hic15(occupant.head)`",
                 "not a criterion", "the criteria are listed in docs/language.md §17");
          continue;
        }
        const CriterionSpec* spec = FindCriterion(value.PathText());
        if (!spec) {
          std::vector<std::string> names;
          for (const CriterionSpec& c : AllCriterionSpecs()) names.emplace_back(c.name);
          Report(DiagnosticKind::kInvalidEnumValue, value.range,
                 fmt::format("unknown injury criterion `{}`", value.PathText()), "not a criterion",
                 lang::DidYouMean(value.PathText(), names));
          continue;
        }
        const EntityKind kind = *EntityKindFromName(spec->target_kind);
        Criterion criterion;
        criterion.kind = static_cast<Criterion::Kind>(spec - AllCriterionSpecs().data());
        // The Viscous Criterion reads a chest's deflection: a slip joint between the spine and
        // the sternum gives one (a rigid thorax segment does not, and is noted when lowered).
        const bool viscous = criterion.kind == Criterion::Kind::kViscousCriterion;
        Entity* target = Resolve(scope, *value.arguments[0].value,
                                 viscous ? std::vector<EntityKind>{kind, EntityKind::kJoint}
                                         : std::vector<EntityKind>{kind});
        if (!target) continue;
        if (target->kind == EntityKind::kJoint && viscous &&
            scenario_.joints[static_cast<std::size_t>(target->index)].type != JointType::kSlip) {
          Report(DiagnosticKind::kWrongKindOfName, value.arguments[0].value->range,
                 fmt::format("`viscous_criterion` of a joint reads its sliding as the chest's "
                             "deflection: `{}` is not a slip joint",
                             value.arguments[0].value->PathText()),
                 "not a slip joint",
                 "name the slip joint between the spine and the sternum, or the chest segment");
          continue;
        }
        (target->kind == EntityKind::kSegment ? criterion.segment : criterion.joint) =
            target->index;
        criterion.iso_filter = iso_filter;
        criterion.range = value.range;
        if (!ReadCriterionArguments(scope, value, *spec, criterion)) continue;
        scenario_.criteria.push_back(criterion);
      }
    }
  }
}

}  // namespace sled::compiler::internal
