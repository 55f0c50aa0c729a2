#include "lang/format/formatter.h"
#include "lang/syntax/lexical.h"

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "lang/source/utf8.h"
#include "lang/syntax/parser.h"

namespace sled::lang {
namespace {

constexpr std::size_t kIndentWidth = 2;
constexpr std::size_t kContinuationIndent = 4;
constexpr std::size_t kColumnLimit = 100;

bool HasOwnSpelling(const ast::Expr& expr) { return IsNumberSpelling(expr.text); }

int LevelOf(const ast::Expr& expr) {
  // A negative number without a spelling prints with a sign, which reads as unary minus.
  if (expr.kind == ast::ExprKind::kNumber && !HasOwnSpelling(expr) && expr.number < 0) {
    return kUnaryPrecedence;
  }
  return PrecedenceOf(expr.kind, expr.op);
}

void AppendUnit(const ast::Unit& unit, std::string& out) {
  // Factors keep their order (the tree is order-sensitive); a negative exponent after the first
  // factor is written with `/`, and a leading one as `s^-1` since `1/s` is not a unit.
  bool first = true;
  for (const ast::UnitFactor& factor : unit.factors) {
    int exponent = factor.exponent;
    if (!first) {
      out += exponent < 0 ? '/' : '*';
      if (exponent < 0) exponent = -exponent;
    }
    first = false;
    out += factor.symbol;
    if (exponent != 1) out += fmt::format("^{}", exponent);
  }
}

void AppendString(std::string_view text, std::string& out) {
  out += '"';
  for (const char c : text) {
    switch (c) {
      case '"':
        out += "\\\"";
        break;
      case '\\':
        out += "\\\\";
        break;
      case '\n':
        out += "\\n";
        break;
      case '\t':
        out += "\\t";
        break;
      case '\r':
        break;  // a string cannot hold a carriage return, and it has no escape
      default:
        out += c;
    }
  }
  out += '"';
}

void AppendExpr(const ast::Expr& expr, std::string& out);

void AppendOperand(const ast::Expr& expr, int min_level, std::string& out) {
  const bool parens = LevelOf(expr) < min_level;
  if (parens) out += '(';
  AppendExpr(expr, out);
  if (parens) out += ')';
}

void AppendPath(const std::vector<std::string>& path, std::string& out) {
  for (std::size_t i = 0; i < path.size(); ++i) {
    if (i > 0) out += '.';
    out += path[i];
  }
}

void AppendExpr(const ast::Expr& expr, std::string& out) {
  switch (expr.kind) {
    case ast::ExprKind::kNumber:
      out += HasOwnSpelling(expr) ? expr.text : fmt::format("{}", expr.number);
      if (expr.unit) {
        out += ' ';
        AppendUnit(*expr.unit, out);
      }
      return;
    case ast::ExprKind::kVector:
      out += '(';
      for (std::size_t i = 0; i < expr.operands.size(); ++i) {
        if (i > 0) out += ", ";
        AppendOperand(expr.operands[i], kArrowPrecedence, out);
      }
      // `(a,)` is a one-element vector; `(a)` would read back as a parenthesised value.
      if (expr.operands.size() == 1 && !expr.unit) out += ',';
      out += ')';
      if (expr.unit) {
        out += ' ';
        AppendUnit(*expr.unit, out);
      }
      return;
    case ast::ExprKind::kPath:
      AppendPath(expr.path, out);
      return;
    case ast::ExprKind::kString:
      AppendString(expr.text, out);
      return;
    case ast::ExprKind::kBool:
      out += expr.text;
      return;
    case ast::ExprKind::kCall:
      AppendPath(expr.path, out);
      out += '(';
      for (std::size_t i = 0; i < expr.arguments.size(); ++i) {
        const ast::Argument& argument = expr.arguments[i];
        if (i > 0) out += ", ";
        if (!argument.name.empty()) out += argument.name + " = ";
        if (argument.value) AppendOperand(*argument.value, kArrowPrecedence, out);
      }
      out += ')';
      return;
    case ast::ExprKind::kUnary:
      out += expr.op;
      if (!expr.operands.empty()) AppendOperand(expr.operands[0], kUnaryPrecedence, out);
      return;
    case ast::ExprKind::kBinary: {
      if (expr.operands.size() != 2) return;
      // Left-associative + - * /; `^` takes a primary on the left and a unary on the right.
      const int level = LevelOf(expr);
      const int left = level == kPowerPrecedence ? kPrimaryPrecedence : level;
      const int right = level == kPowerPrecedence ? kUnaryPrecedence : level + 1;
      // `^` binds tightest and is written tight, as in `length^2`, except after a unit, where
      // `2 m^2` would read as the unit m^2.
      const ast::Expr& base = expr.operands[0];
      const bool spaced =
          level != kPowerPrecedence ||
          ((base.kind == ast::ExprKind::kNumber || base.kind == ast::ExprKind::kVector) &&
           base.unit.has_value());
      AppendOperand(expr.operands[0], left, out);
      if (spaced) out += ' ';
      out += expr.op;
      if (spaced) out += ' ';
      AppendOperand(expr.operands[1], right, out);
      return;
    }
    case ast::ExprKind::kArrow:
      for (std::size_t i = 0; i < expr.operands.size(); ++i) {
        if (i > 0) out += " -> ";
        AppendOperand(expr.operands[i], kSumPrecedence, out);
      }
      return;
    case ast::ExprKind::kParen:
      out += '(';
      if (!expr.operands.empty()) AppendExpr(expr.operands[0], out);
      out += ')';
      return;
  }
}

std::string ExprText(const ast::Expr& expr) {
  std::string out;
  AppendExpr(expr, out);
  return out;
}

bool IsEmpty(const ast::Block& block) {
  return block.statements.empty() && block.closing_comments.empty();
}

class Printer {
 public:
  std::string Take() { return std::move(out_); }

