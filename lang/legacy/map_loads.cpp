// DeckMapper (deck_mapper.h), card D.9: ATB's applied forces and torques as `load` statements.
// FORCE_TORQUE turns the direction (the x axis of the card's yaw, pitch and roll, in the
// segment's axes) with the segment, so every load is `frame = segment`; a force acts at the
// card's point, a torque (NFVSEG < 0) about the direction.
#include "lang/legacy/deck_mapper.h"

#include <cstdlib>
#include <string>

#include <fmt/format.h>

#include "lang/legacy/ast_pieces.h"

namespace sled::lang::legacy::mapping {

void DeckMapper::MapLoads(ast::Block& scenario) {
  for (std::size_t k = 0; k < deck_.loads.size(); ++k) {
    const LoadCard& card = deck_.loads[k];
    Ref segment_ref = card.segment;
    segment_ref.number = std::abs(segment_ref.number);
    const std::string segment = Segment(segment_ref, "NFVSEG");
    if (segment.empty()) continue;
    const bool torque = card.torque();
    auto function = FunctionFor(card.function, torque ? Use::kLoadTorque : Use::kLoadForce);
    if (!function) continue;
    const std::string name = NameOf(fmt::format("load_{}", k + 1), "load", taken_);
    ast::Statement load = Declaration("load", Path(name), CardComment("D.9", card.line));
    load.clauses.push_back({"on", {}, Path(segment)});
    const Vec3 direction = TurnedX(card.orientation[0], card.orientation[1]);
    if (torque) {
      Add(load, Attribute("torque", std::move(*function)));
      Add(load, Attribute("axis", Vector(direction, "")));
    } else {
      Add(load, Attribute("force", std::move(*function)));
      Add(load, Attribute("direction", Vector(direction, "")));
      if (!IsZero(card.point)) Add(load, Attribute("point", Vector(card.point, L)));
    }
    Add(load, Attribute("frame", Path("segment")));
    scenario.statements.push_back(std::move(load));
  }
}

}  // namespace sled::lang::legacy::mapping
