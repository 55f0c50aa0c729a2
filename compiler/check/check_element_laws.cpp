// Force and torque laws that push the wrong way: a contact that pulls the surfaces together, a
// belt that pushes, a spring or a joint characteristic that drives away from its rest instead of
// back to it (a negative stiffness). Such a law is accepted by every other check, runs, and
// gives an answer no test can have had: refused here (E0420), at the function's text.
#include <cmath>
#include <optional>
#include <set>
#include <utility>

#include <fmt/format.h>

#include "compiler/check/checkers.h"

namespace sled::compiler::internal {
namespace {

// Where the law first has the wrong sign for an argument x > 0 of the element's working range
// (force against deflection, strain, elongation or angle): f(x) < 0 for x > 0, and for an
// element that works both ways (springs, joints) f(x) > 0 for x < 0. Tables are checked at their
// rows (linear between them), a polynomial near zero by its lowest non-zero coefficient (its sign
// there) and a constant as it is. Returns the argument and the value, or nothing.
std::optional<std::pair<double, double>> WrongSign(const Function& function, bool both_ways) {
  switch (function.kind) {
    case Function::Kind::kConstant:
      if (function.constant < 0) return std::pair{1.0, function.constant};
      return std::nullopt;
    case Function::Kind::kPolynomial:
      for (std::size_t k = 0; k < function.coefficients.size(); ++k) {
        const double c = function.coefficients[k];
        if (c == 0.0) continue;
        if (c < 0) return std::pair{0.0, c};
        return std::nullopt;
      }
      return std::nullopt;
    case Function::Kind::kTable:
      for (const auto& [x, f] : function.points) {
        if ((x > 0 && f < 0) || (both_ways && x < 0 && f > 0)) return std::pair{x, f};
      }
      return std::nullopt;
  }
  return std::nullopt;
}

}  // namespace

void ElementLawChecker::CheckElementLaws() {
  std::set<std::pair<FunctionId, std::string>> reported;  // a law shared by pairs: once
  auto check = [&](FunctionId id, const std::string& element, const SourceRange& element_range,
                   std::string_view law, std::string_view argument, std::string_view unit,
                   std::string_view physical, bool both_ways) {
    if (id < 0) return;
    const Function& function = scenario_.functions[static_cast<std::size_t>(id)];
    const auto wrong = WrongSign(function, both_ways);
    if (!wrong || !reported.insert({id, element}).second) return;
    const std::string where =
        function.kind == Function::Kind::kTable
            ? fmt::format("{} {:g} at {} {:g} {}", law, wrong->second, argument, wrong->first, unit)
        : function.kind == Function::Kind::kPolynomial
            ? fmt::format("its lowest term is negative ({:g}), so is the {} near zero {}",
                          wrong->second, law, argument)
            : fmt::format("a negative {} ({:g})", law, wrong->second);
    const bool inline_law = function.name.empty() && function.range.valid();
    Report(DiagnosticKind::kNonPhysicalLaw, inline_law ? function.range : element_range,
           fmt::format("{}: {}", element, where),
           inline_law ? "pushes the wrong way"
                      : fmt::format("function `{}` pushes the wrong way", function.name),
           fmt::format("{}; give the law's size with a positive sign (a stiffness in N/m, a "
                       "table of positive values)",
                       physical));
  };
  for (const Contact& contact : scenario_.contacts) {
    check(contact.force, "a contact's force", contact.range, "force", "deflection", "m",
          "a contact force pushes the surfaces apart: it is positive for every positive "
          "deflection",
          false);
  }
  for (const Belt& belt : scenario_.belts) {
    check(belt.force, fmt::format("belt `{}`", belt.name), belt.range, "force", "strain", "",
          "webbing pulls when stretched: its force is positive for every positive strain", false);
  }
  for (const SpringDamper& spring : scenario_.springs) {
    check(spring.stiffness, fmt::format("spring `{}`", spring.name), spring.range, "force",
          "elongation", "m",
          "a spring pulls back when stretched and pushes back when compressed: its force has the "
          "sign of the elongation",
          true);
  }
  for (const Joint& joint : scenario_.joints) {
    const std::pair<FunctionId, const char*> slots[] = {{joint.flexure, "flexure"},
                                                        {joint.twist, "twist"},
                                                        {joint.precession, "precession"},
                                                        {joint.nutation, "nutation"},
                                                        {joint.spin, "spin"}};
    const bool slip = joint.type == JointType::kSlip;
    for (const auto& [id, slot] : slots) {
      check(id, fmt::format("joint `{}` {}", joint.name, slot), joint.range,
            slip ? "force" : "torque", slip ? "displacement" : "angle", slip ? "m" : "rad",
            slip ? "a slip joint's force function resists its displacement: its value has the sign "
                   "of the displacement (a motor is a `load`)"
                 : "a joint's torque function resists its angle: its value has the sign of the "
                   "angle (a motor is a `load`)",
            true);
    }
  }
}

}  // namespace sled::compiler::internal
