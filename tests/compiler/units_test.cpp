// Units and dimensions: the unit table against the units' exact definitions, the resolution of
// written units, dimension names, and the arithmetic of constant folding.
#include <cmath>
#include <numbers>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "compiler/units/dimension.h"
#include "compiler/units/quantity.h"
#include "compiler/units/unit_table.h"
#include "lang/ast/ast.h"
#include "lang/diagnostics/diagnostic.h"

namespace sled::compiler {
namespace {

using lang::DiagnosticCollector;
using lang::SourceRange;

constexpr double kPi = std::numbers::pi;

// Independent reference values, built from the definitions rather than copied from the table.
constexpr double kInchInMetres = 2.54 / 100.0;
constexpr double kFootInMetres = 12.0 * kInchInMetres;
constexpr double kMileInMetres = 5280.0 * kFootInMetres;
constexpr double kPoundInKilograms = 0.45359237;
constexpr double kStandardGravity = 9.80665;
constexpr double kPoundForceInNewtons = kPoundInKilograms * kStandardGravity;

// A unit as the parser would build it: factors laid out one after another in file 1, each range
// covering its symbol and exponent.
lang::ast::Unit MakeUnit(std::vector<std::pair<std::string, int>> factors) {
  lang::ast::Unit unit;
  std::uint32_t offset = 100;
  for (auto& [symbol, exponent] : factors) {
    const auto length = static_cast<std::uint32_t>(symbol.size() + (exponent == 1 ? 0 : 3));
    unit.factors.push_back({symbol, exponent, SourceRange{{1}, offset, offset + length}});
    offset += length + 1;
  }
  unit.range = SourceRange{{1}, 100, offset - 1};
  return unit;
}

ResolvedUnit ResolveOrFail(std::vector<std::pair<std::string, int>> factors) {
  DiagnosticCollector diagnostics;
  auto resolved = ResolveUnit(MakeUnit(std::move(factors)), diagnostics);
  EXPECT_TRUE(resolved.has_value());
  EXPECT_TRUE(diagnostics.diagnostics().empty());
  return resolved.value_or(ResolvedUnit{std::nan(""), {}});
}

// ---------------------------------------------------------------------------------------------
// Dimensions

TEST(Dimension, NamedDimensionsHaveTheirBaseExponents) {
  EXPECT_EQ(dim::kForce, (Dimension{.length = 1, .mass = 1, .time = -2}));
  EXPECT_EQ(dim::kTorque, (Dimension{.length = 2, .mass = 1, .time = -2}));
  EXPECT_EQ(dim::kRotationalStiffness,
            (Dimension{.length = 2, .mass = 1, .time = -2, .angle = -1}));
  EXPECT_EQ(dim::kRotationalDamping, (Dimension{.length = 2, .mass = 1, .time = -1, .angle = -1}));
  EXPECT_EQ(dim::kStiffness, (Dimension{.mass = 1, .time = -2}));
  EXPECT_EQ(dim::kDamping, (Dimension{.mass = 1, .time = -1}));
  EXPECT_EQ(dim::kPressure, (Dimension{.length = -1, .mass = 1, .time = -2}));
  EXPECT_EQ(dim::kDensity, (Dimension{.length = -3, .mass = 1}));
  EXPECT_EQ(dim::kImpulse, (Dimension{.length = 1, .mass = 1, .time = -1}));
  EXPECT_EQ(dim::kFrequency, (Dimension{.time = -1}));
  EXPECT_EQ(dim::kAngularAcceleration, (Dimension{.time = -2, .angle = 1}));
  EXPECT_EQ(dim::kInertia, (Dimension{.length = 2, .mass = 1}));
  EXPECT_EQ(dim::kSpecificGasConstant, (Dimension{.length = 2, .time = -2, .temperature = -1}));
}

TEST(Dimension, AngleSeparatesTorqueFromRotationalStiffnessAndFrequencyFromAngularVelocity) {
  EXPECT_NE(dim::kTorque, dim::kRotationalStiffness);
  EXPECT_NE(dim::kFrequency, dim::kAngularVelocity);
  EXPECT_NE(dim::kAngle, dim::kDimensionless);
}

TEST(Dimension, OperatorsCombineExponents) {
  const Dimension velocity{.length = 1, .time = -1};
  EXPECT_EQ(velocity * velocity, (Dimension{.length = 2, .time = -2}));
  EXPECT_EQ(velocity / velocity, Dimension{});
  EXPECT_EQ(velocity.Pow(3), (Dimension{.length = 3, .time = -3}));
  EXPECT_EQ(velocity.Pow(-2), (Dimension{.length = -2, .time = 2}));
  EXPECT_EQ(velocity.Pow(0), Dimension{});
  EXPECT_TRUE(Dimension{}.IsDimensionless());
  EXPECT_FALSE(dim::kAngle.IsDimensionless());
}

TEST(Dimension, DescribesNamedDimensionsWithTheirSiUnit) {
  const std::vector<std::pair<Dimension, std::string>> expected = {
      {dim::kDimensionless, "dimensionless"},
      {dim::kLength, "length [m]"},
      {dim::kMass, "mass [kg]"},
      {dim::kTime, "time [s]"},
      {dim::kAngle, "angle [rad]"},
      {dim::kArea, "area [m^2]"},
      {dim::kVolume, "volume [m^3]"},
      {dim::kVelocity, "velocity [m/s]"},
      {dim::kAcceleration, "acceleration [m/s^2]"},
      {dim::kAngularVelocity, "angular velocity [rad/s]"},
      {dim::kAngularAcceleration, "angular acceleration [rad/s^2]"},
      {dim::kForce, "force [N]"},
      {dim::kTorque, "torque [N*m]"},
      {dim::kStiffness, "stiffness [N/m]"},
      {dim::kDamping, "damping [N*s/m]"},
      {dim::kRotationalStiffness, "rotational stiffness [N*m/rad]"},
      {dim::kRotationalDamping, "rotational damping [N*m*s/rad]"},
      {dim::kInertia, "inertia [kg*m^2]"},
      {dim::kPressure, "pressure [Pa]"},
      {dim::kFrequency, "frequency [Hz]"},
      {dim::kDensity, "density [kg/m^3]"},
      {dim::kImpulse, "impulse [N*s]"},
      {dim::kTemperature, "temperature [K]"},
      {dim::kSpecificGasConstant, "specific gas constant [J/kg/K]"},
  };
  for (const auto& [dimension, description] : expected) {
    EXPECT_EQ(DescribeDimension(dimension), description);
  }
}

TEST(Dimension, SharedDimensionsAreDescribedByTheCrashModelName) {
  EXPECT_EQ(DescribeDimension(dim::kEnergy), "torque [N*m]");
  EXPECT_EQ(DescribeDimension(dim::kMassFlow), "damping [N*s/m]");
}

TEST(Dimension, DescribesUnnamedCombinationsAsFormulas) {
  EXPECT_EQ(DescribeDimension({.length = 2, .mass = 1, .time = -1}),
            "mass*length^2/time [kg*m^2/s]");
  EXPECT_EQ(DescribeDimension({.length = -1}), "1/length [1/m]");
  EXPECT_EQ(DescribeDimension({.length = 1, .time = -1, .angle = -1}),
            "length/time/angle [m/s/rad]");
  EXPECT_EQ(DescribeDimension({.length = 4}), "length^4 [m^4]");
  EXPECT_EQ(DescribeDimension({.mass = -2, .time = 3}), "time^3/mass^2 [s^3/kg^2]");
}

TEST(Dimension, SiUnitSymbolIsEmptyWhenDimensionless) {
  EXPECT_EQ(SiUnitSymbol(dim::kDimensionless), "");
  EXPECT_EQ(SiUnitSymbol(dim::kRotationalStiffness), "N*m/rad");
}

TEST(Dimension, DescribesBothSidesOfAMismatch) {
  EXPECT_EQ(DescribeMismatch(dim::kLength, dim::kTime), "length [m] and time [s]");
}

TEST(Dimension, MismatchHelpPointsAtMissingUnitsAndAngles) {
  EXPECT_EQ(MismatchHelp(dim::kAngle, dim::kDimensionless),
            "the value has no unit; give it a unit of angle [rad]");
  EXPECT_EQ(MismatchHelp(dim::kDimensionless, dim::kLength),
            "write a plain number here, without a unit");
  EXPECT_EQ(MismatchHelp(dim::kRotationalStiffness, dim::kTorque),
            "the dimensions differ only by an angle; check for a missing or extra `deg` or `rad`");
  EXPECT_EQ(MismatchHelp(dim::kTorque, dim::kRotationalStiffness),
            "the dimensions differ only by an angle; check for a missing or extra `deg` or `rad`");
  EXPECT_EQ(MismatchHelp(dim::kMass, dim::kAcceleration),
            "`g` is standard gravity; write `gram` for grams");
  EXPECT_EQ(MismatchHelp(dim::kLength, dim::kTime), "");
  EXPECT_EQ(MismatchHelp(dim::kLength, dim::kLength), "");
}

// ---------------------------------------------------------------------------------------------
// The unit table

struct ExpectedUnit {
  std::string symbol;
  double value_in_si;
  Dimension dimension;
};

// Every unit of the table, with its SI value from its definition.
const std::vector<ExpectedUnit>& ExpectedUnits() {
  static const std::vector<ExpectedUnit> kExpected = {
      {"m", 1.0, dim::kLength},
      {"mm", 0.001, dim::kLength},
      {"cm", 0.01, dim::kLength},
      {"km", 1000.0, dim::kLength},
      {"in", kInchInMetres, dim::kLength},
      {"ft", kFootInMetres, dim::kLength},
      {"kg", 1.0, dim::kMass},
      {"gram", 0.001, dim::kMass},
      {"lb", kPoundInKilograms, dim::kMass},
      // A slug is the mass that one pound-force accelerates at one foot per second squared.
      {"slug", kPoundForceInNewtons / kFootInMetres, dim::kMass},
      {"tonne", 1000.0, dim::kMass},
      {"N", 1.0, dim::kForce},
      {"kN", 1000.0, dim::kForce},
      {"lbf", kPoundForceInNewtons, dim::kForce},
      {"s", 1.0, dim::kTime},
      {"ms", 0.001, dim::kTime},
      {"us", 0.000001, dim::kTime},
      {"min", 60.0, dim::kTime},
      {"h", 3600.0, dim::kTime},
      {"deg", kPi / 180.0, dim::kAngle},
      {"rad", 1.0, dim::kAngle},
      {"rev", 2.0 * kPi, dim::kAngle},
      {"g", kStandardGravity, dim::kAcceleration},
      {"Hz", 1.0, dim::kFrequency},
      {"Pa", 1.0, dim::kPressure},
      {"kPa", 1000.0, dim::kPressure},
      {"MPa", 1000000.0, dim::kPressure},
      {"psi", kPoundForceInNewtons / (kInchInMetres * kInchInMetres), dim::kPressure},
      {"bar", 100000.0, dim::kPressure},
      {"J", 1.0, dim::kEnergy},
      {"kJ", 1000.0, dim::kEnergy},
      {"L", 0.1 * 0.1 * 0.1, dim::kVolume},  // a cubic decimetre
      {"mph", kMileInMetres / 3600.0, dim::kVelocity},
      {"K", 1.0, dim::kTemperature},
  };
  return kExpected;
}

TEST(UnitTable, EveryUnitMatchesItsDefinition) {
  for (const ExpectedUnit& expected : ExpectedUnits()) {
    SCOPED_TRACE(expected.symbol);
    const UnitInfo* unit = FindUnit(expected.symbol);
    ASSERT_NE(unit, nullptr);
    EXPECT_EQ(unit->symbol, expected.symbol);
    EXPECT_DOUBLE_EQ(unit->scale_to_si, expected.value_in_si);
    EXPECT_EQ(unit->dimension, expected.dimension);
    EXPECT_FALSE(unit->description.empty());
  }
}

TEST(UnitTable, DefinedConstantsAreExact) {
  // The values the definitions fix to the last digit.
  EXPECT_EQ(FindUnit("in")->scale_to_si, 0.0254);
  EXPECT_EQ(FindUnit("ft")->scale_to_si, 0.3048);
  EXPECT_EQ(FindUnit("lb")->scale_to_si, 0.45359237);
  EXPECT_EQ(FindUnit("g")->scale_to_si, 9.80665);
  EXPECT_EQ(FindUnit("lbf")->scale_to_si, 4.4482216152605);
  EXPECT_EQ(FindUnit("mph")->scale_to_si, 0.44704);
  EXPECT_EQ(FindUnit("slug")->scale_to_si, 14.593902937206364);
  EXPECT_NEAR(FindUnit("psi")->scale_to_si, 6894.757293168361, 1e-11);
}

TEST(UnitTable, EveryUnitIsTestedAndSymbolsAreUnique) {
  std::set<std::string> table_symbols;
  for (const UnitInfo& unit : AllUnits()) {
    EXPECT_TRUE(table_symbols.insert(std::string(unit.symbol)).second) << unit.symbol;
  }
  std::set<std::string> tested_symbols;
  for (const ExpectedUnit& expected : ExpectedUnits()) tested_symbols.insert(expected.symbol);
  EXPECT_EQ(table_symbols, tested_symbols);
}

TEST(UnitTable, SymbolsAreCaseSensitive) {
  EXPECT_EQ(FindUnit("G"), nullptr);
  EXPECT_EQ(FindUnit("M"), nullptr);
  EXPECT_EQ(FindUnit("hz"), nullptr);
  EXPECT_EQ(FindUnit("g")->dimension, dim::kAcceleration);
  EXPECT_EQ(FindUnit("gram")->dimension, dim::kMass);
}

// ---------------------------------------------------------------------------------------------
// Resolving written units

TEST(ResolveUnit, KilometresPerHourToMetresPerSecond) {
  const ResolvedUnit unit = ResolveOrFail({{"km", 1}, {"h", -1}});
  EXPECT_EQ(unit.dimension, dim::kVelocity);
  EXPECT_DOUBLE_EQ(56.0 * unit.scale_to_si, 15.555555555555555);
  EXPECT_DOUBLE_EQ(56.0 * unit.scale_to_si, 56000.0 / 3600.0);
}

TEST(ResolveUnit, MilePerHourIsExact) {
  const ResolvedUnit unit = ResolveOrFail({{"mph", 1}});
  EXPECT_EQ(unit.scale_to_si, 0.44704);
  EXPECT_EQ(unit.dimension, dim::kVelocity);
  const ResolvedUnit miles_per_hour = ResolveOrFail({{"ft", 1}, {"h", -1}});
  EXPECT_DOUBLE_EQ(5280.0 * miles_per_hour.scale_to_si, 0.44704);
}

TEST(ResolveUnit, PoundForcePerPoundIsStandardGravity) {
  const ResolvedUnit unit = ResolveOrFail({{"lbf", 1}, {"lb", -1}});
  EXPECT_EQ(unit.dimension, dim::kAcceleration);
  EXPECT_DOUBLE_EQ(unit.scale_to_si, 9.80665);
}

TEST(ResolveUnit, StandardGravityIsMetresPerSecondSquared) {
  const ResolvedUnit g = ResolveOrFail({{"g", 1}});
  const ResolvedUnit si = ResolveOrFail({{"m", 1}, {"s", -2}});
  EXPECT_EQ(g.dimension, si.dimension);
  EXPECT_EQ(si.dimension, dim::kAcceleration);
  EXPECT_EQ(si.scale_to_si, 1.0);
  EXPECT_EQ(g.scale_to_si, 9.80665);
}

TEST(ResolveUnit, TorquePerDegreeIsRotationalStiffness) {
  const ResolvedUnit unit = ResolveOrFail({{"N", 1}, {"m", 1}, {"deg", -1}});
  EXPECT_EQ(unit.dimension, dim::kRotationalStiffness);
  EXPECT_DOUBLE_EQ(unit.scale_to_si, 180.0 / kPi);
  EXPECT_NEAR(2.5 * unit.scale_to_si, 143.2394487827058, 1e-12);
}

TEST(ResolveUnit, ComposedUnits) {
  EXPECT_EQ(ResolveOrFail({{"N", 1}, {"m", 1}}).dimension, dim::kTorque);
  EXPECT_EQ(ResolveOrFail({{"N", 1}, {"m", 1}, {"s", 1}, {"rad", -1}}).dimension,
            dim::kRotationalDamping);
  EXPECT_EQ(ResolveOrFail({{"kg", 1}, {"m", 2}}).dimension, dim::kInertia);
  EXPECT_EQ(ResolveOrFail({{"N", 1}, {"s", 1}, {"m", -1}}).dimension, dim::kDamping);
  EXPECT_EQ(ResolveOrFail({{"kg", 1}, {"m", -3}}).dimension, dim::kDensity);
  EXPECT_EQ(ResolveOrFail({{"kg", 1}, {"s", -1}}).dimension, dim::kMassFlow);
  EXPECT_EQ(ResolveOrFail({{"N", 1}, {"s", 1}}).dimension, dim::kImpulse);
  EXPECT_EQ(ResolveOrFail({{"rad", 1}, {"s", -2}}).dimension, dim::kAngularAcceleration);

  const ResolvedUnit stiffness = ResolveOrFail({{"kN", 1}, {"mm", -1}});
  EXPECT_EQ(stiffness.dimension, dim::kStiffness);
  EXPECT_DOUBLE_EQ(stiffness.scale_to_si, 1e6);

  const ResolvedUnit rpm = ResolveOrFail({{"rev", 1}, {"min", -1}});
  EXPECT_EQ(rpm.dimension, dim::kAngularVelocity);
  EXPECT_DOUBLE_EQ(rpm.scale_to_si, 2.0 * kPi / 60.0);

  const ResolvedUnit inertia = ResolveOrFail({{"kg", 1}, {"mm", 2}});
  EXPECT_DOUBLE_EQ(inertia.scale_to_si, 1e-6);
}

TEST(ResolveUnit, UnitsAgreeWithTheirDerivations) {
  // One slug at one foot per second squared is one pound-force.
  EXPECT_DOUBLE_EQ(ResolveOrFail({{"slug", 1}, {"ft", 1}, {"s", -2}}).scale_to_si,
                   ResolveOrFail({{"lbf", 1}}).scale_to_si);
  // A psi is a pound-force per square inch.
  const ResolvedUnit psi = ResolveOrFail({{"psi", 1}});
  const ResolvedUnit lbf_per_square_inch = ResolveOrFail({{"lbf", 1}, {"in", -2}});
  EXPECT_EQ(psi.dimension, lbf_per_square_inch.dimension);
  EXPECT_DOUBLE_EQ(psi.scale_to_si, lbf_per_square_inch.scale_to_si);
  // A litre is a thousand cubic centimetres; a joule is a newton metre; a hertz is one per second.
  EXPECT_DOUBLE_EQ(ResolveOrFail({{"L", 1}}).scale_to_si,
                   1000.0 * ResolveOrFail({{"cm", 3}}).scale_to_si);
  EXPECT_EQ(ResolveOrFail({{"kJ", 1}}).dimension, ResolveOrFail({{"N", 1}, {"m", 1}}).dimension);
  EXPECT_EQ(ResolveOrFail({{"Hz", 1}}).dimension, ResolveOrFail({{"s", -1}}).dimension);
  EXPECT_EQ(ResolveOrFail({{"MPa", 1}}).dimension, ResolveOrFail({{"N", 1}, {"mm", -2}}).dimension);
  EXPECT_DOUBLE_EQ(ResolveOrFail({{"MPa", 1}}).scale_to_si,
                   ResolveOrFail({{"N", 1}, {"mm", -2}}).scale_to_si);
  // A full revolution is 360 degrees.
  EXPECT_DOUBLE_EQ(ResolveOrFail({{"rev", 1}}).scale_to_si,
                   360.0 * ResolveOrFail({{"deg", 1}}).scale_to_si);
}

TEST(ResolveUnit, EmptyUnitIsDimensionless) {
  const ResolvedUnit unit = ResolveOrFail({});
  EXPECT_EQ(unit.scale_to_si, 1.0);
  EXPECT_EQ(unit.dimension, dim::kDimensionless);
}

TEST(ResolveUnit, UnknownUnitReportsE0301OnItsFactor) {
  DiagnosticCollector diagnostics;
  const lang::ast::Unit unit = MakeUnit({{"N", 1}, {"mx", 1}});
  EXPECT_FALSE(ResolveUnit(unit, diagnostics).has_value());
  ASSERT_EQ(diagnostics.diagnostics().size(), 1u);
  const lang::Diagnostic& diagnostic = diagnostics.diagnostics()[0];
  EXPECT_EQ(diagnostic.code(), "E0301");
  EXPECT_EQ(diagnostic.message, "unknown unit `mx`");
  ASSERT_NE(diagnostic.primary_range(), nullptr);
  EXPECT_EQ(*diagnostic.primary_range(), unit.factors[1].range);
  EXPECT_EQ(*diagnostic.primary_range(), (SourceRange{{1}, 102, 104}));
  EXPECT_EQ(diagnostic.help, "did you mean `m`?");
  EXPECT_EQ(diagnostics.error_count(), 1);
}

TEST(ResolveUnit, UnknownUnitSuggestsTheClosestSymbol) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"degs", "did you mean `deg`?"},
      {"kgs", "did you mean `kg`?"},
      {"slugs", "did you mean `slug`?"},
      {"kpa", "did you mean `kPa`?"},
      {"furlong", ""},
  };
  for (const auto& [written, help] : cases) {
    SCOPED_TRACE(written);
    DiagnosticCollector diagnostics;
    EXPECT_FALSE(ResolveUnit(MakeUnit({{written, 1}}), diagnostics).has_value());
    ASSERT_EQ(diagnostics.diagnostics().size(), 1u);
    EXPECT_EQ(diagnostics.diagnostics()[0].code(), "E0301");
    EXPECT_EQ(diagnostics.diagnostics()[0].help, help);
  }
}

