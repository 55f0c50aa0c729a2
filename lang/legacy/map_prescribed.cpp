// C cards whose MSEG is a body segment (a reference segment, checked by the reader): ATB makes
// the segment a vehicle segment, its motion the card's (INPUT_VEHICLE sets its reciprocal mass
// and inertia to zero and its initial state from X0, the angles and VIPS; VEHPOS gives it the
// pulse's acceleration). sled says the same with a vehicle of the card's motion and a weld of
// the segment to that vehicle's origin at the card's orientation: the segment moves exactly as
// the vehicle does, the rest of its body hanging from it.
#include "lang/legacy/deck_mapper.h"

#include <string>
#include <vector>

#include <fmt/format.h>

#include "lang/ast/make_expr.h"
#include "lang/legacy/ast_pieces.h"

namespace sled::lang::legacy::mapping {

const VehicleCard* DeckMapper::PrescribedCard(int segment) const {
  for (const VehicleCard& card : deck_.prescribed_segments) {
    if (card.segment == segment) return &card;
  }
  return nullptr;
}

void DeckMapper::MapPrescribedSegments(ast::Block& scenario) {
  for (std::size_t p = 0; p < deck_.prescribed_segments.size(); ++p) {
    const VehicleCard& card = deck_.prescribed_segments[p];
    const std::string& vehicle = prescribed_vehicles_[p];
    const auto index = static_cast<std::size_t>(card.segment - 1);
    scenario.statements.push_back(VehicleStatement(card, vehicle));

    const std::string segment = body_ + "." + segments_[index];
    ast::Statement weld = Declaration(
        "constraint", Path(NameOf(segments_[index] + "_prescribed", "constraint", taken_)),
        CardComment("C.2.a", card.line) +
            fmt::format(": MSEG {}, segment `{}` moves with the card's motion", card.segment,
                        segments_[index]));
    std::vector<ast::Expr> chain;
    chain.push_back(Path(vehicle));
    chain.push_back(Path(segment));
    weld.clauses.push_back({":", {}, Call("welded", {{"", ast::MakeArrow(std::move(chain))}})});
    AddAttachments(weld, vehicle, Vec3{}, segment, Vec3{});
    scenario.statements.push_back(std::move(weld));

    // Held at the vehicle's origin, so placed and moved by it; turned as the card turns it.
    if (!IsZero(card.orientation)) {
      ast::Statement initial = Declaration(
          "initial", Path(card.segment == 1 ? body_ : segment),
          CardComment("C.2.a", card.line) + ": the prescribed segment's yaw, pitch and roll");
      Add(initial, Attribute("orientation", Vector(card.orientation, "deg")));
      scenario.statements.push_back(std::move(initial));
    }
  }
}

}  // namespace sled::lang::legacy::mapping
