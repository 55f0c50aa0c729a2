#include "compiler/lsp/tree_lookup.h"

#include <algorithm>

#include "compiler/lsp/analysis.h"

namespace sled::lsp {

namespace ast = lang::ast;

std::vector<const ast::Expr*> ExpressionsAt(const ast::Statement& statement, lang::FileId file,
                                            std::uint32_t offset) {
  // Iterative, so a hostile file's deeply nested value cannot exhaust the stack.
  std::vector<const ast::Expr*> pending;
  if (statement.target) pending.push_back(&*statement.target);
  for (const ast::Clause& clause : statement.clauses) pending.push_back(&clause.value);
  for (const ast::Expr& value : statement.values) pending.push_back(&value);
  std::vector<const ast::Expr*> found;
  while (!pending.empty()) {
    const ast::Expr* expr = pending.back();
    pending.pop_back();
    if (!Holds(expr->range, file, offset)) continue;
    found.push_back(expr);
    for (const ast::Expr& operand : expr->operands) pending.push_back(&operand);
    for (const ast::Argument& argument : expr->arguments) {
      if (argument.value) pending.push_back(argument.value.get());
    }
  }
  std::stable_sort(found.begin(), found.end(), [](const ast::Expr* a, const ast::Expr* b) {
    return a->range.size() < b->range.size();
  });
  return found;
}

}  // namespace sled::lsp
