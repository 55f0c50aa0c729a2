// libFuzzer target for the whole front end: any bytes are parsed AND checked (names, units,
// imports, topology, lints) without crashing, and every diagnostic renders. The parser fuzzer
// covers the grammar; this one reaches the checker with the trees the parser lets through.
//
//   build-fuzz/tests/fuzz/sled_check_fuzzer -max_total_time=60 CORPUS_DIR
#include <cstddef>
#include <cstdint>
#include <string>

#include "compiler/check/check.h"
#include "lang/diagnostics/render.h"
#include "lang/syntax/parser.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace sled;
  const std::string text(reinterpret_cast<const char*>(data), size);
  lang::SourceManager sources;
  // Inside the source tree, so relative imports reach real modules as well as missing ones.
  const lang::FileId file =
      sources.Add(std::string(SLED_SOURCE_ROOT) + "/examples/fuzz.sled", text);
  lang::DiagnosticCollector collector;
  compiler::CheckOptions check_options;
  check_options.diagnostics = &collector;
  check_options.stdlib_root = std::string(SLED_SOURCE_ROOT) + "/stdlib";
  const compiler::CheckedScenario scenario = compiler::ParseAndCheck(sources, file, check_options);
  if (!collector.has_errors()) (void)compiler::Dump(scenario);
  for (const lang::Diagnostic& diagnostic : collector.diagnostics()) {
    (void)lang::RenderRich(sources, diagnostic);
    (void)lang::RenderCompact(sources, diagnostic);
  }
  return 0;
}
