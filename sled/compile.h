// sled::Compile: a scene (a .sled file, text in memory, or a tree made with sled::lang::build)
// through the whole front end (parse, check, lint, lower) to a runtime::Model, with the
// diagnostics of every stage. The one pipeline of `sled check`, `sled run`, `sled study`, the
// tests and programs that embed sled (docs/architecture.md).
//
//   sled::Compilation compiled = sled::Compile(sled::Source::File("scene.sled"));
//   std::cerr << compiled.Render(lang::DiagnosticStyle::kCompact);
//   if (!compiled.ok()) return 1;
//   sled::RunResult run = sled::Simulate(compiled.model());  // sled/simulate.h
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "compiler/check/checked_scenario.h"
#include "lang/ast/ast.h"
#include "lang/diagnostics/diagnostic.h"
#include "lang/diagnostics/render.h"
#include "lang/source/source_manager.h"
#include "runtime/model/model.h"

namespace sled {

class Compilation;
struct CompileOptions;

// Where a scene comes from. Move-only; Compile takes it by value.
class Source {
 public:
  // A .sled file; its `import`s of local modules resolve from its folder.
  static Source File(std::string path);
  // Text in memory, shown in diagnostics as `name`; local imports resolve from name's folder.
  static Source Text(std::string text, std::string name = "scene.sled");
  // A tree built with sled::lang::build (lang/builder/builder.h) or parsed by lang::Parse, with
  // the SourceManager that holds its buffers (diagnostics point into them).
  static Source Tree(std::unique_ptr<lang::SourceManager> sources, lang::ast::File tree);

  Source(Source&&) noexcept;
  Source& operator=(Source&&) noexcept;
  ~Source();

 private:
  Source();
  enum class Kind { kFile, kText, kTree };
  Kind kind_ = Kind::kFile;
  std::string path_;  // the file, or the text's name
  std::string text_;
  std::unique_ptr<lang::SourceManager> sources_;
  std::unique_ptr<lang::ast::File> tree_;

  friend Compilation Compile(Source source, const CompileOptions& options);
};

struct CompileOptions {
  // The standard library folder for `import std.x.y`; empty: compiler::DefaultStdlibRoot()
  // ($SLED_STDLIB, else beside the installed program, else the source tree's stdlib/).
  std::string stdlib;
  // Folders searched for other imports after the importing file's own folder, in order; the
  // folders of $SLED_PATH come after these.
  std::vector<std::string> module_path;
  // `--set NAME=VALUE`: parameter overrides, the value as source text (`60 km/h`).
  std::vector<std::pair<std::string, std::string>> overrides;
  bool lints = true;
  // Lower the checked scenario to a Model. False stops after checking (`sled check`): no Model
  // and no lowering notes, and a module without a scenario is no error.
  bool lower = true;
};

// What Compile produced: every diagnostic of every stage (sorted by position), the checked
// scenario, and the Model when lowering was asked for and nothing reported an error.
// Move-only; it owns the text the diagnostics point into.
class Compilation {
 public:
  Compilation(Compilation&&) noexcept;
  Compilation& operator=(Compilation&&) noexcept;
  ~Compilation();

  // No stage reported an error (warnings and notes may have been reported).
  bool ok() const { return !collector_.has_errors(); }
  bool has_model() const { return model_.has_value(); }
  // The compiled Model; std::logic_error when there is none (errors, or CompileOptions::lower
  // was false).
  const runtime::Model& model() const;
  runtime::Model& model();

  // The parsed file; null when the file could not be read.
  const lang::ast::File* ast() const { return ast_.get(); }
  const compiler::CheckedScenario& scenario() const { return scenario_; }

  const std::vector<lang::Diagnostic>& diagnostics() const { return collector_.diagnostics(); }
  int error_count() const { return collector_.error_count(); }
  int warning_count() const { return collector_.warning_count(); }
  // The diagnostics as text: one line each in the compact style (`PATH:LINE:COL:
  // error[E0204]: message`), or the rich style with source lines, carets, help and counts.
  std::string Render(lang::DiagnosticStyle style = lang::DiagnosticStyle::kCompact,
                     bool color = false) const;
  // The notes (N04xx: what the Model leaves out or simulates otherwise than written), compact,
  // one per entry: what `sled run` lists among summary.json's warnings.
  std::vector<std::string> Notes() const;
  const lang::SourceManager& sources() const { return *sources_; }

 private:
  Compilation();
  std::unique_ptr<lang::SourceManager> sources_;
  lang::DiagnosticCollector collector_;
  std::unique_ptr<lang::ast::File> ast_;
  compiler::CheckedScenario scenario_;
  std::optional<runtime::Model> model_;

  friend Compilation Compile(Source source, const CompileOptions& options);
};

// Parses, checks, lints and (unless options.lower is false) lowers the scene. Never throws for
// bad input: every problem is a diagnostic of the result.
Compilation Compile(Source source, const CompileOptions& options = {});

}  // namespace sled
