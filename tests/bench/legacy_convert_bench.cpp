// Converting a 600-card deck (the target: at most 5 ms): the corpus deck
// examples/legacy/seated_occupant.ain with its seat-foam and knee-bolster tables grown to 999
// and 375 points (456 more E.4.b cards), read, mapped and printed as `sled convert
// --approximate-airbags` does (the deck has a driver airbag).
//
//   cmake -S . -B build-bench -DSLED_BENCH=ON ... && cmake --build build-bench
//   ./build-bench/tests/bench/sled_bench_legacy_convert_bench
#include <benchmark/benchmark.h>

#include <string>

#include <fmt/format.h>

#include "lang/diagnostics/diagnostic.h"
#include "lang/format/formatter.h"
#include "lang/legacy/convert.h"
#include "lang/source/source_manager.h"

namespace {

// Replaces the table of the function titled `title` by one of `points` points.
void GrowTable(std::string& deck, std::string_view title, int points) {
  const std::size_t head = deck.rfind(title);  // the E.1 card, after any D.2 plane of that title
  const std::size_t count = deck.find('\n', deck.find('\n', head) + 1) + 1;  // after E.2
  const int old_points = std::stoi(deck.substr(count, 6));
  std::size_t rows_end = deck.find('\n', count) + 1;
  for (int line = 0; line < (old_points + 2) / 3; ++line) rows_end = deck.find('\n', rows_end) + 1;
  std::string table = fmt::format("{:6d}\n", points);
  for (int i = 0; i < points; i += 3) {
    for (int k = i; k < i + 3 && k < points; ++k) {
      table += fmt::format("{:12.4f}{:12.2f}", 0.01 * k, 3.0 * k + 0.001 * k * k);
    }
    table += '\n';
  }
  deck = deck.substr(0, count) + table + deck.substr(rows_end);
}

std::string LargeDeck(int* cards) {
  std::string deck =
      sled::lang::ReadFile(std::string(SLED_SOURCE_ROOT) + "/examples/legacy/seated_occupant.ain")
          .value_or("");
  GrowTable(deck, "   1    SEAT FOAM", 999);
  GrowTable(deck, "   4    KNEE BOLSTER", 375);
  *cards = 0;
  for (std::size_t at = 0; at < deck.size(); at = deck.find('\n', at) + 1) {
    if (deck[at] != '#') ++*cards;
  }
  return deck;
}

void BM_ConvertDeck(benchmark::State& state) {
  int cards = 0;
  const std::string deck = LargeDeck(&cards);
  for (auto _ : state) {
    sled::lang::SourceManager sources;
    sled::lang::DiagnosticCollector collector;
    const sled::lang::FileId id = sources.Add("large.ain", deck);
    sled::lang::legacy::ConvertOptions options;
    options.diagnostics = &collector;
    options.approximate_airbags = true;  // the deck's driver airbag, as the corpus test converts it
    const auto file = sled::lang::legacy::ConvertDeck(sources, id, options);
    if (collector.has_errors()) {
      for (const auto& diagnostic : collector.diagnostics()) {
        if (diagnostic.severity != sled::lang::Severity::kError) continue;
        state.SkipWithError(diagnostic.message.c_str());
        break;
      }
      break;
    }
    std::string text = sled::lang::Format(file);
    benchmark::DoNotOptimize(text);
  }
  state.counters["cards"] = cards;
}
BENCHMARK(BM_ConvertDeck)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
