// D.6: constraints (ATB's INPUT_CONSTRAINTS reads them; what each KQTYPE holds is set up in ATB's
// SETUP). KQTYPE 1 holds point RK1 of segment KQ1 at point RK2 of segment KQ2 in all three
// directions, sled's `fixed_point`; 2 holds them along the line between them, at their initial
// distance, sled's `fixed_distance` with its default distance. 3, 4 and 6 take their point and
// direction from a contact (ATB's PLELP and SEGSEG) that D.6 does not name, 5 is a tension element
// over two cards whose second card enters ATB's constraint equations, and a negative KQTYPE is a
// constraint ATB switches on and off during the run: those are refused.
#include <optional>
#include <string>
#include <utility>

#include <fmt/format.h>

#include "lang/legacy/restraint_readers.h"

namespace sled::lang::legacy {
namespace {

// Why sled refuses a KQTYPE, and the help; nothing for the kinds it converts or that do not exist.
std::optional<std::pair<std::string, std::string>> Refusal(int type) {
  if (type == 3 || type == 4 || type == 6) {
    return std::pair{fmt::format("KQTYPE {}: a constraint whose point and direction ATB takes "
                                 "from a contact (PLELP, SEGSEG) that D.6 does not name",
                                 type),
                     std::string("write a `constraint ... : sliding(...)` by hand where the point "
                                 "slides; sled has no rolling constraint (E0422)")};
  }
  if (type == 5) {
    return std::pair{std::string("KQTYPE 5: a tension element, whose second D.6 card enters "
                                 "ATB's constraint equations in a way the reference does not "
                                 "document"),
                     std::string("write a `tension` element (stiffness, damping, free length) "
                                 "by hand")};
  }
  if (type < 0) {
    return std::pair{fmt::format("KQTYPE {}: a constraint that ATB switches off until the run "
                                 "turns it on",
                                 type),
                     std::string("sled's constraints act from the start; convert it by hand")};
  }
  return std::nullopt;
}

}  // namespace

void ReadConstraints(DeckFields& fields, int count, int bags) {
  DeckSource& r = fields.source();
  for (int k = 0; k < count && !r.truncated(); ++k) {
    const Card card = r.Next(fmt::format("D.6 (constraint {})", k + 1), {"(3I6,6F6.0)"});
    const int type = r.Integer(card, 1, 6, "KQTYPE, the kind of constraint");
    const int kq1 = r.Integer(card, 7, 12, "KQ1, the first segment");
    const int kq2 = r.Integer(card, 13, 18, "KQ2, the second segment");
    ConstraintCard constraint;
    constraint.line = card.line;
    constraint.at_first = fields.Triple(card, 19, 6, "RK1, the point on the first segment");
    constraint.at_second = fields.Triple(card, 37, 6, "RK2, the point on the second segment");
    if (card.line == 0) return;
    if (type == 1 || type == 2) {
      constraint.kind =
          type == 1 ? ConstraintCard::Kind::kFixedPoint : ConstraintCard::Kind::kFixedDistance;
    } else if (const auto refused = Refusal(type)) {
      fields.Refuse(card, 1, 6, refused->first, refused->second);
      continue;
    } else {
      fields.Invalid(card, 1, 6, fmt::format("KQTYPE is {}", type),
                     "the constraint kinds are 1 (a fixed point) to 6");
      continue;
    }
    const auto first = fields.FrameOf(card, 7, 12, kq1, bags, "KQ1, the first segment");
    const auto second = fields.FrameOf(card, 13, 18, kq2, bags, "KQ2, the second segment");
    if (!first || !second) continue;
    // A body segment whose motion a C card prescribes (MSEG) moves as told, as vehicles do.
    const auto prescribed = [&](const DeckFrame& frame) {
      if (frame.kind != DeckFrame::Kind::kSegment) return true;
      for (const VehicleCard& vehicle : fields.deck().prescribed_segments) {
        if (vehicle.segment == frame.index) return true;
      }
      return false;
    };
    if (prescribed(*first) && prescribed(*second)) {
      fields.Invalid(card, 7, 18, "both KQ1 and KQ2 have prescribed motion",
                     "a constraint holds a body segment whose motion is free (not a C card's "
                     "MSEG): name one at least");
      continue;
    }
    if (first->kind == second->kind && first->index == second->index) {
      fields.Invalid(card, 7, 18, fmt::format("KQ1 and KQ2 are both segment {}", kq1),
                     "a constraint joins two different segments");
      continue;
    }
    constraint.first = *first;
    constraint.second = *second;
    fields.deck().constraints.push_back(constraint);
  }
}

}  // namespace sled::lang::legacy
