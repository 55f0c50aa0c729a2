#include "compiler/sweep/design.h"

#include <algorithm>
#include <charconv>
#include <cmath>

#include <fmt/format.h>

#include "compiler/sweep/design_csv.h"
#include "compiler/sweep/design_text.h"
#include "compiler/sweep/design_units.h"
#include "compiler/sweep/sampling.h"

namespace sled::compiler {
namespace {

// One `--vary`: a parameter with its grid values, or the range it is sampled in.
struct Factor {
  DesignVariable variable;
  bool sampled = false;
  std::vector<double> values;  // grid values; for a sampled range its two ends
  lang::SourceRange range;     // the values as written
};

// A grid value computed as low + k * step, written as the user would (0.3, not
// 0.30000000000000004) when twelve significant digits say the same within rounding.
double Tidy(double value, double scale) {
  const std::string text = fmt::format("{:.12g}", value);
  double tidy = value;
  std::from_chars(text.data(), text.data() + text.size(), tidy);
  return std::abs(tidy - value) <= 1e-12 * scale ? tidy : value;
}

// The unit the values of a spec are in: the last one written after a value, else the step's.
std::optional<lang::ast::Unit> SpecUnit(const VarySpec& spec) {
  for (auto it = spec.values.rbegin(); it != spec.values.rend(); ++it) {
    if (it->unit) return it->unit;
  }
  if (spec.step && spec.step->unit) return spec.step->unit;
  return std::nullopt;
}

std::optional<Factor> FactorOf(const lang::SourceManager& sources, const VarySpec& spec,
                               const ScenarioParameter& parameter,
                               lang::DiagnosticConsumer& diagnostics) {
  auto variable =
      VariableInUnit(sources, parameter, SpecUnit(spec), spec.values_range, diagnostics);
  if (!variable) return std::nullopt;
  Factor factor;
  factor.variable = std::move(*variable);
  factor.range = spec.values_range;
  std::vector<double> written;
  for (const WrittenQuantity& value : spec.values) {
    auto number = ValueInUnit(sources, value, factor.variable, parameter, diagnostics);
    if (!number) return std::nullopt;
    written.push_back(*number);
  }
  const std::string unit = factor.variable.unit.empty() ? "" : " " + factor.variable.unit;
  if (spec.kind == VarySpec::Kind::kList) {
    factor.values = std::move(written);
    return factor;
  }
  const double low = written[0];
  const double high = written[1];
  const std::string range_text(sources.Text(spec.values_range));
  if (!(low <= high)) {
    ReportDesign(
        diagnostics, lang::DiagnosticKind::kEmptyDesignRange, spec.values_range,
        fmt::format("the range of `{}` is empty: it starts at {}{} and ends below, at "
                    "{}{}",
                    spec.name, low, unit, high, unit),
        "ends before it starts",
        fmt::format("write the lower end first: `{}={}..{}{}`", spec.name, high, low, unit));
    return std::nullopt;
  }
  const double scale = std::max({std::abs(low), std::abs(high), 1e-300});
  if (spec.kind == VarySpec::Kind::kInterval) {
    if (low == high) {
      ReportDesign(diagnostics, lang::DiagnosticKind::kEmptyDesignRange, spec.values_range,
                   fmt::format("the range of `{}` holds one value, {}{}: there is nothing to "
                               "sample",
                               spec.name, low, unit),
                   "one value",
                   fmt::format("give two different ends, or fix the value with `--set "
                               "\"{}={}{}\"`",
                               spec.name, low, unit));
      return std::nullopt;
    }
    factor.sampled = true;
    factor.values = {low, high};
    return factor;
  }
  long long count = 0;
  if (spec.kind == VarySpec::Kind::kStep) {
    auto step = ValueInUnit(sources, *spec.step, factor.variable, parameter, diagnostics);
    if (!step) return std::nullopt;
    if (!(*step > 0)) {
      ReportDesign(
          diagnostics, lang::DiagnosticKind::kEmptyDesignRange, spec.step->range,
          fmt::format("the step of `{}` is {}{}; a step is positive", spec.name, *step, unit),
          "not positive", "write a positive step; the range goes from low to high");
      return std::nullopt;
    }
    const double steps = (high - low) / *step;
    if (steps > static_cast<double>(kMaxDesignPoints)) {
      ReportDesign(diagnostics, lang::DiagnosticKind::kInvalidDesign, spec.values_range,
                   fmt::format("`{}` would take {:.3g} values, more than a sweep's {}", spec.name,
                               steps + 1, kMaxDesignPoints),
                   "too many values", "take a larger step");
      return std::nullopt;
    }
    count = static_cast<long long>(std::floor(steps + 1e-9)) + 1;
    if (count < 2 && high > low) {
      ReportDesign(diagnostics, lang::DiagnosticKind::kEmptyDesignRange, spec.step->range,
                   fmt::format("the step {}{} is larger than the range {}: `{}` would take "
                               "one value, {}{}",
                               *step, unit, range_text, spec.name, low, unit),
                   "larger than the range",
                   "take a step no larger than the range, or list the values with commas");
      return std::nullopt;
    }
    for (long long k = 0; k < count; ++k) {
      const double value = low + static_cast<double>(k) * *step;
      factor.values.push_back(std::abs(value - high) <= 1e-9 * scale ? high : Tidy(value, scale));
    }
    return factor;
  }
  count = spec.count;
  if (count < 1 || (count == 1 && low != high) ||
      count > static_cast<long long>(kMaxDesignPoints)) {
    ReportDesign(diagnostics, lang::DiagnosticKind::kEmptyDesignRange, spec.count_range,
                 fmt::format("`count {}` cannot spread `{}` over {}", count, spec.name, range_text),
                 count < 1 ? "no values" : "too few or too many values",
                 fmt::format("a count is at least 2 for a range (the two ends) and at most {}",
                             kMaxDesignPoints));
    return std::nullopt;
  }
  for (long long k = 0; k < count; ++k) {
    const double value =
        count == 1 ? low
                   : low + (high - low) * static_cast<double>(k) / static_cast<double>(count - 1);
    factor.values.push_back(k == count - 1 ? high : Tidy(value, scale));
  }
  return factor;
}

}  // namespace

std::string Design::ValueText(std::size_t run, std::size_t variable) const {
  const std::string& unit = variables.at(variable).unit;
  return fmt::format("{}{}{}", points.at(run).at(variable), unit.empty() ? "" : " ", unit);
}

std::vector<std::pair<std::string, std::string>> Design::Overrides(std::size_t run) const {
  std::vector<std::pair<std::string, std::string>> overrides;
  for (std::size_t v = 0; v < variables.size(); ++v) {
    overrides.emplace_back(variables[v].name, ValueText(run, v));
  }
  return overrides;
}

std::optional<Design> BuildDesign(const lang::SourceManager& sources, const DesignRequest& request,
                                  const CheckedScenario& scene,
                                  lang::DiagnosticConsumer& diagnostics) {
  lang::ErrorTrackingConsumer tracked(diagnostics);
  Design design;
  design.seed = request.seed;
  std::vector<Factor> factors;
  std::vector<std::pair<std::string, lang::SourceRange>> seen;
  // A name already fixed by --set or varied by an earlier --vary: E0605.
  auto claim = [&](const std::string& name, lang::SourceRange range) {
    if (std::find(request.fixed.begin(), request.fixed.end(), name) != request.fixed.end()) {
      ReportDesign(tracked, lang::DiagnosticKind::kInvalidDesign, range,
                   fmt::format("`{}` is fixed by `--set` and varied by the design", name),
                   "also set with --set", "drop one: a parameter is either set or varied");
      return false;
    }
    for (const auto& [other, where] : seen) {
      if (other != name) continue;
      auto diagnostic =
          lang::MakeDiagnostic(lang::DiagnosticKind::kInvalidDesign, range,
                               fmt::format("`{}` is varied twice", name), "varied again here");
      diagnostic.labels.push_back({where, "first varied here", false});
      diagnostic.help = "give all of a parameter's values in one `--vary` or one column";
      tracked.Consume(std::move(diagnostic));
      return false;
    }
    seen.emplace_back(name, range);
    return true;
  };
  if (request.csv) {
    auto from_csv = ReadCsvDesign(sources, *request.csv, scene, tracked);
    if (!from_csv) return std::nullopt;
    for (std::size_t v = 0; v < from_csv->variables.size(); ++v) {
      if (!claim(from_csv->variables[v].name, from_csv->headers[v])) return std::nullopt;
    }
    design.method = "csv";
    design.variables = std::move(from_csv->variables);
    design.points = std::move(from_csv->points);
  }

  for (const lang::FileId file : request.vary) {
    auto spec = ParseVary(sources, file, tracked);
    if (!spec) continue;
    const ScenarioParameter* parameter =
        FindDesignParameter(scene, spec->name, spec->name_range, tracked);
    if (parameter == nullptr || !claim(spec->name, spec->name_range) ||
        !IsScalarParameter(*parameter, spec->name_range, tracked) || !parameter->valid) {
      continue;
    }
    if (auto factor = FactorOf(sources, *spec, *parameter, tracked)) {
      factors.push_back(std::move(*factor));
    }
  }
  if (tracked.seen_error()) return std::nullopt;

  std::vector<std::size_t> sampled;
  for (std::size_t f = 0; f < factors.size(); ++f) {
    if (factors[f].sampled) sampled.push_back(f);
  }
  if (!sampled.empty() && request.sampling == Sampling::kNone) {
    const Factor& first = factors[sampled[0]];
    ReportDesign(
        tracked, lang::DiagnosticKind::kInvalidDesign, first.range,
        fmt::format("the range of `{}` has no `step` or `count`, and no `--sample` draws points "
                    "in it",
                    first.variable.name),
        "a range to sample",
        "add `step S` or `count N` for a grid, or `--sample lhs=N` (or `sobol=N`) to sample it");
    return std::nullopt;
  }
  if (sampled.empty() && request.sampling != Sampling::kNone) {
    const lang::SourceRange where = factors.empty() ? lang::SourceRange{} : factors.front().range;
    ReportDesign(tracked, lang::DiagnosticKind::kInvalidDesign, where,
                 "`--sample` draws points in ranges written without `step` or `count`, "
                 "and the design has none",
                 "a grid", "write a range to sample as `NAME=LOW..HIGH UNIT`");
    return std::nullopt;
  }
  if (request.sampling == Sampling::kSobol &&
      sampled.size() > static_cast<std::size_t>(kMaxSobolDimensions)) {
    ReportDesign(tracked, lang::DiagnosticKind::kInvalidDesign, factors[sampled.back()].range,
                 fmt::format("Sobol sampling takes at most {} ranges; the design has {}",
                             kMaxSobolDimensions, sampled.size()),
                 "too many ranges", "use `--sample lhs=N`, which takes any number");
    return std::nullopt;
  }

  // The grid: every combination of the listed values, the first `--vary` varying slowest;
  // each combined with every sampled point.
  double size = design.points.empty() ? 1.0 : static_cast<double>(design.points.size());
  for (const Factor& factor : factors) {
    if (!factor.sampled) size *= static_cast<double>(factor.values.size());
  }
  if (request.sampling != Sampling::kNone) size *= request.samples;
  if (size > static_cast<double>(kMaxDesignPoints)) {
    ReportDesign(
        tracked, lang::DiagnosticKind::kInvalidDesign,
        factors.empty() ? lang::SourceRange{} : factors.back().range,
        fmt::format("the design has {:.4g} runs, more than a sweep's {}", size, kMaxDesignPoints),
        "too many runs", "take fewer values, or split the sweep in parts");
    return std::nullopt;
  }
  std::vector<std::vector<double>> unit_points;
  if (request.sampling == Sampling::kLatinHypercube) {
    unit_points = LatinHypercube(request.samples, static_cast<int>(sampled.size()), request.seed);
    design.method = design.method.empty() ? "lhs" : design.method + "+lhs";
  } else if (request.sampling == Sampling::kSobol) {
    unit_points = Sobol(request.samples, static_cast<int>(sampled.size()), request.seed);
    design.method = design.method.empty() ? "sobol" : design.method + "+sobol";
  }
  if (design.method.empty()) design.method = "grid";

  std::vector<std::vector<double>> points =
      design.points.empty() ? std::vector<std::vector<double>>{{}} : std::move(design.points);
  for (const Factor& factor : factors) {
    design.variables.push_back(factor.variable);
    if (factor.sampled) continue;
    std::vector<std::vector<double>> grown;
    for (const auto& point : points) {
      for (const double value : factor.values) {
        grown.push_back(point);
        grown.back().push_back(value);
      }
    }
    points = std::move(grown);
  }
  if (!unit_points.empty()) {
    // Sampled variables follow in their `--vary` order; their columns are put in place below.
    std::vector<std::vector<double>> grown;
    for (const auto& point : points) {
      for (const auto& u : unit_points) {
        grown.push_back(point);
        for (std::size_t s = 0; s < sampled.size(); ++s) {
          const Factor& factor = factors[sampled[s]];
          grown.back().push_back(factor.values[0] + u[s] * (factor.values[1] - factor.values[0]));
        }
      }
    }
    points = std::move(grown);
  }
  // Columns are grid factors then sampled ones; reorder to the variables' order.
  const std::size_t fixed_columns = design.variables.size() - factors.size();
  std::vector<std::size_t> column_of(factors.size());
  std::size_t next = fixed_columns;
  for (std::size_t f = 0; f < factors.size(); ++f) {
    if (!factors[f].sampled) column_of[f] = next++;
  }
  for (std::size_t f = 0; f < factors.size(); ++f) {
    if (factors[f].sampled) column_of[f] = next++;
  }
  design.points.clear();
  for (const auto& point : points) {
    std::vector<double> ordered(point.begin(), point.begin() + static_cast<long>(fixed_columns));
    for (std::size_t f = 0; f < factors.size(); ++f) ordered.push_back(point[column_of[f]]);
    design.points.push_back(std::move(ordered));
  }
  return design;
}

}  // namespace sled::compiler
