// The flagship's whole run beside MuJoCo's humanoid, in the same binary and sitting, with the
// ratio printed after the table (docs/flagship.md).
//
//   sled_bench_whole_run_bench --benchmark_repetitions=10 --benchmark_enable_random_interleaving
//
// BM_FlagshipWholeRun: examples/frontal_sled.sled from its file to its output folder, as
// `sled run` does it (compile: parse, check, lower; run; filters and criteria; timeseries.csv,
// timeseries_filtered.csv, summary.json, animation.glb), without the process's start, and with
// its two threads (the output rows and the files beside the integration: SimulateOptions::
// threaded, OutputFolderOptions::parallel_writes). BM_FlagshipWholeRunOneThread: the same on
// one thread (`sled run --single-thread`, a sweep's runs). Wall time is what they are compared
// by; their CPU time is the whole process's (both threads).
// BM_MujocoHumanoidWholeRun: MuJoCo's 27-DOF humanoid (the MJCF file
// shared/reference/mujoco-humanoid.xml beside the source tree, or $SLED_HUMANOID) loaded and
// stepped for 200 ms at 0.1 ms steps (2,000 mj_step), the same simulated time as the flagship.
// BM_FlagshipRunOnly / BM_MujocoHumanoidStepsOnly: the same without loading (and, for sled,
// without writing the folder).
#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>
#include <mujoco/mujoco.h>

#include "sled/compile.h"
#include "sled/output_folder.h"
#include "sled/simulate.h"

namespace sled::bench {
namespace {

constexpr double kHumanoidStep = 1e-4;  // [s]
constexpr int kHumanoidSteps = 2000;    // 200 ms

std::string FlagshipPath() { return std::string(SLED_SOURCE_ROOT) + "/examples/frontal_sled.sled"; }

std::string HumanoidPath() {
  if (const char* path = std::getenv("SLED_HUMANOID")) return path;
  return std::string(SLED_SOURCE_ROOT) + "/../shared/reference/mujoco-humanoid.xml";
}

// A fresh, empty output folder under the system's temporary directory.
std::string OutputDirectory() {
  const std::filesystem::path folder =
      std::filesystem::temp_directory_path() / "sled_whole_run_bench";
  std::filesystem::remove_all(folder);
  std::filesystem::create_directories(folder);
  return folder.string();
}

// Compiles the flagship, or stops the benchmark with the diagnostics.
std::unique_ptr<Compilation> CompileFlagship(benchmark::State& state) {
  auto compiled = std::make_unique<Compilation>(Compile(Source::File(FlagshipPath())));
  if (!compiled->ok()) {
    state.SkipWithError(
        ("the flagship does not compile:\n" + compiled->Render(lang::DiagnosticStyle::kCompact))
            .c_str());
    return nullptr;
  }
  return compiled;
}

void FlagshipWholeRun(benchmark::State& state, bool threaded) {
  const std::string directory = OutputDirectory();
  for (auto _ : state) {
    const std::unique_ptr<Compilation> compiled = CompileFlagship(state);
    if (!compiled) return;
    OutputFolderOptions options;
    options.directory = directory;
    options.parallel_writes = threaded;
    OutputFolder folder(compiled->model(), options);
    SimulateOptions simulate;
    simulate.threaded = threaded;
    const RunResult result = Simulate(compiled->model(), simulate, {&folder});
    if (result.failed() || !result.sink_errors.empty()) {
      state.SkipWithError("the flagship's run failed or its folder was not written");
      return;
    }
    benchmark::DoNotOptimize(result.series.values.data());
  }
}

void BM_FlagshipWholeRun(benchmark::State& state) { FlagshipWholeRun(state, true); }
void BM_FlagshipWholeRunOneThread(benchmark::State& state) { FlagshipWholeRun(state, false); }

void BM_FlagshipRunOnly(benchmark::State& state) {
  const std::unique_ptr<Compilation> compiled = CompileFlagship(state);
  if (!compiled) return;
  for (auto _ : state) {
    const RunResult result = Simulate(compiled->model());
    if (result.failed()) {
      state.SkipWithError("the flagship's run failed");
      return;
    }
    benchmark::DoNotOptimize(result.series.values.data());
  }
}

struct MujocoDeleter {
  void operator()(mjModel* m) const { mj_deleteModel(m); }
  void operator()(mjData* d) const { mj_deleteData(d); }
};
using MujocoModel = std::unique_ptr<mjModel, MujocoDeleter>;
using MujocoData = std::unique_ptr<mjData, MujocoDeleter>;

MujocoModel LoadHumanoid(benchmark::State& state) {
  std::array<char, 1000> error{};
  MujocoModel m(mj_loadXML(HumanoidPath().c_str(), nullptr, error.data(), error.size()));
  if (!m) {
    state.SkipWithError(("MuJoCo could not load " + HumanoidPath() + ": " + error.data()).c_str());
    return nullptr;
  }
  m->opt.timestep = kHumanoidStep;
  return m;
}

void StepHumanoid(const mjModel* m, mjData* d) {
  for (int k = 0; k < kHumanoidSteps; ++k) mj_step(m, d);
}

void BM_MujocoHumanoidWholeRun(benchmark::State& state) {
  for (auto _ : state) {
    const MujocoModel m = LoadHumanoid(state);
    if (!m) return;
    const MujocoData d(mj_makeData(m.get()));
    StepHumanoid(m.get(), d.get());
    benchmark::DoNotOptimize(d->qpos[0]);
  }
}

void BM_MujocoHumanoidStepsOnly(benchmark::State& state) {
  const MujocoModel m = LoadHumanoid(state);
  if (!m) return;
  const MujocoData d(mj_makeData(m.get()));
  for (auto _ : state) {
    mj_resetData(m.get(), d.get());
    StepHumanoid(m.get(), d.get());
    benchmark::DoNotOptimize(d->qpos[0]);
  }
}

BENCHMARK(BM_FlagshipWholeRun)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MeasureProcessCPUTime();
BENCHMARK(BM_FlagshipWholeRunOneThread)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_MujocoHumanoidWholeRun)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_FlagshipRunOnly)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_MujocoHumanoidStepsOnly)->Unit(benchmark::kMillisecond)->UseRealTime();

