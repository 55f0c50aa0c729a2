// The reader of card group B, the body: B.1, a B.2 card per segment, B.3 to B.5 per joint and
// B.6 per segment, read through DeckFields into the Deck (docs/legacy.md, "B: the body").
#pragma once

#include "lang/legacy/deck_fields.h"

namespace sled::lang::legacy {

// MAXSEG of ATB V5.3.1's MODULE_STANDARD: segments and joints of a body, and the ellipsoid
// numbers of D.5 below the extra ones.
inline constexpr int kMaxSegments = 60;

void ReadBody(DeckFields& fields);

}  // namespace sled::lang::legacy
