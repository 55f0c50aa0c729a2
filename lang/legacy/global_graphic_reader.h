// The F.4 cards: the allowed contacts of ATB's "globalgraphic" joints (INPUT_GLOBALGRAPHIC_FORCE).
#pragma once

#include "lang/legacy/deck_fields.h"

namespace sled::lang::legacy {

// F.4.a (a count per joint, read only when the deck has joints, as INPUT_FCARDS calls the reader
// only for NJNT > 0) and the F.4.b cards it announces. The functions of an F.4.b card act only in
// a JTYPE 3 joint's globographic stop (VISPR calls GLOBAL for JTYPE 3 alone), which B.3.a already
// refuses, so for every other joint they are read and left out (W0503); NF(1) = 0 makes ATB add
// a rolling constraint (KQTYPE -4), which sled has not: refused.
void ReadGlobalGraphicJoints(DeckFields& fields, int joints);

}  // namespace sled::lang::legacy
