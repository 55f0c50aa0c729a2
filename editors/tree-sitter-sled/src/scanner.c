// External scanner of the sled grammar: the unit written after a number or a vector, and the
// binary minus.
//
// sled's parser (lang/syntax/grammar.h) reads a unit as factors joined by `*` or `/` with no
// blanks inside, each a name with an optional power (`N*m/deg`, `m/s^2`, `kg*m^-1`), after
// blanks on the same line; a name that is a clause word or a boolean, or that is followed by
// `=`, `.`, `(` or `:`, is no unit (it starts a statement, a path or a call). A regular
// expression token cannot look past the name for `=` after blanks, so the scanner does.
#include <stdbool.h>
#include <stdint.h>
#include <string.h>

#include "tree_sitter/parser.h"

// A binary operator stands on the line of its left operand (grammar.h: `sp` before it): a `-`
// that starts a line starts a new row or statement with a negative number. The scanner runs
// before the blanks and line breaks between tokens are skipped, so it can tell.

enum TokenType { UNIT, BINARY_MINUS };

void *tree_sitter_sled_external_scanner_create(void) { return NULL; }
void tree_sitter_sled_external_scanner_destroy(void *payload) { (void)payload; }
unsigned tree_sitter_sled_external_scanner_serialize(void *payload, char *buffer) {
  (void)payload;
  (void)buffer;
  return 0;
}
void tree_sitter_sled_external_scanner_deserialize(void *payload, const char *buffer,
                                                   unsigned length) {
  (void)payload;
  (void)buffer;
  (void)length;
}

static bool is_name_start(int32_t c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
}
static bool is_name_char(int32_t c) { return is_name_start(c) || (c >= '0' && c <= '9'); }
static bool is_blank(int32_t c) { return c == ' ' || c == '\t'; }

static bool is_reserved(const char *word) {
  static const char *const kReserved[] = {"on", "with", "at", "as", "filter", "true", "false"};
  for (unsigned i = 0; i < sizeof kReserved / sizeof kReserved[0]; ++i) {
    if (strcmp(word, kReserved[i]) == 0) return true;
  }
  return false;
}

// Reads one factor (a name and an optional `^-?digits`) and marks its end; false when what
// follows is no factor.
static bool scan_factor(TSLexer *lexer) {
  char word[64];
  unsigned length = 0;
  if (!is_name_start(lexer->lookahead)) return false;
  while (is_name_char(lexer->lookahead)) {
    if (length + 1 < sizeof word) word[length++] = (char)lexer->lookahead;
    lexer->advance(lexer, false);
  }
  word[length] = '\0';
  if (is_reserved(word)) return false;
  lexer->mark_end(lexer);
  if (lexer->lookahead == '^') {
    lexer->advance(lexer, false);
    if (lexer->lookahead == '-') lexer->advance(lexer, false);
    if (!(lexer->lookahead >= '0' && lexer->lookahead <= '9')) return true;  // `^` is an operator
    while (lexer->lookahead >= '0' && lexer->lookahead <= '9') lexer->advance(lexer, false);
    lexer->mark_end(lexer);
  }
  return true;
}

bool tree_sitter_sled_external_scanner_scan(void *payload, TSLexer *lexer,
                                            const bool *valid_symbols) {
  (void)payload;
  if (!valid_symbols[UNIT] && !valid_symbols[BINARY_MINUS]) return false;
  // Blanks on the same line only: neither a unit nor an operator starts on the next line.
  while (is_blank(lexer->lookahead)) lexer->advance(lexer, true);
  if (lexer->lookahead == '-') {
    if (!valid_symbols[BINARY_MINUS]) return false;
    lexer->advance(lexer, false);
    if (lexer->lookahead == '>') return false;  // `->`
    lexer->mark_end(lexer);
    lexer->result_symbol = BINARY_MINUS;
    return true;
  }
  if (!valid_symbols[UNIT] || !scan_factor(lexer)) return false;
  while (lexer->lookahead == '*' || lexer->lookahead == '/') {
    lexer->advance(lexer, false);
    if (!is_name_start(lexer->lookahead)) break;  // `*` or `/` as an operator: the unit ends
    if (!scan_factor(lexer)) break;
  }
  // What follows the unit decides: `=` (not `==`), `.`, `(` or `:` after blanks means the last
  // name was no unit. The PEG rule rejects the whole unit then; so does this.
  while (is_blank(lexer->lookahead)) lexer->advance(lexer, false);
  const int32_t next = lexer->lookahead;
  if (next == '.' || next == '(' || next == ':') return false;
  if (next == '=') {
    lexer->advance(lexer, false);
    if (lexer->lookahead != '=') return false;
  }
  lexer->result_symbol = UNIT;
  return true;
}
