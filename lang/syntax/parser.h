// lang::Parse: .sled text to the AST. Never throws on user input: every problem becomes a
// diagnostic, and statements the grammar rejects are skipped so one run reports many errors.
#pragma once

#include "lang/ast/ast.h"
#include "lang/diagnostics/diagnostic.h"
#include "lang/source/source_manager.h"

namespace sled::lang {

struct ParseOptions {
  DiagnosticConsumer* diagnostics = nullptr;  // required
  // Deepest nesting of blocks and expressions before E0106 (guards the stack on hostile input).
  int max_depth = 64;
};

ast::File Parse(const SourceManager& sources, FileId file, const ParseOptions& options);

// Parses one value (an expression) on its own, as `--set NAME=VALUE` needs.
std::optional<ast::Expr> ParseValue(const SourceManager& sources, FileId file,
                                    const ParseOptions& options);

}  // namespace sled::lang