TEST(ResolveUnit, CommonMistakesGetASpecificHint) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"kph", "write `km/h`"},
      {"kmh", "write `km/h`"},
      {"sec", "write `s` for seconds"},
      {"msec", "write `ms` for milliseconds"},
      {"grams", "write `gram` for grams; `g` is standard gravity"},
      {"gr", "write `gram` for grams; `g` is standard gravity"},
      {"G", "write `g` for standard gravity"},
      {"Nm", "write `N*m`"},
      {"lbs", "write `lb` for pound-mass or `lbf` for pound-force"},
      {"degree", "write `deg`"},
      {"degrees", "write `deg`"},
      {"rpm", "write `rev/min`"},
  };
  for (const auto& [written, help] : cases) {
    SCOPED_TRACE(written);
    DiagnosticCollector diagnostics;
    const lang::ast::Unit unit = MakeUnit({{written, -1}});
    EXPECT_FALSE(ResolveUnit(unit, diagnostics).has_value());
    ASSERT_EQ(diagnostics.diagnostics().size(), 1u);
    const lang::Diagnostic& diagnostic = diagnostics.diagnostics()[0];
    EXPECT_EQ(diagnostic.code(), "E0301");
    EXPECT_EQ(diagnostic.message, "unknown unit `" + written + "`");
    EXPECT_EQ(diagnostic.help, help);
    EXPECT_EQ(*diagnostic.primary_range(), unit.factors[0].range);
  }
}

