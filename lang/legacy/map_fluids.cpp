// E.6, F.7 and F.9: `wind { ... }` and `water { ... }` (DeckMapper, deck_mapper.h). ATB pushes a
// segment's ellipsoid with the wind where it crosses a plane (WINDY, WIND_AREA): a tabulated
// pressure, or the dynamic pressure of a segment's velocity; sled's wind pushes the whole
// ellipsoid with a pressure of time, or with the drag of the air's velocity relative to it. The
// water's buoyancy and drag carry over with the law the warnings state (its force routines are
// not in the reference).
#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "lang/ast/make_expr.h"
#include "lang/legacy/ast_pieces.h"
#include "lang/legacy/deck_mapper.h"

namespace sled::lang::legacy::mapping {
namespace {

double Length(const Vec3& v) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }

// A direction: a vector without a unit.
ast::Expr Direction(const Vec3& v) {
  ast::Expr expr = Vector(v, "m");
  expr.unit.reset();
  return expr;
}

ast::Statement Names(const std::vector<std::string>& paths) {
  ast::Statement segments;
  segments.keyword = "segments";
  segments.has_value = true;
  for (const std::string& path : paths) segments.values.push_back(Path(path));
  return segments;
}

}  // namespace

const WindFunctionCard* DeckMapper::WindFunction(const Ref& ref) {
  for (const WindFunctionCard& function : deck_.wind_functions) {
    if (function.number == ref.number) return &function;
  }
  Report(DiagnosticKind::kDeckUndefinedFunction, ref,
         fmt::format("card {}: wind function {} is not defined", ref.card, ref.number),
         "define it with E.6 cards (D.1.a's NWINDF of them, after the E cards)");
  return nullptr;
}

// A body segment the wind or water acts on, by deck number, or empty after reporting a bad number,
// an ellipsoid other than the segment's own (0 names it too) or a segment without a contact
// ellipsoid; `field` names the ellipsoid's field for the help.
std::string DeckMapper::SegmentInFluid(const Ref& ref, const Ref& ellipsoid, std::string_view fluid,
                                       std::string_view field) {
  if (ellipsoid.number != 0 && ellipsoid.number != ref.number) {
    Report(DiagnosticKind::kDeckNotExpressible, ellipsoid,
           fmt::format("card {}: ellipsoid {} of segment {}, not the segment's own", ellipsoid.card,
                       ellipsoid.number, ref.number),
           fmt::format("sled's {} acts on a segment's own contact ellipsoid: set {} to the "
                       "segment's number",
                       fluid, field));
    return {};
  }
  std::string path = Segment(ref, "segment");
  if (path.empty()) return path;
  const SegmentCard& segment = deck_.segments[static_cast<std::size_t>(ref.number - 1)];
  if (Length(segment.semi_axes) == 0) {
    Report(DiagnosticKind::kDeckInvalidValue, ref,
           fmt::format("card {}: segment {} has no contact ellipsoid for the {} to act on",
                       ref.card, ref.number, fluid),
           "give the segment's ellipsoid on B.2.a (or D.5)");
    return {};
  }
  return path;
}

// The ground's ATB number: after the segments, the vehicles and the airbags.
bool DeckMapper::IsGround(int number) const {
  return number == 0 || number == static_cast<int>(deck_.segments.size() + deck_.vehicles.size() +
                                                   deck_.airbags.size()) +
                                      1;
}

// One `wind` block for each pair of MWSEG(5) and MWSEG(6) the F.7.b cards name, in the order
// of their first card: each is an air of its own (sled's winds may be several, each segment in
// one; ATB's F.7.a puts each segment on one card).
void DeckMapper::MapWind(ast::Block& scenario) {
  std::vector<std::vector<const WindCard*>> winds;
  for (const WindCard& card : deck_.winds) {
    auto same = std::find_if(winds.begin(), winds.end(), [&](const auto& wind) {
      return wind.front()->force.number == card.force.number &&
             wind.front()->drag.number == card.drag.number;
    });
    if (same == winds.end()) {
      winds.push_back({&card});
    } else {
      same->push_back(&card);
    }
  }
  for (const auto& cards : winds) MapOneWind(scenario, cards);
}

