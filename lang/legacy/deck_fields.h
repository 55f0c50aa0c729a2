// The helpers every card group's reader shares: fields read by their declared columns through a
// DeckSource into the Deck being filled, with the diagnostics of docs/legacy.md (refused fields
// E0507, invalid values E0512, counts out of range E0505, unverified fields W0501, fields ATB
// ignores W0503, fields converted to sled's nearest model W0504). deck_reader.cpp reads groups A to
// H with them; the restraint groups that take many cards (harnesses, airbags, constraints) have
// files of their own.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "lang/legacy/deck.h"
#include "lang/legacy/deck_source.h"

namespace sled::lang::legacy {

class DeckFields {
 public:
  DeckFields(DeckSource& source, Deck& deck) : r_(source), deck_(deck) {}

  DeckSource& source() { return r_; }
  Deck& deck() { return deck_; }

  // Three reals of `width` columns from `first`.
  Vec3 Triple(const Card& card, int first, int width, std::string_view what);
  // A count checked against its limit; out of range is reported and read as zero.
  int Count(const Card& card, int first, int last, std::string_view what, int limit);
  Ref Reference(const Card& card, int first, int last, std::string_view what);
  // Counts per item, `per_card` to a card of `format` (`(18I4)`, `(8I4)`). `one_read`: ATB reads
  // all of them in one READ, so a .lin deck may give them on one line (F.2.a, F.8.b); else one
  // READ per card (F.1.a, F.3.a, F.4.a).
  std::vector<int> CountsPerItem(const std::string& label, int items, std::string_view format,
                                 int per_card, bool one_read, std::string_view what, int limit);
  // Five function numbers from `first` (force-deflection, inertial spike, R factor, G factor,
  // friction, 4 columns each): the spike is refused; the R and G factors, or the functions of
  // ATB's rate-dependent force (negative numbers, ReadRateTerms), go to `unloading`, for the
  // mapper to convert.
  void ReadRateTerms(const Card& card, int first, int spike, UnloadingRefs* unloading);
  void ReadFunctionNumbers(const Card& card, int first, Ref* force, Ref* friction,
                           UnloadingRefs* unloading);

  // The frame ATB segment number `number` names (columns first..last of `card`): a body
  // segment, a vehicle or the ground. Airbags (between the vehicles and the ground, `bags` of
  // them) and numbers outside the deck are reported as `what` and give nothing.
  std::optional<DeckFrame> FrameOf(const Card& card, int first, int last, int number, int bags,
                                   std::string_view what);

  // Three semi-axes of 6 columns from `first`: each positive, or (when `may_be_absent`, a
  // segment without a contact ellipsoid) all three zero; else E0512.
  void CheckSemiAxes(const Card& card, int first, const Vec3& semi_axes, bool may_be_absent);

  void Refuse(const Card& card, int first, int last, std::string_view what, std::string help);
  void RefuseNonZero(const Card& card, int first, int last, double value, std::string_view what,
                     std::string help);
  void Unverified(const Card& card, int first, int last, std::string_view what);
  void Ignored(const Card& card, int first, int last, std::string_view what, std::string help);
  void Invalid(const Card& card, int first, int last, std::string_view what, std::string help);
  void Approximated(const Card& card, int first, int last, std::string_view what);

 protected:
  // "card LABEL, COLUMNS: WHAT" at the columns, with `help`.
  void ReportField(DiagnosticKind kind, const Card& card, int first, int last,
                   std::string_view what, std::string help);

  DeckSource& r_;
  Deck& deck_;
};

}  // namespace sled::lang::legacy
