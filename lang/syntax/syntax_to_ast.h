// The second step of lang::Parse: the concrete syntax tree the grammar built (syntax_tree.h) to
// the AST (lang/ast/ast.h). Decodes numbers, strings, units and operators; a number out of range
// or an expression nested deeper than the AST may hold is a diagnostic, never a throw.
#pragma once

#include <string_view>

#include "lang/ast/ast.h"
#include "lang/diagnostics/diagnostic.h"
#include "lang/syntax/syntax_tree.h"

namespace sled::lang::syntax {

// Appends the statements of a file's tree (the headers and rows under `root`) to `body`; `text`
// is the buffer the tree's offsets point into.
void ConvertFile(const Node& root, std::string_view text, FileId file,
                 DiagnosticConsumer& diagnostics, ast::Block& body);

// One value's tree (ParseValue) as an expression.
ast::Expr ConvertValue(const Node& value, std::string_view text, FileId file,
                       DiagnosticConsumer& diagnostics);

}  // namespace sled::lang::syntax
