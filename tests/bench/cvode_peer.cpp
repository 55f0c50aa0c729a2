// The CVODE peer of the numerics suite (benchmark only, never a test): the right-hand side
// sled integrates (runtime::MultibodySystem as an OdeSystem) integrated by SUNDIALS CVODE (BDF,
// Newton with a dense difference-quotient Jacobian), beside sled's own integrators, on stiff
// cases of examples/numerics/suite.txt. Each run is measured as `sled study` measures it: its
// outputs at the scene's output times against a dopri5 reference at 1e-10, the largest
// deviation of a channel over the largest range of its kind (runtime/post/series_error.h).
//
//   sled_bench_cvode_peer [CASE...]     (default: the cases without events or load histories)
//
// Prints one CSV row per run: case,method,tolerance,wall_seconds,steps,evaluations,error_all,
// failed. scripts/numerics.sh runs it when it is built and adds its table to docs/numerics.md.
#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <set>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "runtime/dynamics.h"
#include "runtime/outputs.h"
#include "runtime/post/injury_criteria.h"
#include "runtime/post/series_error.h"
#include "runtime/run.h"
#include "runtime/system.h"
#include "tests/verification/compile.h"
#include "tests/verification/numerics_suite.h"

namespace {

using sled::runtime::Model;
using sled::runtime::TimeSeries;

// Cases without events or load histories: CVODE locates no events and never calls
// MultibodySystem::Project, which commits load histories after a step (and renormalises
// quaternions: under CVODE their drift stays within the tolerance, and shows in the error).
const std::vector<std::string> kDefaultCases = {"contact_1e5", "contact_1e6",   "contact_1e7",
                                                "contact_1e8", "contact_1e9",   "pulse_100g",
                                                "mass_ratio",  "inertia_ratio", "pendulum_chain"};

struct Outcome {
  TimeSeries series;
  double wall_seconds = 0.0;
  long steps = 0;
  long evaluations = 0;
  bool failed = false;
};

int RightHandSide(sunrealtype t, N_Vector y, N_Vector dy, void* user) {
  auto* system = static_cast<sled::runtime::MultibodySystem*>(user);
  const std::size_t n = system->size();
  const bool ok = system->Derivative(t, std::span<const double>(N_VGetArrayPointer(y), n),
                                     std::span<double>(N_VGetArrayPointer(dy), n));
  return ok ? 0 : 1;  // a recoverable error: CVODE retries with a smaller step
}

// The scene integrated by CVODE BDF at the model's tolerances, sampled at the output times.
Outcome RunCvode(const Model& model) {
  Outcome outcome;
  sled::runtime::Data data = sled::runtime::MakeData(model);
  sled::runtime::MultibodySystem system(model, data);
  const auto n = static_cast<sunindextype>(system.size());
  TimeSeries& series = outcome.series;
  series.names = sled::runtime::ChannelNames(model);
  series.columns = 1 + series.names.size();
  const std::size_t rows = sled::runtime::OutputRowCount(model);
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
  system.Store(std::span<double>(N_VGetArrayPointer(y), system.size()));
  // The quadratures beyond ControlledSize feed nothing back; sled leaves them out of its error
  // control, and so does the peer (an absolute tolerance nothing reaches).
  for (sunindextype i = 0; i < n; ++i) {
    N_VGetArrayPointer(weights)[i] =
        static_cast<std::size_t>(i) < system.ControlledSize() ? model.absolute_tolerance : 1e30;
  }
  void* cvode = CVodeCreate(CV_BDF, context);
  SUNMatrix matrix = SUNDenseMatrix(n, n, context);
  SUNLinearSolver solver = SUNLinSol_Dense(y, matrix, context);
  CVodeInit(cvode, RightHandSide, model.start_time, y);
  CVodeSVtolerances(cvode, model.relative_tolerance, weights);
  CVodeSetUserData(cvode, &system);
  CVodeSetLinearSolver(cvode, solver, matrix);
  CVodeSetMaxNumSteps(cvode, 10'000'000);
  CVodeSetMinStep(cvode, model.min_step);
  if (model.max_step > 0) CVodeSetMaxStep(cvode, model.max_step);

  const auto wall_start = std::chrono::steady_clock::now();
  sled::runtime::Failure failure;
  system.Load(model.start_time, std::span<const double>(N_VGetArrayPointer(y), system.size()));
  if (sled::runtime::Forward(model, data, &failure)) append_row();
  for (std::size_t row = 1; row < rows && !outcome.failed; ++row) {
    const double t_out =
        std::min(model.start_time + static_cast<double>(row) * step, model.end_time);
    // Land exactly on each output time, as sled's integrators do.
    CVodeSetStopTime(cvode, t_out);
    sunrealtype t = 0;
    const int status = CVode(cvode, t_out, y, &t, CV_NORMAL);
    system.Load(t, std::span<const double>(N_VGetArrayPointer(y), system.size()));
    if (status < 0 || !sled::runtime::Forward(model, data, &failure)) {
      outcome.failed = true;
      break;
    }
    append_row();
  }
  outcome.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  long steps = 0, evaluations = 0, jacobian_evaluations = 0;
  CVodeGetNumSteps(cvode, &steps);
  CVodeGetNumRhsEvals(cvode, &evaluations);
  CVodeGetNumLinRhsEvals(cvode, &jacobian_evaluations);
  outcome.steps = steps;
  outcome.evaluations = evaluations + jacobian_evaluations;

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
  outcome.failed = summary.failed;
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

int main(int argc, char** argv) {
  std::set<std::string> wanted(argv + 1, argv + argc);
  if (wanted.empty()) wanted.insert(kDefaultCases.begin(), kDefaultCases.end());
  const std::vector<double> ladder = {1e-2, 1e-3, 1e-4, 1e-5, 1e-6};
  std::cout << "case,method,tolerance,wall_seconds,steps,evaluations,error_all,failed\n";
  for (const sled::verification::SuiteCase& suite_case : sled::verification::LoadSuite()) {
    if (!wanted.count(suite_case.name)) continue;
    sled::lang::SourceManager sources;
    const auto file = sources.Load(suite_case.file.string());
    if (!file) continue;
    const sled::verification::Compiled compiled =
        sled::verification::CompileFile(sources, *file, suite_case.overrides);
    if (!compiled.errors.empty()) {
      std::cerr << suite_case.name << ": " << compiled.errors;
      continue;
    }
    const Model& scene = compiled.lowered.model;
    const Outcome reference = RunSled(WithTolerance(scene, "dopri5", 1e-10));
    const auto reference_criteria = sled::runtime::post::EvaluateCriteria(scene, reference.series);
    for (const double tolerance : ladder) {
      for (const std::string method : {"exponential", "dopri5", "rosenbrock", "cvode"}) {
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
        std::cout << fmt::format("{},{},{},{},{},{},{},{}\n", suite_case.name, method, tolerance,
                                 best.wall_seconds, best.steps, best.evaluations, error.overall,
                                 best.failed ? 1 : 0)
                  << std::flush;
      }
    }
  }
  return 0;
}
