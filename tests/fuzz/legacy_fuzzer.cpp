// libFuzzer target for `sled convert`: any bytes, read as a fixed-column `.ain` deck (blanks
// ignored and blanks as zeros) and as a list-directed `.lin` deck, must convert or fail with
// diagnostics without crashing, every diagnostic must render, and a deck that converted must
// format to text.
//
//   build-fuzz/tests/fuzz/sled_legacy_fuzzer -max_total_time=60 CORPUS_DIR
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "lang/diagnostics/diagnostic.h"
#include "lang/diagnostics/render.h"
#include "lang/format/formatter.h"
#include "lang/legacy/convert.h"
#include "lang/source/source_manager.h"

namespace {

using namespace sled::lang;

void ConvertAs(const std::string& text, legacy::DeckFormat format, legacy::BlankMode blanks) {
  SourceManager sources;
  const FileId file =
      sources.Add(format == legacy::DeckFormat::kList ? "fuzz.lin" : "fuzz.ain", text);
  DiagnosticCollector collector;
  legacy::ConvertOptions options;
  options.diagnostics = &collector;
  options.format = format;
  options.blanks = blanks;
  const ast::File converted = legacy::ConvertDeck(sources, file, options);
  for (const Diagnostic& diagnostic : collector.diagnostics()) {
    if (RenderRich(sources, diagnostic).empty() || RenderCompact(sources, diagnostic).empty()) {
      std::fprintf(stderr, "sled_legacy_fuzzer: a diagnostic rendered empty\n");
      std::abort();
    }
  }
  if (!collector.has_errors() && Format(converted).empty()) {
    std::fprintf(stderr, "sled_legacy_fuzzer: a converted deck formatted to nothing\n");
    std::abort();
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  ConvertAs(text, legacy::DeckFormat::kFixed, legacy::BlankMode::kIgnore);
  ConvertAs(text, legacy::DeckFormat::kFixed, legacy::BlankMode::kZero);
  ConvertAs(text, legacy::DeckFormat::kList, legacy::BlankMode::kIgnore);
  return 0;
}
