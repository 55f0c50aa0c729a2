// compiler::Check: AST to CheckedScenario. Resolves names and imports, converts every value to
// SI, checks the model's physical validity and topology, and runs the lints. Reports problems as
// diagnostics and returns what it could check; callers test the consumer for errors.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "compiler/check/checked_scenario.h"
#include "compiler/check/library_paths.h"
#include "lang/ast/ast.h"
#include "lang/diagnostics/diagnostic.h"
#include "lang/source/source_manager.h"

namespace sled::compiler {

struct CheckOptions {
  lang::DiagnosticConsumer* diagnostics = nullptr;  // required
  // Where `import std.x.y` looks: the standard library's root folder. Empty means
  // DefaultStdlibRoot() (compiler/check/library_paths.h).
  std::string stdlib_root;
  // Where other imports look after the importing file's own folder, in order (sled::Compile
  // adds the folders of $SLED_PATH).
  std::vector<std::string> module_path;
  // `--set NAME=VALUE`: parameter overrides, as source text of a value.
  std::vector<std::pair<std::string, std::string>> overrides;
  bool lints = true;
};

// Checks a parsed file. Imports are read into `sources` and parsed there.
CheckedScenario Check(lang::SourceManager& sources, const lang::ast::File& file,
                      const CheckOptions& options);

// Parses a file of `sources` and checks it, reporting both stages' diagnostics to
// options.diagnostics (sled::Compile, sled/compile.h, runs this and the lowering).
CheckedScenario ParseAndCheck(lang::SourceManager& sources, lang::FileId file,
                              const CheckOptions& options);

}  // namespace sled::compiler
