// Reading one fixed-column numeric field the way a Fortran formatted READ does (`Iw`, `Fw.0`):
// blanks are ignored (BLANK='NULL', the ATB V.3 default) or read as zeros (BZ, the FORTRAN IV
// convention of CVS-III decks); an all-blank field is zero; an `Fw.0` field without a decimal
// point is a whole number; exponents may be written with E or D.
#pragma once

#include <string>
#include <string_view>

namespace sled::lang::legacy {

enum class BlankMode { kIgnore, kZero };

enum class FieldProblem {
  kNone,
  kNotANumber,    // letters or stray characters
  kNotAnInteger,  // a decimal point or exponent in an integer field
  kOutOfRange,    // too large for a double or an int
};

struct FieldValue {
  double number = 0.0;
  FieldProblem problem = FieldProblem::kNone;
  bool blank = true;  // the field held only blanks
};

// `text` is the field's columns (shorter when the card ends inside the field).
FieldValue ReadRealField(std::string_view text, BlankMode blanks);
FieldValue ReadIntegerField(std::string_view text, BlankMode blanks);

}  // namespace sled::lang::legacy
