// Facts about the grammar that the printers need too (the formatter and the C++ builder must
// produce text the parser reads back as the same tree): how tightly each expression binds, and
// what a number looks like.
#pragma once

#include <cstddef>
#include <string_view>

#include "lang/ast/ast.h"

namespace sled::lang {

// Binding strength, loosest first, as in the grammar: arrow, sum, product, unary, power, primary.
// An operand weaker than its position allows must be printed in parentheses.
enum Precedence : int {
  kArrowPrecedence = 0,
  kSumPrecedence,
  kProductPrecedence,
  kUnaryPrecedence,
  kPowerPrecedence,
  kPrimaryPrecedence,
};

// The precedence of an expression of this kind and operator (op only matters for kBinary).
Precedence PrecedenceOf(ast::ExprKind kind, char op);

// The length of the number spelled at text[begin] (digits [. digits] [e [+-] digits]), or 0.
std::size_t NumberSpellingLength(std::string_view text, std::size_t begin = 0);

// True when the whole of `text` is a number as the grammar spells it.
inline bool IsNumberSpelling(std::string_view text) {
  return !text.empty() && NumberSpellingLength(text) == text.size();
}

}  // namespace sled::lang
