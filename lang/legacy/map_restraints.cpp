// DeckMapper (deck_mapper.h), card group D and the F contacts: planes, vehicle and extra
// ellipsoids, contacts, belts, spring-dampers, airbags, constraints and harnesses.
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

void DeckMapper::MapSurfaces(ast::Block& scenario) {
  for (std::size_t p = 0; p < deck_.planes.size(); ++p) {
    const PlaneCard& card = deck_.planes[p];
    ast::Statement plane = Declaration("plane", Path(planes_[p]), CardComment("D.2", card.line));
    plane.clauses.push_back({"on", {}, Path(Primary())});
    ast::Statement corners;
    corners.keyword = "corners";
    corners.has_value = true;
    for (const Vec3& corner : card.corners) corners.values.push_back(Vector(corner, L));
    Add(plane, std::move(corners));
    scenario.statements.push_back(std::move(plane));
  }
  for (const VehicleEllipsoidCard& card : deck_.vehicle_ellipsoids) {
    const std::string& vehicle = vehicles_[static_cast<std::size_t>(card.vehicle - 1)];
    const std::string name = NameOf(vehicle + "_ellipsoid", "ellipsoid", taken_);
    vehicle_ellipsoid_names_[card.vehicle] = name;  // a later card replaces an earlier one
    scenario.statements.push_back(EllipsoidOn(card, name, vehicle));
  }
  std::vector<ast::Statement> contacts;
  for (const ContactCard& card : deck_.contacts) {
    std::string segment, other;
    if (card.with_plane) {
      segment = Segment(card.segment, "segment");
      other = planes_[static_cast<std::size_t>(card.other.number - 1)];
    } else {
      segment = Surface(card.segment, card.ellipsoid, scenario);
      other = Surface(card.other, card.other_ellipsoid, scenario);
    }
    auto force = FunctionFor(card.force, Use::kContact, card.unloading);
    const auto friction = Friction(card.friction);
    if (segment.empty() || other.empty() || !force || !friction) continue;
    ast::Statement contact = Declaration(
        "contact", Path(segment), CardComment(card.with_plane ? "F.1.b" : "F.3.b", card.line));
    contact.clauses.push_back({"with", {}, Path(other)});
    Add(contact, Attribute("force", std::move(*force)));
    if (!AddRateTerms(contact, card.unloading)) continue;
    if (*friction != 0) Add(contact, Attribute("friction", Number(*friction)));
    if (card.output) contact_outputs_.emplace_back(segment, other);
    contacts.push_back(std::move(contact));
  }
  for (const VehicleEllipsoidCard& card : deck_.extra_ellipsoids) {
    if (placed_extras_.count(card.number) == 0) {
      Report(DiagnosticKind::kDeckIgnoredField, Ref{card.number, card.where, "D.5"},
             fmt::format("extra ellipsoid {} (D.5, line {}) is named by no F.3.b card, so ATB "
                         "puts it on no segment; it is left out",
                         card.number, card.line),
             "name it in MS_SEG(1) or MS_SEG(3) of an F.3.b card, or remove the D.5 card");
    }
  }
  for (ast::Statement& contact : contacts) scenario.statements.push_back(std::move(contact));
}

ast::Statement DeckMapper::EllipsoidOn(const VehicleEllipsoidCard& card, const std::string& name,
                                       const std::string& frame) {
  ast::Statement ellipsoid = Declaration("ellipsoid", Path(name), CardComment("D.5", card.line));
  ellipsoid.clauses.push_back({"on", {}, Path(frame)});
  Add(ellipsoid, Attribute("semi_axes", Vector(card.semi_axes, L)));
  if (!IsZero(card.center)) Add(ellipsoid, Attribute("center", Vector(card.center, L)));
  if (!IsZero(card.orientation))
    Add(ellipsoid, Attribute("orientation", Vector(card.orientation, "deg")));
  if (card.degree != 2) Add(ellipsoid, Attribute("degree", Number(card.degree)));
  return ellipsoid;
}

