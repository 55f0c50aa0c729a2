// Card group F.4: ATB's globalgraphic joints. INPUT_GLOBALGRAPHIC_FORCE reads a count per joint
// (F.4.a, 18 per card) and that many F.4.b cards of NJ, MS_SEG(3), NF(5), NX and NOUT each. The
// name is not about graphics: the five functions (torque-deflection, Herron formula, R, G,
// friction) feed the globographic joint stop that VISPR computes, through GLOBAL, only for joints
// of JTYPE 3.
#include "lang/legacy/global_graphic_reader.h"

#include <string>
#include <vector>

#include <fmt/format.h>

namespace sled::lang::legacy {
namespace {

constexpr int kMaxGlobalContacts = 20;  // the per-item bound of the other F.x.a counts

void ReadGlobalGraphicCard(DeckFields& f, const Card& card, int joint) {
  DeckSource& r = f.source();
  const int nj = r.Integer(card, 1, 4, "NJ, the joint");
  if (nj != joint) {
    f.Invalid(card, 1, 4, fmt::format("NJ is {} on a card for joint {}", nj, joint),
              "the F.4.b cards follow the order of the F.4.a counts (ATB stops: STOP 14 in "
              "INPUT_GLOBALGRAPHIC_FORCE)");
  }
  const int force = r.Integer(card, 17, 20, "NF(1), the torque-deflection function");
  const int friction = r.Integer(card, 33, 36, "NF(5), the friction function");
  if (friction == 0) {
    f.Invalid(card, 33, 36, "NF(5), the friction function, is 0",
              "ATB stops on it (STOP 105 in INPUT_GLOBALGRAPHIC_FORCE): give a function number");
  }
  if (force == 0) {
    f.Refuse(card, 17, 20,
             fmt::format("NF(1) is 0 on joint {}'s globalgraphic card: ATB adds a rolling "
                         "constraint (KQTYPE -4) between MS_SEG(2) and MS_SEG(1)",
                         joint),
             "sled has no rolling constraint (F.3.b refuses one too); remove the card or give a "
             "torque-deflection function");
    return;
  }
  f.Ignored(card, 1, 44,
            fmt::format("joint {}'s globalgraphic functions (F.4.b) are read and left out", joint),
            "ATB uses them only in the globographic stop of a JTYPE 3 joint (VISPR calls GLOBAL "
            "for JTYPE 3 alone), and B.3.a refuses JTYPE 3, so no value of the run depends on "
            "them");
}

}  // namespace

void ReadGlobalGraphicJoints(DeckFields& fields, int joints) {
  if (joints <= 0) return;  // INPUT_FCARDS reads F.4 only when NJNT > 0
  const std::vector<int> counts =
      fields.CountsPerItem("F.4.a", joints, "(18I4)", 18, false,
                           "IGLOB, a number of globalgraphic contacts", kMaxGlobalContacts);
  DeckSource& r = fields.source();
  for (int j = 0; j < joints && !r.truncated(); ++j) {
    for (int k = 0; k < counts[static_cast<std::size_t>(j)] && !r.truncated(); ++k) {
      const Card card =
          r.Next(fmt::format("F.4.b (joint {}, contact {})", j + 1, k + 1), {"(18I4)", 11});
      ReadGlobalGraphicCard(fields, card, j + 1);
    }
  }
}

}  // namespace sled::lang::legacy
