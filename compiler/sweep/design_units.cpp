#include "compiler/sweep/design_units.h"

#include <fmt/format.h>

#include "compiler/units/quantity.h"
#include "compiler/units/unit_table.h"

namespace sled::compiler {
namespace {

// A few units of a dimension for a hint: "km/h, m/s or mph".
std::string UnitsOf(Dimension dimension) {
  const std::string si = SiUnitSymbol(dimension);
  std::vector<std::string_view> symbols = {si};
  for (const UnitInfo& unit : AllUnits()) {
    if (unit.dimension == dimension && symbols.size() < 4 && unit.symbol != si) {
      symbols.push_back(unit.symbol);
    }
  }
  std::string text;
  for (std::size_t i = 0; i < symbols.size(); ++i) {
    text += i == 0 ? "" : i + 1 == symbols.size() ? " or " : ", ";
    text += fmt::format("`{}`", symbols[i]);
  }
  return text;
}

// The parameter's dimension, or nullopt when it is a bare zero (which fits any dimension: the
// scene's own checks judge a value there).
std::optional<Dimension> DimensionOf(const ScenarioParameter& parameter) {
  if (parameter.bare && parameter.value.size() == 1 && parameter.value[0] == 0.0) {
    return std::nullopt;
  }
  return parameter.dimension;
}

void ReportUnitMismatch(lang::DiagnosticConsumer& diagnostics, lang::SourceRange range,
                        const ScenarioParameter& parameter, const std::string& found) {
  const Dimension expected = parameter.dimension;
  auto diagnostic = lang::MakeDiagnostic(
      lang::DiagnosticKind::kDesignUnitMismatch, range,
      fmt::format(
          "`{}` is {}, but {}", parameter.name,
          expected.IsDimensionless() ? "a plain number" : "a " + DescribeDimension(expected),
          found),
      expected.IsDimensionless() ? "no unit belongs here" : "not " + SiUnitSymbol(expected));
  const std::string units = UnitsOf(expected);
  diagnostic.help =
      expected.IsDimensionless()
          ? fmt::format(
                "the scenario declares `{}` without a unit: write the values as plain "
                "numbers",
                parameter.name)
          : fmt::format("the scenario declares `{} = {}`; write its values with a unit of {}{}",
                        parameter.name, FormatQuantity(parameter.value.at(0), expected),
                        DescribeDimension(expected), units.empty() ? "" : ", such as " + units);
  diagnostics.Consume(std::move(diagnostic));
}

}  // namespace

bool IsScalarParameter(const ScenarioParameter& parameter, lang::SourceRange range,
                       lang::DiagnosticConsumer& diagnostics) {
  if (parameter.value.size() == 1) return true;
  ReportDesign(diagnostics, lang::DiagnosticKind::kInvalidDesign, range,
               fmt::format("`{}` is a vector; a design varies numbers", parameter.name),
               "a vector parameter",
               fmt::format("declare a scalar `param` for the component that varies and "
                           "build the vector from it: `({}_x, 0, 0) mm`",
                           parameter.name));
  return false;
}

const ScenarioParameter* FindDesignParameter(const CheckedScenario& scene, const std::string& name,
                                             lang::SourceRange range,
                                             lang::DiagnosticConsumer& diagnostics) {
  std::vector<std::string> names;
  for (const ScenarioParameter& parameter : scene.parameters) {
    if (parameter.name == name) return &parameter;
    names.push_back(parameter.name);
  }
  auto diagnostic = lang::MakeDiagnostic(
      lang::DiagnosticKind::kUnknownDesignParameter, range,
      fmt::format("the design varies `{}`, which is no `param` of the scenario", name),
      "no such parameter");
  const std::string hint = lang::DidYouMean(name, names);
  diagnostic.help = !hint.empty() ? hint
                    : names.empty()
                        ? "the scenario declares no `param`: declare one (`param speed = 56 km/h`) "
                          "and use it where the value belongs"
                        : "a design varies the `param` declarations of the scenario itself";
  diagnostics.Consume(std::move(diagnostic));
  return nullptr;
}

std::optional<DesignVariable> VariableInUnit(const lang::SourceManager& sources,
                                             const ScenarioParameter& parameter,
                                             const std::optional<lang::ast::Unit>& unit,
                                             lang::SourceRange where,
                                             lang::DiagnosticConsumer& diagnostics) {
  DesignVariable variable;
  variable.name = parameter.name;
  if (unit) {
    const auto resolved = ResolveUnit(*unit, diagnostics);
    if (!resolved) return std::nullopt;
    variable.unit = std::string(sources.Text(unit->range));
    variable.scale_to_si = resolved->scale_to_si;
    variable.dimension = resolved->dimension;
  }
  const std::optional<Dimension> expected = DimensionOf(parameter);
  if (expected && *expected != variable.dimension) {
    ReportUnitMismatch(diagnostics, unit ? unit->range : where, parameter,
                       unit
                           ? fmt::format("`{}` is {}", variable.unit,
                                         variable.dimension.IsDimensionless()
                                             ? "dimensionless"
                                             : "a unit of " + DescribeDimension(variable.dimension))
                           : fmt::format("`{}` has no unit", sources.Text(where)));
    return std::nullopt;
  }
  return variable;
}

std::optional<double> ValueInUnit(const lang::SourceManager& sources, const WrittenQuantity& value,
                                  const DesignVariable& variable,
                                  const ScenarioParameter& parameter,
                                  lang::DiagnosticConsumer& diagnostics) {
  if (!value.unit || sources.Text(value.unit->range) == variable.unit) return value.number;
  const auto resolved = ResolveUnit(*value.unit, diagnostics);
  if (!resolved) return std::nullopt;
  if (resolved->dimension != variable.dimension) {
    const std::string written(sources.Text(value.unit->range));
    if (DimensionOf(parameter)) {
      ReportUnitMismatch(diagnostics, value.unit->range, parameter,
                         fmt::format("`{}` is {}", written,
                                     resolved->dimension.IsDimensionless()
                                         ? "dimensionless"
                                         : "a unit of " + DescribeDimension(resolved->dimension)));
    } else {
      // A bare-zero parameter takes any unit, but one design must use one dimension.
      auto diagnostic = lang::MakeDiagnostic(
          lang::DiagnosticKind::kDesignUnitMismatch, value.unit->range,
          fmt::format("`{}` is {}, but the other values of `{}` are in `{}`", written,
                      DescribeDimension(resolved->dimension), parameter.name, variable.unit),
          "another dimension");
      diagnostic.help = "give every value of one parameter in units of one dimension";
      diagnostics.Consume(std::move(diagnostic));
    }
    return std::nullopt;
  }
  // Through SI, so that `800 mm` among metres reads 0.8.
  return value.number * resolved->scale_to_si / variable.scale_to_si;
}

}  // namespace sled::compiler