// The surface of an F.3.b side: frame `frame` (a body segment or a vehicle) with ellipsoid
// `ellipsoid` (0 or the frame's own number: the frame's own; at or above NGRND an extra D.5
// ellipsoid, declared on this frame the first time a card puts it there). Empty after a report.
std::string DeckMapper::Surface(const Ref& frame, const Ref& ellipsoid, ast::Block& scenario) {
  const int segments = static_cast<int>(segments_.size());
  const int vehicles = static_cast<int>(vehicles_.size());
  std::string frame_name;
  if (frame.number >= 1 && frame.number <= segments) {
    frame_name = body_ + "." + segments_[static_cast<std::size_t>(frame.number - 1)];
  } else if (frame.number > segments && frame.number <= segments + vehicles) {
    frame_name = vehicles_[static_cast<std::size_t>(frame.number - segments - 1)];
  } else {
    Report(DiagnosticKind::kDeckCountOutOfRange, frame,
           fmt::format("card {}: segment {} does not exist", frame.card, frame.number),
           fmt::format("body segments are 1 to {} and vehicles {} to {}", segments, segments + 1,
                       segments + vehicles));
    return {};
  }
  const bool vehicle = frame.number > segments;
  if (ellipsoid.number == 0 || ellipsoid.number == frame.number) {
    if (!vehicle) return frame_name;
    const auto found = vehicle_ellipsoid_names_.find(frame.number - segments);
    if (found != vehicle_ellipsoid_names_.end()) return found->second;
    Report(DiagnosticKind::kDeckInvalidValue, frame,
           fmt::format("card {}: vehicle segment {} has no ellipsoid", frame.card, frame.number),
           fmt::format("give it one with a D.5 card numbered {}", frame.number));
    return {};
  }
  // A later D.5 card of the same number replaces an earlier one, as in ATB.
  for (auto it = deck_.extra_ellipsoids.rbegin(); it != deck_.extra_ellipsoids.rend(); ++it) {
    const VehicleEllipsoidCard& card = *it;
    if (card.number != ellipsoid.number) continue;
    auto key = std::make_pair(card.number, frame_name);
    auto found = extra_names_.find(key);
    if (found == extra_names_.end()) {
      const std::string name = NameOf(
          fmt::format("{}_ellipsoid_{}", frame_name.substr(frame_name.rfind('.') + 1), card.number),
          "ellipsoid", taken_);
      found = extra_names_.emplace(key, name).first;
      placed_extras_.insert(card.number);
      scenario.statements.push_back(EllipsoidOn(card, name, frame_name));
    }
    return found->second;
  }
  Report(DiagnosticKind::kDeckInvalidValue, ellipsoid,
         fmt::format("card {}: ellipsoid {} is neither segment {}'s own nor an extra D.5 "
                     "ellipsoid",
                     ellipsoid.card, ellipsoid.number, frame.number),
         "leave the field 0 for the segment's own ellipsoid, or give an extra ellipsoid's "
         "number (a D.5 card's M at or above NGRND)");
  return {};
}

