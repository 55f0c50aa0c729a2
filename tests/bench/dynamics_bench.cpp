// One forward-dynamics evaluation (all generalized accelerations and joint wrenches) of sled
// against MuJoCo 2.2.2 (mj_forward, contacts disabled) on the same bodies, measured in the same
// run (docs/architecture.md); the ratios are printed after the table. The bodies and states come
// from tests/verification/tree_models.h, which the MuJoCo comparison test checks agree to 1e-9.
//
//   sled_bench_dynamics_bench --benchmark_repetitions=5 --benchmark_enable_random_interleaving
//
// (interleaving spreads a busy machine's noise over sled and MuJoCo alike).
//
// BM_SledForward / BM_MujocoForward: the 15-segment, 40-DOF CVS occupant.
// BM_SledForwardScaling / BM_MujocoForwardScaling: chains of N segments (free root, then ball,
// ball, pin, ...), with the time per segment as a counter; sled's fit is O(N), MuJoCo's is left
// to the fit (a chain's mass matrix is dense).
// BM_SledForwardFourBar / BM_SledForwardFourBarOpen: examples/four_bar.sled with its loop-closing
// constraint (the KKT system, KLU) and without it (the open chain), so the difference is the
// cost of the constraint.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "runtime/dynamics/dynamics.h"
#include "tests/verification/compile.h"
#include "tests/verification/tree_models.h"

