#include "compiler/units/quantity.h"

#include <cmath>

#include <fmt/format.h>

namespace sled::compiler {
namespace {

// Bounds a dimension's exponents after a power, so that nested powers such as `((m^9)^9)^9...`
// are rejected instead of overflowing.
constexpr int kMaxDimensionExponent = 99;

ArithmeticResult Failure(ArithmeticStatus status) { return {status, {}}; }

bool WithinDimensionLimit(int base_exponent, int power) {
  const long long exponent = static_cast<long long>(base_exponent) * power;
  return exponent >= -kMaxDimensionExponent && exponent <= kMaxDimensionExponent;
}

}  // namespace

std::optional<Quantity> Add(Quantity a, Quantity b) {
  if (a.dimension != b.dimension) return std::nullopt;
  return Quantity{a.value + b.value, a.dimension};
}

std::optional<Quantity> Subtract(Quantity a, Quantity b) {
  if (a.dimension != b.dimension) return std::nullopt;
  return Quantity{a.value - b.value, a.dimension};
}

Quantity Negate(Quantity a) { return {-a.value, a.dimension}; }

Quantity Multiply(Quantity a, Quantity b) { return {a.value * b.value, a.dimension * b.dimension}; }

ArithmeticResult Divide(Quantity dividend, Quantity divisor) {
  if (divisor.value == 0.0) return Failure(ArithmeticStatus::kDivisionByZero);
  return {ArithmeticStatus::kOk,
          {dividend.value / divisor.value, dividend.dimension / divisor.dimension}};
}

ArithmeticResult Power(Quantity base, Quantity exponent) {
  if (!exponent.dimension.IsDimensionless() || !std::isfinite(exponent.value)) {
    return Failure(ArithmeticStatus::kInvalidExponent);
  }
  const double e = exponent.value;
  if (base.value == 0.0 && e < 0.0) return Failure(ArithmeticStatus::kDivisionByZero);
  if (base.dimension.IsDimensionless()) {
    const double value = std::pow(base.value, e);
    if (std::isnan(value)) return Failure(ArithmeticStatus::kInvalidExponent);
    return {ArithmeticStatus::kOk, {value, dim::kDimensionless}};
  }
  if (e != std::trunc(e) || std::fabs(e) > kMaxPowerExponent) {
    return Failure(ArithmeticStatus::kInvalidExponent);
  }
  const int whole = static_cast<int>(e);
  const Dimension& d = base.dimension;
  if (!WithinDimensionLimit(d.length, whole) || !WithinDimensionLimit(d.mass, whole) ||
      !WithinDimensionLimit(d.time, whole) || !WithinDimensionLimit(d.angle, whole) ||
      !WithinDimensionLimit(d.temperature, whole)) {
    return Failure(ArithmeticStatus::kInvalidExponent);
  }
  return {ArithmeticStatus::kOk, {std::pow(base.value, e), d.Pow(whole)}};
}

std::string FormatQuantity(double value_in_si, Dimension dimension) {
  const std::string unit = SiUnitSymbol(dimension);
  if (unit.empty()) return fmt::format("{:g}", value_in_si);
  return fmt::format("{:g} {}", value_in_si, unit);
}

}  // namespace sled::compiler