void DeckMapper::MapRestraints(ast::Block& scenario) {
  for (std::size_t b = 0; b < deck_.belts.size(); ++b) {
    const BeltCard& card = deck_.belts[b];
    if (card.contact_line == 0) continue;  // the F.2.b card was missing: reported by the reader
    const std::string segment = Segment(card.segment, "segment");
    auto force = FunctionFor(card.force, Use::kBelt, card.unloading);
    const auto friction = Friction(card.friction);
    if (RefuseRateTerms(card.unloading, "a belt")) continue;
    if (segment.empty() || !force || !friction) continue;
    ast::Statement belt = Declaration(
        "belt", Path(belts_[b]),
        CardComment("D.3", card.line) + fmt::format(" and F.2.b, line {}", card.contact_line));
    belt.clauses.push_back({"on", {}, Path(Primary())});
    std::vector<ast::Expr> path;
    path.push_back(Vector(card.anchor_a, L));
    path.push_back(Path(segment));
    path.push_back(Vector(card.anchor_b, L));
    AddBeltAttributes(belt, std::move(path), std::move(*force), card.slack, *friction);
    if (card.output) belt_outputs_.push_back(belts_[b]);
    scenario.statements.push_back(std::move(belt));
  }
  MapHarnesses(scenario);
  MapAirbags(scenario);
  for (std::size_t s = 0; s < deck_.springs.size(); ++s) {
    const SpringCard& card = deck_.springs[s];
    const std::string first = Segment(card.first, "segment M");
    const std::string second = Segment(card.second, "segment N");
    if (first.empty() || second.empty()) continue;
    const std::string name = NameOf(fmt::format("spring_{}", s + 1), "spring", taken_);
    ast::Statement spring = Declaration("spring", Path(name), CardComment("D.8", card.line));
    std::vector<ast::Expr> chain;
    chain.push_back(Path(first));
    chain.push_back(Path(second));
    spring.clauses.push_back({":", {}, ast::MakeArrow(std::move(chain))});
    AddAttachments(spring, first, card.at_first, second, card.at_second);
    std::vector<std::pair<std::string, ast::Expr>> coefficients;
    coefficients.emplace_back("", Number(0));
    coefficients.emplace_back("", Number(card.linear, F + "/" + L));
    if (card.quadratic != 0)
      coefficients.emplace_back("", Number(card.quadratic, F + "/" + L + "^2"));
    Add(spring, Attribute("stiffness", Call("polynomial", std::move(coefficients))));
    if (card.damping != 0)
      Add(spring, Attribute("damping", Number(card.damping, F + "*" + T + "/" + L)));
    if (card.free_length != 0) Add(spring, Attribute("free_length", Number(card.free_length, L)));
    scenario.statements.push_back(std::move(spring));
  }
  MapConstraints(scenario);
  // D.7: mutual pairs become mirror pairs.
  ast::Statement symmetry =
      Declaration("symmetry", Path("mirror"), CardComment("D.7", deck_.symmetry_line));
  for (std::size_t i = 0; i < deck_.symmetry.size(); ++i) {
    const Ref& ref = deck_.symmetry[i];
    if (ref.number == 0) continue;
    const auto other = static_cast<std::size_t>(ref.number - 1);
    if (other >= deck_.symmetry.size() || deck_.symmetry[other].number != static_cast<int>(i + 1)) {
      Report(DiagnosticKind::kDeckInvalidValue, ref,
             fmt::format("card {}: segment {} names {} as its mirror, but not the reverse",
                         ref.card, i + 1, ref.number),
             "symmetry pairs are mutual");
      continue;
    }
    if (other < i) continue;
    ast::Statement pair;
    pair.keyword = "pair";
    pair.has_value = true;
    pair.values.push_back(Path(body_ + "." + segments_[i]));
    pair.values.push_back(Path(body_ + "." + segments_[other]));
    Add(symmetry, std::move(pair));
  }
  if (!symmetry.block->statements.empty()) scenario.statements.push_back(std::move(symmetry));
}

// `at FIRST = ...` and `at SECOND = ...` of a spring or constraint.
void DeckMapper::AddAttachments(ast::Statement& statement, const std::string& first,
                                const Vec3& at_first, const std::string& second,
                                const Vec3& at_second) {
  for (const auto& [frame, at] : {std::pair{&first, &at_first}, std::pair{&second, &at_second}}) {
    ast::Statement attachment = Attribute("at", Vector(*at, L));
    attachment.target = Path(*frame);
    Add(statement, std::move(attachment));
  }
}

std::string DeckMapper::FrameName(const DeckFrame& frame) const {
  switch (frame.kind) {
    case DeckFrame::Kind::kSegment:
      return body_ + "." + segments_[static_cast<std::size_t>(frame.index - 1)];
    case DeckFrame::Kind::kVehicle:
      return vehicles_[static_cast<std::size_t>(frame.index)];
    case DeckFrame::Kind::kGround:
      break;
  }
  return "ground";
}

