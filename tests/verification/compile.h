// Scenes for the verification tests through the public API (sled/sled.h), as `sled run` takes
// them: sled::Compile against the source tree's standard library, then sled::Simulate.
#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "sled/compile.h"
#include "sled/simulate.h"

namespace sled::verification {

struct Compiled {
  Compilation compilation;
  std::string errors;  // compact diagnostics when the scene has errors; empty when it compiled

  const runtime::Model& model() const { return compilation.model(); }
  // The lowering's notes (N04xx), compact, one per line.
  std::string notes() const {
    std::string text;
    for (const std::string& note : compilation.Notes()) text += note + "\n";
    return text;
  }
};

inline Compiled CompileSource(Source source,
                              const std::vector<std::pair<std::string, std::string>>& overrides) {
  CompileOptions options;
  options.stdlib = (std::filesystem::path(SLED_SOURCE_ROOT) / "stdlib").string();
  options.overrides = overrides;
  Compiled compiled{Compile(std::move(source), options), {}};
  if (!compiled.compilation.ok()) {
    compiled.errors = compiled.compilation.Render(lang::DiagnosticStyle::kCompact);
  }
  return compiled;
}

// `overrides` are `--set NAME=VALUE` pairs, the value as source text.
inline Compiled CompileFile(
    const std::filesystem::path& path,
    const std::vector<std::pair<std::string, std::string>>& overrides = {}) {
  return CompileSource(Source::File(path.string()), overrides);
}

inline Compiled CompileText(const std::string& text) {
  return CompileSource(Source::Text(text, "scene.sled"), {});
}

// A scene compiled and run as `sled run` runs it: its outputs, and what the run and the model
// were (errors is empty when the scene compiled).
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
  const runtime::Model& model = compiled.model();
  run.nv = static_cast<std::size_t>(model.nv);
  RunResult result = Simulate(model);
  run.series = std::move(result.series);
  run.summary = std::move(result.summary);
  return run;
}

// The value of the channel named `name` (with its unit: `b.s.position.x [m]`) at `row`.
inline double ChannelAt(const runtime::TimeSeries& series, const std::string& name,
                        std::size_t row) {
  for (std::size_t c = 0; c < series.names.size(); ++c) {
    if (series.names[c] == name) return series.values[row * series.columns + 1 + c];
  }
  ADD_FAILURE() << "no column " << name;
  return 0;
}

inline double TimeAt(const runtime::TimeSeries& series, std::size_t row) {
  return series.values[row * series.columns];
}

}  // namespace sled::verification
