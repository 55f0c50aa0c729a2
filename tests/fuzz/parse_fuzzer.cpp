// libFuzzer target for the .sled front end: any bytes must parse without crashing, every
// diagnostic must render, and (when the formatter exists) a file that parsed cleanly must format
// to text that parses cleanly again.
//
//   build-fuzz/tests/fuzz/sled_parse_fuzzer -max_total_time=60 CORPUS_DIR
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "lang/ast/ast.h"
#include "lang/diagnostics/diagnostic.h"
#include "lang/diagnostics/render.h"
#include "lang/source/source_manager.h"
#include "lang/syntax/parser.h"

#if __has_include("lang/format/formatter.h")
#include "lang/format/formatter.h"
#define SLED_FUZZ_FORMATTER 1
#endif

namespace {

using namespace sled::lang;

[[noreturn]] void Fail(const char* what, const std::string& text) {
  std::fprintf(stderr, "sled_parse_fuzzer: %s\n--- text ---\n%s\n--- end ---\n", what,
               text.c_str());
  std::abort();
}

// Renders every diagnostic in both forms; the results are only checked for being non-empty, the
// point is that rendering any range the parser produced is memory-safe.
void RenderAll(const SourceManager& sources, const DiagnosticCollector& collector,
               const std::string& text) {
  for (const Diagnostic& diagnostic : collector.diagnostics()) {
    if (RenderRich(sources, diagnostic).empty()) Fail("RenderRich returned nothing", text);
    if (RenderCompact(sources, diagnostic).empty()) Fail("RenderCompact returned nothing", text);
    RenderRich(sources, diagnostic, RenderOptions{.color = true});
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::string text(reinterpret_cast<const char*>(data), size);
  SourceManager sources;
  const FileId file = sources.Add("fuzz.sled", text);
  DiagnosticCollector collector;
  ParseOptions options;
  options.diagnostics = &collector;
  const ast::File parsed = Parse(sources, file, options);
  RenderAll(sources, collector, text);
  (void)ast::Dump(parsed);

#ifdef SLED_FUZZ_FORMATTER
  // lang/format/formatter.h promises: a tree the parser produced formats to text that parses
  // cleanly back to the same tree, and formatting that text again changes nothing.
  if (!collector.has_errors()) {
    const std::string formatted = Format(parsed);
    const FileId again = sources.Add("fuzz-formatted.sled", formatted);
    DiagnosticCollector reparse;
    ParseOptions reparse_options;
    reparse_options.diagnostics = &reparse;
    const ast::File reparsed = Parse(sources, again, reparse_options);
    const auto report = [&] {
      std::string out = text + "\n--- formatted ---\n" + formatted + "\n--- diagnostics ---\n";
      for (const Diagnostic& diagnostic : reparse.diagnostics()) {
        out += RenderCompact(sources, diagnostic) + "\n";
      }
      return out;
    };
    if (reparse.has_errors()) Fail("the formatter's output does not parse", report());
    if (ast::Dump(reparsed) != ast::Dump(parsed)) {
      Fail("the formatter's output parses to a different tree", report());
    }
    if (Format(reparsed) != formatted) Fail("formatting is not idempotent", report());
  }
#endif
  return 0;
}
