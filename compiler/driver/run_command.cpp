#include "compiler/driver/run_command.h"

#include <cstdio>
#include <filesystem>
#include <iostream>

#include <fmt/format.h>

#include "compiler/check/check.h"
#include "compiler/lower/lower.h"
#include "lang/diagnostics/render.h"
#include "lang/syntax/parser.h"
#include "runtime/output_writer.h"
#include "runtime/post/channel_filters.h"
#include "runtime/post/injury_criteria.h"
#include "runtime/run.h"

namespace sled::driver {
namespace {

constexpr int kExitOk = 0;
constexpr int kExitInputErrors = 1;
constexpr int kExitNumericalFailure = 3;

void PrintDiagnostics(const lang::SourceManager& sources, lang::DiagnosticCollector& collector,
                      const RunCommandOptions& options) {
  collector.SortByPosition();
  for (const auto& diagnostic : collector.diagnostics()) {
    std::cerr << (options.compact_diagnostics
                      ? lang::RenderCompact(sources, diagnostic) + "\n"
                      : lang::RenderRich(sources, diagnostic, {options.color}) + "\n");
  }
}

void ShowProgress(double fraction, void* context) {
  (void)context;
  std::fprintf(stderr, "\r  simulating: %3d %%", static_cast<int>(fraction * 100 + 0.5));
  std::fflush(stderr);
}

// One line per criterion value: `  hic15(occupant.head) = 173.4 (limit 700, FMVSS 208): pass`.
void PrintCriteria(const std::vector<runtime::post::CriterionValue>& criteria) {
  for (const runtime::post::CriterionValue& c : criteria) {
    const std::string what =
        fmt::format("{}({}){}", c.name, c.target, c.variant.empty() ? "" : " " + c.variant);
    if (!c.computed) {
      std::cerr << fmt::format("  {}: not computed: {}\n", what, c.reason);
      continue;
    }
    std::cerr << fmt::format("  {} = {:.4g}{}{} (limit {:g}{}, {}): {}\n", what, c.value,
                             c.unit.empty() ? "" : " ", c.unit, c.limit,
                             c.unit.empty() ? "" : " " + c.unit, c.limit_source,
                             c.pass ? "pass" : "FAIL");
  }
}

}  // namespace

int RunCommand(const RunCommandOptions& options) {
  lang::SourceManager sources;
  lang::DiagnosticCollector collector;
  const auto file = sources.Load(options.file);
  if (!file) {
    std::cerr << fmt::format("sled: cannot read `{}`\n", options.file);
    return kExitInputErrors;
  }
  compiler::CheckOptions check_options;
  check_options.diagnostics = &collector;
  check_options.stdlib_root = options.stdlib;
  check_options.overrides = options.overrides;
  const compiler::CheckedScenario scenario = compiler::ParseAndCheck(sources, *file, check_options);
  PrintDiagnostics(sources, collector, options);
  if (collector.has_errors()) return kExitInputErrors;

  compiler::LowerOptions lower_options;
  lower_options.diagnostics = &collector;
  compiler::Lowered lowered = compiler::Lower(scenario, sources, lower_options);
  for (const std::string& note : lowered.notes) std::cerr << note << '\n';

  std::string directory = options.output_directory;
  if (directory.empty()) directory = std::filesystem::path(options.file).stem().string() + "-out";
  std::error_code error;
  std::filesystem::create_directories(directory, error);
  if (error) {
    std::cerr << fmt::format("sled: cannot create `{}`: {}\n", directory, error.message());
    return kExitInputErrors;
  }

  runtime::Data data = runtime::MakeData(lowered.model);
  runtime::TimeSeries series;
  runtime::RunOptions run_options;
  if (options.progress) run_options.progress = ShowProgress;
  runtime::RunSummary summary = runtime::Run(lowered.model, data, series, run_options);
  if (options.progress) std::fprintf(stderr, "\r%30s\r", "");
  // Name the scenario line of the segment or joint that failed.
  if (summary.failed) {
    const runtime::Model& model = lowered.model;
    for (std::size_t s = 0; s < model.nsegment(); ++s) {
      if (model.segment_name[s] == summary.failure.where) {
        summary.failure.source = model.segment_source[s];
      } else if (model.joint_name[s] == summary.failure.where) {
        summary.failure.source = model.joint_source[s];
      }
    }
  }

  // Filtered channels and injury criteria, from the rows there are (up to a failure).
  runtime::post::FilteredChannels filtered =
      runtime::post::FilterOutputChannels(lowered.model, series);
  const std::vector<runtime::post::CriterionValue> criteria =
      runtime::post::EvaluateCriteria(lowered.model, series);
  std::vector<std::string> warnings = lowered.notes;
  for (std::string& warning : filtered.warnings) {
    std::cerr << "sled: " << warning << '\n';
    warnings.push_back(std::move(warning));
  }

  std::string write_error;
  const std::filesystem::path out(directory);
  const bool written =
      runtime::WriteTimeSeriesCsv((out / "timeseries.csv").string(), series, &write_error) &&
      (filtered.series.names.empty() ||
       runtime::WriteTimeSeriesCsv((out / "timeseries_filtered.csv").string(), filtered.series,
                                   &write_error)) &&
      runtime::WriteSummaryJson((out / "summary.json").string(), lowered.model, series, summary,
                                warnings, &write_error, criteria);
  if (!written) {
    std::cerr << "sled: " << write_error << '\n';
    return kExitInputErrors;
  }
  PrintCriteria(criteria);
  if (summary.failed) {
    const runtime::Failure& f = summary.failure;
    std::cerr << fmt::format(
        "sled: the simulation failed at t = {:.6g} s{}: {}{}\n  outputs up to the failure are in "
        "`{}`\n",
        f.time, f.where.empty() ? "" : fmt::format(" in `{}`", f.where), f.cause,
        f.source.file.empty()
            ? ""
            : fmt::format(" ({}:{}:{})", f.source.file, f.source.line, f.source.column),
        directory);
    return kExitNumericalFailure;
  }
  std::cerr << fmt::format(
      "sled: {} rows to `{}` in {:.3f} s ({} steps, {} rejected, {} "
      "evaluations)\n",
      series.rows(), directory, summary.wall_seconds, summary.stats.steps, summary.stats.rejected,
      summary.stats.evaluations);
  const runtime::EnergySummary& energy = summary.energy;
  std::cerr << fmt::format(
      "sled: energy balance closes to {:.2g} % (largest residual {:.3g} J of {:.4g} J; at the "
      "end kinetic {:.4g} J, absorbed {:.4g} J, prescribed work {:.4g} J)\n",
      100 * energy.relative(), energy.largest_residual, energy.scale, energy.kinetic,
      energy.absorbed, energy.prescribed_work);
  return kExitOk;
}

}  // namespace sled::driver
