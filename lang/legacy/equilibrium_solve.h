// ATB's equilibrium solve (G.1.a I1 = 15, EQUILB) computed at conversion for the cases it can
// be computed exactly: G.5 variables that move reference segments along the inertial axes
// (NTV 1) or turn segments' G.3.a angles (NTV 2) until each named segment's contact force on
// its plane is the given GX. The force of a plane contact at rest is its loading function of the
// ellipsoid's penetration, so the converter finds the penetrations F(d) = GX, solves the
// variables for them by Newton, and writes the moved G.2 positions and G.3.a angles; the run
// starts from them as ATB's does after EQUILB.
#pragma once

#include <vector>

#include "lang/legacy/deck_fields.h"

namespace sled::lang::legacy {

// One G.5 card.
struct EquilibriumVariable {
  Card card;
  int kind = 0;                  // NTV: 1 a G.2 position coordinate, 2 a G.3 angle
  int coordinate = 0;            // NI1: 1 to 3
  int segment = 0;               // NSGE
  double force = 0;              // GX
  int plane = 0;                 // JPL
  int contact_segment = 0;       // JSG
  std::vector<int> moved_along;  // KSGE
};

// Moves the G.2 positions and G.3.a angles of `fields.deck()` as EQUILB would, or refuses (E0507)
// at the G.1.a I1 columns, the G.4 NCON columns or the G.5 field what the conversion cannot
// reproduce: G.6 constraints, a contact segment that hangs from a joint, and the values EQUILB
// rewrites besides the positions (locked joints' unlock torques, fixed-point constraints).
void SolveEquilibrium(DeckFields& fields, const Card& g1, const Card& g4, int constraints,
                      const std::vector<EquilibriumVariable>& variables);

}  // namespace sled::lang::legacy
