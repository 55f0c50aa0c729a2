#include "lang/ast/ast.h"

#include <fmt/format.h>

namespace sled::lang::ast {

Expr::Expr(const Expr& other)
    : kind(other.kind),
      range(other.range),
      number(other.number),
      text(other.text),
      path(other.path),
      unit(other.unit),
      op(other.op),
      operands(other.operands) {
  arguments.reserve(other.arguments.size());
  for (const Argument& argument : other.arguments) {
    arguments.push_back({argument.name, argument.name_range,
                         argument.value ? std::make_unique<Expr>(*argument.value) : nullptr});
  }
}

Expr& Expr::operator=(const Expr& other) {
  if (this != &other) *this = Expr(other);
  return *this;
}

std::string Expr::PathText() const {
  std::string text_out;
  for (const std::string& part : path) {
    if (!text_out.empty()) text_out += '.';
    text_out += part;
  }
  return text_out;
}

Statement::Statement(const Statement& other)
    : kind(other.kind),
      keyword(other.keyword),
      keyword_range(other.keyword_range),
      target(other.target),
      clauses(other.clauses),
      has_value(other.has_value),
      values(other.values),
      block(other.block ? std::make_unique<Block>(*other.block) : nullptr),
      range(other.range),
      leading_comments(other.leading_comments),
      trailing_comment(other.trailing_comment),
      blank_line_before(other.blank_line_before) {}

Statement& Statement::operator=(const Statement& other) {
  if (this != &other) *this = Statement(other);
  return *this;
}

const Clause* Statement::FindClause(std::string_view word) const {
  for (const Clause& clause : clauses) {
    if (clause.word == word) return &clause;
  }
  return nullptr;
}

namespace {

void DumpUnit(const Unit& unit, std::string& out) {
  out += " [";
  bool first = true;
  for (const UnitFactor& factor : unit.factors) {
    if (!first) out += ' ';
    first = false;
    out +=
        factor.exponent == 1 ? factor.symbol : fmt::format("{}^{}", factor.symbol, factor.exponent);
  }
  out += ']';
}

void DumpBlock(const Block& block, int depth, std::string& out);

void DumpExpr(const Expr& expr, std::string& out) {
  switch (expr.kind) {
    case ExprKind::kNumber:
      out += fmt::format("(num {}", expr.number);
      if (expr.unit) DumpUnit(*expr.unit, out);
      out += ')';
      return;
    case ExprKind::kVector:
      out += "(vec";
      for (const Expr& operand : expr.operands) {
        out += ' ';
        DumpExpr(operand, out);
      }
      if (expr.unit) DumpUnit(*expr.unit, out);
      out += ')';
      return;
    case ExprKind::kPath:
      out += fmt::format("(path {})", expr.PathText());
      return;
    case ExprKind::kString:
      out += fmt::format("(str \"{}\")", expr.text);
      return;
    case ExprKind::kBool:
      out += fmt::format("(bool {})", expr.text);
      return;
    case ExprKind::kCall:
      out += fmt::format("(call {}", expr.PathText());
      for (const Argument& argument : expr.arguments) {
        out += argument.name.empty() ? " " : fmt::format(" {}=", argument.name);
        if (argument.value) DumpExpr(*argument.value, out);
      }
      out += ')';
      return;
    case ExprKind::kUnary:
      out += fmt::format("({} ", expr.op);
      DumpExpr(expr.operands.at(0), out);
      out += ')';
      return;
    case ExprKind::kBinary:
      out += fmt::format("({} ", expr.op);
      DumpExpr(expr.operands.at(0), out);
      out += ' ';
      DumpExpr(expr.operands.at(1), out);
      out += ')';
      return;
    case ExprKind::kArrow:
      out += "(->";
      for (const Expr& operand : expr.operands) {
        out += ' ';
        DumpExpr(operand, out);
      }
      out += ')';
      return;
    case ExprKind::kParen:
      out += "(paren ";
      DumpExpr(expr.operands.at(0), out);
      out += ')';
      return;
  }
}

void DumpStatement(const Statement& statement, int depth, std::string& out) {
  out += std::string(static_cast<std::size_t>(depth) * 2, ' ');
  if (statement.kind == StatementKind::kRow) {
    out += "(row ";
    DumpExpr(statement.values.at(0), out);
    out += ")\n";
    return;
  }
  out += fmt::format("({}", statement.keyword);
  if (statement.target) {
    out += " target=";
    DumpExpr(*statement.target, out);
  }
  for (const Clause& clause : statement.clauses) {
    out += fmt::format(" {}=", clause.word);
    DumpExpr(clause.value, out);
  }
  if (statement.has_value) {
    out += " =";
    for (const Expr& value : statement.values) {
      out += ' ';
      DumpExpr(value, out);
    }
  }
  if (statement.block) {
    out += ' ';
    DumpBlock(*statement.block, depth, out);
  }
  out += ")\n";
}

void DumpBlock(const Block& block, int depth, std::string& out) {
  out += "{\n";
  for (const Statement& statement : block.statements) DumpStatement(statement, depth + 1, out);
  out += std::string(static_cast<std::size_t>(depth) * 2, ' ') + "}";
}

}  // namespace

std::string Dump(const File& file) {
  std::string out;
  for (const Statement& statement : file.body.statements) DumpStatement(statement, 0, out);
  return out;
}

std::string Dump(const Expr& expr) {
  std::string out;
  DumpExpr(expr, out);
  return out;
}

}  // namespace sled::lang::ast
