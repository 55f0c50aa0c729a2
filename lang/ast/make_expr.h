// Building expression nodes by hand, for code that makes syntax trees without parsing text (the
// legacy deck translator, tests of the formatter).
#pragma once

#include <utility>
#include <vector>

#include "lang/ast/ast.h"

namespace sled::lang::ast {

// `left op right`, op one of + - * / ^.
inline Expr MakeBinary(char op, Expr left, Expr right) {
  Expr expr;
  expr.kind = ExprKind::kBinary;
  expr.op = op;
  expr.operands.push_back(std::move(left));
  expr.operands.push_back(std::move(right));
  return expr;
}

// `-operand`.
inline Expr MakeNegation(Expr operand) {
  Expr expr;
  expr.kind = ExprKind::kUnary;
  expr.op = '-';
  expr.operands.push_back(std::move(operand));
  return expr;
}

// `a -> b -> ...`.
inline Expr MakeArrow(std::vector<Expr> chain) {
  Expr expr;
  expr.kind = ExprKind::kArrow;
  expr.operands = std::move(chain);
  return expr;
}

}  // namespace sled::lang::ast
