// The readers of the restraint card groups that take many cards, each in a file of its own:
// airbags (D.4, F.6), harnesses (F.8) and constraints (D.6). They read through DeckFields into the
// Deck and report what sled cannot express where they read it.
#pragma once

#include "lang/legacy/deck_fields.h"

namespace sled::lang::legacy {

// F.8.a to F.8.d for D.1's NHRNSS harnesses; `bags` is D.1's NBAG (airbags take segment numbers
// between the vehicles and the ground).
void ReadHarnesses(DeckFields& fields, int harnesses, int bags);

// D.4 for D.1's NBAG airbags, and their F.6 cards: ATB's free bags, converted to sled's
// `model = atb_free` with a W0504 for each difference.
void ReadAirbags(DeckFields& fields, int count);
void ReadAirbagContacts(DeckFields& fields, int count);

// D.6 for D.1's NQ constraints.
void ReadConstraints(DeckFields& fields, int count, int bags);

}  // namespace sled::lang::legacy