// D.4 and F.6: `airbag NAME on PRIMARY { model = atb_free ... }`, ATB's free bag deploying from
// its point, with the cylinder's flow as a named inflow table.
void DeckMapper::MapAirbags(ast::Block& scenario) {
  for (std::size_t b = 0; b < deck_.airbags.size(); ++b) {
    const AirbagCard& card = deck_.airbags[b];
    const std::string name = NameOf(card.title, fmt::format("airbag_{}", b + 1), taken_, "airbag");
    const std::string inflow_name = NameOf(name + "_inflow", "inflow", taken_);
    ast::Statement inflow = Declaration("function", Path(inflow_name),
                                        CardComment("D.4.d", card.cylinder_line) +
                                            ": ATB's cylinder, its flow from CYTD tabulated");
    std::vector<ast::Expr> signature;
    signature.push_back(Path("time"));
    signature.push_back(Path("mass_flow"));
    inflow.has_value = true;
    inflow.values.push_back(Call("table", {{"", ast::MakeArrow(std::move(signature))}}));
    for (const auto& [t, flow] : card.inflow) {
      Add(inflow, Row(Number(t, T), Number(flow, F + "*" + T + "/" + L)));
    }
    scenario.statements.push_back(std::move(inflow));

    ast::Statement airbag = Declaration(
        "airbag", Path(name),
        CardComment("D.4.a", card.line) + (card.title.empty() ? "" : ": " + card.title) +
            (card.contact_line ? fmt::format(" (F.6, line {})", card.contact_line) : ""));
    airbag.clauses.push_back({"on", {}, Path(Primary())});
    Add(airbag, Attribute("model", Path("atb_free")));
    Add(airbag, Attribute("position", Vector(card.deploy_point, L)));
    // ATB's bag deploys along its -x; sled's along its x: turn the axes half a turn about z.
    double yaw = card.orientation[0] + 180;
    if (yaw > 180) yaw -= 360;
    const Vec3 orientation{yaw, -card.orientation[1], -card.orientation[2]};
    if (!IsZero(orientation)) Add(airbag, Attribute("orientation", Vector(orientation, "deg")));
    Add(airbag, Attribute("semi_axes", Vector(card.semi_axes, L)));
    Add(airbag, Attribute("deploy_at", Number(card.deploy_at, T)));
    Add(airbag, Attribute("inflow", Path(inflow_name)));
    // The reference temperature that gives the full bag ATB's SWITCH (FillFreeBag).
    Add(airbag, Attribute("gas_temperature", Number(card.reference_temperature, "K")));
    Add(airbag, Attribute("gamma", Number(card.gamma)));
    // ATB's gas constant is per weight; per mass it is times G.
    Add(airbag, Attribute("gas_constant", ast::MakeBinary('*', Number(card.gas_constant, L + "/K"),
                                                          Path("deck_g"))));
    if (card.vent_area > 0 && card.vent_discharge > 0) {
      Add(airbag, Attribute("vent_area", Number(card.vent_area, L + "^2")));
      Add(airbag, Attribute("discharge_coefficient", Number(card.vent_discharge)));
    }
    Add(airbag, Attribute("ambient_pressure", Number(card.ambient_pressure, F + "/" + L + "^2")));
    if (card.vent_pressure > 0) {
      Add(airbag,
          Attribute("vent_opening_pressure", Number(card.vent_pressure, F + "/" + L + "^2")));
    }
    if (card.bag_weight > 0) {
      Add(airbag,
          Attribute("bag_mass", ast::MakeBinary('/', Number(card.bag_weight, F), Path("deck_g"))));
    }
    if (card.mass_factor != 1) Add(airbag, Attribute("mass_factor", Number(card.mass_factor)));
    if (card.spring > 0) {
      Add(airbag, Attribute("tether_stiffness", Number(card.spring, F + "/" + L)));
    }
    ast::Statement contacts;
    contacts.keyword = "contacts";
    contacts.has_value = true;
    for (const Ref& segment : card.contacts) {
      const std::string path = Segment(segment, "segment");
      if (!path.empty()) contacts.values.push_back(Path(path));
    }
    if (!contacts.values.empty()) Add(airbag, std::move(contacts));
    scenario.statements.push_back(std::move(airbag));
  }
}

// D.6: `constraint constraint_N : fixed_point(A -> B) { at A = ...  at B = ... }`.
void DeckMapper::MapConstraints(ast::Block& scenario) {
  for (std::size_t c = 0; c < deck_.constraints.size(); ++c) {
    const ConstraintCard& card = deck_.constraints[c];
    const std::string first = FrameName(card.first), second = FrameName(card.second);
    ast::Statement constraint = Declaration(
        "constraint", Path(NameOf(fmt::format("constraint_{}", c + 1), "constraint", taken_)),
        CardComment("D.6", card.line));
    std::vector<ast::Expr> chain;
    chain.push_back(Path(first));
    chain.push_back(Path(second));
    const char* kind =
        card.kind == ConstraintCard::Kind::kFixedPoint ? "fixed_point" : "fixed_distance";
    constraint.clauses.push_back({":", {}, Call(kind, {{"", ast::MakeArrow(std::move(chain))}})});
    AddAttachments(constraint, first, card.at_first, second, card.at_second);
    scenario.statements.push_back(std::move(constraint));
  }
}