TEST(ResolveUnit, ReportsEveryBadFactor) {
  DiagnosticCollector diagnostics;
  const lang::ast::Unit unit = MakeUnit({{"kph", 1}, {"m", 12}, {"sec", -1}});
  EXPECT_FALSE(ResolveUnit(unit, diagnostics).has_value());
  ASSERT_EQ(diagnostics.diagnostics().size(), 3u);
  EXPECT_EQ(diagnostics.diagnostics()[0].code(), "E0301");
  EXPECT_EQ(*diagnostics.diagnostics()[0].primary_range(), unit.factors[0].range);
  EXPECT_EQ(diagnostics.diagnostics()[1].code(), "E0305");
  EXPECT_EQ(*diagnostics.diagnostics()[1].primary_range(), unit.factors[1].range);
  EXPECT_EQ(diagnostics.diagnostics()[2].code(), "E0301");
  EXPECT_EQ(*diagnostics.diagnostics()[2].primary_range(), unit.factors[2].range);
}

TEST(ResolveUnit, ExponentsUpToNineAreAllowed) {
  const ResolvedUnit up = ResolveOrFail({{"m", 9}});
  EXPECT_EQ(up.dimension, dim::kLength.Pow(9));
  const ResolvedUnit down = ResolveOrFail({{"mm", -9}});
  EXPECT_EQ(down.dimension, dim::kLength.Pow(-9));
  EXPECT_DOUBLE_EQ(down.scale_to_si, 1e27);
}

