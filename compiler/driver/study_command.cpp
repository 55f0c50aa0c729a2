#include "compiler/driver/study_command.h"

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>

#include <fmt/format.h>

#include "compiler/driver/process_pool.h"
#include "compiler/driver/progress_line.h"
#include "output/output_writer.h"
#include "output/post/global_error.h"
#include "output/post/injury_criteria.h"
#include "output/post/series_error.h"
#include "output/report/svg_plot.h"
#include "output/run_record.h"
#include "runtime/integrate/ode.h"
#include "runtime/run/run.h"
#include "sled/simulate.h"

namespace sled::driver {
namespace {

constexpr int kExitOk = 0;
constexpr int kExitInputErrors = 1;
constexpr int kExitNumericalFailure = 3;
constexpr int kExitInterrupted = 130;

// How many times the reference may go a decade tighter than a hundredth of the ladder's end.
constexpr int kMaxReferenceRefinements = 2;

// One run of the scene with a method and a relative tolerance (the absolute tolerance keeps
// the scene's ratio to it).
struct Sample {
  std::string method;
  double tolerance = 0.0;
  double wall_seconds = 0.0;  // the fastest of the repeats
  runtime::RunSummary summary;
  runtime::TimeSeries series;
  std::vector<runtime::post::CriterionValue> criteria;
  runtime::post::SeriesError error;
  double estimate = -1.0;  // the global error estimate; -1: none
};

using runtime::post::SeriesError;

// The scene with another method and relative tolerance (the absolute tolerance keeps the
// scene's ratio to it).
runtime::Model ModelFor(const runtime::Model& scene, const std::string& method, double tolerance) {
  runtime::Model model = scene;
  model.integrator = method;
  model.absolute_tolerance = scene.absolute_tolerance / scene.relative_tolerance * tolerance;
  model.relative_tolerance = tolerance;
  return model;
}

// One run as the study measures it; `criteria` stays empty (Evaluate fills it).
Sample RunSample(const runtime::Model& scene, const std::string& method, double tolerance) {
  const runtime::Model model = ModelFor(scene, method, tolerance);
  Sample sample;
  sample.method = method;
  sample.tolerance = tolerance;
  // Short runs are repeated (up to three times, while under 0.2 s in all) and the fastest
  // counts: a shared machine's noise only ever adds time.
  double total = 0.0;
  for (int repeat = 0; repeat < 3 && (repeat == 0 || total < 0.2); ++repeat) {
    runtime::Data data = runtime::MakeData(model);
    runtime::TimeSeries series;
    runtime::RunSummary summary = runtime::Run(model, data, series);
    total += summary.wall_seconds;
    if (repeat == 0 || summary.wall_seconds < sample.wall_seconds) {
      sample.wall_seconds = summary.wall_seconds;
    }
    sample.summary = std::move(summary);
    sample.series = std::move(series);
  }
  return sample;
}

// Runs each (method, tolerance) as RunSample does, in worker processes, `jobs` at a time
// (process_pool.h): a forked child computes what this process would, bit for bit, and sends its
// summary and rows back (output/run_record.h); the criteria are evaluated here from the rows.
// kExitOk; kExitInterrupted when interrupted, kExitInputErrors after saying which worker ended
// without its result.
int RunSamples(const runtime::Model& scene,
               const std::vector<std::pair<std::string, double>>& wanted, int jobs,
               const std::function<void()>& on_done, std::vector<Sample>* samples) {
  std::vector<std::optional<std::string>> records;
  const bool finished = RunInWorkers(
      wanted.size(), jobs,
      [&](std::size_t i) {
        Sample sample = RunSample(scene, wanted[i].first, wanted[i].second);
        sample.summary.wall_seconds = sample.wall_seconds;  // the fastest of the repeats
        return runtime::SaveRunRecord(sample.summary, sample.series);
      },
      &records, [&](std::size_t) { on_done(); });
  if (!finished) return kExitInterrupted;
  samples->clear();
  for (std::size_t i = 0; i < wanted.size(); ++i) {
    Sample sample;
    sample.method = wanted[i].first;
    sample.tolerance = wanted[i].second;
    if (!records[i] ||
        !runtime::LoadRunRecord(std::move(*records[i]), &sample.summary, &sample.series)) {
      std::cerr << fmt::format("sled: the worker running {} at {:.0e} ended without a result\n",
                               sample.method, sample.tolerance);
      return kExitInputErrors;
    }
    sample.wall_seconds = sample.summary.wall_seconds;
    sample.criteria = runtime::post::EvaluateCriteria(
        ModelFor(scene, sample.method, sample.tolerance), sample.series);
    samples->push_back(std::move(sample));
  }
  return kExitOk;
}

void Compare(const runtime::Model& model, Sample& sample, const Sample& reference) {
  sample.error = runtime::post::CompareSeries(model, sample.series, sample.criteria,
                                              reference.series, reference.criteria);
}

// A measure for the table: `-` when the scene has nothing to measure, `<F` below the floor F
// (what the two references differ by: errors below it are not resolved).
std::string Measure(double value, double floor = -1.0) {
  if (value < 0 || std::isnan(value)) return "-";
  if (floor > 0 && value < floor) return fmt::format("<{:.1e}", floor);
  return fmt::format("{:.2e}", value);
}

std::string Row(const runtime::Model& model, const Sample& s, const SeriesError& floor) {
  return fmt::format(
      "{:<12} {:>8.0e} {:>9.4f} {:>7} {:>6} {:>9}  {:>9} {:>9} {:>9} {:>9}  {:>9}{}", s.method,
      s.tolerance, s.wall_seconds, s.summary.stats.steps, s.summary.stats.rejected,
      s.summary.stats.evaluations, Measure(s.error.overall, floor.overall),
      Measure(s.error.position, floor.position),
      Measure(s.error.peak_acceleration, floor.peak_acceleration),
      Measure(s.error.criteria, floor.criteria), Measure(s.estimate),
      s.summary.failed ? fmt::format("  failed {}", DescribeFailure(model, s.summary.failure))
                       : "");
}

// The floor row under the table: what the two references differ by, column by column.
std::string FloorRow(const SeriesError& floor) {
  return fmt::format("{:<56}  {:>9} {:>9} {:>9} {:>9}", "floor (the references differ by)",
                     Measure(floor.overall), Measure(floor.position),
                     Measure(floor.peak_acceleration), Measure(floor.criteria));
}

// Each run's global error estimate (output/post/global_error.h) from the run of the same
// method at a tenth of its tolerance, when the ladder holds one.
void EstimateFromLadder(const runtime::Model& model, std::vector<Sample>& samples) {
  for (Sample& s : samples) {
    for (const Sample& tighter : samples) {
      if (tighter.method != s.method ||
          std::abs(tighter.tolerance * runtime::post::kCompanionRatio / s.tolerance - 1) > 1e-9) {
        continue;
      }
      if (s.summary.failed || tighter.summary.failed) break;
      s.estimate = runtime::post::ErrorFromCompanion(model, s.series, s.criteria, tighter.series,
                                                     tighter.criteria);
    }
  }
}

// What the ladder says of the scene's own settings: the fastest run of any method whose error
// is no larger than theirs (below the reference's uncertainty counts as equal), that is the
// cheapest way the study found to the same accuracy. The integrator's own running sum of local
// error estimates is not used: it is in the state's units and bounds the error loosely (1e-1
// against a measured 2.5e-6 on the mass-ratio case).
std::string FastestAsAccurate(const std::vector<Sample>& samples, const Sample& own,
                              const SeriesError& floors) {
  const double floor = std::max(floors.overall, 0.0);
  if (own.summary.failed || !(own.error.overall >= 0)) {
    return "the scene's own settings did not finish, so there is no accuracy to match";
  }
  const double goal = std::max(own.error.overall, floor);
  const Sample* fastest = nullptr;
  for (const Sample& s : samples) {
    if (s.summary.failed || !(s.error.overall >= 0) || s.error.overall > goal) continue;
    if (fastest == nullptr || s.wall_seconds < fastest->wall_seconds) fastest = &s;
  }
  if (fastest == nullptr) {
    return "no run of the ladder was as accurate as the scene's own settings: add a tighter "
           "tolerance to --tolerances to see what that accuracy costs";
  }
  if (fastest->method == own.method && fastest->tolerance == own.tolerance) {
    return "no run of the ladder reached that accuracy faster than the scene's own settings";
  }
  return fmt::format(
      "the same accuracy, fastest in the ladder: {} at {:.0e}, error {} in {:.4f} s (the scene's "
      "own settings: {:.4f} s)",
      fastest->method, fastest->tolerance, Measure(fastest->error.overall, floors.overall),
      fastest->wall_seconds, own.wall_seconds);
}

// The work-precision plot: log10 of the error against log10 of the run time, one line per
// method.
std::string WorkPrecisionSvg(const std::vector<std::string>& methods,
                             const std::vector<Sample>& samples) {
  static const char* const kColors[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd"};
  report::PlotSpec spec;
  spec.title = "error against run time";
  spec.x_label = "log10 run time [s]";
  spec.y_label = "log10 error (of the channels' ranges)";
  for (std::size_t m = 0; m < methods.size(); ++m) {
    report::PlotSeries series;
    series.style.color = kColors[m % 4];
    for (const Sample& s : samples) {
      if (s.method != methods[m] || s.summary.failed || !(s.error.overall > 0)) continue;
      series.x.push_back(std::log10(std::max(s.wall_seconds, 1e-6)));
      series.y.push_back(std::log10(s.error.overall));
    }
    spec.legend.push_back({methods[m], series.style});
    spec.series.push_back(std::move(series));
  }
  return report::RenderSvgPlot(spec);
}

}  // namespace

bool ParseTolerances(const std::string& text, std::vector<double>* tolerances, std::string* error) {
  for (const std::string& item : SplitAtCommas(text)) {
    double value = 0.0;
    const auto [end, status] = std::from_chars(item.data(), item.data() + item.size(), value);
    if (item.empty() || status != std::errc() || end != item.data() + item.size() || !(value > 0) ||
        !(value < 1)) {
      *error = fmt::format(
          "`--tolerances {}`: `{}` is not a relative tolerance; write numbers between 0 and 1 "
          "separated by commas (1e-3,1e-5)",
          text, item);
      return false;
    }
    // The reference runs at a hundredth of the tightest tolerance; doubles must meet that.
    if (value / 100 < runtime::kMinRelativeTolerance) {
      *error = fmt::format(
          "`--tolerances {}`: {} is too tight: the reference would run at {:.1e}, tighter than "
          "doubles can meet ({:.1e}); the tightest tolerance is {:.1e}",
          text, item, value / 100, runtime::kMinRelativeTolerance,
          100 * runtime::kMinRelativeTolerance);
      return false;
    }
    tolerances->push_back(value);
  }
  std::sort(tolerances->begin(), tolerances->end(), std::greater<>());
  tolerances->erase(std::unique(tolerances->begin(), tolerances->end()), tolerances->end());
  return true;
}

int StudyCommand(const StudyOptions& options) {
  const std::optional<Compilation> compiled = CompileScene(options.scene);
  if (!compiled) return kExitInputErrors;
  const runtime::Model& scene = compiled->model();
  std::vector<double> ladder = options.tolerances;
  if (ladder.empty()) ladder = {1e-3, 1e-4, 1e-5, 1e-6, 1e-7};
  const std::vector<std::string> methods = {"auto", "exponential", "dopri5", "rosenbrock", "cvs"};

  // The reference, and a second method at the same tolerance to say how good it is.
  double tightest = ladder.back() / 100;
  // On a terminal, how many runs of the study have finished; nothing when piped.
  ProgressLine progress(options.scene.progress);
  std::size_t runs = 3 + methods.size() * ladder.size();
  std::size_t done = 0;
  auto count = [&] {
    progress.Show(fmt::format("  study: {} of {} runs done", ++done, runs), true);
  };
  const int jobs = options.jobs > 0 ? options.jobs : AvailableCores();
  progress.Show(fmt::format("  study: {} runs on {} worker{}", runs, jobs, jobs == 1 ? "" : "s"),
                true);
  std::vector<Sample> first;
  if (const int status =
          RunSamples(scene, {{"dopri5", tightest}, {"exponential", tightest}}, jobs, count, &first);
      status != kExitOk) {
    return status;
  }
  // Where the answer is sensitive (an Euler joint's angles near gimbal lock change 290 times
  // faster than the motion, and carry its error as much), two methods at a hundredth of the
  // ladder's end may still differ by more than the ladder's end: both go a decade tighter, up to
  // kMaxReferenceRefinements times while doubles can meet it, until they agree to it.
  for (int refinement = 0; refinement < kMaxReferenceRefinements &&
                           tightest / 10 >= 10 * runtime::kMinRelativeTolerance &&
                           !first[0].summary.failed && !first[1].summary.failed;
       ++refinement) {
    Sample check = first[1];
    Compare(scene, check, first[0]);
    if (check.error.overall <= ladder.back()) break;
    tightest /= 10;
    runs += 2;
    if (const int status = RunSamples(scene, {{"dopri5", tightest}, {"exponential", tightest}},
                                      jobs, count, &first);
        status != kExitOk) {
      return status;
    }
  }
  const Sample& reference = first[0];
  std::string directory = options.scene.output_directory;
  if (directory.empty()) {
    directory = std::filesystem::path(options.scene.file).stem().string() + "-study";
  }
  if (reference.summary.failed) {
    progress.Clear();
    // Nothing to measure against: a numerical failure of the scene itself. Its rows up to the
    // failure are kept for a look at what went wrong.
    std::cerr << fmt::format("sled: the reference run failed {}\n",
                             DescribeFailure(scene, reference.summary.failure));
    std::error_code code;
    std::filesystem::create_directories(directory, code);
    const std::string path = (std::filesystem::path(directory) / "reference.csv").string();
    std::string error;
    if (code || !runtime::WriteTimeSeriesCsv(path, reference.series, &error)) {
      std::cerr << fmt::format("sled: cannot write into `{}`\n", directory);
      return kExitInputErrors;
    }
    std::cerr << fmt::format("  its outputs up to the failure are in `{}`\n", path);
    return kExitNumericalFailure;
  }
  Sample check = first[1];
  Compare(scene, check, reference);
  // The floor under every column: what the two references differ by.
  const SeriesError floor = check.error;

  // The ladder, then the scene's own settings last.
  std::vector<std::pair<std::string, double>> wanted;
  for (const std::string& method : methods) {
    for (const double tolerance : ladder) wanted.emplace_back(method, tolerance);
  }
  wanted.emplace_back(scene.integrator, scene.relative_tolerance);
  std::vector<Sample> samples;
  if (const int status = RunSamples(scene, wanted, jobs, count, &samples); status != kExitOk) {
    return status;
  }
  progress.Clear();
  for (Sample& sample : samples) Compare(scene, sample, reference);
  Sample own = std::move(samples.back());
  samples.pop_back();
  EstimateFromLadder(scene, samples);

  std::cout << fmt::format("{:<12} {:>8} {:>9} {:>7} {:>6} {:>9}  {:>9} {:>9} {:>9} {:>9}  {:>9}\n",
                           "method", "tol", "time [s]", "steps", "rej", "evals", "all", "position",
                           "peak acc", "criteria", "estimate");
  for (const Sample& s : samples) std::cout << Row(scene, s, floor) << '\n';
  std::cout << FloorRow(floor) << '\n';
  std::cout << fmt::format(
      "\nerrors are relative: a channel's largest deviation from the reference over the largest "
      "range of its kind (all channels, positions), a peak's or a criterion's relative error; "
      "`<F`: below the floor F, not resolved; estimate: the run's global error estimate from "
      "the run of its method at a tenth of its tolerance\n"
      "reference: dopri5 at {:.0e} ({:.4f} s), checked by the exponential method at {:.0e} "
      "({:.4f} s)\n",
      tightest, reference.wall_seconds, tightest, check.wall_seconds);
  std::cout << fmt::format(
      "the scene's own settings ({} at {:.0e}): error {} of the channels' ranges, {} in the "
      "criteria, in {:.4f} s\n",
      own.method, own.tolerance, Measure(own.error.overall, floor.overall),
      Measure(own.error.criteria, floor.criteria), own.wall_seconds);
  std::cout << FastestAsAccurate(samples, own, floor) << '\n';

  // A reference that cannot be confirmed makes every figure above meaningless: said loudly, and
  // the study fails (after writing its files, for a look).
  std::string unconfirmed;
  if (check.summary.failed) {
    unconfirmed = fmt::format(
        "the reference's cross-check (the exponential method at {:.0e}) failed {}, so the "
        "reference is confirmed only up to there; the errors cannot be trusted",
        tightest, DescribeFailure(scene, check.summary.failure));
  } else if (!(floor.overall <= ladder.back())) {
    unconfirmed = fmt::format(
        "the reference has not converged: dopri5 and the exponential method at {:.0e} differ by "
        "{:.2e} of the channels' ranges, more than the ladder's tightest tolerance {:.0e}, so the "
        "errors of the tighter runs are not resolved: the answer is more sensitive than that "
        "tolerance resolves (chaotic motion, or something the error control does not see); "
        "tighten the ladder's end, or shorten the run",
        tightest, floor.overall, ladder.back());
  }

  std::error_code code;
  std::filesystem::create_directories(directory, code);
  std::ofstream csv(std::filesystem::path(directory) / "study.csv");
  csv << "method,tolerance,wall_seconds,steps,rejected,evaluations,error_all,error_position,"
         "error_peak_acceleration,error_criteria,failed,decaying_steps,error_estimate,floor_all,"
         "floor_position,floor_peak_acceleration,floor_criteria\n";
  for (const Sample& s : samples) {
    csv << fmt::format("{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}\n", s.method,
                       s.tolerance, s.wall_seconds, s.summary.stats.steps, s.summary.stats.rejected,
                       s.summary.stats.evaluations, s.error.overall, s.error.position,
                       s.error.peak_acceleration, s.error.criteria, s.summary.failed ? 1 : 0,
                       s.summary.stats.decaying_steps, s.estimate, floor.overall, floor.position,
                       floor.peak_acceleration, floor.criteria);
  }
  std::ofstream svg(std::filesystem::path(directory) / "study.svg");
  svg << WorkPrecisionSvg(methods, samples);
  if (!csv || !svg) {
    std::cerr << fmt::format("sled: cannot write into `{}`\n", directory);
    return kExitInputErrors;
  }
  std::cerr << fmt::format("sled: study.csv and study.svg in `{}`\n", directory);
  if (!unconfirmed.empty()) {
    std::cerr << fmt::format("sled: error: {}\n", unconfirmed);
    return kExitNumericalFailure;
  }
  return kExitOk;
}

}  // namespace sled::driver
