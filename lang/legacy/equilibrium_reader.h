// The G.4 to G.6 cards of an equilibrium run (G.1.a I1 = 15), read by ATB's INPUT_EQUILB.
#pragma once

#include "lang/legacy/deck_fields.h"

namespace sled::lang::legacy {

// G.4 (NVAR, NCON), NVAR G.5 cards and NCON G.6 cards, checked as INPUT_EQUILB checks them (its
// STOPs 2600 to 2614 are E0512 at the field), then solved (equilibrium_solve.h): the G.2
// positions of the deck move as EQUILB moves them, or the case the conversion cannot solve is
// refused at its card (G.1.a `g1` for what EQUILB rewrites besides the positions).
void ReadEquilibriumCards(DeckFields& fields, const Card& g1);

}  // namespace sled::lang::legacy