void DeckMapper::AddBeltAttributes(ast::Statement& belt, std::vector<ast::Expr> path,
                                   ast::Expr force, double slack, double friction) {
  Add(belt, Attribute("path", ast::MakeArrow(std::move(path))));
  Add(belt, Attribute("force", std::move(force)));
  if (slack > 0) Add(belt, Attribute("slack", Number(slack, L)));
  if (friction != 0) Add(belt, Attribute("friction", Number(friction)));
}

// One friction coefficient for several points that each name a friction function; empty after
// reporting a point whose coefficient differs from the first's.
std::optional<double> DeckMapper::CommonFriction(const std::vector<const Ref*>& refs,
                                                 std::string_view what) {
  std::optional<double> common;
  const Ref* first = nullptr;
  for (const Ref* ref : refs) {
    const auto friction = Friction(*ref);
    if (!friction) return std::nullopt;
    if (!common) {
      common = friction;
      first = ref;
    } else if (*friction != *common) {
      Report(DiagnosticKind::kDeckNotExpressible, *ref,
             fmt::format("card {}: a friction of {} here and {} at {}", ref->card, *friction,
                         *common, first->card),
             fmt::format("sled takes one friction for {}; give its points the same "
                         "friction function",
                         what));
      return std::nullopt;
    }
  }
  return common.value_or(0.0);
}

// F.8: `harness NAME on FRAME { friction  belt NAME { path ... } }`, the harness friction from
// its tie points, each belt's friction from the points it wraps.
void DeckMapper::MapHarnesses(ast::Block& scenario) {
  for (std::size_t h = 0; h < deck_.harnesses.size(); ++h) {
    const HarnessCard& card = deck_.harnesses[h];
    if (card.belts.empty()) continue;  // no belt with points: nothing acts in ATB either
    ast::Statement harness =
        Declaration("harness", Path(NameOf(fmt::format("harness_{}", h + 1), "harness", taken_)),
                    CardComment("F.8.a", card.line));
    if (card.vehicle >= 0) {
      harness.clauses.push_back(
          {"on", {}, Path(vehicles_[static_cast<std::size_t>(card.vehicle)])});
    }
    std::vector<const Ref*> tie_friction;
    for (const HarnessBeltCard& belt : card.belts) {
      for (const HarnessPoint* end : {&belt.points.front(), &belt.points.back()}) {
        if (end->tie != 0) tie_friction.push_back(&end->friction);
      }
    }
    const auto friction = CommonFriction(tie_friction, "a harness's tie points");
    if (!friction) continue;
    if (*friction != 0) Add(harness, Attribute("friction", Number(*friction)));
    bool complete = true;
    for (std::size_t b = 0; b < card.belts.size(); ++b) {
      const HarnessBeltCard& belt = card.belts[b];
      if (belt.points.size() < 3) continue;  // reported by the reader
      std::vector<ast::Expr> path;
      std::vector<const Ref*> wrap_friction;
      path.push_back(Vector(belt.points.front().anchor, L));
      for (std::size_t k = 1; k + 1 < belt.points.size(); ++k) {
        const std::string segment = Segment(belt.points[k].segment, "segment KS");
        if (segment.empty()) complete = false;
        path.push_back(Path(segment));
        wrap_friction.push_back(&belt.points[k].friction);
      }
      path.push_back(Vector(belt.points.back().anchor, L));
      auto force = FunctionFor(belt.force, Use::kBelt, belt.unloading);
      const auto wrap = CommonFriction(wrap_friction, "a belt's wrapped segments");
      if (RefuseRateTerms(belt.unloading, "a harness belt")) complete = false;
      if (!force || !wrap || !complete) {
        complete = false;
        continue;
      }
      ast::Statement out =
          Declaration("belt",
                      Path(belt.part == 0 ? fmt::format("belt_{}", belt.number)
                                          : fmt::format("belt_{}_{}", belt.number, belt.part)),
                      CardComment("F.8.c", belt.line));
      AddBeltAttributes(out, std::move(path), std::move(*force), belt.slack, *wrap);
      Add(harness, std::move(out));
    }
    if (complete) scenario.statements.push_back(std::move(harness));
  }
}

}  // namespace sled::lang::legacy::mapping
