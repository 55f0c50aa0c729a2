// The fields of one card, declared once by the card's Fortran FORMAT (as ATB V.3's READ statement
// gives it, e.g. `(A4,2X,10F6.0,I4)`): each field's columns and kind. The fixed-column reader reads
// a field by its columns; the list-directed reader reads the same fields as the card's items, in
// column order, so both readers share one declaration of every card.
#pragma once

#include <string_view>
#include <vector>

namespace sled::lang::legacy {

enum class FieldKind { kText, kInteger, kReal };

struct FieldSpan {
  int first = 0;  // 1-based, inclusive
  int last = 0;
  FieldKind kind = FieldKind::kReal;
};

// What a card holds and how a `.lin` deck reads it. `fortran` is the FORMAT of one record (no `/`;
// a record of a READ that continues over several records is declared with `continues`).
struct CardSpec {
  std::string_view fortran;
  // The number of items this record's READ takes (-1: every field of the format). A record that
  // holds only the first few fields of a repeated format (a table's last line) says how many.
  int items = -1;
  // True when ATB reads this record in the same list-directed READ as the previous one (format
  // reversion: a table's lines, F.2.b's NX and NOUT), so in a `.lin` deck its items follow the
  // previous record's without starting a new line.
  bool continues = false;
  // A field that only the fixed-column READ has (G.1.a's J1); a `.lin` deck reads it as zero.
  int ain_only_column = 0;
};

// The fields of a FORMAT with repeat counts, groups, `nX`, `Aw`, `Iw` and `Fw.d` (or `Ew.d`,
// `Gw.d`, `Dw.d`). Parsed formats are cached: the declarations are string literals.
const std::vector<FieldSpan>& FieldsOf(std::string_view fortran);

}  // namespace sled::lang::legacy