TEST(ResolveUnit, ExponentsBeyondNineReportE0305) {
  for (int exponent : {10, -10, 1000000}) {
    SCOPED_TRACE(exponent);
    DiagnosticCollector diagnostics;
    const lang::ast::Unit unit = MakeUnit({{"kg", 1}, {"s", exponent}});
    EXPECT_FALSE(ResolveUnit(unit, diagnostics).has_value());
    ASSERT_EQ(diagnostics.diagnostics().size(), 1u);
    const lang::Diagnostic& diagnostic = diagnostics.diagnostics()[0];
    EXPECT_EQ(diagnostic.code(), "E0305");
    EXPECT_EQ(diagnostic.message,
              "exponent " + std::to_string(exponent) + " on unit `s` is out of range");
    EXPECT_EQ(*diagnostic.primary_range(), unit.factors[1].range);
  }
}

// ---------------------------------------------------------------------------------------------
// Quantities

TEST(Quantity, AddsAndSubtractsEqualDimensions) {
  const auto sum = Add({0.05, dim::kLength}, {0.02, dim::kLength});
  ASSERT_TRUE(sum.has_value());
  EXPECT_DOUBLE_EQ(sum->value, 0.07);
  EXPECT_EQ(sum->dimension, dim::kLength);
  const auto difference = Subtract({2.0, dim::kTime}, {0.5, dim::kTime});
  ASSERT_TRUE(difference.has_value());
  EXPECT_DOUBLE_EQ(difference->value, 1.5);
  EXPECT_EQ(difference->dimension, dim::kTime);
}

