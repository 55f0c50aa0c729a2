// The C cards (INPUT_VEHICLE): C.1 and C.2.a for up to six vehicles, read through DeckFields
// into Deck::vehicles (vehicle segments, the primary last) and Deck::prescribed_segments (body
// segments whose motion a card prescribes, MSEG 1 to NSEG).
#pragma once

#include "lang/legacy/deck_fields.h"

namespace sled::lang::legacy {

// Reads C cards until the primary vehicle (MSEG 0). The B cards come first: MSEG is checked
// against NSEG and the joints.
void ReadVehicles(DeckFields& fields);

}  // namespace sled::lang::legacy
