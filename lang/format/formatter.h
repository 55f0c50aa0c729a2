// The canonical text of a .sled file, as `sled fmt` writes it. The checker and the legacy
// translator reuse the expression printer to quote values in messages and generated files.
//
// Canonical form: two spaces per block level, one statement per line, `}` on its own line and
// `{}` for an empty block; a block written on one line (ast::Block::one_line) stays on one line,
// statements two spaces apart, when it fits in 100 columns and holds no comment and no block that
// is not empty; numbers keep their spelling and units their factor order; binary operators and
// `->` are spaced, except `^` (tight unless its base has a unit) and unary minus; comments stay
// where they were attached and at most one blank line separates statements; a value list longer
// than 100 columns wraps after its commas with a 4-space continuation indent; the text ends with
// exactly one newline.
//
// Any tree the parser produced formats to text that parses back to the same tree (equal
// ast::Dump), and formatting is idempotent. A synthetic tree gets parentheses where precedence
// requires them, so its text means what the tree means.
#pragma once

#include <optional>
#include <string>

#include "lang/ast/ast.h"
#include "lang/diagnostics/diagnostic.h"
#include "lang/source/source_manager.h"

namespace sled::lang {

// The whole file in canonical form; empty when the file holds no statement and no comment.
std::string Format(const ast::File& file);

// Parses buffer `file` and formats it, as `sled fmt` and the language server do; nullopt when
// the parser reported errors (to `diagnostics`): the statements it skipped are not in the tree,
// and formatting would lose them.
std::optional<std::string> FormatBuffer(const SourceManager& sources, FileId file,
                                        DiagnosticConsumer& diagnostics);

// One expression on a single line, as it would appear in a statement.
std::string Format(const ast::Expr& expr);

}  // namespace sled::lang