TEST(Quantity, AddingDifferentDimensionsFails) {
  EXPECT_FALSE(Add({1.0, dim::kLength}, {1.0, dim::kTime}).has_value());
  EXPECT_FALSE(Subtract({1.0, dim::kTorque}, {1.0, dim::kRotationalStiffness}).has_value());
  EXPECT_FALSE(Add({0.7, dim::kDimensionless}, {0.1, dim::kAngle}).has_value());
}

TEST(Quantity, MultipliesAndDividesDimensions) {
  const Quantity torque = Multiply({2000.0, dim::kForce}, {0.05, dim::kLength});
  EXPECT_DOUBLE_EQ(torque.value, 100.0);
  EXPECT_EQ(torque.dimension, dim::kTorque);

  const ArithmeticResult speed = Divide({1000.0, dim::kLength}, {100.0, dim::kTime});
  ASSERT_TRUE(speed.ok());
  EXPECT_DOUBLE_EQ(speed.quantity.value, 10.0);
  EXPECT_EQ(speed.quantity.dimension, dim::kVelocity);

  const Quantity negated = Negate({9.81, dim::kAcceleration});
  EXPECT_EQ(negated.value, -9.81);
  EXPECT_EQ(negated.dimension, dim::kAcceleration);
}

TEST(Quantity, DivisionByZeroIsReportedAsSuch) {
  const ArithmeticResult result = Divide({1.0, dim::kLength}, {0.0, dim::kTime});
  EXPECT_FALSE(result.ok());
  EXPECT_EQ(result.status, ArithmeticStatus::kDivisionByZero);
  EXPECT_EQ(Divide({0.0, dim::kLength}, {-0.0, dim::kLength}).status,
            ArithmeticStatus::kDivisionByZero);
  EXPECT_EQ(Power({0.0, dim::kLength}, {-1.0, dim::kDimensionless}).status,
            ArithmeticStatus::kDivisionByZero);
  EXPECT_EQ(Power({0.0, dim::kDimensionless}, {-0.5, dim::kDimensionless}).status,
            ArithmeticStatus::kDivisionByZero);
}

