#include "compiler/driver/run_command.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <set>

#include <fmt/format.h>

#include "compiler/driver/driver_diagnostics.h"
#include "compiler/driver/interrupt_signals.h"
#include "compiler/driver/owned_folder.h"
#include "compiler/driver/progress_line.h"
#include "compiler/driver/report_command.h"
#include "output/checkpoint_file.h"
#include "output/post/criterion_value.h"
#include "runtime/run/checkpoint.h"
#include "sled/output_folder.h"
#include "sled/simulate.h"

namespace sled::driver {
namespace {

constexpr int kExitOk = 0;
constexpr int kExitInputErrors = 1;
constexpr int kExitUsage = 2;
constexpr int kExitNumericalFailure = 3;

// The ISO-MME test name: the scene file's stem with characters other than letters, digits, `-`
// and `_` replaced by `_`.
std::string TestName(const std::string& file) {
  std::string name = std::filesystem::path(file).stem().string();
  for (char& c : name) {
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_') c = '_';
  }
  return name.empty() ? "sled" : name;
}

// One line per criterion value: `  hic15(occupant.head) = 173.4 (limit 700, FMVSS 208): pass`;
// criteria of rows that do not cover the whole run say so instead of judging.
void PrintCriteria(const std::vector<runtime::post::CriterionValue>& criteria) {
  for (const runtime::post::CriterionValue& c : criteria) {
    const std::string what =
        fmt::format("{}({}){}", c.name, c.target, c.variant.empty() ? "" : " " + c.variant);
    if (!c.computed) {
      std::cerr << fmt::format("  {}: not computed: {}\n", what, c.reason);
      continue;
    }
    const std::string unit = c.unit.empty() ? "" : " " + c.unit;
    const std::string limit =
        c.has_limit ? fmt::format("limit {:g}{}, {}", c.limit, unit, c.limit_source) : "no limit";
    const std::string verdict =
        c.incomplete   ? fmt::format("incomplete: over {:.4g} ms to {:.4g} ms of the run only",
                                     c.seen_from * 1e3, c.seen_until * 1e3)
        : !c.has_limit ? std::string("-")
        : c.pass       ? std::string("pass")
                       : std::string("FAIL");
    std::cerr << fmt::format("  {} = {:.4g}{} ({}): {}\n", what, c.value, unit, limit, verdict);
  }
}

constexpr int kExitSignalBase = 128;  // + the signal's number, as shells report it

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

std::optional<Compilation> CompileScene(const RunCommandOptions& options) {
  CompileOptions compile_options;
  compile_options.stdlib = options.stdlib;
  compile_options.overrides = options.overrides;
  Compilation compiled = Compile(Source::File(options.file), compile_options);
  std::cerr << compiled.Render(
      options.compact_diagnostics ? lang::DiagnosticStyle::kCompact : lang::DiagnosticStyle::kRich,
      options.color);
  if (!compiled.ok()) return std::nullopt;
  return compiled;
}

int RunCommand(const RunCommandOptions& options) {
  std::optional<Compilation> compiled = CompileScene(options);
  if (!compiled) return kExitInputErrors;
  const compiler::CheckedScenario& scenario = compiled->scenario();
  const runtime::Model& model = compiled->model();
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
    if (const std::string why = CheckpointStepError(model, checkpoint_every); !why.empty()) {
      std::cerr << fmt::format("sled: `--checkpoint-every`: {}\n", why);
      return kExitUsage;
    }
  }
  runtime::Checkpoint checkpoint;
  if (!resume.empty()) {
    std::string why;
    if (output::ReadCheckpoint(resume, &checkpoint, &why)) {
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

  // The folder, before any time is spent simulating: writable, ours alone, and cleared of what
  // an earlier run left there (a checkpoint resumed from is kept).
  std::string directory = options.output_directory;
  if (directory.empty()) directory = std::filesystem::path(options.file).stem().string() + "-out";
  std::string folder_error;
  const std::unique_ptr<OwnedFolder> owned = OwnedFolder::Open(directory, &folder_error);
  if (!owned) {
    std::cerr << "sled: " << folder_error << '\n';
    return kExitInputErrors;
  }
  std::vector<std::filesystem::path> keep;
  if (!resume.empty()) keep.emplace_back(resume);
  const OwnedFolder::Cleared cleared = owned->RemoveEarlierOutputs(keep);
  if (!cleared.error.empty()) {
    std::cerr << fmt::format("sled: {}; the folder would mix two runs' outputs\n", cleared.error);
    return kExitInputErrors;
  }

  // SIGINT, SIGTERM and SIGHUP stop the run after its current row; what it has is written.
  const InterruptSignals signals;
  OutputFolderOptions folder_options;
  folder_options.directory = directory;
  folder_options.test_name = TestName(options.file);
  folder_options.iso_mme = options.iso_mme;
  folder_options.parallel_writes = options.threaded;
  folder_options.notes = compiled->Notes();
  folder_options.interrupted_by = [&signals] {
    return std::string(InterruptSignals::Name(signals.signal()));
  };
  OutputFolder folder(model, folder_options);
  SimulateOptions simulate_options;
  ProgressLine progress(options.progress);
  if (progress.enabled()) {
    simulate_options.progress = [&progress](double fraction) {
      ProgressLine::ShowRunFraction(fraction, &progress);
    };
  }
  simulate_options.stop_times = options.dump_times;
  simulate_options.checkpoint_every = checkpoint_every;
  simulate_options.checkpoint_directory = directory;
  simulate_options.stop = signals.stop();
  if (!resume.empty()) simulate_options.resume = &checkpoint;
  simulate_options.error_estimate = options.error_estimate;
  simulate_options.threaded = options.threaded;
  const RunResult result = Simulate(model, simulate_options, {&folder});
  const runtime::RunSummary& summary = result.summary;
  const int signal = summary.interrupted ? signals.signal() : 0;
  progress.Clear();
  for (const std::string& warning : result.warnings) std::cerr << "sled: " << warning << '\n';

  // Every file that could not be written, with its cause.
  std::vector<std::string> write_errors = folder.dump_errors();
  if (!summary.output_error.empty())
    write_errors.insert(write_errors.begin(), summary.output_error);
  for (const std::string& failed : result.sink_errors) {  // one line per file
    std::size_t start = 0;
    while (start <= failed.size()) {
      const std::size_t end = std::min(failed.find('\n', start), failed.size());
      write_errors.push_back(failed.substr(start, end - start));
      start = end + 1;
    }
  }
  if (folder.dumps_written().size() + folder.dump_errors().size() < options.dump_times.size()) {
    std::cerr << fmt::format(
        "sled: the run stopped at t = {:.6g} s, before some `--dump-at` times\n", summary.end_time);
  }
  // The page reads the files just written; a run that failed numerically has its page too.
  if (write_errors.empty() && options.report && ReportCommand(directory, "") != kExitOk) {
    return kExitInputErrors;
  }
  for (const std::string& failed : write_errors) std::cerr << "sled: " << failed << '\n';
  // What an earlier run left here and this one did not write again is gone: say so.
  std::set<std::string> written = folder.written();
  for (const std::string& path : folder.dumps_written()) {
    written.insert(std::filesystem::path(path).filename().string());
  }
  for (const std::string& path : summary.checkpoints) {
    written.insert(std::filesystem::path(path).filename().string());
  }
  if (options.report) written.insert("report.html");
  std::string stale;
  for (const std::string& name : cleared.removed) {
    if (!written.count(name)) stale += (stale.empty() ? "" : ", ") + name;
  }
  if (!stale.empty()) {
    std::cerr << fmt::format(
        "sled: removed what an earlier run wrote in `{}` and this one does "
        "not: {}\n",
        directory, stale);
  }

  // What happened, then the criteria.
  if (summary.failed) {
    std::cerr << fmt::format(
        "sled: the simulation failed {}\n  outputs up to the failure are in `{}`\n",
        DescribeFailure(model, summary.failure), directory);
  } else if (summary.interrupted) {
    std::cerr << fmt::format(
        "sled: interrupted by {} at t = {:.6g} s of {:.6g} s; the {} rows so far and summary.json "
        "(status \"interrupted\") are in `{}`\n",
        InterruptSignals::Name(signal), summary.end_time, model.end_time, result.series.rows(),
        directory);
  } else if (!summary.output_error.empty()) {
    std::cerr << fmt::format(
        "sled: the run stopped at t = {:.6g} s: an output could not be written\n",
        summary.end_time);
  } else if (!write_errors.empty()) {
    std::cerr << fmt::format(
        "sled: the run reached its end ({} rows), but {} of its outputs could not be written "
        "(above)\n",
        result.series.rows(), write_errors.size());
  } else {
    std::cerr << fmt::format(
        "sled: {} rows to `{}` in {:.3f} s ({} steps, {} rejected, {} evaluations, {} more for "
        "output rows)\n",
        result.series.rows(), directory, summary.wall_seconds, summary.stats.steps,
        summary.stats.rejected, summary.stats.evaluations, summary.output_evaluations);
  }
  if (summary.integrator == "auto") {
    const runtime::IntegratorStats& s = summary.stats;
    std::cerr << fmt::format(
        "sled: auto: dopri5 {:.4g} s of the run in {} steps ({:.3f} s), the exponential method "
        "{:.4g} s in {} steps ({:.3f} s); {} switch{}\n",
        s.explicit_share.simulated, s.explicit_share.steps, s.explicit_share.wall_seconds,
        s.exponential_share.simulated, s.exponential_share.steps, s.exponential_share.wall_seconds,
        s.switches, s.switches == 1 ? "" : "es");
  }
  if (summary.settle.converged) {
    std::cerr << fmt::format(
        "sled: settled in {:.4g} s ({} steps): centres of mass at most {:.3g} m/s, segments "
        "turning at most {:.3g} rad/s, forces changing by {:.3g} of the largest\n",
        summary.settle.time, summary.settle.steps, summary.settle.largest_velocity,
        summary.settle.largest_angular_velocity, summary.settle.largest_force_change);
  }
  if (!summary.checkpoints.empty()) {
    std::cerr << fmt::format("sled: {} checkpoint{}, the last `{}`\n", summary.checkpoints.size(),
                             summary.checkpoints.size() == 1 ? "" : "s",
                             summary.checkpoints.back());
  }
  if (summary.complete() && summary.error_estimate >= 0) {
    std::cerr << fmt::format(
        "sled: global error estimate {:.2g} of the channels' ranges (from a run at a tenth of the "
        "tolerances)\n",
        summary.error_estimate);
  }
  if (summary.complete()) {
    const runtime::EnergySummary& energy = summary.energy;
    std::cerr << fmt::format(
        "sled: energy balance closes to {:.2g} % (largest residual {:.3g} J of {:.4g} J; at the "
        "end kinetic {:.4g} J, absorbed {:.4g} J, prescribed work {:.4g} J{})\n",
        100 * energy.relative(), energy.largest_residual, energy.scale, energy.kinetic,
        energy.absorbed, energy.prescribed_work,
        model.loads.size() + model.fluids.size() > 0
            ? fmt::format(", applied work {:.4g} J", energy.applied_work)
            : "");
  }
  PrintCriteria(result.criteria);
  if (!write_errors.empty()) return kExitInputErrors;
  if (summary.failed) return kExitNumericalFailure;
  if (summary.interrupted) return kExitSignalBase + signal;
  return kExitOk;
}

}  // namespace sled::driver
