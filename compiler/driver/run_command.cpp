#include "compiler/driver/run_command.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include <fmt/format.h>

#include "compiler/check/check.h"
#include "compiler/driver/driver_diagnostics.h"
#include "compiler/driver/progress_line.h"
#include "compiler/driver/report_command.h"
#include "compiler/lower/lower.h"
#include "lang/syntax/parser.h"
#include "runtime/checkpoint.h"
#include "runtime/export/animation_glb.h"
#include "runtime/export/animation_recorder.h"
#include "runtime/export/iso_mme_writer.h"
#include "runtime/export/state_dump.h"
#include "runtime/output_writer.h"
#include "runtime/post/channel_filters.h"
#include "runtime/post/channel_peaks.h"
#include "runtime/post/injury_criteria.h"
#include "runtime/run.h"

namespace sled::driver {
namespace {

constexpr int kExitOk = 0;
constexpr int kExitInputErrors = 1;
constexpr int kExitUsage = 2;
constexpr int kExitNumericalFailure = 3;

// What `sled run` does where the run stops: records an animation frame at each output row and
// writes the state printout at each dump time.
class RunRecorder : public runtime::RunObserver {
 public:
  RunRecorder(runtime::AnimationRecorder& animation, std::filesystem::path directory)
      : animation_(animation), directory_(std::move(directory)) {}

  void OnRow(const runtime::Model& model, const runtime::Data& data) override {
    (void)model;
    animation_.Record(data);
  }
  void OnStop(const runtime::Model& model, const runtime::Data& data) override {
    const std::filesystem::path path = directory_ / runtime::StateDumpFileName(data.time);
    std::string error;
    if (runtime::WriteStateDump(path.string(), model, data, &error)) {
      written_.push_back(path.string());
    } else {
      errors_.push_back(error);
    }
  }
  const std::vector<std::string>& written() const { return written_; }
  const std::vector<std::string>& errors() const { return errors_; }

