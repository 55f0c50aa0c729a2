// Parse and check of a 1,000-line scenario (issue 2 asks for at most 20 ms). The scene is
// generated: a chain body of segments and joints with torque functions, contact ellipsoids,
// a vehicle with surfaces and contacts, and outputs, so every checker stage is exercised.
//
// Run: build/tests/bench/sled_bench_parse_check_bench --benchmark_counters_tabular=true
#include <benchmark/benchmark.h>

#include <string>

#include "lang/syntax/parser.h"
#include "tests/bench/bench_scene.h"

namespace {

using sled::bench::CountLines;
using sled::bench::MakeScenario;

void BM_ParseAndCheck(benchmark::State& state) {
  const std::string text = MakeScenario(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    if (sled::bench::ParseAndCheck(text)) state.SkipWithError("the generated scene has errors");
  }
  state.counters["lines"] = CountLines(text);
}

void BM_ParseOnly(benchmark::State& state) {
  const std::string text = MakeScenario(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    sled::lang::SourceManager sources;
    const sled::lang::FileId file = sources.Add("bench.sled", text);
    sled::lang::DiagnosticCollector diagnostics;
    sled::lang::ParseOptions parse_options;
    parse_options.diagnostics = &diagnostics;
    auto ast = sled::lang::Parse(sources, file, parse_options);
    benchmark::DoNotOptimize(ast);
  }
  state.counters["lines"] = CountLines(text);
}

// 80 segments give a scene of just over 1,000 lines.
BENCHMARK(BM_ParseAndCheck)->Arg(80)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ParseOnly)->Arg(80)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
