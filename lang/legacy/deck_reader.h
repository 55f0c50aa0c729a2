// The card groups A to H of an ATB V.3 deck (the layout of /work/shared/reference/legacy-decks.md,
// written up in docs/legacy.md), read once for both deck formats through a DeckSource (fixed-column
// `.ain` or list-directed `.lin`) and validated as they are read. Fields sled cannot express are
// refused (E0507) where they are read; fields whose meaning the format reference marks unverified
// are converted with a warning (W0501), fields ATB itself ignores are left out with W0503, and
// fields sled's model only approximates are converted with W0504.
#pragma once

#include "lang/legacy/deck.h"
#include "lang/legacy/deck_source.h"

namespace sled::lang::legacy {

Deck ReadDeck(DeckSource& source);

}  // namespace sled::lang::legacy
