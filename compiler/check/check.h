// compiler::Check: AST to CheckedScenario. Resolves names and imports, converts every value to
// SI, checks the model's physical validity and topology, and runs the lints. Reports problems as
// diagnostics and returns what it could check; callers test the consumer for errors.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "compiler/check/checked_scenario.h"
#include "lang/ast/ast.h"
#include "lang/diagnostics/diagnostic.h"
#include "lang/source/source_manager.h"

namespace sled::compiler {

struct CheckOptions {
  lang::DiagnosticConsumer* diagnostics = nullptr;  // required
  // Where `import std.x.y` looks: the standard library's root folder. Empty means the folder
  // this build was configured with, or $SLED_STDLIB when set.
  std::string stdlib_root;
  // `--set NAME=VALUE`: parameter overrides, as source text of a value.
  std::vector<std::pair<std::string, std::string>> overrides;
  bool lints = true;
};

// Checks a parsed file. Imports are read into `sources` and parsed there.
CheckedScenario Check(lang::SourceManager& sources, const lang::ast::File& file,
                      const CheckOptions& options);

// Parses a file of `sources` and checks it, reporting both stages' diagnostics to
// options.diagnostics: the front end of `sled run`, the tests and the fuzzers.
CheckedScenario ParseAndCheck(lang::SourceManager& sources, lang::FileId file,
                              const CheckOptions& options);

// The standard library folder Check uses when CheckOptions::stdlib_root is empty.
std::string DefaultStdlibRoot();

}  // namespace sled::compiler