namespace sled::verification {
namespace {

constexpr std::uint64_t kStateSeed = 1;

// One body tree in both programs, set to the same random state.
struct Subject {
  explicit Subject(const BodyTree& tree_in)
      : tree(tree_in), model(BuildModel(tree)), data(runtime::MakeData(model)) {
    std::string error;
    m = LoadMjcf(BuildMjcf(tree), &error);
    if (!m) {
      std::fprintf(stderr, "MuJoCo rejected %s: %s\n", tree.name.c_str(), error.c_str());
      std::abort();
    }
    d.reset(mj_makeData(m.get()));
    map = MapToMujoco(tree, m.get());
    data.model = &model;
    SetRandomState(model, kStateSeed, data);
    CopyStateToMujoco(tree, model, data, map, m.get(), d.get());
  }
  BodyTree tree;
  runtime::Model model;
  runtime::Data data;
  MujocoModelPtr m;
  MujocoDataPtr d;
  MujocoMap map;
};

Subject& Cvs() {
  static Subject subject(CvsBody());
  return subject;
}

Subject& ChainOf(int n) {
  static std::map<int, std::unique_ptr<Subject>> subjects;
  auto& subject = subjects[n];
  if (!subject) subject = std::make_unique<Subject>(Chain(n));
  return *subject;
}

// examples/four_bar.sled lowered, at its initial state; `open` drops the loop-closing constraint.
struct FourBar {
  explicit FourBar(bool open) : model(Load(open)), data(runtime::MakeData(model)) {}
  static runtime::Model Load(bool open) {
    const std::string root = SLED_SOURCE_ROOT;
    verification::Compiled compiled = verification::CompileFile(root + "/examples/four_bar.sled");
    if (!compiled.errors.empty()) {
      std::fprintf(stderr, "examples/four_bar.sled does not check:\n%s", compiled.errors.c_str());
      std::abort();
    }
    runtime::Model model = std::move(compiled.compilation.model());
    if (open) {
      model.constraint_name.clear();
      model.constraint_kind.clear();
      model.constraint_first.clear();
      model.constraint_second.clear();
      model.constraint_point_first.clear();
      model.constraint_point_second.clear();
      model.constraint_distance.clear();
      model.constraint_axis.clear();
    }
    return model;
  }
  runtime::Model model;
  runtime::Data data;
};

void RunSledModel(benchmark::State& state, const runtime::Model& model, runtime::Data& data) {
  data.model = &model;
  for (auto _ : state) {
    const bool ok = runtime::Forward(model, data, nullptr);
    benchmark::DoNotOptimize(ok);
    benchmark::DoNotOptimize(data.vdot.data());
    benchmark::ClobberMemory();
  }
  if (!runtime::Forward(model, data, nullptr)) state.SkipWithError("sled's Forward failed");
}

void RunSled(benchmark::State& state, Subject& subject) {
  RunSledModel(state, subject.model, subject.data);
}

void RunMujoco(benchmark::State& state, Subject& subject) {
  for (auto _ : state) {
    mj_forward(subject.m.get(), subject.d.get());
    benchmark::DoNotOptimize(subject.d->qacc);
    benchmark::ClobberMemory();
  }
}

void SetPerSegment(benchmark::State& state, int segments) {
  state.SetComplexityN(segments);
  // Seconds per segment: the inverse of the rate of segments processed.
  state.counters["per_segment"] = benchmark::Counter(
      segments, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void BM_SledForward(benchmark::State& state) { RunSled(state, Cvs()); }
void BM_MujocoForward(benchmark::State& state) { RunMujoco(state, Cvs()); }

void BM_SledForwardScaling(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  RunSled(state, ChainOf(n));
  SetPerSegment(state, n);
}

void BM_MujocoForwardScaling(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  RunMujoco(state, ChainOf(n));
  SetPerSegment(state, n);
}

void BM_SledForwardFourBar(benchmark::State& state) {
  static FourBar four_bar(false);
  RunSledModel(state, four_bar.model, four_bar.data);
}
void BM_SledForwardFourBarOpen(benchmark::State& state) {
  static FourBar four_bar(true);
  RunSledModel(state, four_bar.model, four_bar.data);
}

BENCHMARK(BM_SledForward)->Unit(benchmark::kNanosecond);
BENCHMARK(BM_MujocoForward)->Unit(benchmark::kNanosecond);
BENCHMARK(BM_SledForwardScaling)
    ->Unit(benchmark::kNanosecond)
    ->Arg(5)
    ->Arg(10)
    ->Arg(15)
    ->Arg(30)
    ->Arg(45)
    ->Arg(60)
    ->Complexity(benchmark::oN);
// A chain's mass matrix is dense, so MuJoCo's LDL^T is not O(N) here: let the fit choose.
BENCHMARK(BM_MujocoForwardScaling)
    ->Unit(benchmark::kNanosecond)
    ->Arg(5)
    ->Arg(10)
    ->Arg(15)
    ->Arg(30)
    ->Arg(45)
    ->Arg(60)
    ->Complexity();
BENCHMARK(BM_SledForwardFourBar)->Unit(benchmark::kNanosecond);
BENCHMARK(BM_SledForwardFourBarOpen)->Unit(benchmark::kNanosecond);

// The console table, plus the CPU time per iteration of every repetition, kept to print the
// sled/MuJoCo ratios (medians over repetitions) after the table.
class RatioReporter : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    for (const Run& run : runs) {
      if (run.error_occurred || run.report_big_o || run.report_rms) continue;
      std::string key = run.run_name.function_name;
      if (!run.run_name.args.empty()) key += "/" + run.run_name.args;
      const double ns =
          run.GetAdjustedCPUTime() * 1e9 / benchmark::GetTimeUnitMultiplier(run.time_unit);
      if (run.run_type == Run::RT_Iteration) {
        times_[key].push_back(ns);
      } else if (run.aggregate_name == "median") {
        // Only aggregates reach the display with --benchmark_report_aggregates_only.
        aggregate_medians_[key] = ns;
      }
    }
    ConsoleReporter::ReportRuns(runs);
  }

  void PrintRatios() const {
    std::printf("\nsled / MuJoCo 2.2.2, one forward-dynamics evaluation (CPU time, median):\n");
    Print("cvs15: 15 segments, 40 DOF", "BM_SledForward", "BM_MujocoForward");
    for (const int n : {5, 10, 15, 30, 45, 60}) {
      const std::string args = "/" + std::to_string(n);
      Print("chain of " + std::to_string(n), "BM_SledForwardScaling" + args,
            "BM_MujocoForwardScaling" + args);
    }
  }

 private:
  static double Median(std::vector<double> x) {
    std::sort(x.begin(), x.end());
    const std::size_t h = x.size() / 2;
    return x.size() % 2 ? x[h] : 0.5 * (x[h - 1] + x[h]);
  }
  // The median CPU time per iteration of a benchmark; < 0 when it did not run.
  double MedianOf(const std::string& key) const {
    if (const auto it = times_.find(key); it != times_.end()) return Median(it->second);
    if (const auto it = aggregate_medians_.find(key); it != aggregate_medians_.end()) {
      return it->second;
    }
    return -1.0;
  }
  void Print(const std::string& label, const std::string& sled, const std::string& mujoco) const {
    const double ts = MedianOf(sled), tm = MedianOf(mujoco);
    if (ts <= 0 || tm <= 0) return;
    std::printf("  %-28s sled %9.1f ns   MuJoCo %9.1f ns   ratio %.2f\n", label.c_str(), ts, tm,
                ts / tm);
  }

  std::map<std::string, std::vector<double>> times_;
  std::map<std::string, double> aggregate_medians_;
};

}  // namespace
}  // namespace sled::verification

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  sled::verification::RatioReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  reporter.PrintRatios();
  benchmark::Shutdown();
  return 0;
}