  void PrintBlockBody(const ast::Block& block, std::size_t depth) {
    // One blank line is kept where the source had one or more; none opens a block or the file.
    bool first = true;
    auto blank_line = [&](bool wanted) {
      if (!first && wanted) out_ += '\n';
      first = false;
    };
    for (const ast::Statement& statement : block.statements) {
      for (const ast::Comment& comment : statement.leading_comments) {
        blank_line(comment.blank_line_before);
        PrintComment(comment, depth);
      }
      blank_line(statement.blank_line_before);
      PrintStatement(statement, depth);
    }
    for (const ast::Comment& comment : block.closing_comments) {
      blank_line(comment.blank_line_before);
      PrintComment(comment, depth);
    }
  }

 private:
  static std::string Indent(std::size_t depth) { return std::string(depth * kIndentWidth, ' '); }

  void PrintComment(const ast::Comment& comment, std::size_t depth) {
    out_ += Indent(depth);
    out_ += "//";
    out_ += comment.text;
    out_ += '\n';
  }

  void PrintStatement(const ast::Statement& statement, std::size_t depth) {
    const std::string indent = Indent(depth);
    std::string line = indent;
    if (statement.kind == ast::StatementKind::kRow) {
      if (!statement.values.empty()) AppendExpr(statement.values[0], line);
    } else {
      PrintHeader(statement, depth, line);
    }
    const bool has_body = statement.kind == ast::StatementKind::kHeader && statement.block &&
                          !IsEmpty(*statement.block);
    if (has_body && statement.block->one_line) {
      if (auto inside = OneLineBody(*statement.block);
          inside && CountCharacters(line) + 1 + CountCharacters(*inside) + 2 <= kColumnLimit) {
        line += ' ' + *inside + " }";
        AppendTrailingComment(statement, line);
        out_ += line + '\n';
        return;
      }
    }
    if (has_body) {
      out_ += line;
      out_ += '\n';
      PrintBlockBody(*statement.block, depth + 1);
      line = indent + "}";
    }
    AppendTrailingComment(statement, line);
    out_ += line;
    out_ += '\n';
  }

  static void AppendTrailingComment(const ast::Statement& statement, std::string& line) {
    if (!statement.trailing_comment) return;
    line += "  //";
    line += statement.trailing_comment->text;
  }

