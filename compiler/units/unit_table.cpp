#include "compiler/units/unit_table.h"

#include <array>
#include <numbers>
#include <string>
#include <utility>

#include <fmt/format.h>

namespace sled::compiler {
namespace {

// Exact definitions (NIST SP 811, ISO 80000).
constexpr double kInch = 0.0254;
constexpr double kFoot = 0.3048;
constexpr double kPound = 0.45359237;
constexpr double kStandardGravity = 9.80665;
constexpr double kPoundForce = kPound * kStandardGravity;  // 4.4482216152605 N, exact in binary
// lbf/(ft/s^2) and lbf/in^2, correctly rounded from the exact quotients.
constexpr double kSlug = 14.593902937206364829;
constexpr double kPsi = 6894.7572931683613367;
constexpr double kDegree = std::numbers::pi / 180.0;

// A common misspelling and what to write instead.
struct UnitHint {
  std::string_view written;
  std::string_view help;
};

constexpr std::array kUnitHints = {
    UnitHint{"kph", "write `km/h`"},
    UnitHint{"kmh", "write `km/h`"},
    UnitHint{"kmph", "write `km/h`"},
    UnitHint{"sec", "write `s` for seconds"},
    UnitHint{"secs", "write `s` for seconds"},
    UnitHint{"msec", "write `ms` for milliseconds"},
    UnitHint{"hr", "write `h` for hours"},
    UnitHint{"grams", "write `gram` for grams; `g` is standard gravity"},
    UnitHint{"gr", "write `gram` for grams; `g` is standard gravity"},
    UnitHint{"G", "write `g` for standard gravity"},
    UnitHint{"Nm", "write `N*m`"},
    UnitHint{"Nmm", "write `N*mm`"},
    UnitHint{"lbs", "write `lb` for pound-mass or `lbf` for pound-force"},
    UnitHint{"degree", "write `deg`"},
    UnitHint{"degrees", "write `deg`"},
    UnitHint{"rpm", "write `rev/min`"},
};

std::string_view HintFor(std::string_view symbol) {
  for (const UnitHint& hint : kUnitHints) {
    if (hint.written == symbol) return hint.help;
  }
  return {};
}

const std::vector<std::string>& AllSymbols() {
  static const std::vector<std::string> kSymbols = [] {
    std::vector<std::string> symbols;
    for (const UnitInfo& unit : AllUnits()) symbols.emplace_back(unit.symbol);
    return symbols;
  }();
  return kSymbols;
}

// scale^exponent for a small positive exponent, by repeated multiplication.
double WholePower(double scale, int exponent) {
  double result = 1.0;
  for (int i = 0; i < exponent; ++i) result *= scale;
  return result;
}

}  // namespace

const std::vector<UnitInfo>& AllUnits() {
  static const std::vector<UnitInfo> kUnits = {
      // Length.
      {"m", 1.0, dim::kLength, "metre"},
      {"mm", 1e-3, dim::kLength, "millimetre"},
      {"cm", 1e-2, dim::kLength, "centimetre"},
      {"km", 1e3, dim::kLength, "kilometre"},
      {"in", kInch, dim::kLength, "inch (0.0254 m)"},
      {"ft", kFoot, dim::kLength, "foot (0.3048 m)"},
      // Mass.
      {"kg", 1.0, dim::kMass, "kilogram"},
      {"gram", 1e-3, dim::kMass, "gram (`g` is standard gravity)"},
      {"lb", kPound, dim::kMass, "pound-mass (0.45359237 kg)"},
      {"slug", kSlug, dim::kMass, "slug (1 lbf*s^2/ft)"},
      {"tonne", 1e3, dim::kMass, "tonne (1000 kg)"},
      // Time.
      {"s", 1.0, dim::kTime, "second"},
      {"ms", 1e-3, dim::kTime, "millisecond"},
      {"us", 1e-6, dim::kTime, "microsecond"},
      {"min", 60.0, dim::kTime, "minute"},
      {"h", 3600.0, dim::kTime, "hour"},
      // Angle.
      {"rad", 1.0, dim::kAngle, "radian"},
      {"deg", kDegree, dim::kAngle, "degree"},
      {"rev", 2.0 * std::numbers::pi, dim::kAngle, "revolution (2*pi rad)"},
      // Force.
      {"N", 1.0, dim::kForce, "newton"},
      {"kN", 1e3, dim::kForce, "kilonewton"},
      {"lbf", kPoundForce, dim::kForce, "pound-force (4.4482216152605 N)"},
      // Acceleration.
      {"g", kStandardGravity, dim::kAcceleration, "standard gravity (9.80665 m/s^2)"},
      // Velocity.
      {"mph", 0.44704, dim::kVelocity, "mile per hour (0.44704 m/s)"},
      // Frequency.
      {"Hz", 1.0, dim::kFrequency, "hertz"},
      // Pressure.
      {"Pa", 1.0, dim::kPressure, "pascal"},
      {"kPa", 1e3, dim::kPressure, "kilopascal"},
      {"MPa", 1e6, dim::kPressure, "megapascal"},
      {"bar", 1e5, dim::kPressure, "bar (100 kPa)"},
      {"psi", kPsi, dim::kPressure, "pound-force per square inch"},
      // Energy.
      {"J", 1.0, dim::kEnergy, "joule"},
      {"kJ", 1e3, dim::kEnergy, "kilojoule"},
      // Volume.
      {"L", 1e-3, dim::kVolume, "litre"},
      // Temperature (absolute only: degrees Celsius are an offset scale, not a unit factor).
      {"K", 1.0, dim::kTemperature, "kelvin"},
  };
  return kUnits;
}

const UnitInfo* FindUnit(std::string_view symbol) {
  for (const UnitInfo& unit : AllUnits()) {
    if (unit.symbol == symbol) return &unit;
  }
  return nullptr;
}

std::optional<ResolvedUnit> ResolveUnit(const lang::ast::Unit& unit,
                                        lang::DiagnosticConsumer& diagnostics) {
  // Multiplied and divided scales are kept apart so that `km/h` is 1000/3600, rounded once.
  double numerator = 1.0;
  double denominator = 1.0;
  Dimension dimension;
  bool ok = true;
  for (const lang::ast::UnitFactor& factor : unit.factors) {
    const UnitInfo* info = FindUnit(factor.symbol);
    if (info == nullptr) {
      auto diagnostic = lang::MakeDiagnostic(lang::DiagnosticKind::kUnknownUnit, factor.range,
                                             fmt::format("unknown unit `{}`", factor.symbol),
                                             "not a unit sled knows");
      const std::string_view hint = HintFor(factor.symbol);
      diagnostic.help =
          hint.empty() ? lang::DidYouMean(factor.symbol, AllSymbols()) : std::string(hint);
      diagnostics.Consume(std::move(diagnostic));
      ok = false;
    }
    if (factor.exponent > kMaxUnitExponent || factor.exponent < -kMaxUnitExponent) {
      auto diagnostic = lang::MakeDiagnostic(
          lang::DiagnosticKind::kInvalidExponent, factor.range,
          fmt::format("exponent {} on unit `{}` is out of range", factor.exponent, factor.symbol),
          "exponent too large");
      diagnostic.notes.push_back(
          fmt::format("a unit's exponent must be a whole number from {} to {}", -kMaxUnitExponent,
                      kMaxUnitExponent));
      diagnostics.Consume(std::move(diagnostic));
      ok = false;
    }
    if (!ok) continue;
    if (factor.exponent > 0) {
      numerator *= WholePower(info->scale_to_si, factor.exponent);
    } else {
      denominator *= WholePower(info->scale_to_si, -factor.exponent);
    }
    dimension = dimension * info->dimension.Pow(factor.exponent);
  }
  if (!ok) return std::nullopt;
  return ResolvedUnit{numerator / denominator, dimension};
}

}  // namespace sled::compiler