 private:
  runtime::AnimationRecorder& animation_;
  std::filesystem::path directory_;
  std::vector<std::string> written_;
  std::vector<std::string> errors_;
};

// The ISO-MME test name: the scene file's stem with characters other than letters, digits, `-`
// and `_` replaced by `_`.
std::string TestName(const std::string& file) {
  std::string name = std::filesystem::path(file).stem().string();
  for (char& c : name) {
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_') c = '_';
  }
  return name.empty() ? "sled" : name;
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

bool ParseFormats(const std::string& text, bool* iso_mme, std::string* error) {
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t comma = std::min(text.find(',', start), text.size());
    const std::string format = text.substr(start, comma - start);
    if (format == "iso-mme") {
      *iso_mme = true;
    } else if (format != "csv") {
      *error =
          fmt::format("`--format {}`: unknown format `{}`; write csv or iso-mme", text, format);
      return false;
    }
    start = comma + 1;
  }
  return true;
}

bool ParseTime(const std::string& text, double* seconds) {
  double value = 0.0;
  const auto [end, status] = std::from_chars(text.data(), text.data() + text.size(), value);
  const std::string unit(end, text.data() + text.size());
  const double scale = unit.empty() || unit == "s" ? 1.0 : unit == "ms" ? 1e-3 : 0.0;
  if (text.empty() || status != std::errc() || scale == 0.0 || !std::isfinite(value) || value < 0) {
    return false;
  }
  *seconds = value * scale;
  return true;
}

std::vector<std::string> SplitAtCommas(const std::string& text) {
  std::vector<std::string> items;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t comma = std::min(text.find(',', start), text.size());
    items.push_back(text.substr(start, comma - start));
    start = comma + 1;
  }
  return items;
}

bool ParseDumpTimes(const std::string& text, std::vector<double>* times, std::string* error) {
  for (const std::string& item : SplitAtCommas(text)) {
    double value = 0.0;
    if (!ParseTime(item, &value)) {
      *error = fmt::format(
          "`--dump-at {}`: `{}` is not a time; write times in seconds or with ms, separated by "
          "commas (0.05,80ms)",
          text, item);
      return false;
    }
    times->push_back(value);
  }
  std::sort(times->begin(), times->end());
  times->erase(std::unique(times->begin(), times->end()), times->end());
  return true;
}

std::optional<CompiledScene> CompileScene(const RunCommandOptions& options) {
  lang::SourceManager sources;
  lang::DiagnosticCollector collector;
  const auto file = LoadUserFile(sources, options.file, collector);
  if (!file) {
    PrintDiagnostics(sources, collector, options.compact_diagnostics, options.color);
    return std::nullopt;
  }
  compiler::CheckOptions check_options;
  check_options.diagnostics = &collector;
  check_options.stdlib_root = options.stdlib;
  check_options.overrides = options.overrides;
  CompiledScene compiled;
  compiled.scenario = compiler::ParseAndCheck(sources, *file, check_options);
  if (!compiled.scenario.has_scenario && !collector.has_errors()) {
    // A module for `import` checks clean but holds nothing to simulate.
    auto diagnostic = lang::MakeDiagnostic(
        lang::DiagnosticKind::kMissingAttribute, lang::SourceRange{*file, 0, 0},
        fmt::format("`{}` has no `scenario` to run", options.file), "no `scenario` block");
    diagnostic.help =
        "a file to run holds `scenario \"name\" { ... }`; a file without one is a module that "
        "scenarios `import`";
    collector.Consume(std::move(diagnostic));
  }
  PrintDiagnostics(sources, collector, options.compact_diagnostics, options.color);
  if (collector.has_errors()) return std::nullopt;

  compiler::LowerOptions lower_options;
  lower_options.diagnostics = &collector;
  compiled.lowered = compiler::Lower(compiled.scenario, sources, lower_options);
  for (const std::string& note : compiled.lowered.notes) std::cerr << note << '\n';
  return compiled;
}

void LocateFailure(const runtime::Model& model, runtime::Failure& failure) {
  if (failure.where.empty()) return;
  for (std::size_t s = 0; s < model.nsegment() && failure.source.file.empty(); ++s) {
    if (model.segment_name[s] == failure.where) {
      failure.source = model.segment_source[s];
    } else if (model.joint_name[s] == failure.where) {
      failure.source = model.joint_source[s];
    }
  }
  for (std::size_t c = 0; c < model.constraint_source.size() && failure.source.file.empty(); ++c) {
    if (model.constraint_name[c] == failure.where) failure.source = model.constraint_source[c];
  }
}

std::string DescribeFailure(const runtime::Model& model, runtime::Failure failure) {
  LocateFailure(model, failure);
  return fmt::format(
      "at t = {:.6g} s{}: {}{}", failure.time,
      failure.where.empty() ? "" : fmt::format(" in `{}`", failure.where), failure.cause,
      failure.source.file.empty() ? ""
                                  : fmt::format(" ({}:{}:{})", failure.source.file,
                                                failure.source.line, failure.source.column));
}

int RunCommand(const RunCommandOptions& options) {
  std::optional<CompiledScene> compiled = CompileScene(options);
  if (!compiled) return kExitInputErrors;
  const compiler::CheckedScenario& scenario = compiled->scenario;
  compiler::Lowered& lowered = compiled->lowered;
  const runtime::Model& model = lowered.model;
  for (const double t : options.dump_times) {
    if (t < model.start_time - 1e-12 || t > model.end_time + 1e-12) {
      std::cerr << fmt::format(
          "sled: `--dump-at`: {} s is outside the run, which goes from {} s to {} s\n", t,
          model.start_time, model.end_time);
      return kExitUsage;
    }
  }

  // The scene's `restart` block, unless the command line says otherwise; a relative checkpoint
  // file is found from the scene's folder.
  const double checkpoint_every = options.checkpoint_every > 0
                                      ? options.checkpoint_every
                                      : scenario.run.checkpoint_every.value_or(0.0);
  std::string resume = options.resume;
  if (resume.empty() && !scenario.run.resume_from.empty()) {
    const std::filesystem::path from(scenario.run.resume_from);
    resume = from.is_absolute()
                 ? from.string()
                 : (std::filesystem::path(options.file).parent_path() / from).string();
  }
  if (checkpoint_every > 0) {
    const double rows = checkpoint_every / model.output_every;
    if (!(model.output_every > 0) || std::llround(rows) < 1 ||
        std::abs(rows - static_cast<double>(std::llround(rows))) > 1e-9 * rows) {
      std::cerr << fmt::format(
          "sled: `--checkpoint-every`: {} s is not a multiple of the output step {} s; "
          "checkpoints are taken at output rows\n",
          checkpoint_every, model.output_every);
      return kExitUsage;
    }
  }
  runtime::Checkpoint checkpoint;
  if (!resume.empty()) {
    std::string why;
    if (runtime::ReadCheckpoint(resume, &checkpoint, &why)) {
      why = runtime::CheckpointMismatch(checkpoint, runtime::FingerprintOf(model));
    }
    if (why.empty() && !(checkpoint.time < model.end_time)) {
      why = fmt::format("it is at t = {} s, not before the scene's end time {} s", checkpoint.time,
                        model.end_time);
    }
    if (!why.empty()) {
      std::cerr << fmt::format("sled: cannot resume from `{}`: {}\n", resume, why);
      return kExitInputErrors;
    }
  }

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
  runtime::AnimationRecorder animation(model, runtime::OutputRowCount(model));
  RunRecorder recorder(animation, directory);
  runtime::RunOptions run_options;
  ProgressLine progress(options.progress);
  if (progress.enabled()) {
    run_options.progress = ProgressLine::ShowRunFraction;
    run_options.progress_context = &progress;
  }
  run_options.observer = &recorder;
  run_options.stop_times = options.dump_times;
  run_options.checkpoint_every = checkpoint_every;
  run_options.checkpoint_directory = directory;
  if (!resume.empty()) run_options.resume = &checkpoint;
  runtime::RunSummary summary = runtime::Run(lowered.model, data, series, run_options);
  progress.Clear();
  if (summary.failed) LocateFailure(model, summary.failure);

  // Filtered channels and injury criteria, from the rows there are (up to a failure).
  runtime::post::FilteredChannels filtered =
      runtime::post::FilterOutputChannels(lowered.model, series);
  const std::vector<runtime::post::CriterionValue> criteria =
      runtime::post::EvaluateCriteria(lowered.model, series);
  std::vector<std::string> warnings = lowered.notes;
  for (const std::string& note : summary.notes) {
    std::cerr << "sled: " << note << '\n';
    warnings.push_back(note);
  }
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
                                warnings, &write_error, criteria,
                                runtime::post::ChannelPeaks(series, filtered.series)) &&
      runtime::WriteAnimationGlb((out / "animation.glb").string(), model, animation,
                                 &write_error) &&
      (!options.iso_mme ||
       runtime::WriteIsoMme((out / "iso-mme").string(), TestName(options.file), model, series,
                            filtered.series, criteria, &write_error));
  for (const std::string& failed : recorder.errors()) std::cerr << "sled: " << failed << '\n';
  if (recorder.written().size() + recorder.errors().size() < options.dump_times.size()) {
    std::cerr << fmt::format(
        "sled: the run stopped at t = {:.6g} s, before some `--dump-at` times\n", summary.end_time);
  }
  if (!written || !recorder.errors().empty()) {
    if (!written) std::cerr << "sled: " << write_error << '\n';
    return kExitInputErrors;
  }
  // The page reads the files just written; a run that failed numerically has its page too.
  if (options.report && ReportCommand(directory, "") != kExitOk) return kExitInputErrors;
  PrintCriteria(criteria);
  if (summary.failed) {
    std::cerr << fmt::format(
        "sled: the simulation failed {}\n  outputs up to the failure are in `{}`\n",
        DescribeFailure(model, summary.failure), directory);
    return kExitNumericalFailure;
  }
  std::cerr << fmt::format(
      "sled: {} rows to `{}` in {:.3f} s ({} steps, {} rejected, {} "
      "evaluations)\n",
      series.rows(), directory, summary.wall_seconds, summary.stats.steps, summary.stats.rejected,
      summary.stats.evaluations);
  if (!summary.checkpoints.empty()) {
    std::cerr << fmt::format("sled: {} checkpoint{}, the last `{}`\n", summary.checkpoints.size(),
                             summary.checkpoints.size() == 1 ? "" : "s",
                             summary.checkpoints.back());
  }
  const runtime::EnergySummary& energy = summary.energy;
  std::cerr << fmt::format(
      "sled: energy balance closes to {:.2g} % (largest residual {:.3g} J of {:.4g} J; at the "
      "end kinetic {:.4g} J, absorbed {:.4g} J, prescribed work {:.4g} J)\n",
      100 * energy.relative(), energy.largest_residual, energy.scale, energy.kinetic,
      energy.absorbed, energy.prescribed_work);
  return kExitOk;
}

}  // namespace sled::driver