void DeckMapper::MapOneWind(ast::Block& scenario, const std::vector<const WindCard*>& cards) {
  const WindCard& first = *cards.front();
  std::vector<std::string> segments;
  for (const WindCard* card_of : cards) {
    const WindCard& card = *card_of;
    const std::string path = SegmentInFluid(card.segment, card.ellipsoid, "wind", "MWSEG(2)");
    if (path.empty()) return;
    segments.push_back(path);
  }
  Report(DiagnosticKind::kDeckApproximated, first.plane,
         fmt::format("card {}: the plane MWSEG(4): ATB pushes only the part of the ellipsoid "
                     "beyond it (no force while the ellipsoid is behind the plane, the projected "
                     "area times 1 - s^2 while it crosses, s the plane's place between the "
                     "ellipsoid's centre and its far side), sled the whole ellipsoid from the "
                     "start: the same once every ellipsoid is wholly beyond its plane",
                     first.plane.card));
  if (first.grid) {
    Report(DiagnosticKind::kDeckApproximated, first.segment,
           fmt::format("card {}: a negative MWSEG(1), ATB's grid method: sled integrates the "
                       "ellipsoid's projected area in closed form (the grid's resolution error "
                       "is not measured)",
                       first.segment.card));
  }
  // The drag coefficient: 1 without a function (ATB's default), else a constant table's value.
  double drag = 1.0;
  if (first.drag.number != 0) {
    const WindFunctionCard* table = WindFunction(first.drag);
    if (table == nullptr) return;
    const bool constant = table->heat_ratio == 0 && !table->rows.empty() &&
                          std::all_of(table->rows.begin(), table->rows.end(), [&](const auto& row) {
                            return row[1] == table->rows.front()[1];
                          });
    if (!constant) {
      Report(DiagnosticKind::kDeckNotExpressible, first.drag,
             fmt::format("card {}: a drag coefficient that changes with time (wind function {})",
                         first.drag.card, first.drag.number),
             "a sled wind has one drag coefficient: give the function the same FX on every "
             "E.6.d card");
      return;
    }
    drag = table->rows.front()[1];
  }
  const WindFunctionCard* wind = WindFunction(first.force);
  if (wind == nullptr) return;
  ast::Statement block =
      Declaration("wind", Path("x"),
                  CardComment("F.7.b", first.line) +
                      fmt::format(", wind function {} (E.6.a, line {})", wind->number, wind->line));
  block.target.reset();
  // NSR, the frame the wind is given in (WINDY): the velocity wind's V is NSV's velocity less
  // NSR's, the table's (FX, FY, FZ) are in NSR's axes. sled's `carried_by`: the air at rest in
  // that frame, its direction in the frame's axes.
  const Ref& reference = wind->reference;
  std::string carrier;
  if (!IsGround(reference.number)) {
    const auto segment_count = static_cast<int>(deck_.segments.size());
    const auto vehicle_count = static_cast<int>(deck_.vehicles.size());
    if (reference.number >= 1 && reference.number <= segment_count) {
      carrier = FrameName({DeckFrame::Kind::kSegment, reference.number});
    } else if (reference.number > segment_count &&
               reference.number <= segment_count + vehicle_count) {
      carrier = FrameName({DeckFrame::Kind::kVehicle, reference.number - segment_count - 1});
    } else {
      Report(DiagnosticKind::kDeckNotExpressible, reference,
             fmt::format("card {}: NSR is {}, an airbag", reference.card, reference.number),
             "a wind is carried by the ground, a vehicle or a body segment: set NSR to one");
      return;
    }
  }
  if (wind->heat_ratio != 0) {
    // The dynamic pressure 0.5 (RK PR / C^2) V^2 of NSV's velocity V: air at rest, of the
    // density of an ideal gas of that pressure and speed of sound.
    const double density =
        wind->heat_ratio * wind->pressure / (wind->sonic_speed * wind->sonic_speed);
    Add(block, Attribute("speed", Number(0.0, L + "/" + T)));
    Add(block, Attribute("direction", Path("x")));
    Add(block, Attribute("density", Number(density, F + "*" + T + "^2/" + L + "^4")));
    Report(DiagnosticKind::kDeckApproximated, wind->moving,
           fmt::format("card {}: the wind of NSV's velocity V (segment {}): ATB pushes each "
                       "ellipsoid with 0.5 rho Cd V_i |V_i| along each ground axis i, sled with "
                       "0.5 rho Cd |v| v of the ellipsoid's own velocity v: along an axis they "
                       "are equal, along a diagonal of two axes ATB's force is 70.7 % of sled's "
                       "(57.7 % along a diagonal of three) and turned towards the larger "
                       "component; for an ellipsoid that moves unlike NSV the difference is its "
                       "velocity relative to NSV's{}",
                       wind->moving.card, wind->moving.number,
                       carrier.empty() ? ""
                                       : fmt::format("; V is relative to NSR's centre ({}), "
                                                     "sled's to NSR's velocity at each "
                                                     "ellipsoid: the same while NSR does not turn",
                                                     carrier)));
  } else {
    // A table of the pressure vector against time: one direction, its length the pressure.
    Vec3 direction{1, 0, 0};
    for (const auto& row : wind->rows) {
      const Vec3 force{row[1], row[2], row[3]};
      if (Length(force) > 0) {
        direction = force;
        break;
      }
    }
    const double norm = Length(direction);
    for (double& component : direction) component /= norm;  // unit: a row along it keeps its value
    for (const auto& row : wind->rows) {
      const Vec3 force{row[1], row[2], row[3]};
      const double along =
          force[0] * direction[0] + force[1] * direction[1] + force[2] * direction[2];
      if (std::abs(Length(force) - along) > 1e-9 * std::max(Length(force), 1e-300)) {
        Report(DiagnosticKind::kDeckNotExpressible, Ref{wind->number, wind->where, "E.6.d"},
               fmt::format("card E.6.d (wind function {}): the pressure turns (FX, FY, FZ are "
                           "not along one direction at every time)",
                           wind->number),
               "sled's wind pushes along one direction; split the turning blast by hand");
        return;
      }
    }
    const std::string name =
        NameOf(wind->title, fmt::format("wind_{}", wind->number), taken_, "pressure");
    ast::Statement pressure =
        Declaration("function", Path(name),
                    CardComment("E.6.d", wind->table_line) + ": the wind's pressure against time");
    std::vector<ast::Expr> signature;
    signature.push_back(Path("time"));
    signature.push_back(Path("pressure"));
    pressure.has_value = true;
    pressure.values.push_back(Call("table", {{"", ast::MakeArrow(std::move(signature))}}));
    for (const auto& row : wind->rows) {
      const double along = row[1] * direction[0] + row[2] * direction[1] + row[3] * direction[2];
      Add(pressure, Row(Number(row[0], T), Number(along, F + "/" + L + "^2")));
    }
    if (wind->rows.size() == 1) {
      // A one-point table is constant: two rows at the same value.
      Add(pressure,
          Row(Number(wind->rows.front()[0] + 1, T),
              Number(Length({wind->rows.front()[1], wind->rows.front()[2], wind->rows.front()[3]}),
                     F + "/" + L + "^2")));
    }
    scenario.statements.push_back(std::move(pressure));
    Add(block, Attribute("pressure", Path(name)));
    Add(block, Attribute("direction", Direction(direction)));
    Report(DiagnosticKind::kDeckUnverifiedField, Ref{wind->number, wind->where, "E.6.a"},
           fmt::format("card E.6.a (wind function {}): the table is read against the run's "
                       "time: ATB's against the time since the ellipsoid first crossed its "
                       "plane, which INPUT_WIND_FORCE starts at 0 (its other updates are not "
                       "in the reference)",
                       wind->number));
  }
  if (!carrier.empty()) Add(block, Attribute("carried_by", Path(carrier)));
  if (drag != 1.0) Add(block, Attribute("drag", Number(drag)));
  Add(block, Names(segments));
  scenario.statements.push_back(std::move(block));
}

