// The readers of ATB's wind and water cards (INPUT_WIND, INPUT_WIND_FORCE, INPUT_WATER and the
// routines it calls): E.6 after the E cards, F.7 and F.9. They read through DeckFields into the
// Deck and report what sled's `wind` and `water` cannot express where they read it.
#pragma once

#include "lang/legacy/deck_fields.h"

namespace sled::lang::legacy {

// E.6.a to E.6.d for D.1.a's NWINDF wind functions.
void ReadWindFunctions(DeckFields& fields, int count);

// F.7.a and F.7.b (when NWINDF is not 0). False when the cards that follow cannot be found (a
// segment with blocking ellipsoids, whose F.7.c layout differs between the two readers).
bool ReadWind(DeckFields& fields);

// F.9.a to F.9.m (when NWATER is not 0). False when the cards that follow cannot be found
// (personal flotation devices, whose F.9.h to F.9.j layout is not in the reference).
bool ReadWater(DeckFields& fields);

}  // namespace sled::lang::legacy
