// The readers of ATB's applied forces and torques (D.9, INPUT_FORCE_TORQUE; what each card means
// for the run is from FORCE_TORQUE) and joint actuators (D.1.b and F.10, INPUT_DCARDS and
// INPUT_ROBOTICS). Read through DeckFields into the Deck.
#pragma once

#include "lang/legacy/deck_fields.h"

namespace sled::lang::legacy {

// The largest D.1.a NFORCE (MAX_FOR_TORQ in V5.3.1's MODULE_STANDARD; ATB stops above it).
inline constexpr int kMaxAppliedLoads = 5;

// D.9 for D.1.a's NFORCE forces and torques. A card on a vehicle segment is left out with a
// W0503 (ATB adds the load to a segment whose motion it prescribes, which does not move it); a
// segment number outside the deck is E0512.
void ReadAppliedLoads(DeckFields& fields, int count);

// D.1.a NEXTCD and, when it is not 0, the D.1.b card that follows D.1.a: the number of F.10
// actuators (NRTORQ, at most the number of joints, as ATB's STOP 110).
int ReadActuatorCount(DeckFields& fields, const Card& d1);

// The F.10 cards (6I4, after F.9, INPUT_ROBOTICS) into the deck's actuators: a joint that is not
// a pin (STOP 111) or a base segment that is neither of the joint's (STOP 112) is E0512.
void ReadActuators(DeckFields& fields, int count);

}  // namespace sled::lang::legacy
