#include "lang/legacy/fortran_field.h"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <limits>

namespace sled::lang::legacy {
namespace {

// The field with blanks removed (BN) or replaced by zeros after the first non-blank (BZ: leading
// blanks are still nothing, since a right-justified number would otherwise change).
std::string Squeeze(std::string_view text, BlankMode blanks, bool* all_blank) {
  std::string out;
  out.reserve(text.size());
  *all_blank = true;
  for (const char c : text) {
    if (c == ' ') {
      if (blanks == BlankMode::kZero && !out.empty()) out += '0';
      continue;
    }
    *all_blank = false;
    out += c;
  }
  return out;
}

bool IsDigit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }

}  // namespace

FieldValue ReadRealField(std::string_view text, BlankMode blanks) {
  FieldValue value;
  std::string s = Squeeze(text, blanks, &value.blank);
  if (value.blank) return value;
  // Grammar: [sign] digits [. digits] [ (E|D) [sign] digits | sign digits ].
  std::size_t i = 0;
  if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
  std::size_t digits = 0;
  while (i < s.size() && IsDigit(s[i])) ++i, ++digits;
  if (i < s.size() && s[i] == '.') {
    ++i;
    while (i < s.size() && IsDigit(s[i])) ++i, ++digits;
  }
  if (digits == 0) {
    value.problem = FieldProblem::kNotANumber;
    return value;
  }
  if (i < s.size()) {
    const std::size_t exponent_at = i;
    if (s[i] == 'E' || s[i] == 'e' || s[i] == 'D' || s[i] == 'd') {
      s[i] = 'e';
      ++i;
    } else if (s[i] == '+' || s[i] == '-') {
      s.insert(i, 1, 'e');  // `1.5-3` is 1.5e-3 in Fortran input
      ++i;
    }
    if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
    std::size_t exponent_digits = 0;
    while (i < s.size() && IsDigit(s[i])) ++i, ++exponent_digits;
    if (i != s.size() || exponent_digits == 0 || exponent_at == i) {
      value.problem = FieldProblem::kNotANumber;
      return value;
    }
  }
  value.number = std::strtod(s.c_str(), nullptr);
  if (!std::isfinite(value.number)) {
    value.number = 0.0;
    value.problem = FieldProblem::kOutOfRange;
  }
  return value;
}

FieldValue ReadIntegerField(std::string_view text, BlankMode blanks) {
  FieldValue value;
  const std::string s = Squeeze(text, blanks, &value.blank);
  if (value.blank) return value;
  std::size_t i = 0;
  if (s[i] == '+' || s[i] == '-') ++i;
  const std::size_t first_digit = i;
  while (i < s.size() && IsDigit(s[i])) ++i;
  if (i != s.size() || i == first_digit) {
    // Tell a real number written where an integer belongs from plain garbage.
    const FieldValue as_real = ReadRealField(text, blanks);
    value.problem = as_real.problem == FieldProblem::kNone ? FieldProblem::kNotAnInteger
                                                           : FieldProblem::kNotANumber;
    return value;
  }
  const double number = std::strtod(s.c_str(), nullptr);
  if (std::fabs(number) > static_cast<double>(std::numeric_limits<int>::max())) {
    value.problem = FieldProblem::kOutOfRange;
    return value;
  }
  value.number = number;
  return value;
}

}  // namespace sled::lang::legacy
