// ATB's R and G factors (F.x.b NF(3), NF(4); F.8.c columns 9-16) as ATB's own unloading law on
// the force function, `unloading = atb(energy_return = R, permanent_set = G)`, which the runtime
// simulates as ATB does (runtime/forces/atb_unloading.h, from DEF_NEW_QUADRATIC and
// DEF_NEW_CUBIC): R and G are functions of the largest deflection x_max (R = 1 and G = 0
// without), R(x_max) = 1 unloads along the loading function, otherwise a quadratic from zero
// force at G x_max through (x_max, f(x_max)) gives back R of the loading energy, and reloading
// climbs a cubic to the loading function at x_max. A constant factor is written as a number,
// one that changes with x_max as a function of the force function's argument (the deflection
// of a contact, the strain of a webbing) to a ratio, declared from its E cards. An inertial
// spike (NF(2)) is added to the loading force until the deflection first reaches the spike
// function's D3: `spike = NAME  spike_end = D3` in the same law.
#include <fmt/format.h>

#include "lang/legacy/ast_pieces.h"
#include "lang/legacy/deck_mapper.h"

namespace sled::lang::legacy::mapping {

std::optional<DeckMapper::FactorValue> DeckMapper::Factor(const Ref& ref, Use use, double none) {
  if (ref.number == 0) return FactorValue{none, {}};
  const FunctionCard* function = Function(ref);
  if (function == nullptr) return std::nullopt;
  used_.insert(function->number);
  if (function->form == FunctionCard::Form::kConstant) return FactorValue{function->constant, {}};
  // A factor that changes with the largest deflection: its own function, of the same argument.
  auto declared = FunctionFor(ref, use == Use::kBelt ? Use::kBeltFactor : Use::kContactFactor);
  if (!declared) return std::nullopt;
  return FactorValue{0.0, declared->PathText()};
}

bool DeckMapper::AddSpike(const Ref& spike, Use use, FunctionUnloading& unloading) {
  if (spike.number <= 0) return true;
  const FunctionCard* function = Function(spike);
  if (function == nullptr) return false;
  if (!(function->d3 > 0)) {
    Report(DiagnosticKind::kDeckNotExpressible, Ref{spike.number, function->d3_where, "E.2"},
           fmt::format("card E.2: function {}, the inertial spike of card {}, has D3 = {}",
                       spike.number, spike.card, function->d3),
           "ATB drops the spike at the first largest deflection past its end: the spike "
           "function's D3 when it is above 0 (DEF_NEW_CUBIC); with D3 at 0 or below the end is "
           "set in FRCDFL, which the reference does not have. Give the spike's end as D3");
    return false;
  }
  Report(DiagnosticKind::kDeckUnverifiedField, spike,
         fmt::format("card {}: the inertial spike (function {}) is added to the loading force "
                     "until the largest deflection reaches its D3 = {}, then dropped, as the V.3 "
                     "description says; FRCDFL, which sets that end and evaluates the loading "
                     "curve, is not in the reference",
                     spike.card, spike.number, function->d3),
         "compare the converted run with ATB's where the spike matters");
  declaring_spike_ = true;
  auto declared = FunctionFor(spike, use);
  declaring_spike_ = false;
  if (!declared) return false;
  unloading.atb = true;
  unloading.spike = FactorValue{0.0, declared->PathText()};
  unloading.spike_end = function->d3;
  return true;
}

std::optional<DeckMapper::FunctionUnloading> DeckMapper::Unloading(const UnloadingRefs& refs,
                                                                   Use use) {
  // A spike puts the function under ATB's law even when it is elastic (R = 1): ATB then
  // unloads along its loading curve, the function plus the spike while it lasts.
  FunctionUnloading spiked;
  spiked.argument_unit = use == Use::kBelt ? "" : L;
  if (!AddSpike(refs.spike, use, spiked)) return std::nullopt;
  const auto r = Factor(refs.r_factor, use, 1.0);
  if (!r) return std::nullopt;
  if (r->function.empty() && (r->constant < 0 || r->constant > 1)) {
    Report(DiagnosticKind::kDeckInvalidValue, refs.r_factor,
           fmt::format("card {}: the R factor (function {}) is {}", refs.r_factor.card,
                       refs.r_factor.number, r->constant),
           "R is the share of the loading energy the unloading curve gives back: 0 to 1");
    return std::nullopt;
  }
  if (r->function.empty() && r->constant == 1) {
    // ATB does not use G when R is 1: the contact unloads along its loading function.
    const FunctionCard* g = refs.g_factor.number != 0 ? Function(refs.g_factor) : nullptr;
    if (g != nullptr) used_.insert(g->number);
    if (g != nullptr && (g->form != FunctionCard::Form::kConstant || g->constant != 0)) {
      Report(DiagnosticKind::kDeckIgnoredField, refs.g_factor,
             fmt::format("card {}: the G factor (function {}) is not used, as ATB does not use "
                         "it when R is 1: the contact unloads along its loading function",
                         refs.g_factor.card, refs.g_factor.number),
             "give an R factor below 1 for a contact that loses energy");
    }
    return spiked;
  }
  const auto g = Factor(refs.g_factor, use, 0.0);
  if (!g) return std::nullopt;
  if (g->function.empty() && (g->constant < 0 || g->constant >= 1)) {
    Report(DiagnosticKind::kDeckInvalidValue, refs.g_factor,
           fmt::format("card {}: the G factor (function {}) is {}", refs.g_factor.card,
                       refs.g_factor.number, g->constant),
           "G is the permanent deflection as a share of the largest: from 0 up to, not "
           "including, 1 (ATB divides by 1 - G)");
    return std::nullopt;
  }
  spiked.atb = true;
  spiked.r = *r;
  spiked.g = *g;
  return spiked;
}

void DeckMapper::AddUnloading(ast::Statement& statement, const FunctionUnloading& unloading) {
  if (!unloading.atb) return;
  auto factor = [](const FactorValue& value) {
    return value.function.empty() ? Number(value.constant) : Path(value.function);
  };
  std::vector<std::pair<std::string, ast::Expr>> arguments;
  arguments.emplace_back("energy_return", factor(unloading.r));
  arguments.emplace_back("permanent_set", factor(unloading.g));
  if (!unloading.spike.function.empty()) {
    arguments.emplace_back("spike", Path(unloading.spike.function));
    arguments.emplace_back("spike_end", Number(unloading.spike_end, unloading.argument_unit));
  }
  if (unloading.origin != 0) {
    arguments.emplace_back("origin", Number(unloading.origin, unloading.argument_unit));
  }
  Add(statement, Attribute("unloading", Call("atb", std::move(arguments))));
}

bool DeckMapper::AddRateTerms(ast::Statement& contact, const UnloadingRefs& refs) {
  const std::pair<const Ref*, std::pair<const char*, Use>> terms[] = {
      {&refs.rate_scaled_force, {"rate_scaled_force", Use::kRateScaledForce}},
      {&refs.rate_scale, {"rate_scale", Use::kRateScale}},
      {&refs.rate_force, {"rate_force", Use::kRateForce}}};
  bool ok = true;
  for (const auto& [ref, attribute] : terms) {
    if (ref->number == 0) continue;
    auto function = FunctionFor(*ref, attribute.second);
    if (!function) {
      ok = false;
      continue;
    }
    Add(contact, Attribute(attribute.first, std::move(*function)));
  }
  return ok;
}

bool DeckMapper::RefuseRateTerms(const UnloadingRefs& refs, std::string_view element) {
  if (!refs.HasRateTerms()) return false;
  const Ref& at = refs.rate_scaled_force.number != 0 ? refs.rate_scaled_force
                  : refs.rate_scale.number != 0      ? refs.rate_scale
                                                     : refs.rate_force;
  Report(DiagnosticKind::kDeckNotExpressible, at,
         fmt::format("card {}: ATB's rate-dependent force (a negative function number) on {}",
                     at.card, element),
         "sled takes ATB's rate-dependent force (F2(D) F3(D') + F4(D')) on contacts only; give "
         "this card's NF(2) to NF(4) as 0");
  return true;
}

}  // namespace sled::lang::legacy::mapping