TEST(Quantity, PowerOfADimensionedBaseTakesSmallWholeExponents) {
  const ArithmeticResult area = Power({3.0, dim::kLength}, {2.0, dim::kDimensionless});
  ASSERT_TRUE(area.ok());
  EXPECT_DOUBLE_EQ(area.quantity.value, 9.0);
  EXPECT_EQ(area.quantity.dimension, dim::kArea);

  const ArithmeticResult inverse = Power({4.0, dim::kTime}, {-1.0, dim::kDimensionless});
  ASSERT_TRUE(inverse.ok());
  EXPECT_DOUBLE_EQ(inverse.quantity.value, 0.25);
  EXPECT_EQ(inverse.quantity.dimension, dim::kFrequency);

  const ArithmeticResult nine = Power({2.0, dim::kLength}, {-9.0, dim::kDimensionless});
  ASSERT_TRUE(nine.ok());
  EXPECT_DOUBLE_EQ(nine.quantity.value, 1.0 / 512.0);
  EXPECT_EQ(nine.quantity.dimension, dim::kLength.Pow(-9));
}

TEST(Quantity, InvalidExponentsAreRejected) {
  // A fractional power of a dimensioned base.
  EXPECT_EQ(Power({2.0, dim::kLength}, {0.5, dim::kDimensionless}).status,
            ArithmeticStatus::kInvalidExponent);
  // An exponent with a unit.
  EXPECT_EQ(Power({2.0, dim::kDimensionless}, {2.0, dim::kTime}).status,
            ArithmeticStatus::kInvalidExponent);
  // A whole exponent too large.
  EXPECT_EQ(Power({2.0, dim::kLength}, {10.0, dim::kDimensionless}).status,
            ArithmeticStatus::kInvalidExponent);
  // No real result.
  EXPECT_EQ(Power({-8.0, dim::kDimensionless}, {1.0 / 3.0, dim::kDimensionless}).status,
            ArithmeticStatus::kInvalidExponent);
  // Nested powers whose dimension exponents run away.
  EXPECT_EQ(Power({2.0, dim::kLength.Pow(81)}, {9.0, dim::kDimensionless}).status,
            ArithmeticStatus::kInvalidExponent);
  // Not a number.
  EXPECT_EQ(Power({2.0, dim::kLength}, {std::nan(""), dim::kDimensionless}).status,
            ArithmeticStatus::kInvalidExponent);
}

