// An airbag's `model`: sled's energy-balance bag (the default) or ATB's free bag (`atb_free`),
// and the attributes only the free bag has. docs/language.md §13, `airbag`.
#include <array>
#include <string_view>

#include <fmt/format.h>

#include "compiler/check/checkers.h"

namespace sled::compiler::internal {

void RestraintChecker::CheckAirbagModel(Scope& scope, const BoundBlock& bound, Airbag& bag) {
  if (const ast::Statement* model = One(bound, "model")) {
    const ast::Expr* word = SingleValue(*model);
    if (word && word->kind == ast::ExprKind::kPath && word->path.size() == 1 &&
        (word->path[0] == "energy" || word->path[0] == "atb_free")) {
      bag.free_bag = word->path[0] == "atb_free";
    } else if (word) {
      Report(DiagnosticKind::kInvalidEnumValue, word->range,
             "an airbag's `model` is `energy` or `atb_free`", "not an airbag model",
             "`energy`: sled's energy-balance bag fixed in its frame; `atb_free`: ATB's free bag");
    }
  }
  if (bag.free_bag) {
    bag.bag_mass = ReadQuantity(scope, bound, BlockKind::kAirbag, "bag_mass").value_or(0.0);
    bag.mass_factor = ReadQuantity(scope, bound, BlockKind::kAirbag, "mass_factor").value_or(1.0);
    bag.tether_stiffness =
        ReadQuantity(scope, bound, BlockKind::kAirbag, "tether_stiffness").value_or(0.0);
    bag.vent_opening_pressure =
        ReadQuantity(scope, bound, BlockKind::kAirbag, "vent_opening_pressure").value_or(0.0);
    return;
  }
  // The energy-balance bag is fixed in its frame and vents from the ambient pressure up: the
  // free bag's attributes would be ignored, so they are refused.
  constexpr std::array<std::string_view, 4> kFreeBagOnly = {
      "bag_mass", "mass_factor", "tether_stiffness", "vent_opening_pressure"};
  for (std::string_view name : kFreeBagOnly) {
    const auto found = bound.attributes.find(std::string(name));
    if (found == bound.attributes.end() || found->second.empty()) continue;
    Report(DiagnosticKind::kAirbagModelAttribute, found->second.front()->range,
           fmt::format("airbag `{}` has `{}`, which only ATB's free bag has", bag.name, name),
           "not an attribute of the energy-balance bag",
           "add `model = atb_free` for ATB's free bag, or remove it");
  }
}

}  // namespace sled::compiler::internal
