// DeckMapper (deck_mapper.h), the H cards: output requests.
#include "lang/legacy/deck_mapper.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "lang/ast/make_expr.h"
#include "lang/legacy/ast_pieces.h"

namespace sled::lang::legacy::mapping {

// One H request. KREF 0 is each card's default: H.1 and H.4 in the segment's own axes (sled's
// default too), the relative H.2, H.3, H.5 and H.6 relative to the primary vehicle.
void DeckMapper::MapOutput(const OutputCard& card, ast::Statement& block) {
  using Kind = OutputCard::Kind;
  auto request = [&](const char* keyword, const std::string& target) {
    ast::Statement statement;
    statement.keyword = keyword;
    statement.target = Path(target);
    return statement;
  };
  if (card.kind == Kind::kJointParameters || card.kind == Kind::kJointForce) {
    const std::string joint = Joint(card.segment);
    if (joint.empty()) return;
    const bool parameters = card.kind == Kind::kJointParameters;
    if (parameters) {
      Report(DiagnosticKind::kDeckApproximated, card.segment,
             fmt::format("card {}: ATB's H.7 lists seven joint parameters of joint {}; sled "
                         "outputs its angles and torques (`joint_angle`, `joint_torque`)",
                         card.segment.card, card.segment.number),
             "docs/legacy.md, H cards");
    }
    AddRequest(block, request(parameters ? "joint_angle" : "joint_force", joint), card);
    AddRequest(block, request("joint_torque", joint), card);
    return;
  }
  const std::string segment = Segment(card.segment, "segment");
  if (segment.empty()) return;
  static constexpr const char* kKeywords[] = {"acceleration",     "velocity",
                                              "position",         "angular_acceleration",
                                              "angular_velocity", "orientation"};
  ast::Statement statement = request(kKeywords[static_cast<int>(card.kind)], segment);
  const bool point = card.kind == Kind::kAcceleration || card.kind == Kind::kVelocity ||
                     card.kind == Kind::kPosition;
  if (point) statement.clauses.push_back({"at", {}, Vector(card.point, L)});
  const bool in_axes = card.kind == Kind::kAcceleration || card.kind == Kind::kAngularAcceleration;
  if (in_axes) {
    if (card.frame) statement.clauses.push_back({"expressed_in", {}, Path(FrameName(*card.frame))});
  } else {
    const std::string frame = card.frame ? FrameName(*card.frame) : Primary();
    statement.clauses.push_back({"relative_to", {}, Path(frame)});
    if (card.kind == Kind::kVelocity && card.frame &&
        card.frame->kind == DeckFrame::Kind::kSegment) {
      // ATB's H.2 is R^T (v_p - v_F); seen from a turning frame sled also takes away the
      // frame's turning, w_F x r (the deck's vehicles only translate: there it is exact).
      Report(DiagnosticKind::kDeckApproximated, card.reference,
             fmt::format("card {}: KREF {} is a body segment, which turns: ATB's relative "
                         "velocity is the difference of the two velocities in its axes, "
                         "sled's the velocity seen from it, which differs by the segment's "
                         "angular velocity times the distance between the point and it",
                         card.reference.card, card.reference.number),
             "for ATB's quantity, request `velocity ... expressed_in` of both and subtract");
    }
  }
  AddRequest(block, std::move(statement), card);
}

// sled names a request's column after its kind, target and frame, so two requests that differ
// only in their point (two H.1 points on one segment, which ATB allows) would be one column:
// the second is named with `as`. The same request twice is one column: the second is left out
// (ATB prints it twice); H.7 and H.9 of one joint both give its `joint_torque`, once.
void DeckMapper::AddRequest(ast::Statement& block, ast::Statement request, const OutputCard& card) {
  std::string label = request.keyword + " " + request.target->PathText();
  for (const ast::Clause& clause : request.clauses) {
    if (clause.word != "at") label += " " + clause.word + " " + clause.value.PathText();
  }
  const std::string point = request.FindClause("at") ? fmt::format("{} {} {}", card.point[0],
                                                                   card.point[1], card.point[2])
                                                     : std::string();
  auto [requested, inserted] = output_labels_.try_emplace(label);
  if (!inserted) {
    if (requested->second.count(point) != 0) {
      if (request.keyword != "joint_torque") {
        Report(DiagnosticKind::kDeckIgnoredField, card.segment,
               fmt::format("card {}: the same output request as an earlier H card ({} of {}); "
                           "sled outputs it once",
                           card.segment.card, request.keyword, request.target->PathText()),
               "remove the repeated request");
      }
      return;
    }
    const std::string& target = request.target->path.back();
    std::string name;
    for (int n = 2; name.empty() || !taken_outputs_.insert(name).second; ++n)
      name = fmt::format("{}_{}_{}", target, request.keyword, n);
    request.clauses.push_back({"as", {}, Path(name)});
  }
  requested->second.insert(point);
  Add(block, std::move(request));
}

void DeckMapper::MapOutputs(ast::Block& scenario) {
  ast::Statement output =
      Declaration("output", Path("x"), "cards H.1 to H.9, and NOUT of the F cards");
  output.target.reset();
  for (const OutputCard& card : deck_.outputs) MapOutput(card, output);
  for (const auto& [a, b] : contact_outputs_) {
    ast::Statement request;
    request.keyword = "contact_force";
    request.target = Path(a);
    request.clauses.push_back({"with", {}, Path(b)});
    Add(output, std::move(request));
  }
  for (const std::string& belt : belt_outputs_) {
    ast::Statement request;
    request.keyword = "belt_force";
    request.target = Path(belt);
    Add(output, std::move(request));
  }
  if (!output.block->statements.empty()) scenario.statements.push_back(std::move(output));
}

}  // namespace sled::lang::legacy::mapping
