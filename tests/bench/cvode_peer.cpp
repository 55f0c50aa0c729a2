// The CVODE peer of the numerics suite (benchmark only, never a test): the right-hand side
// sled integrates (runtime::MultibodySystem as an OdeSystem) integrated by SUNDIALS CVODE (BDF,
// Newton with a dense difference-quotient Jacobian), beside sled's own integrators, on every
// case of examples/numerics/suite.txt. CVODE is driven as sled's AdaptiveIntegrator drives the
// system (runtime/integrate/adaptive_integrator.cpp), with CVODE's own facilities:
//
// - events: the system's event functions are CVODE's root functions (CVodeRootInit). At a root
//   CVODE returns the end of its final bracket, just past the root (as sled's EventLocator
//   does); every component that crossed goes to HandleEvent with its direction, the state is
//   projected and its histories committed, and CVODE restarts there (CVodeReInit), as sled
//   restarts its history after every event;
// - the projection after each step (unit quaternions, loop constraints) is CVODE's projection
//   (CVodeSetProjFn), which corrects its own history of the solution;
// - the load histories (contact hysteresis and impulse engagement, belt webbing and loading)
//   are committed after each accepted step, on that step's own state: CVODE runs one step at a
//   time (CV_ONE_STEP) and never interpolates a state that is committed;
// - CVODE lands exactly on each output time (CVodeSetStopTime), as sled's integrators do.
//
// Each run is measured as `sled study` measures it: its outputs at the scene's output times
// against a dopri5 reference at 1e-10, the largest deviation of a channel over the largest range
// of its kind (output/post/series_error.h).
//
//   sled_bench_cvode_peer [CASE...]     (default: every case of the suite)
//
// Prints one CSV row per run: case,method,tolerance,wall_seconds,steps,evaluations,events,
// error_all,failed. On standard error, per case: its events and histories, and each method's
// error at the tightest tolerance. scripts/numerics.sh runs it when it is built and adds its
// table to docs/numerics.md.
#include <cvode/cvode.h>
#include <cvode/cvode_proj.h>
#include <nvector/nvector_serial.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "output/post/injury_criteria.h"
#include "output/post/series_error.h"
#include "runtime/dynamics/dynamics.h"
#include "runtime/run/outputs.h"
#include "runtime/run/run.h"
#include "runtime/run/system.h"
#include "tests/verification/compile.h"
#include "tests/verification/numerics_suite.h"

