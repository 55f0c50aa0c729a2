// The reader of card group G, the initial conditions: G.1.a, a G.2 card per reference segment
// and a G.3.a card per segment, read through DeckFields into the Deck (docs/legacy.md, "G:
// initial conditions").
#pragma once

#include "lang/legacy/deck_fields.h"

namespace sled::lang::legacy {

// `bags`: D.1.a's NBAG, which numbers the frames after the vehicles.
void ReadInitialConditions(DeckFields& fields, int bags);

}  // namespace sled::lang::legacy