// The console table, plus every repetition's wall and CPU time per iteration, for the
// flagship/humanoid ratios (medians over the repetitions) after the table.
class RatioReporter : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    for (const Run& run : runs) {
      if (run.error_occurred) continue;
      // Repetitions and their median (alone with --benchmark_report_aggregates_only): adding
      // the median to the repetitions leaves their median as it is.
      const bool median = run.run_type == Run::RT_Aggregate && run.aggregate_name == "median";
      if (run.run_type != Run::RT_Iteration && !median) continue;
      const double to_ms = 1e3 / benchmark::GetTimeUnitMultiplier(run.time_unit);
      wall_[run.run_name.function_name].push_back(run.GetAdjustedRealTime() * to_ms);
      cpu_[run.run_name.function_name].push_back(run.GetAdjustedCPUTime() * to_ms);
    }
    ConsoleReporter::ReportRuns(runs);
  }

  // Wall time, and the CPU time, which other work on a busy machine disturbs less.
  void PrintRatios() const {
    for (const auto* times : {&wall_, &cpu_}) {
      std::printf("\nflagship / MuJoCo humanoid, 200 ms simulated (%s time, median):\n",
                  times == &wall_ ? "wall" : "CPU");
      Print(*times, "whole run", "BM_FlagshipWholeRun", "BM_MujocoHumanoidWholeRun");
      Print(*times, "without loading or writing", "BM_FlagshipRunOnly",
            "BM_MujocoHumanoidStepsOnly");
    }
  }

 private:
  static double Median(std::vector<double> x) {
    std::sort(x.begin(), x.end());
    const std::size_t h = x.size() / 2;
    return x.size() % 2 ? x[h] : 0.5 * (x[h - 1] + x[h]);
  }
  using Times = std::map<std::string, std::vector<double>>;  // [ms] per iteration
  static void Print(const Times& times, const char* label, const std::string& sled,
                    const std::string& mujoco) {
    const auto s = times.find(sled), m = times.find(mujoco);
    if (s == times.end() || m == times.end()) return;
    const double ts = Median(s->second), tm = Median(m->second);
    std::printf("  %-28s flagship %8.2f ms   humanoid %8.2f ms   ratio %.2f\n", label, ts, tm,
                ts / tm);
  }

  Times wall_, cpu_;
};

}  // namespace
}  // namespace sled::bench

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  sled::bench::RatioReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  reporter.PrintRatios();
  benchmark::Shutdown();
  return 0;
}
