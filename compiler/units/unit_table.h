// The unit symbols sled knows, and the resolution of a written unit such as `N*m/deg` to a scale
// and a dimension. Values are SI internally (m, kg, s, rad); every scale is exact by definition
// (1 in = 0.0254 m, 1 lb = 0.45359237 kg, standard gravity 9.80665 m/s^2).
//
// `g` is standard gravity, as in "20 g"; a gram is `gram`.
#pragma once

#include <optional>
#include <string_view>
#include <vector>

#include "compiler/units/dimension.h"
#include "lang/ast/ast.h"
#include "lang/diagnostics/diagnostic.h"

namespace sled::compiler {

struct UnitInfo {
  std::string_view symbol;
  double scale_to_si = 1.0;  // the SI value of one of this unit
  Dimension dimension;
  std::string_view description;
};

// Every unit, in a fixed order (by dimension, SI unit first).
const std::vector<UnitInfo>& AllUnits();

// The unit with this exact (case-sensitive) symbol, or null.
const UnitInfo* FindUnit(std::string_view symbol);

// The largest magnitude of a unit factor's exponent: `m^9` is allowed, `m^10` is not.
inline constexpr int kMaxUnitExponent = 9;

// A written unit in SI terms: a value `v` in this unit is `v * scale_to_si` in SI units.
struct ResolvedUnit {
  double scale_to_si = 1.0;
  Dimension dimension;
};

// Resolves every factor of `unit`. Reports E0301 for each unknown symbol (with a hint for common
// mistakes such as `kph` or a "did you mean") and E0305 for each exponent beyond
// ±kMaxUnitExponent, on that factor's range, and then returns nullopt.
std::optional<ResolvedUnit> ResolveUnit(const lang::ast::Unit& unit,
                                        lang::DiagnosticConsumer& diagnostics);

}  // namespace sled::compiler
