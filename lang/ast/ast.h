// The abstract syntax tree shared by every front end: the .sled parser, the legacy deck reader
// and the embedded C++ builder all produce it; the checker, formatter and dumper consume it.
//
// The tree is deliberately generic. A file is a list of statements; a statement is
//   keyword [target] [clause...] [= value, ...] [{ block }]
// or a table row `value -> value [-> value...]`. What each keyword means, where it may appear and
// which dimension its value has is the checker's schema, not the grammar's business. That keeps
// the grammar small, the formatter exact, and new model features a schema entry rather than a
// grammar change.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "lang/source/source_range.h"

namespace sled::lang::ast {

// One factor of a unit: `m` or `s^2`; a factor after `/` has a negative exponent.
struct UnitFactor {
  std::string symbol;
  int exponent = 1;
  SourceRange range;
};

// A unit written after a number or a vector, such as `N*m/deg` or `m/s^2`.
struct Unit {
  std::vector<UnitFactor> factors;
  SourceRange range;
};

struct Block;
struct Expr;

// A named or positional argument of a call: `delta_v = 56 km/h` or `0`.
struct Argument {
  std::string name;  // empty for a positional argument
  SourceRange name_range;
  std::unique_ptr<Expr> value;
};

enum class ExprKind {
  kNumber,  // 11.7 kg (text keeps the spelling; unit optional)
  kVector,  // (0, 0, -9.81) m/s^2
  kPath,    // occupant.pelvis
  kString,  // "frontal sled"
  kBool,    // true, false
  kCall,    // half_sine(delta_v = 56 km/h), table(deflection -> force)
  kUnary,   // -x
  kBinary,  // a * b (op is one of + - * / ^)
  kArrow,   // a -> b -> c
  kParen,   // (a + b): kept so the formatter prints what was written
};

struct Expr {
  ExprKind kind = ExprKind::kNumber;
  SourceRange range;

  double number = 0.0;              // kNumber: the value
  std::string text;                 // kNumber: spelling; kString: contents; kBool: "true"/"false"
  std::vector<std::string> path;    // kPath, kCall (the callee)
  std::optional<Unit> unit;         // kNumber, kVector
  char op = 0;                      // kUnary ('-'), kBinary
  std::vector<Expr> operands;       // kVector components, kArrow chain, kUnary (1), kBinary (2),
                                    // kParen (1)
  std::vector<Argument> arguments;  // kCall

  Expr() = default;
  Expr(Expr&&) noexcept = default;
  Expr& operator=(Expr&&) noexcept = default;
  Expr(const Expr& other);
  Expr& operator=(const Expr& other);

  // The dotted text of a path or callee.
  std::string PathText() const;
};

// `// text` kept for the formatter; `text` excludes the slashes and trailing spaces.
struct Comment {
  std::string text;
  SourceRange range;
  bool blank_line_before = false;  // an empty line separates it from what precedes it
};

// A clause of a statement header: `on sled`, `with seat_pan`, `at (0, 0, 0) mm`, `as occupant`,
// or `: ball(pelvis -> abdomen)` (word ":").
struct Clause {
  std::string word;
  SourceRange word_range;
  Expr value;
};

enum class StatementKind {
  kHeader,  // keyword [target] [clauses] [= values] [block]
  kRow,     // value -> value ... (values[0] is the arrow expression)
};

struct Statement {
  StatementKind kind = StatementKind::kHeader;
  std::string keyword;
  SourceRange keyword_range;
  std::optional<Expr> target;  // a path or a string
  std::vector<Clause> clauses;
  bool has_value = false;    // `=` was written
  std::vector<Expr> values;  // after `=`, comma separated
  std::unique_ptr<Block> block;
  SourceRange range;

  // Trivia for the formatter.
  std::vector<Comment> leading_comments;
  std::optional<Comment> trailing_comment;
  bool blank_line_before = false;  // an empty line right before the statement (after comments)

  Statement() = default;
  Statement(Statement&&) noexcept = default;
  Statement& operator=(Statement&&) noexcept = default;
  Statement(const Statement& other);
  Statement& operator=(const Statement& other);

  const Clause* FindClause(std::string_view word) const;
};

struct Block {
  std::vector<Statement> statements;
  std::vector<Comment> closing_comments;  // comments after the last statement
  SourceRange range;                      // from `{` to `}`
  bool had_syntax_errors = false;         // a statement inside was skipped by recovery
  // Layout, like comments, and left out of Dump: `{` and `}` were on one line in the source, so
  // the formatter keeps the block on one line where it can (`time { end = 1 s  output_every = 1 ms
  // }`).
  bool one_line = false;
};

struct File {
  FileId file;
  Block body;  // the top-level statements; range covers the file
};

// A canonical, range-free S-expression of the tree: equal dumps mean equal trees. Used by
// `sled check --dump-ast`, the round-trip tests and the builder-versus-text test.
std::string Dump(const File& file);
std::string Dump(const Expr& expr);

}  // namespace sled::lang::ast
