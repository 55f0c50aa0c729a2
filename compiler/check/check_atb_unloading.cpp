// `unloading = atb(energy_return = R, permanent_set = G)`: ATB's unloading law on a function
// (runtime/forces/atb_unloading.h), its factors each a number or a function of the largest
// deflection; optionally an inertial spike (`spike`, `spike_end`) and the origin D0 (`origin`). A
// named function's factors may be functions declared after it, so while the named functions are
// defined (CheckContext::DefineFunction) the law is read once they all are (ResolvePendingAtbLaws).
#include <fmt/format.h>

#include "compiler/check/context.h"

namespace sled::compiler::internal {
namespace {

constexpr std::string_view kFormHelp =
    "write `unloading = atb(energy_return = R, permanent_set = G)`, each a number or a function "
    "of the largest deflection, with `spike = S  spike_end = D` for an inertial spike and "
    "`origin = D0` for where the function starts";

}  // namespace

void CheckContext::ReadAtbUnloading(Scope& scope, const BoundBlock& bound, Function& function,
                                    int index) {
  const ast::Statement* law = One(bound, "unloading");
  const ast::Expr* value = law != nullptr ? SingleValue(*law) : nullptr;
  if (value == nullptr) return;
  const ast::Expr& call = *value;
  if (call.kind != ast::ExprKind::kCall || call.PathText() != "atb") {
    Report(DiagnosticKind::kWrongValueKind, call.range, "`unloading` takes ATB's law, `atb(...)`",
           "not `atb(...)`", std::string(kFormHelp));
    return;
  }
  // The other unloading attributes describe sled's own curve: with ATB's law they contradict it.
  const AttributeKey others[] = {"energy_loss", "permanent_set", "unload_slope"};
  for (const AttributeKey other : others) {
    const ast::Statement* given = One(bound, other);
    if (given == nullptr) continue;
    Report(DiagnosticKind::kOverdeterminedUnloading, given->range,
           fmt::format("`{}` and `unloading = atb(...)` both describe the unloading", other.view()),
           "given with `unloading`",
           "keep one: ATB's law takes its energy return and permanent set as arguments of "
           "`atb(...)`");
  }
  function.energy_loss = function.permanent_set = 0.0;
  function.unload_slope.reset();
  if (defining_functions_ && index >= 0) {
    pending_atb_laws_.push_back({&scope, law, index});
    return;
  }
  ReadAtbLaw(scope, *law, call, function);
}

void CheckContext::ResolvePendingAtbLaws() {
  for (const PendingAtbLaw& pending : pending_atb_laws_) {
    const auto at = static_cast<std::size_t>(pending.index);
    if (!function_valid_.at(at)) continue;
    // A copy: reading the factors may add functions to scenario_.functions.
    Function function = scenario_.functions[at];
    ReadAtbLaw(*pending.scope, *pending.law, *SingleValue(*pending.law), function);
    scenario_.functions[at] = std::move(function);
  }
  pending_atb_laws_.clear();
}

void CheckContext::ReadAtbLaw(Scope& scope, const ast::Statement& law, const ast::Expr& call,
                              Function& function) {
  const Dimension ratio = dim::kDimensionless;
  const std::string form_help(kFormHelp);
  bool ok = true;
  const ast::Argument* spike_end = nullptr;
  for (const ast::Argument& argument : call.arguments) {
    const std::string_view name = argument.name;
    if (name == "spike_end" || name == "origin") {
      // Deflections (the function's argument): where the spike ends, where the function starts.
      const auto value = ExpectQuantity(scope, *argument.value, function.argument, name);
      if (!value) {
        ok = false;
        continue;
      }
      if (name == "origin") {
        function.atb_origin = *value;
        continue;
      }
      spike_end = &argument;
      function.atb_spike_end = *value;
      if (!(*value > 0)) {
        Report(DiagnosticKind::kValueOutOfRange, argument.value->range,
               "the inertial spike's end is not above zero", "out of range",
               "`spike_end` is the deflection at which ATB drops the spike: above zero");
        ok = false;
      }
      continue;
    }
    if (name == "spike") {
      // A force of the same argument, added to the loading force while it lasts.
      const auto id =
          ExpectFunction(scope, law, *argument.value, function.argument, function.result, name);
      if (!id) {
        ok = false;
        continue;
      }
      // ATB evaluates the spike as written: unloading attributes on it would be ignored.
      const Function& spike = scenario_.functions[static_cast<std::size_t>(*id)];
      if (spike.energy_loss > 0 || spike.permanent_set > 0 || spike.unload_slope ||
          spike.atb_unloading) {
        Report(DiagnosticKind::kUnloadingNotApplied, argument.value->range,
               "the inertial spike does not unload by its own attributes", "a spike that unloads",
               "the spike is added to the loading force as written and unloads with the "
               "function it is added to: remove the spike's unloading attributes");
        ok = false;
        continue;
      }
      function.atb_spike = *id;
      continue;
    }
    const bool is_return = name == "energy_return";
    if (!is_return && name != "permanent_set") {
      Report(DiagnosticKind::kUnknownArgument,
             name.empty() ? argument.value->range : argument.name_range,
             name.empty() ? std::string("`atb` takes named arguments")
                          : fmt::format("`atb` takes no argument `{}`", name),
             "unknown argument", form_help);
      ok = false;
      continue;
    }
    const auto id = ExpectFunction(scope, law, *argument.value, function.argument, ratio,
                                   is_return ? "energy_return" : "permanent_set");
    if (!id) {
      ok = false;
      continue;
    }
    // A constant factor is checked here; one that varies is evaluated as given, as ATB does.
    const Function& factor = scenario_.functions[static_cast<std::size_t>(*id)];
    const bool constant = factor.kind == Function::Kind::kConstant;
    if (constant && is_return && !(factor.constant >= 0 && factor.constant <= 1)) {
      Report(DiagnosticKind::kValueOutOfRange, argument.value->range,
             fmt::format("an energy return of {} is outside 0 to 1", factor.constant),
             "out of range", "R is the share of the loading energy that unloading gives back");
      ok = false;
    }
    if (constant && !is_return && !(factor.constant >= 0 && factor.constant < 1)) {
      Report(DiagnosticKind::kValueOutOfRange, argument.value->range,
             fmt::format("a permanent set of {} is outside 0 to 1 (1 excluded)", factor.constant),
             "out of range",
             "G is where the force reaches zero, as a share of the largest deflection");
      ok = false;
    }
    (is_return ? function.energy_return : function.atb_permanent_set) = *id;
  }
  if (ok && function.energy_return < 0) {
    Report(DiagnosticKind::kMissingArgument, call.range, "`atb` needs `energy_return`",
           "no energy return", form_help);
    ok = false;
  }
  // A spike and its end go together: ATB drops the spike at its end, and has no default.
  if (ok && (function.atb_spike >= 0) != (spike_end != nullptr)) {
    Report(DiagnosticKind::kMissingArgument, call.range,
           function.atb_spike >= 0 ? "`atb` with `spike` needs `spike_end`"
                                   : "`atb` with `spike_end` needs `spike`",
           "spike without its end",
           "give the inertial spike as `spike = FUNCTION  spike_end = DEFLECTION`: ATB adds the "
           "spike to the loading force until the deflection first reaches its end");
    ok = false;
  }
  function.atb_unloading = ok;
}

void CheckContext::RefuseAtbUnloading(std::optional<FunctionId> id, const BoundBlock& bound,
                                      AttributeKey name, std::string_view element) {
  if (!id || *id < 0 || !scenario_.functions[static_cast<std::size_t>(*id)].atb_unloading) return;
  const ast::Statement* statement = One(bound, name);
  Report(DiagnosticKind::kUnloadingNotApplied,
         statement ? statement->range : scenario_.functions[static_cast<std::size_t>(*id)].range,
         fmt::format("the `{}` of {} does not unload by ATB's law (`unloading = atb(...)`)",
                     name.view(), element),
         "a function with ATB's unloading",
         "ATB's law applies to contact forces and belt webbing; give a joint's torque "
         "`energy_loss`, `permanent_set` or `unload_slope`, or the joint's own `energy_loss`");
}

}  // namespace sled::compiler::internal
