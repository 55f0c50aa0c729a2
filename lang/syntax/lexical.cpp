#include "lang/syntax/lexical.h"

namespace sled::lang {

Precedence PrecedenceOf(ast::ExprKind kind, char op) {
  switch (kind) {
    case ast::ExprKind::kArrow:
      return kArrowPrecedence;
    case ast::ExprKind::kBinary:
      return op == '+' || op == '-' ? kSumPrecedence
             : op == '^'            ? kPowerPrecedence
                                    : kProductPrecedence;
    case ast::ExprKind::kUnary:
      return kUnaryPrecedence;
    default:
      return kPrimaryPrecedence;
  }
}

std::size_t NumberSpellingLength(std::string_view text, std::size_t begin) {
  std::size_t i = begin;
  const auto digits = [&] {
    const std::size_t start = i;
    while (i < text.size() && text[i] >= '0' && text[i] <= '9') ++i;
    return i - start;
  };
  if (digits() == 0) return 0;
  if (i < text.size() && text[i] == '.') {
    ++i;
    digits();
  }
  if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
    const std::size_t mantissa_end = i;
    ++i;
    if (i < text.size() && (text[i] == '+' || text[i] == '-')) ++i;
    if (digits() == 0) i = mantissa_end;  // `2e` is the number 2 followed by a name
  }
  return i - begin;
}

}  // namespace sled::lang
