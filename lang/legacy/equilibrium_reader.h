// The G.4 to G.6 cards of an equilibrium run (G.1.a I1 = 15), read by ATB's INPUT_EQUILB.
#pragma once

#include "lang/legacy/deck_fields.h"

namespace sled::lang::legacy {

// G.4 (NVAR, NCON), NVAR G.5 cards and NCON G.6 cards, checked as INPUT_EQUILB checks them (its
// STOPs 2600 to 2614 are E0512 at the field). They are read so a refused I1 = 15 does not turn
// the H cards into a cascade of errors: EQUILB itself is not converted (docs/legacy.md, G.1.a).
void ReadEquilibriumCards(DeckFields& fields);

}  // namespace sled::lang::legacy
