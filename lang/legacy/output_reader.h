// The H cards: ATB V.3's output requests (INPUT_HCARDS), read through DeckFields into the Deck's
// outputs. H.1 to H.3 are point accelerations, velocities and displacements; H.4 to H.6 segment
// angular accelerations, velocities and displacements; H.7 joint parameters; H.8 wind forces;
// H.9 joint forces and torques; H.10 total-body centres of gravity. A zero count requests
// nothing; what sled cannot output is refused where the deck asks for it.
#pragma once

#include "lang/legacy/deck_fields.h"

namespace sled::lang::legacy {

// H.1 to H.10, and H.11 when D.1.b's NRTORQ (`actuators`) is not 0. `bags` is D.1's NBAG
// (airbags take segment numbers between the vehicles and the ground).
void ReadOutputRequests(DeckFields& fields, int bags, int actuators);

}  // namespace sled::lang::legacy
