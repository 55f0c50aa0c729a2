// Edit to diagnostics in the language server (issue 21 asks for under 20 ms on a 1,000-line
// file): a one-character edit of an open document through textDocument/didChange, measured
// until the server has its publishDiagnostics ready, in-process (no pipe). The peer in the same
// run is the bare parse and check of the same text (BM_ParseAndCheckPeer): the ratio is what the
// server adds (applying the edit, the checker's name index, the diagnostics as JSON).
//
// Run: build/tests/bench/sled_bench_lsp_bench --benchmark_counters_tabular=true
#include <benchmark/benchmark.h>

#include <fstream>
#include <iterator>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "compiler/lsp/server.h"
#include "tests/bench/bench_scene.h"

namespace {

using sled::lsp::Json;

const std::string kUri = "file://" + std::string(SLED_SOURCE_ROOT) + "/examples/bench.sled";

void Open(sled::lsp::Server& server, const std::string& text) {
  server.Handle(R"({"jsonrpc":"2.0","id":0,"method":"initialize","params":{"capabilities":{}}})");
  server.Handle(
      Json{{"jsonrpc", "2.0"},
           {"method", "textDocument/didOpen"},
           {"params", {{"textDocument", {{"uri", kUri}, {"version", 1}, {"text", text}}}}}}
          .dump());
}

// Edits `line` in place: a digit of a number toggles, so every edit changes the text and the
// document stays valid.
void EditToDiagnostics(benchmark::State& state, const std::string& text, int line, int column) {
  sled::lsp::Server server(
      {.stdlib = std::string(SLED_SOURCE_ROOT) + "/stdlib", .module_path = {}});
  Open(server, text);
  int version = 1;
  std::size_t published = 0;
  for (auto _ : state) {
    ++version;
    const Json change = {{"jsonrpc", "2.0"},
                         {"method", "textDocument/didChange"},
                         {"params",
                          {{"textDocument", {{"uri", kUri}, {"version", version}}},
                           {"contentChanges",
                            {{{"range",
                               {{"start", {{"line", line}, {"character", column}}},
                                {"end", {{"line", line}, {"character", column + 1}}}}},
                              {"text", version % 2 ? "1" : "2"}}}}}}};
    const std::vector<std::string> out = server.Handle(change.dump());
    published += out.size();
    benchmark::DoNotOptimize(out);
  }
  if (published == 0) state.SkipWithError("no diagnostics were published");
  state.counters["lines"] = sled::bench::CountLines(text);
}

// The line and UTF-16 column (ASCII here) of `needle` in `text`, plus `offset` characters.
std::pair<int, int> PositionOf(const std::string& text, std::string_view needle, int offset) {
  const std::size_t at = text.find(needle);
  int line = 0;
  std::size_t line_start = 0;
  for (std::size_t i = 0; i < at; ++i) {
    if (text[i] == '\n') {
      ++line;
      line_start = i + 1;
    }
  }
  return {line, static_cast<int>(at - line_start) + offset};
}

// The 1,000-line generated scene; the edit changes the mass of segment s40 (`mass = 2.4 kg`).
void BM_EditToDiagnostics(benchmark::State& state) {
  const std::string text = sled::bench::MakeScenario(static_cast<int>(state.range(0)));
  const auto [line, column] = PositionOf(text, "mass = 2.4", 7);
  EditToDiagnostics(state, text, line, column);
}

// The bare front end on the same text: the peer.
void BM_ParseAndCheckPeer(benchmark::State& state) {
  const std::string text = sled::bench::MakeScenario(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    if (sled::bench::ParseAndCheck(text)) state.SkipWithError("the generated scene has errors");
  }
  state.counters["lines"] = sled::bench::CountLines(text);
}

// The flagship scene, whose imports (a 15-segment human, a vehicle interior, a pulse) are read
// and checked again on every edit: the edit changes `belt_slack = 5 mm` (line 18).
void BM_EditToDiagnosticsFlagship(benchmark::State& state) {
  std::ifstream in(std::string(SLED_SOURCE_ROOT) + "/examples/frontal_sled.sled");
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto [line, column] = PositionOf(text, "belt_slack = 5 mm", 13);
  EditToDiagnostics(state, text, line, column);
}

BENCHMARK(BM_EditToDiagnostics)->Arg(80)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ParseAndCheckPeer)->Arg(80)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_EditToDiagnosticsFlagship)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
