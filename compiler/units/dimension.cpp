#include "compiler/units/dimension.h"

#include <array>
#include <string_view>

#include <fmt/format.h>

namespace sled::compiler {
namespace {

struct NamedDimension {
  Dimension dimension;
  std::string_view name;
  std::string_view si_unit;
};

// Energy shares torque's dimension and mass flow shares damping's, so neither has an entry:
// the dimension is described as torque or damping (see dimension.h).
constexpr std::array kNamedDimensions = {
    NamedDimension{dim::kLength, "length", "m"},
    NamedDimension{dim::kMass, "mass", "kg"},
    NamedDimension{dim::kTime, "time", "s"},
    NamedDimension{dim::kAngle, "angle", "rad"},
    NamedDimension{dim::kTemperature, "temperature", "K"},
    NamedDimension{dim::kArea, "area", "m^2"},
    NamedDimension{dim::kVolume, "volume", "m^3"},
    NamedDimension{dim::kVelocity, "velocity", "m/s"},
    NamedDimension{dim::kAcceleration, "acceleration", "m/s^2"},
    NamedDimension{dim::kAngularVelocity, "angular velocity", "rad/s"},
    NamedDimension{dim::kAngularAcceleration, "angular acceleration", "rad/s^2"},
    NamedDimension{dim::kForce, "force", "N"},
    NamedDimension{dim::kTorque, "torque", "N*m"},
    NamedDimension{dim::kStiffness, "stiffness", "N/m"},
    NamedDimension{dim::kDamping, "damping", "N*s/m"},
    NamedDimension{dim::kRotationalStiffness, "rotational stiffness", "N*m/rad"},
    NamedDimension{dim::kRotationalDamping, "rotational damping", "N*m*s/rad"},
    NamedDimension{dim::kInertia, "inertia", "kg*m^2"},
    NamedDimension{dim::kPressure, "pressure", "Pa"},
    NamedDimension{dim::kFrequency, "frequency", "Hz"},
    NamedDimension{dim::kDensity, "density", "kg/m^3"},
    NamedDimension{dim::kImpulse, "impulse", "N*s"},
    NamedDimension{dim::kSpecificGasConstant, "specific gas constant", "J/kg/K"},
};

const NamedDimension* FindNamed(Dimension dimension) {
  for (const auto& named : kNamedDimensions) {
    if (named.dimension == dimension) return &named;
  }
  return nullptr;
}

struct BaseFactor {
  int exponent;
  std::string_view name;
  std::string_view si_unit;
};

// The base dimensions in the order a formula lists them: mass*length^2/time.
std::array<BaseFactor, 5> BaseFactors(Dimension dimension) {
  return {{{dimension.mass, "mass", "kg"},
           {dimension.length, "length", "m"},
           {dimension.time, "time", "s"},
           {dimension.angle, "angle", "rad"},
           {dimension.temperature, "temperature", "K"}}};
}

// Writes positive exponents joined by `*` and then each negative one after its own `/`:
// "kg*m^2/s", "1/m/s". Every factor after a `/` is divided, as in the language's units.
std::string Formula(Dimension dimension, bool use_si_units) {
  std::string numerator;
  std::string denominator;
  for (const BaseFactor& factor : BaseFactors(dimension)) {
    if (factor.exponent == 0) continue;
    const std::string_view symbol = use_si_units ? factor.si_unit : factor.name;
    const int magnitude = factor.exponent > 0 ? factor.exponent : -factor.exponent;
    std::string term(symbol);
    if (magnitude != 1) term += fmt::format("^{}", magnitude);
    if (factor.exponent > 0) {
      if (!numerator.empty()) numerator += '*';
      numerator += term;
    } else {
      denominator += '/';
      denominator += term;
    }
  }
  if (numerator.empty() && !denominator.empty()) numerator = "1";
  return numerator + denominator;
}

}  // namespace

std::string SiUnitSymbol(Dimension dimension) {
  if (const NamedDimension* named = FindNamed(dimension)) return std::string(named->si_unit);
  return Formula(dimension, /*use_si_units=*/true);
}

std::string DescribeDimension(Dimension dimension) {
  if (dimension.IsDimensionless()) return "dimensionless";
  if (const NamedDimension* named = FindNamed(dimension)) {
    return fmt::format("{} [{}]", named->name, named->si_unit);
  }
  return fmt::format("{} [{}]", Formula(dimension, /*use_si_units=*/false),
                     Formula(dimension, /*use_si_units=*/true));
}

std::string DescribeMismatch(Dimension a, Dimension b) {
  return fmt::format("{} and {}", DescribeDimension(a), DescribeDimension(b));
}

std::string MismatchHelp(Dimension expected, Dimension found) {
  if (expected == found) return {};
  if (found.IsDimensionless()) {
    return fmt::format("the value has no unit; give it a unit of {}", DescribeDimension(expected));
  }
  if (expected.IsDimensionless()) return "write a plain number here, without a unit";
  const Dimension difference = found / expected;
  if (difference == dim::kAngle.Pow(difference.angle)) {
    return "the dimensions differ only by an angle; check for a missing or extra `deg` or `rad`";
  }
  if (difference == dim::kAcceleration / dim::kMass) {
    return "`g` is standard gravity; write `gram` for grams";
  }
  return {};
}

std::string DimensionHelp(Dimension expected, Dimension found) {
  std::string help = MismatchHelp(expected, found);
  if (!help.empty()) return help;
  return fmt::format("give a value in {}; check its unit and the names it uses",
                     DescribeDimension(expected));
}

}  // namespace sled::compiler
