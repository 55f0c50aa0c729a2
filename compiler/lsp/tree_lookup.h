// Finding things in a document's tree by offset: the expression under the cursor.
#pragma once

#include <cstdint>
#include <vector>

#include "lang/ast/ast.h"

namespace sled::lsp {

// The expressions of `statement` (its target, clauses, values, call arguments and their
// operands, not its block) whose range in `file` holds `offset`, narrowest first.
std::vector<const lang::ast::Expr*> ExpressionsAt(const lang::ast::Statement& statement,
                                                  lang::FileId file, std::uint32_t offset);

}  // namespace sled::lsp
