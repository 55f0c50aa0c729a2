// Cards G.4 to G.6, ATB's equilibrium solve (EQUILB, INPUT_EQUILB): NVAR position variables, each
// a coordinate of a segment's G.2 position (NTV 1) or G.3 yaw, pitch or roll (NTV 2) with the
// segments that move with it, adjusted until the contact force of segment JSG on plane JPL is GX;
// NCON temporary constraints of a segment on a plane whose forces give those GX. The solve itself
// is equilibrium_solve.cpp's.
#include "lang/legacy/equilibrium_reader.h"

#include <string>
#include <vector>

#include <fmt/format.h>

#include "lang/legacy/equilibrium_solve.h"

namespace sled::lang::legacy {
namespace {

constexpr int kMaxVariables = 10;   // NVAR: 1 to 10 (STOP 2600)
constexpr int kMaxConstraints = 5;  // NCON: 0 to 5 (STOP 2601)
constexpr int kMaxMovedAlong = 5;   // NAV: 0 to 5 (STOP 2602)

class EquilibriumReader {
 public:
  explicit EquilibriumReader(DeckFields& fields)
      : f_(fields),
        r_(fields.source()),
        segments_(static_cast<int>(fields.deck().segments.size())),
        planes_(static_cast<int>(fields.deck().planes.size())) {}

  void Read(const Card& g1) {
    const Card g4 = r_.Next("G.4", {"(2I4)"});
    const int variables = r_.Integer(g4, 1, 4, "NVAR, the number of position variables");
    const int constraints = r_.Integer(g4, 5, 8, "NCON, the number of temporary constraints");
    // Past a count ATB stops on, the cards it announces are not read (no cascade from them).
    const bool variables_ok = InRange(g4, 1, 4, variables, 1, kMaxVariables, "NVAR", 2600);
    const bool constraints_ok = InRange(g4, 5, 8, constraints, 0, kMaxConstraints, "NCON", 2601);
    if (!variables_ok || !constraints_ok) return;
    for (int v = 1; v <= variables && !r_.truncated(); ++v) ReadVariable(v);
    for (int c = 1; c <= constraints && !r_.truncated(); ++c) ReadConstraint(c, variables);
    if (valid_ && !r_.truncated()) SolveEquilibrium(f_, g1, g4, constraints, variables_);
  }

 private:
  // G.5 (3I4,2F8.0,8I4): NTV, NI1, NSGE, GX, XDEV, JPL, JSG, NAV and NAV segments.
  void ReadVariable(int v) {
    Card card = r_.Next(fmt::format("G.5 (variable {})", v), {"(3I4,2F8.0,8I4)", 8});
    const int moved = r_.Integer(card, 37, 40, "NAV, the number of segments moved along");
    const bool moved_ok = InRange(card, 37, 40, moved, 0, kMaxMovedAlong, "NAV", 2602);
    if (moved_ok && moved > 0) r_.Extend(card, moved);
    EquilibriumVariable variable;
    variable.card = card;
    variable.kind = r_.Integer(card, 1, 4, "NTV, the variable's kind");
    variable.coordinate = r_.Integer(card, 5, 8, "NI1, the coordinate");
    variable.segment = r_.Integer(card, 9, 12, "NSGE, the segment");
    variable.force = r_.Real(card, 13, 20, "GX, the contact force sought");
    r_.Real(card, 21, 28, "XDEV, the largest change");
    variable.plane = r_.Integer(card, 29, 32, "JPL, the plane");
    variable.contact_segment = r_.Integer(card, 33, 36, "JSG, the segment on the plane");
    InRange(card, 1, 4, variable.kind, 1, 2, "NTV", 2603);
    InRange(card, 5, 8, variable.coordinate, 1, 3, "NI1", 2604);
    InRange(card, 9, 12, variable.segment, 1, segments_, "NSGE", 2605);
    InRange(card, 29, 32, variable.plane, 1, planes_, "JPL", 2606);
    InRange(card, 33, 36, variable.contact_segment, 1, segments_, "JSG", 2607);
    for (int i = 0; moved_ok && i < moved; ++i) {
      const int at = 41 + 4 * i;
      const int along = r_.Integer(card, at, at + 3, "KSGE, a segment moved along");
      InRange(card, at, at + 3, along, 1, segments_, "KSGE", 2610);
      variable.moved_along.push_back(along);
    }
    valid_ = valid_ && moved_ok;
    variables_.push_back(std::move(variable));
  }

  // G.6 (4I4): IPL, ISG, LTYPE, INDGX.
  void ReadConstraint(int c, int variables) {
    const Card card = r_.Next(fmt::format("G.6 (constraint {})", c), {"(4I4)"});
    InRange(card, 1, 4, r_.Integer(card, 1, 4, "IPL, the plane"), 1, planes_, "IPL", 2611);
    InRange(card, 5, 8, r_.Integer(card, 5, 8, "ISG, the segment"), 1, segments_, "ISG", 2612);
    InRange(card, 9, 12, r_.Integer(card, 9, 12, "LTYPE, the constraint's kind"), 3, 4, "LTYPE",
            2613);
    InRange(card, 13, 16, r_.Integer(card, 13, 16, "INDGX, the variable it sets"), 0, variables,
            "INDGX", 2614);
  }

  bool InRange(const Card& card, int first, int last, int value, int low, int high,
               std::string_view name, int stop) {
    if (value >= low && value <= high) return true;
    valid_ = false;
    f_.Invalid(card, first, last, fmt::format("{} is {}", name, value),
               fmt::format("{} is {} to {} (ATB stops otherwise: STOP {} in INPUT_EQUILB)", name,
                           low, high, stop));
    return false;
  }

  DeckFields& f_;
  DeckSource& r_;
  int segments_;
  int planes_;
  bool valid_ = true;  // every count and number in its range: the solve can run
  std::vector<EquilibriumVariable> variables_;
};

}  // namespace

void ReadEquilibriumCards(DeckFields& fields, const Card& g1) {
  EquilibriumReader(fields).Read(g1);
}

}  // namespace sled::lang::legacy
