// E.2's D0, D3 and D4, judged where a card uses the function, since what ATB does with them
// depends on the use:
// - D0 is where ATB starts the function: its integral (the loading energy under an R factor,
//   EVALFD_INTEGRAL) runs from D0 and its permanent deflection is D0 + G (x_max - D0)
//   (DEF_NEW_QUADRATIC). Under ATB's law it is the law's `origin`. Elsewhere ATB reads it for
//   nothing but the function's value below D0, which is in EVALFD (not in the reference): where
//   no argument of the use reaches below D0 (a deflection, a strain or a time, never negative,
//   and D0 at or below zero) it changes nothing and is left out (W0503); otherwise refused.
// - D3 of an inertial spike is where the spike ends (map_unloading.cpp). D3 of a friction
//   function is the restitution of ATB's first-contact impulse (PLSEGF's CREST) and D4 a rolling
//   constraint's friction; D4 of a plane contact's force function moves the force's point off
//   the deepest point (PLELP). None has a counterpart in sled, and what the other uses do with
//   them is in EVALFD and FRCDFL (not in the reference): refused.
#include <fmt/format.h>

#include "lang/legacy/deck_mapper.h"

namespace sled::lang::legacy::mapping {

bool DeckMapper::CheckFunctionFields(const FunctionCard& function, const Ref& ref, Use use,
                                     FunctionUnloading& unloading) {
  enum Field { kOrigin, kThird, kFourth };
  bool ok = true;
  auto report = [&](Field field, const SourceRange& where, DiagnosticKind kind, std::string message,
                    std::string help) {
    if (kind != DiagnosticKind::kDeckIgnoredField) ok = false;
    if (!reported_fields_.insert({function.number, field}).second) return;
    Report(kind, Ref{function.number, where, "E.2"},
           fmt::format("card E.2: function {} (used by card {}): {}", function.number, ref.card,
                       std::move(message)),
           std::move(help));
  };
  if (function.d3 != 0 && !declaring_spike_) {
    report(kThird, function.d3_where, DiagnosticKind::kDeckNotExpressible,
           fmt::format("D3 is {}", function.d3),
           "ATB reads D3 of an inertial-spike function as where the spike ends (that converts), "
           "of a contact's friction function as the restitution of its first-contact impulse "
           "(PLSEGF); other uses are in EVALFD and FRCDFL, which the reference does not have: "
           "leave it 0");
  }
  if (function.d4 != 0) {
    report(kFourth, function.d4_where, DiagnosticKind::kDeckNotExpressible,
           fmt::format("D4 is {}", function.d4),
           "ATB reads D4 of a plane contact's force function as the share of the penetration by "
           "which the force's point moves off the deepest point (PLELP) and of a friction "
           "function as a rolling constraint's friction (PLSEGF); sled has neither: leave it 0");
  }
  if (function.origin == 0) return ok;
  // ATB integrates the function only under an R factor: an elastic law (R = 1) does not.
  const bool integrated =
      unloading.atb && !(unloading.r.function.empty() && unloading.r.constant == 1);
  if (integrated && !declaring_spike_) {
    const bool table_below = function.form == FunctionCard::Form::kTable &&
                             !function.points.empty() &&
                             function.points.front().first > function.origin;
    if (function.origin > 0 || table_below) {
      report(kOrigin, function.origin_where, DiagnosticKind::kDeckNotExpressible,
             fmt::format("D0 is {}", function.origin),
             function.origin > 0
                 ? "the contact deflects from 0, below D0, where ATB's value of the function is "
                   "in EVALFD, which the reference does not have: shift the function to start "
                   "at 0 by hand"
                 : "ATB integrates a table from its first row when that lies above D0 "
                   "(EVALFD_INTEGRAL), while it measures the permanent deflection from D0: give "
                   "D0 as the first row's argument or add a row at D0");
      return false;
    }
    unloading.origin = function.origin;
    return ok;
  }
  const bool never_negative = use == Use::kContact || use == Use::kBelt ||
                              use == Use::kContactFactor || use == Use::kBeltFactor ||
                              use == Use::kRateScaledForce || use == Use::kLoadForce ||
                              use == Use::kLoadTorque;
  if (never_negative && function.origin < 0) {
    report(kOrigin, function.origin_where, DiagnosticKind::kDeckIgnoredField,
           fmt::format("D0 is {}, left out", function.origin),
           "ATB reads D0 for the loading energy of an R factor and for the function's value "
           "below it; here nothing integrates the function and its argument never falls below "
           "zero, so D0 changes nothing");
    return ok;
  }
  report(kOrigin, function.origin_where, DiagnosticKind::kDeckNotExpressible,
         fmt::format("D0 is {}", function.origin),
         "the function's argument here can fall below D0, where ATB's value of the function is "
         "in EVALFD, which the reference does not have: shift the function to start at 0 by "
         "hand");
  return false;
}

}  // namespace sled::lang::legacy::mapping
