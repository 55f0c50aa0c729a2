#include "compiler/driver/sweep_command.h"

#include <charconv>
#include <filesystem>
#include <iostream>

#include <fmt/format.h>

#include "compiler/check/check.h"
#include "compiler/driver/command_help.h"
#include "compiler/driver/driver_diagnostics.h"
#include "compiler/driver/process_pool.h"
#include "compiler/driver/sweep_collect.h"
#include "compiler/driver/sweep_folder.h"
#include "compiler/driver/sweep_point_check.h"
#include "compiler/driver/sweep_runner.h"
#include "compiler/driver/sweep_slurm.h"
#include "compiler/sweep/design.h"
#include "lang/diagnostics/load_file.h"

namespace sled::driver {
namespace {

namespace fs = std::filesystem;

constexpr int kExitOk = 0;
constexpr int kExitInputErrors = 1;
constexpr int kExitUsage = 2;
constexpr int kExitInterrupted = 130;

struct SweepOptions {
  std::string subcommand;  // empty, "resume" or "collect"
  std::string target;      // the scene, or DIR
  std::vector<std::string> vary;
  std::string design_file;
  compiler::Sampling sampling = compiler::Sampling::kNone;
  int samples = 0;
  std::uint64_t seed = 1;
  std::string output_directory;
  int jobs = 0;
  std::vector<std::pair<std::string, std::string>> overrides;
  std::string stdlib;
  std::vector<std::string> passthrough;
  bool compact = false;
  bool check_only = false;
  bool restart = false;
  bool retry_failed = false;
  int slice = 0;
  int slices = 0;
  bool slurm = false;
  SlurmOptions slurm_options;
};

int Usage(const std::string& message) {
  std::cerr << fmt::format("sled: {}\nusage: {}\n`sled sweep --help` lists its options\n", message,
                           FindCommand("sweep")->synopsis);
  return kExitUsage;
}

bool ParsePositive(const std::string& text, int* value) {
  const auto [end, status] = std::from_chars(text.data(), text.data() + text.size(), *value);
  return status == std::errc() && end == text.data() + text.size() && *value > 0;
}

// Parses the words after `sled sweep`; an error message, or empty.
std::string ParseOptions(const std::vector<std::string>& args, SweepOptions& o) {
  std::vector<std::string> positional;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    auto value = [&](std::string* out) {
      if (i + 1 >= args.size()) return false;
      *out = args[++i];
      return true;
    };
    std::string v;
    if (arg == "--diagnostics=compact" || arg == "--diagnostics=rich") {
      o.compact = arg == "--diagnostics=compact";
    } else if (arg == "--check") {
      o.check_only = true;
    } else if (arg == "--restart") {
      o.restart = true;
    } else if (arg == "--retry-failed") {
      o.retry_failed = true;
    } else if (arg == "--slurm") {
      o.slurm = true;
    } else if (arg == "--wait") {
      o.slurm_options.wait = true;
    } else if (arg == "--report") {
      o.passthrough.push_back(arg);
    } else if (arg.size() > 1 && arg[0] == '-') {
      if (!TakesOption(*FindCommand("sweep"), arg)) {
        std::vector<std::string> known;
        for (const std::string_view option : FindCommand("sweep")->options) {
          known.emplace_back(option);
        }
        const std::string hint = lang::DidYouMean(arg, known);
        return fmt::format("unknown option `{}` for `sweep`{}", arg,
                           hint.empty() ? "" : "; " + hint);
      }
      if (!value(&v)) return fmt::format("`{}` needs a value", arg);
      if (arg == "--vary") {
        o.vary.push_back(v);
      } else if (arg == "--design") {
        o.design_file = v;
      } else if (arg == "--sample") {
        const std::size_t equals = v.find('=');
        const std::string method = v.substr(0, equals);
        if (equals == std::string::npos || (method != "lhs" && method != "sobol") ||
            !ParsePositive(v.substr(equals + 1), &o.samples)) {
          return fmt::format("`--sample {}`: write lhs=N or sobol=N with N a positive count", v);
        }
        o.sampling =
            method == "lhs" ? compiler::Sampling::kLatinHypercube : compiler::Sampling::kSobol;
      } else if (arg == "--seed") {
        const auto [end, status] = std::from_chars(v.data(), v.data() + v.size(), o.seed);
        if (status != std::errc() || end != v.data() + v.size()) {
          return fmt::format("`--seed {}`: write a whole number from 0", v);
        }
      } else if (arg == "-o" || arg == "--output") {
        o.output_directory = v;
      } else if (arg == "--jobs" || arg == "--tasks" || arg == "--cpus-per-task") {
        int* target = arg == "--jobs"    ? &o.jobs
                      : arg == "--tasks" ? &o.slurm_options.tasks
                                         : &o.slurm_options.cpus_per_task;
        if (!ParsePositive(v, target))
          return fmt::format("`{} {}`: write a positive count", arg, v);
      } else if (arg == "--set") {
        const std::size_t equals = v.find('=');
        if (equals == std::string::npos || equals == 0) {
          return fmt::format("`--set {}`: write NAME=VALUE", v);
        }
        o.overrides.emplace_back(v.substr(0, equals), v.substr(equals + 1));
      } else if (arg == "--stdlib") {
        o.stdlib = v;
      } else if (arg == "--format") {
        o.passthrough.insert(o.passthrough.end(), {arg, v});
      } else if (arg == "--slice") {
        const std::size_t slash = v.find('/');
        const std::string k = v.substr(0, std::min(slash, v.size()));
        const auto [end, status] = std::from_chars(k.data(), k.data() + k.size(), o.slice);
        if (slash == std::string::npos || status != std::errc() || end != k.data() + k.size() ||
            !ParsePositive(v.substr(slash + 1), &o.slices) || o.slice < 0 || o.slice >= o.slices) {
          return fmt::format("`--slice {}`: write K/T with 0 <= K < T", v);
        }
      } else if (arg == "--partition") {
        o.slurm_options.partition = v;
      } else if (arg == "--account") {
        o.slurm_options.account = v;
      } else if (arg == "--time") {
        o.slurm_options.time_limit = v;
      } else if (arg == "--sbatch") {
        o.slurm_options.sbatch_arguments.push_back(v);
      } else {
        return fmt::format("`{}` takes no value here", arg);
      }
    } else {
      positional.push_back(arg);
    }
  }
  if (!positional.empty() && (positional[0] == "resume" || positional[0] == "collect")) {
    o.subcommand = positional[0];
    positional.erase(positional.begin());
  }
  if (positional.size() != 1) {
    return o.subcommand.empty() ? "`sweep` takes one scenario file"
                                : fmt::format("`sweep {}` takes one sweep folder", o.subcommand);
  }
  o.target = positional[0];
  if (o.subcommand.empty()) {
    if (o.vary.empty() && o.design_file.empty()) {
      return "`sweep` needs a design: `--vary \"NAME=VALUES\"` or `--design POINTS.csv`";
    }
    if (o.sampling != compiler::Sampling::kNone && o.vary.empty()) {
      return "`--sample` draws points in `--vary` ranges, and there is none";
    }
    if (o.slices > 0) return "`--slice` belongs to `sled sweep resume DIR`";
  }
  return "";
}

// The scene checked once with the fixed overrides, the design built and the scene checked at
// every point over `workers` processes; the manifest of the sweep, or nullopt after printing why
// (with *interrupted set when a signal stopped the check).
std::optional<SweepManifest> PlanSweep(const SweepOptions& o, int workers, bool color,
                                       bool* interrupted) {
  lang::SourceManager sources;
  lang::DiagnosticCollector collector;
  const auto file = lang::LoadFileOrReport(sources, o.target, collector);
  if (!file) {
    PrintDiagnostics(sources, collector, o.compact, color);
    return std::nullopt;
  }
  compiler::CheckOptions check_options;
  check_options.diagnostics = &collector;
  check_options.stdlib_root = o.stdlib;
  check_options.overrides = o.overrides;
  const compiler::CheckedScenario scene = compiler::ParseAndCheck(sources, *file, check_options);
  SweepManifest manifest;
  manifest.scene = fs::absolute(o.target).lexically_normal().string();
  for (std::size_t id = 1; id <= sources.size(); ++id) {
    const std::string& path = sources.buffer(lang::FileId{static_cast<std::uint32_t>(id)}).path();
    std::error_code error;
    if (!fs::is_regular_file(path, error)) continue;
    const std::string absolute = fs::absolute(path).lexically_normal().string();
    manifest.files.push_back({absolute, FileDigest(path)});
  }
  compiler::DesignRequest request;
  for (const std::string& text : o.vary) request.vary.push_back(sources.Add("--vary", text));
  if (!o.design_file.empty()) {
    request.csv = lang::LoadFileOrReport(sources, o.design_file, collector);
    if (!request.csv) {
      PrintDiagnostics(sources, collector, o.compact, color);
      return std::nullopt;
    }
  }
  request.sampling = o.sampling;
  request.samples = o.samples;
  request.seed = o.seed;
  for (const auto& [name, value] : o.overrides) request.fixed.push_back(name);
  std::optional<compiler::Design> design;
  if (!collector.has_errors()) design = compiler::BuildDesign(sources, request, scene, collector);
  PrintDiagnostics(sources, collector, o.compact, color);
  if (collector.has_errors() || !design) return std::nullopt;

  manifest.method = design->method;
  manifest.seed = o.seed;
  manifest.vary = o.vary;
  if (!o.design_file.empty()) manifest.design_file = fs::absolute(o.design_file).string();
  for (const compiler::DesignVariable& variable : design->variables) {
    manifest.variables.push_back({variable.name, variable.unit});
  }
  if (!o.stdlib.empty()) {
    manifest.run_arguments.insert(manifest.run_arguments.end(),
                                  {"--stdlib", fs::absolute(o.stdlib).string()});
  }
  for (const auto& [name, value] : o.overrides) {
    manifest.run_arguments.insert(manifest.run_arguments.end(),
                                  {"--set", fmt::format("{}={}", name, value)});
  }
  manifest.run_arguments.insert(manifest.run_arguments.end(), o.passthrough.begin(),
                                o.passthrough.end());

  // Every point, checked as its run will check it, before any run starts.
  for (std::size_t run = 0; run < design->points.size(); ++run) {
    SweepRun entry;
    entry.folder = RunFolderName(run, design->points.size());
    entry.numbers = design->points[run];
    for (const auto& [name, value] : design->Overrides(run)) entry.values.push_back(value);
    manifest.runs.push_back(std::move(entry));
  }
  const PointCheckResult points =
      CheckDesignPoints(o.target, check_options, *design, workers, o.compact, color);
  if (points.interrupted) {
    std::cerr << "sled: interrupted while checking the design's points; nothing ran\n";
    *interrupted = true;
    return std::nullopt;
  }
  if (points.failing > 0) {
    std::string where;
    for (const auto& [name, value] : design->Overrides(points.first)) {
      where += fmt::format("{}{} = {}", where.empty() ? "" : ", ", name, value);
    }
    std::cerr << fmt::format("sled: the scene does not check at run {} of the design ({}):\n",
                             points.first, where);
    std::cerr << points.diagnostics;
    std::cerr << fmt::format(
        "sled: {} of {} runs of the design do not check; narrow the design to values the scene "
        "accepts\n",
        points.failing, design->points.size());
    return std::nullopt;
  }
  if (points.incomplete) {
    std::cerr << "sled: a worker checking the design's points ended without its answer; "
                 "nothing ran (run the command again, or with --jobs 1)\n";
    return std::nullopt;
  }
  return manifest;
}

void PrintDesign(const SweepManifest& manifest) {
  std::cout << "run";
  for (const SweepVariable& variable : manifest.variables) {
    std::cout << "," << variable.name << (variable.unit.empty() ? "" : " [" + variable.unit + "]");
  }
  std::cout << '\n';
  for (std::size_t r = 0; r < manifest.runs.size(); ++r) {
    std::cout << r;
    for (const double number : manifest.runs[r].numbers) std::cout << fmt::format(",{}", number);
    std::cout << '\n';
  }
}

// Makes the sweep folder, or finds the sweep to resume in it; false after saying why.
bool PrepareFolder(const std::string& directory, const SweepManifest& manifest, bool restart) {
  std::error_code error;
  const bool exists = fs::exists(directory, error);
  if (exists && !fs::is_directory(directory, error)) {
    std::cerr << fmt::format("sled: `{}` is a file, not a folder for the sweep\n", directory);
    return false;
  }
  const bool has_manifest = fs::exists(fs::path(directory) / kManifestName, error);
  if (exists && !has_manifest && !fs::is_empty(directory, error)) {
    std::cerr << fmt::format(
        "sled: `{}` holds files of something else; a sweep writes into a new or empty folder, "
        "or resumes the sweep recorded in one\n",
        directory);
    return false;
  }
  fs::create_directories(directory, error);
  std::string why;
  if (error || !LockSweepFolder(directory, &why)) {
    std::cerr << "sled: " << (why.empty() ? fmt::format("cannot create `{}`", directory) : why)
              << '\n';
    return false;
  }
  if (has_manifest) {
    const auto earlier = ReadManifest(directory, &why);
    if (earlier && earlier->SameSweep(manifest) && !restart) {
      std::cerr << fmt::format("sled: resuming the sweep in `{}`\n", directory);
      return true;
    }
    if (!restart) {
      std::cerr << fmt::format(
          "sled: `{}` holds {}; its runs would mix with this one's. Give another folder with "
          "-o, or --restart to discard them\n",
          directory,
          earlier ? "a sweep of another scene, scene version or design"
                  : "a sweep record that cannot be read (" + why + ")");
      return false;
    }
    fs::remove_all(fs::path(directory) / "runs", error);
    for (const char* name : {"sweep.csv", "sweep.html", kManifestName}) {
      fs::remove(fs::path(directory) / name, error);
    }
    fs::remove_all(fs::path(directory) / "slurm", error);
  }
  if (!WriteManifest(directory, manifest, &why)) {
    std::cerr << "sled: " << why << '\n';
    return false;
  }
  return true;
}

int Workers(const SweepOptions& o) { return o.jobs > 0 ? o.jobs : AvailableCores(); }

int RunAndCollect(const std::string& directory, const SweepManifest& manifest,
                  const SweepOptions& o) {
  RunnerOptions runner;
  runner.jobs = Workers(o);
  runner.slice = o.slice;
  runner.slices = o.slices;
  runner.retry_failed = o.retry_failed;
  std::cerr << fmt::format("sled: {} runs of `{}` on {} worker{}\n", manifest.runs.size(),
                           manifest.scene, runner.jobs, runner.jobs == 1 ? "" : "s");
  SweepCollector collector(directory, manifest);
  // A slice (a Slurm task) leaves the table to the job that collects.
  if (o.slices == 0) runner.on_run_done = [&](std::size_t run) { collector.Add(run); };
  const RunnerResult result = RunPending(directory, manifest, runner);
  if (o.slices > 0) return result.interrupted ? kExitInterrupted : kExitOk;
  const int collected = collector.Write();
  if (result.interrupted) {
    std::cerr << fmt::format(
        "sled: interrupted; the runs that finished are kept: run the same command again, or "
        "`sled sweep resume {}`, to run the rest\n",
        directory);
    return kExitInterrupted;
  }
  return collected;
}

int Resume(const SweepOptions& o) {
  std::string error;
  const auto manifest = ReadManifest(o.target, &error);
  if (!manifest) {
    std::cerr << "sled: " << error << '\n';
    return kExitInputErrors;
  }
  if (const std::string changed = ChangedFiles(*manifest); !changed.empty()) {
    std::cerr << fmt::format(
        "sled: {} changed since the sweep in `{}` was planned; its runs would mix two versions "
        "of the scene. Start the sweep again with --restart\n",
        changed, o.target);
    return kExitInputErrors;
  }
  // Slices of one sweep run side by side (a job array); only a whole resume takes the lock.
  if (o.slices == 0 && !LockSweepFolder(o.target, &error)) {
    std::cerr << "sled: " << error << '\n';
    return kExitInputErrors;
  }
  return RunAndCollect(o.target, *manifest, o);
}

}  // namespace

