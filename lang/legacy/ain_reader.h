// The fixed-column `.ain` reader: card groups A to H of an ATB V.3 deck (the column layout of
// /work/shared/reference/legacy-decks.md, written up in docs/legacy.md), validated as they are
// read. Fields sled cannot express are refused (E0507) where they are read; fields whose meaning
// the format reference marks unverified are converted with a warning (W0501).
#pragma once

#include "lang/legacy/card_reader.h"
#include "lang/legacy/deck.h"

namespace sled::lang::legacy {

Deck ReadAinDeck(CardReader& reader);

}  // namespace sled::lang::legacy