void DeckMapper::MapWater(ast::Block& scenario) {
  if (!deck_.water) return;
  const WaterCard& water = *deck_.water;
  // The water frame's z points into the water: along gravity, or the surface is tilted.
  const double g = Length(deck_.gravity);
  const bool level = water.frame[1] == 0 && water.frame[2] == 0 && g > 0 && deck_.gravity[0] == 0 &&
                     deck_.gravity[1] == 0 && deck_.gravity[2] > 0;
  std::vector<std::string> segments;
  std::optional<double> drag;
  for (const WaterCard::Ellipsoid& ellipsoid : water.ellipsoids) {
    const std::string path =
        SegmentInFluid(ellipsoid.segment, ellipsoid.ellipsoid, "water", "NWSE(1)");
    if (path.empty()) return;
    if (drag && *drag != ellipsoid.drag) {
      Report(DiagnosticKind::kDeckNotExpressible, ellipsoid.ellipsoid,
             fmt::format("card {}: a drag coefficient {} unlike the first ellipsoid's {}",
                         ellipsoid.ellipsoid.card, ellipsoid.drag, *drag),
             "sled's water has one drag coefficient: give every F.9.f card the same COED");
      return;
    }
    drag = ellipsoid.drag;
    segments.push_back(path);
  }
  if (water.ellipsoids.empty()) return;
  const Ref& first = water.ellipsoids.front().ellipsoid;
  if (!level) {
    Report(DiagnosticKind::kDeckNotExpressible, first,
           "card F.9.a: a water surface that is not normal to gravity (WFRAME's pitch or roll "
           "not 0, or A.3's gravity not along +z, the water frame's z into the water)",
           "sled's water surface is normal to gravity: give A.3 a gravity along +z and F.9.a "
           "zero pitch and roll");
    return;
  }
  ast::Statement block = Declaration(
      "water", Path("x"), CardComment("F.9.a", water.line) + ", the ellipsoids on F.9.f");
  block.target.reset();
  // Up is against gravity (-z): the surface through WOFSET is -WOFSET_z above the origin.
  Add(block, Attribute("level", Number(-water.offset[2], L)));
  Add(block,
      Attribute("density", ast::MakeBinary('/', Number(water.specific_weight, F + "/" + L + "^3"),
                                           Path("deck_g"))));
  if (*drag != 1.0) Add(block, Attribute("drag", Number(*drag)));
  Add(block, Names(segments));
  scenario.statements.push_back(std::move(block));
  Report(DiagnosticKind::kDeckUnverifiedField, first,
         fmt::format("card {}: the water's forces are read as buoyancy (the weight of the water "
                     "the ellipsoid's submerged part displaces, at that part's centroid) and "
                     "the drag 0.5 rho COED A f |v| v (A the ellipsoid's area across its "
                     "velocity, f its submerged share): ATB's water force routines are not in "
                     "the reference",
                     first.card));
}

}  // namespace sled::lang::legacy::mapping