namespace {

using sled::runtime::Model;
using sled::runtime::TimeSeries;

struct Outcome {
  TimeSeries series;
  double wall_seconds = 0.0;
  long steps = 0;
  long evaluations = 0;
  long events = 0;
  bool failed = false;
  std::string failure;  // when and why, for standard error
};

// What CVODE's callbacks reach through their user data.
struct Driver {
  sled::runtime::MultibodySystem* system = nullptr;
  std::vector<double> scratch;  // sized once: no allocation inside a step
};

std::span<double> Values(N_Vector v, std::size_t n) { return {N_VGetArrayPointer(v), n}; }

int RightHandSide(sunrealtype t, N_Vector y, N_Vector dy, void* user) {
  auto* system = static_cast<Driver*>(user)->system;
  const std::size_t n = system->size();
  const bool ok = system->Derivative(t, Values(y, n), Values(dy, n));
  return ok ? 0 : 1;  // a recoverable error: CVODE retries with a smaller step
}

int EventFunctions(sunrealtype t, N_Vector y, sunrealtype* g, void* user) {
  auto* system = static_cast<Driver*>(user)->system;
  system->Events(t, Values(y, system->size()), std::span<double>(g, system->EventCount()));
  return 0;
}

// CVODE's projection: the correction that takes ycur onto the quaternions' unit spheres and the
// loop constraints (what sled's Project does to y after each accepted step). The error estimate
// is left as it is (CVodeSetProjErrEst off), as sled's error test never sees the projection.
int Projection(sunrealtype t, N_Vector ycur, N_Vector corr, sunrealtype, N_Vector, void* user) {
  auto* driver = static_cast<Driver*>(user);
  const std::size_t n = driver->system->size();
  const std::span<double> y = Values(ycur, n);
  std::copy(y.begin(), y.end(), driver->scratch.begin());
  driver->system->ProjectState(t, driver->scratch);
  const std::span<double> correction = Values(corr, n);
  for (std::size_t i = 0; i < n; ++i) correction[i] = driver->scratch[i] - y[i];
  return 0;
}

// The counters CVODE keeps since its last (re)initialisation.
struct CvodeCounts {
  long steps = 0;
  long evaluations = 0;
};

CvodeCounts CountsOf(void* cvode) {
  long steps = 0, evaluations = 0, jacobian_evaluations = 0;
  CVodeGetNumSteps(cvode, &steps);
  CVodeGetNumRhsEvals(cvode, &evaluations);
  CVodeGetNumLinRhsEvals(cvode, &jacobian_evaluations);
  return {steps, evaluations + jacobian_evaluations};
}

// The scene integrated by CVODE BDF at the model's tolerances, sampled at the output times.
Outcome RunCvode(const Model& model) {
  Outcome outcome;
  sled::runtime::Data data = sled::runtime::MakeData(model);
  sled::runtime::MultibodySystem system(model, data);
  const std::size_t size = system.size();
  const auto n = static_cast<sunindextype>(size);
  const auto event_count = static_cast<int>(system.EventCount());
  Driver driver{&system, std::vector<double>(size)};
  std::vector<int> roots(system.EventCount());
  TimeSeries& series = outcome.series;
  series.names = sled::runtime::ChannelNames(model);
  series.columns = 1 + series.names.size();
  const std::size_t rows = sled::runtime::OutputRowCount(model);
  series.values.reserve(rows * series.columns);
  const double step =
      model.output_every > 0 ? model.output_every : model.end_time - model.start_time;
  auto append_row = [&] {
    const std::size_t start = series.values.size();
    series.values.resize(start + series.columns);
    series.values[start] = data.time;
    sled::runtime::EvaluateChannels(
        model, data, std::span<double>(series.values).subspan(start + 1, series.columns - 1));
  };

  SUNContext context = nullptr;
  SUNContext_Create(nullptr, &context);
  N_Vector y = N_VNew_Serial(n, context);
  N_Vector weights = N_VNew_Serial(n, context);
  const std::span<double> state = Values(y, size);
  system.Store(state);
  // The quadratures beyond ControlledSize feed nothing back; sled leaves them out of its error
  // control, and so does the peer (an absolute tolerance nothing reaches).
  for (std::size_t i = 0; i < size; ++i) {
    N_VGetArrayPointer(weights)[i] = i < system.ControlledSize() ? model.absolute_tolerance : 1e30;
  }
  void* cvode = CVodeCreate(CV_BDF, context);
  SUNMatrix matrix = SUNDenseMatrix(n, n, context);
  SUNLinearSolver solver = SUNLinSol_Dense(y, matrix, context);
  CVodeInit(cvode, RightHandSide, model.start_time, y);
  CVodeSVtolerances(cvode, model.relative_tolerance, weights);
  CVodeSetUserData(cvode, &driver);
  CVodeSetLinearSolver(cvode, solver, matrix);
  CVodeSetMaxNumSteps(cvode, 10'000'000);
  CVodeSetMinStep(cvode, model.min_step);
  if (model.max_step > 0) CVodeSetMaxStep(cvode, model.max_step);
  CVodeSetProjFn(cvode, Projection);
  CVodeSetProjErrEst(cvode, SUNFALSE);
  if (event_count > 0) {
    CVodeRootInit(cvode, event_count, EventFunctions);
    CVodeSetNoInactiveRootWarn(cvode);
  }

  const auto wall_start = std::chrono::steady_clock::now();
  CvodeCounts counted;  // over the runs between restarts, which reset CVODE's counters
  auto fail = [&](double t, const std::string& why) {
    outcome.failed = true;
    outcome.failure = fmt::format("failed at {:.6g} s: {}", t, why);
  };
  sled::runtime::Failure failure;
  system.Load(model.start_time, state);
  if (sled::runtime::Forward(model, data, &failure)) append_row();
  for (std::size_t row = 1; row < rows && !outcome.failed; ++row) {
    const double t_out =
        std::min(model.start_time + static_cast<double>(row) * step, model.end_time);
    CVodeSetStopTime(cvode, t_out);
    sunrealtype t = 0;
    for (;;) {
      const int status = CVode(cvode, t_out, y, &t, CV_ONE_STEP);
      if (status < 0) {
        fail(t, fmt::format("CVODE {}{}", CVodeGetReturnFlagName(status),
                            system.FailureReason().empty() ? "" : ": " + system.FailureReason()));
        break;
      }
      if (status == CV_ROOT_RETURN) {
        // As AdaptiveIntegrator after a located event: the crossing components' handlers, the
        // projection and commit of the state there, and a restart of the method's history.
        CVodeGetRootInfo(cvode, roots.data());
        for (std::size_t k = 0; k < roots.size(); ++k) {
          if (roots[k] == 0) continue;
          ++outcome.events;
          system.HandleEvent(k, roots[k], t, state);
        }
        system.Project(t, state);
        system.CommitStep(t, state);
        const CvodeCounts since = CountsOf(cvode);
        counted.steps += since.steps;
        counted.evaluations += since.evaluations;
        CVodeReInit(cvode, t, y);
        if (t_out - t <= 4 * std::numeric_limits<double>::epsilon() * std::abs(t_out)) break;
        CVodeSetStopTime(cvode, t_out);
        continue;
      }
      // An accepted step, already projected by CVODE: commit its histories on its own state.
      system.CommitStep(t, state);
      if (status == CV_TSTOP_RETURN) break;
    }
    if (outcome.failed) break;
    system.Load(t, state);
    if (!sled::runtime::Forward(model, data, &failure)) {
      fail(t, failure.cause);
      break;
    }
    append_row();
  }
  outcome.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  const CvodeCounts since = CountsOf(cvode);
  outcome.steps = counted.steps + since.steps;
  outcome.evaluations = counted.evaluations + since.evaluations;

  CVodeFree(&cvode);
  SUNLinSolFree(solver);
  SUNMatDestroy(matrix);
  N_VDestroy(weights);
  N_VDestroy(y);
  SUNContext_Free(&context);
  return outcome;
}

Outcome RunSled(const Model& model) {
  Outcome outcome;
  sled::runtime::Data data = sled::runtime::MakeData(model);
  const sled::runtime::RunSummary summary = sled::runtime::Run(model, data, outcome.series);
  outcome.wall_seconds = summary.wall_seconds;
  outcome.steps = summary.stats.steps;
  outcome.evaluations = summary.stats.evaluations;
  outcome.events = summary.stats.events;
  outcome.failed = summary.failed;
  if (summary.failed) {
    outcome.failure =
        fmt::format("failed at {:.6g} s: {}", summary.failure.time, summary.failure.cause);
  }
  return outcome;
}

// The model with a method and a relative tolerance; the absolute one keeps the scene's ratio.
Model WithTolerance(const Model& scene, const std::string& method, double tolerance) {
  Model model = scene;
  model.integrator = method;
  model.absolute_tolerance = scene.absolute_tolerance / scene.relative_tolerance * tolerance;
  model.relative_tolerance = tolerance;
  return model;
}

}  // namespace