TEST(Quantity, DimensionlessBaseTakesRealExponents) {
  const ArithmeticResult root = Power({2.0, dim::kDimensionless}, {0.5, dim::kDimensionless});
  ASSERT_TRUE(root.ok());
  EXPECT_DOUBLE_EQ(root.quantity.value, std::sqrt(2.0));
  EXPECT_EQ(root.quantity.dimension, dim::kDimensionless);
  const ArithmeticResult large = Power({10.0, dim::kDimensionless}, {20.0, dim::kDimensionless});
  ASSERT_TRUE(large.ok());
  EXPECT_DOUBLE_EQ(large.quantity.value, 1e20);
}

TEST(Quantity, FormatsSiValueWithSiUnit) {
  EXPECT_EQ(FormatQuantity(0.05, dim::kLength), "0.05 m");
  EXPECT_EQ(FormatQuantity(2000.0, dim::kForce), "2000 N");
  EXPECT_EQ(FormatQuantity(0.7, dim::kDimensionless), "0.7");
  EXPECT_EQ(FormatQuantity(15.555555555555555, dim::kVelocity), "15.5556 m/s");
  EXPECT_EQ(FormatQuantity(2.5 * 180.0 / kPi, dim::kRotationalStiffness), "143.239 N*m/rad");
  EXPECT_EQ(FormatQuantity(1e-5, dim::kTime), "1e-05 s");
  EXPECT_EQ(FormatQuantity(3.0, {.length = 2, .mass = 1, .time = -1}), "3 kg*m^2/s");
}

}  // namespace
}  // namespace sled::compiler
