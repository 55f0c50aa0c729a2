// A number with a dimension, in SI units, and the arithmetic the checker's constant folding does
// on it (`param v = 56 km/h`, `2 * v`, `(v / 3.6)^2`). These functions only compute; the caller
// reports the diagnostic a failed status names.
#pragma once

#include <optional>
#include <string>

#include "compiler/units/dimension.h"

namespace sled::compiler {

struct Quantity {
  double value = 0.0;  // in SI units (m, kg, s, rad)
  Dimension dimension;
};

enum class ArithmeticStatus {
  kOk,
  kDivisionByZero,   // a zero divisor, or zero to a negative power: report E0306
  kInvalidExponent,  // an exponent with a unit, not a small whole number on a base with a
                     // dimension, or a power with no real result: report E0305
};

struct ArithmeticResult {
  ArithmeticStatus status = ArithmeticStatus::kOk;
  Quantity quantity;  // meaningful only when ok()

  bool ok() const { return status == ArithmeticStatus::kOk; }
};

// The largest magnitude of a whole exponent on a quantity with a dimension: `(2 m)^9` at most.
inline constexpr int kMaxPowerExponent = 9;

// Sums and differences need equal dimensions; nullopt otherwise (the caller reports E0303 with
// DescribeMismatch).
std::optional<Quantity> Add(Quantity a, Quantity b);
std::optional<Quantity> Subtract(Quantity a, Quantity b);

Quantity Negate(Quantity a);
Quantity Multiply(Quantity a, Quantity b);
ArithmeticResult Divide(Quantity dividend, Quantity divisor);

// base^exponent. The exponent must be dimensionless. A dimensionless base takes any real exponent
// with a real result; a base with a dimension takes a whole exponent of at most
// kMaxPowerExponent in magnitude.
ArithmeticResult Power(Quantity base, Quantity exponent);

// The SI value with its SI unit, such as "0.05 m", "2000 N" or "0.7" (printed with `{:g}`).
std::string FormatQuantity(double value_in_si, Dimension dimension);

}  // namespace sled::compiler