int SweepCommand(const std::vector<std::string>& args, bool color) {
  if (!args.empty() && (args[0] == "--help" || args[0] == "-h")) {
    std::cout << CommandHelpText(*FindCommand("sweep"));
    return kExitOk;
  }
  SweepOptions o;
  if (const std::string error = ParseOptions(args, o); !error.empty()) return Usage(error);
  if (o.subcommand == "collect") return CollectSweep(o.target);
  if (o.subcommand == "resume") return Resume(o);

  bool interrupted = false;
  const auto manifest = PlanSweep(o, Workers(o), color, &interrupted);
  if (!manifest) return interrupted ? kExitInterrupted : kExitInputErrors;
  if (o.check_only) {
    PrintDesign(*manifest);
    std::cerr << fmt::format("sled: the design has {} runs; the scene checks at every one\n",
                             manifest->runs.size());
    return kExitOk;
  }
  std::string directory = o.output_directory;
  if (directory.empty()) directory = fs::path(o.target).stem().string() + "-sweep";
  if (!PrepareFolder(directory, *manifest, o.restart)) return kExitInputErrors;
  if (o.slurm) return SubmitSweep(directory, *manifest, o.slurm_options);
  return RunAndCollect(directory, *manifest, o);
}

}  // namespace sled::driver
