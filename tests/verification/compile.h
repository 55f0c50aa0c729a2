// Compiles a scenario for the verification tests as `sled run` does (parse, check against the
// standard library, lower), and runs it, so a test can use a scene written in the language.
#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "compiler/check/check.h"
#include "compiler/lower/lower.h"
#include "lang/diagnostics/render.h"
#include "lang/syntax/parser.h"
#include "runtime/run.h"

namespace sled::verification {

struct Compiled {
  compiler::Lowered lowered;
  std::string errors;  // rendered diagnostics; empty when the scene checks
};

// `overrides` are `--set NAME=VALUE` pairs, the value as source text.
inline Compiled CompileFile(
    lang::SourceManager& sources, lang::FileId file,
    const std::vector<std::pair<std::string, std::string>>& overrides = {}) {
  const std::filesystem::path root = SLED_SOURCE_ROOT;
  lang::DiagnosticCollector collector;
  compiler::CheckOptions check_options;
  check_options.diagnostics = &collector;
  check_options.overrides = overrides;
  check_options.stdlib_root = (root / "stdlib").string();
  const compiler::CheckedScenario scenario = compiler::ParseAndCheck(sources, file, check_options);
  Compiled compiled;
  if (collector.has_errors()) {
    for (const auto& d : collector.diagnostics()) {
      compiled.errors += lang::RenderCompact(sources, d) + "\n";
    }
    return compiled;
  }
  compiled.lowered = compiler::Lower(scenario, sources, {});
  return compiled;
}

inline Compiled CompileText(const std::string& text) {
  lang::SourceManager sources;
  return CompileFile(sources, sources.Add("scene.sled", text));
}

// A scene compiled and run as `sled run` runs it: its outputs, and what the run and the model
// were (errors is empty when the scene checked).
struct SceneRun {
  std::string errors;
  std::size_t nv = 0;
  runtime::TimeSeries series;
  runtime::RunSummary summary;
};

inline SceneRun RunText(const std::string& text) {
  SceneRun run;
  const Compiled compiled = CompileText(text);
  run.errors = compiled.errors;
  if (!run.errors.empty()) return run;
  const runtime::Model& model = compiled.lowered.model;
  run.nv = static_cast<std::size_t>(model.nv);
  runtime::Data data = runtime::MakeData(model);
  run.summary = runtime::Run(model, data, run.series, {});
  return run;
}

}  // namespace sled::verification