// The comma-separated items of `text`.
std::vector<std::string> SplitList(const std::string& text) {
  std::vector<std::string> items;
  std::size_t at = 0;
  while (at < text.size()) {
    const std::size_t comma = std::min(text.find(',', at), text.size());
    items.push_back(text.substr(at, comma - at));
    at = comma + 1;
  }
  return items;
}

// `--tolerances=1e-2,1e-4` chooses the ladder, `--methods=auto,cvode` the methods (default all
// of sled's and CVODE); the other arguments are case names.
int main(int argc, char** argv) {
  std::set<std::string> wanted;
  std::vector<double> ladder = {1e-2, 1e-3, 1e-4, 1e-5, 1e-6};
  std::vector<std::string> methods = {"auto",       "exponential", "dopri5",
                                      "rosenbrock", "cvs",         "cvode"};
  const std::string ladder_option = "--tolerances=";
  const std::string methods_option = "--methods=";
  for (int i = 1; i < argc; ++i) {
    const std::string argument = argv[i];
    if (argument.rfind(methods_option, 0) == 0) {
      methods = SplitList(argument.substr(methods_option.size()));
      continue;
    }
    if (argument.rfind(ladder_option, 0) != 0) {
      wanted.insert(argument);
      continue;
    }
    ladder.clear();
    for (const std::string& item : SplitList(argument.substr(ladder_option.size()))) {
      ladder.push_back(std::stod(item));
    }
  }
  if (ladder.empty()) {
    std::cerr << "sled_bench_cvode_peer: --tolerances= needs a list such as 1e-2,1e-4\n";
    return 2;
  }
  std::cout << "case,method,tolerance,wall_seconds,steps,evaluations,events,error_all,failed\n";
  for (const sled::verification::SuiteCase& suite_case : sled::verification::LoadSuite()) {
    if (!wanted.empty() && !wanted.count(suite_case.name)) continue;
    const sled::verification::Compiled compiled =
        sled::verification::CompileFile(suite_case.file, suite_case.overrides);
    if (!compiled.errors.empty()) {
      std::cerr << suite_case.name << ": " << compiled.errors;
      continue;
    }
    const Model& scene = compiled.model();
    {
      sled::runtime::Data data = sled::runtime::MakeData(scene);
      const sled::runtime::MultibodySystem system(scene, data);
      std::cerr << fmt::format(
          "{}: {} event functions, {} contact pairs with a history, {} belts, {} loop "
          "constraints\n",
          suite_case.name, system.EventCount(),
          std::count(data.contacts.hysteresis.begin(), data.contacts.hysteresis.end(), 1),
          scene.belts.size(), scene.nconstraint());
    }
    const Outcome reference = RunSled(WithTolerance(scene, "dopri5", 1e-10));
    if (reference.failed) std::cerr << suite_case.name << ": the reference failed\n";
    const auto reference_criteria = sled::runtime::post::EvaluateCriteria(scene, reference.series);
    std::map<std::string, std::string> tightest;  // method -> its error at the tightest tolerance
    const double tightest_tolerance = *std::min_element(ladder.begin(), ladder.end());
    for (const double tolerance : ladder) {
      for (const std::string& method : methods) {
        const Model model = WithTolerance(scene, method, tolerance);
        // The fastest of three: a shared machine's noise only ever adds time.
        Outcome best;
        for (int repeat = 0; repeat < 3; ++repeat) {
          Outcome outcome = method == "cvode" ? RunCvode(model) : RunSled(model);
          if (repeat == 0 || outcome.wall_seconds < best.wall_seconds) best = std::move(outcome);
        }
        const auto criteria = sled::runtime::post::EvaluateCriteria(model, best.series);
        const sled::runtime::post::SeriesError error = sled::runtime::post::CompareSeries(
            model, best.series, criteria, reference.series, reference_criteria);
        std::cout << fmt::format("{},{},{},{},{},{},{},{},{}\n", suite_case.name, method, tolerance,
                                 best.wall_seconds, best.steps, best.evaluations, best.events,
                                 error.overall, best.failed ? 1 : 0)
                  << std::flush;
        if (best.failed) {
          std::cerr << fmt::format("{}: {} at {} {}\n", suite_case.name, method, tolerance,
                                   best.failure.empty() ? "failed" : best.failure);
        }
        if (tolerance == tightest_tolerance) {
          tightest[method] = fmt::format("{} {:.2e} ({} steps, {} events)", method, error.overall,
                                         best.steps, best.events);
        }
      }
    }
    std::cerr << suite_case.name << " at " << tightest_tolerance << " against the reference:";
    for (const auto& [method, text] : tightest) std::cerr << "  " << text;
    std::cerr << "\n";
  }
  return 0;
}