  // Whether a statement can follow another on one line without its start reading as part of the
  // other's value: `b = 100  ms` is `b = 100 ms`, and `5  -1 -> 2` is `5 - 1`. A `name = value`
  // attribute and a row that starts with a digit cannot.
  static bool StartsApart(const ast::Statement& statement, std::string_view text) {
    if (statement.kind == ast::StatementKind::kRow) {
      return !text.empty() && text[0] >= '0' && text[0] <= '9';
    }
    return !statement.target && statement.clauses.empty() && statement.has_value;
  }

  // Whether another statement may follow this one on its line: the grammar allows it only after
  // a value or a block. After a bare header the next name would read as its target (`positi  n =
  // 1` is `positi n = 1`) or as a clause.
  static bool EndsComplete(const ast::Statement& statement) {
    return statement.kind == ast::StatementKind::kRow || statement.has_value || statement.block;
  }

  // The statements of a block on one line, two spaces apart (`end = 1 s  output_every = 1 ms`),
  // or nullopt when one of them cannot share a line: it has a comment or a block of its own, or
  // its value list wraps.
  static std::optional<std::string> OneLineBody(const ast::Block& block) {
    if (!block.closing_comments.empty()) return std::nullopt;
    std::string inside;
    for (const ast::Statement& statement : block.statements) {
      if (!statement.leading_comments.empty() || statement.trailing_comment ||
          (statement.block && !IsEmpty(*statement.block))) {
        return std::nullopt;
      }
      Printer alone;
      alone.PrintStatement(statement, 0);
      std::string text = alone.Take();
      text.pop_back();  // the newline
      if (text.find('\n') != std::string::npos) return std::nullopt;
      if (&statement != &block.statements.back() && !EndsComplete(statement)) return std::nullopt;
      if (!inside.empty() && !StartsApart(statement, text)) return std::nullopt;
      if (!inside.empty()) inside += "  ";
      inside += text;
    }
    return inside;
  }

  // Appends `keyword target clause... = values {` to `line`, flushing whole lines to the output
  // when a long value list wraps.
  void PrintHeader(const ast::Statement& statement, std::size_t depth, std::string& line) {
    line += statement.keyword;
    if (statement.target) {
      line += ' ';
      AppendExpr(*statement.target, line);
    }
    for (const ast::Clause& clause : statement.clauses) {
      line += ' ';
      line += clause.word;
      line += ' ';
      AppendExpr(clause.value, line);
    }
    std::string opener;
    if (statement.block) opener = IsEmpty(*statement.block) ? " {}" : " {";
    if (!statement.has_value) {
      line += opener;
      return;
    }
    line += " =";
    std::vector<std::string> values;
    std::size_t total = CountCharacters(line) + CountCharacters(opener);
    for (const ast::Expr& value : statement.values) {
      values.push_back(ExprText(value));
      total += 2 + CountCharacters(values.back());  // ", " or the space after `=`
    }
    const bool wrap = total > kColumnLimit && values.size() > 1;
    const std::string continuation = std::string(depth * kIndentWidth + kContinuationIndent, ' ');
    for (std::size_t i = 0; i < values.size(); ++i) {
      if (i == 0) {
        line += ' ';
      } else if (wrap) {
        // What must still fit on this line after the value: its comma, or the `{` at the end.
        const std::size_t after = i + 1 == values.size() ? CountCharacters(opener) : 1;
        if (CountCharacters(line) + 2 + CountCharacters(values[i]) + after > kColumnLimit) {
          out_ += line;
          out_ += ",\n";
          line = continuation;
        } else {
          line += ", ";
        }
      } else {
        line += ", ";
      }
      line += values[i];
    }
    line += opener;
  }

  std::string out_;
};

}  // namespace

std::string Format(const ast::File& file) {
  Printer printer;
  printer.PrintBlockBody(file.body, 0);
  return printer.Take();
}

std::string Format(const ast::Expr& expr) { return ExprText(expr); }

std::optional<std::string> FormatBuffer(const SourceManager& sources, FileId file,
                                        DiagnosticConsumer& diagnostics) {
  ErrorTrackingConsumer tracking(diagnostics);
  ParseOptions options;
  options.diagnostics = &tracking;
  const ast::File tree = Parse(sources, file, options);
  if (tracking.seen_error()) return std::nullopt;
  return Format(tree);
}

}  // namespace sled::lang
