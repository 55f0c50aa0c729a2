#include "lang/builder/builder.h"
#include "lang/syntax/lexical.h"

#include <charconv>
#include <cmath>
#include <map>
#include <stdexcept>
#include <utility>

#include <fmt/format.h>

namespace sled::lang::build {

struct Value::Node {
  ast::ExprKind kind = ast::ExprKind::kNumber;
  double number = 0.0;
  std::string text;
  std::vector<std::string> path;
  std::optional<ast::Unit> unit;  // factors only; ranges are set when the tree is made
  char op = 0;
  std::vector<Value> operands;
  std::vector<Arg> arguments;
  SourceLocation where;
};

// Reaches the private parts of values and statements for the functions of this file.
class Access {
 public:
  static const Value::Node& NodeOf(const Value& value) { return *value.node_; }
  static Value Make(Value::Node node) {
    return Value(std::make_shared<const Value::Node>(std::move(node)));
  }
  static ast::StatementKind Kind(const Statement& s) { return s.kind_; }
  static const std::string& Keyword(const Statement& s) { return s.keyword_; }
  static const std::optional<Value>& Target(const Statement& s) { return s.target_; }
  static const auto& Clauses(const Statement& s) { return s.clauses_; }
  static bool HasValue(const Statement& s) { return s.has_value_; }
  static const std::vector<Value>& Values(const Statement& s) { return s.values_; }
  static bool HasBlock(const Statement& s) { return s.block_ || !s.children_.empty(); }
  static const auto& Children(const Statement& s) { return s.children_; }
  static const SourceLocation& Where(const Statement& s) { return s.where_; }
};

namespace {

using Node = Value::Node;

// --- Programming errors ---------------------------------------------------------------------

[[noreturn]] void Fail(std::string_view function, const SourceLocation& where,
                       std::string_view message) {
  throw std::invalid_argument(fmt::format("sled::lang::build::{}: {} (called at {}:{}:{})",
                                          function, message, where.file_name(), where.line(),
                                          where.column()));
}

bool IsIdentifierFirst(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
}
bool IsIdentifierOther(char c) { return IsIdentifierFirst(c) || (c >= '0' && c <= '9'); }

bool IsIdentifier(std::string_view text) {
  if (text.empty() || !IsIdentifierFirst(text[0])) return false;
  for (const char c : text) {
    if (!IsIdentifierOther(c)) return false;
  }
  return true;
}

// Words the grammar never reads as a name: booleans and clause words.
bool IsReserved(std::string_view word) {
  return word == "true" || word == "false" || word == "on" || word == "with" || word == "at" ||
         word == "as" || word == "filter" || word == "relative_to" || word == "expressed_in";
}

// A plain name: an identifier that is not a reserved word.
void CheckName(std::string_view name, std::string_view what, std::string_view function,
               const SourceLocation& where) {
  if (!IsIdentifier(name)) {
    Fail(function, where,
         fmt::format("{} `{}` is not a name (letters, digits and `_`, not starting with a digit)",
                     what, name));
  }
  if (IsReserved(name)) {
    Fail(function, where, fmt::format("{} `{}` is a reserved word", what, name));
  }
}

void CheckKeyword(std::string_view keyword, std::string_view function,
                  const SourceLocation& where) {
  if (!IsIdentifier(keyword) || keyword == "true" || keyword == "false") {
    Fail(function, where, fmt::format("`{}` is not a statement keyword", keyword));
  }
}

std::vector<std::string> SplitPath(std::string_view text, std::string_view function,
                                   const SourceLocation& where) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  while (true) {
    const std::size_t dot = text.find('.', start);
    const std::string_view part = text.substr(start, dot - start);
    CheckName(part, fmt::format("name part of `{}`", text), function, where);
    parts.emplace_back(part);
    if (dot == std::string_view::npos) break;
    start = dot + 1;
  }
  return parts;
}

// A unit as the grammar reads it: factor {("*" | "/") factor}, factor = name ["^" ["-"] digits].
// A factor after `/` has a negative exponent; `*` after `/` multiplies again (N/m*s is N*s/m).
std::optional<ast::Unit> ParseUnit(std::string_view text, std::string_view function,
                                   const SourceLocation& where) {
  if (text.empty()) return std::nullopt;
  auto malformed = [&](std::string_view why) {
    Fail(function, where,
         fmt::format("malformed unit `{}`: {}; write factors joined by `*` and `/`, each "
                     "with an optional `^n`, without spaces, as in `N*m/deg` or `m/s^2`",
                     text, why));
  };
  ast::Unit unit;
  std::size_t i = 0;
  int sign = 1;
  while (true) {
    const std::size_t start = i;
    while (i < text.size() && IsIdentifierOther(text[i])) ++i;
    const std::string_view symbol = text.substr(start, i - start);
    if (symbol.empty()) malformed("a unit symbol is missing");
    if (!IsIdentifier(symbol)) malformed(fmt::format("`{}` is not a unit symbol", symbol));
    if (IsReserved(symbol)) malformed(fmt::format("`{}` is a reserved word", symbol));
    ast::UnitFactor factor;
    factor.symbol = std::string(symbol);
    factor.exponent = sign;
    sign = 1;
    if (i < text.size() && text[i] == '^') {
      ++i;
      const bool negative = i < text.size() && text[i] == '-';
      if (negative) ++i;
      const std::size_t digits = i;
      while (i < text.size() && text[i] >= '0' && text[i] <= '9') ++i;
      int exponent = 0;
      const auto [end, error] = std::from_chars(text.data() + digits, text.data() + i, exponent);
      if (digits == i || error != std::errc() || end != text.data() + i || exponent > 1000) {
        malformed("`^` needs a small whole number");
      }
      factor.exponent *= negative ? -exponent : exponent;
    }
    unit.factors.push_back(std::move(factor));
    if (i == text.size()) break;
    if (text[i] == '/') {
      sign = -1;
    } else if (text[i] != '*') {
      malformed(fmt::format("unexpected `{}`", text[i]));
    }
    ++i;
  }
  return unit;
}

// --- Precedence, as the grammar and the formatter see it ------------------------------------

int LevelOf(const Node& node) {
  return PrecedenceOf(node.kind, node.op);  // numbers are never negative here: see MakeQuantity
}

// The operand, in parentheses when it binds more loosely than its place allows, so that the
// printed text parses back to this tree.
Value Bracket(Value operand, int min_level) {
  const Node& node = Access::NodeOf(operand);
  if (LevelOf(node) >= min_level) return operand;
  Node paren;
  paren.kind = ast::ExprKind::kParen;
  paren.where = node.where;
  paren.operands.push_back(std::move(operand));
  return Access::Make(std::move(paren));
}

Value MakeBinary(char op, Value left, Value right) {
  Node node;
  node.kind = ast::ExprKind::kBinary;
  node.op = op;
  node.where = Access::NodeOf(left).where;
  const int level = LevelOf(node);
  node.operands.push_back(
      Bracket(std::move(left), level == kPowerPrecedence ? kPrimaryPrecedence : level));
  node.operands.push_back(
      Bracket(std::move(right), level == kPowerPrecedence ? kUnaryPrecedence : level + 1));
  return Access::Make(std::move(node));
}

Value MakeUnary(Value operand, const SourceLocation& where) {
  Node node;
  node.kind = ast::ExprKind::kUnary;
  node.op = '-';
  node.where = where;
  node.operands.push_back(Bracket(std::move(operand), kUnaryPrecedence));
  return Access::Make(std::move(node));
}

// A number as the parser reads it: the magnitude with its shortest round-trip spelling, and a
// unary minus for a negative value (`-9.81 m/s^2` is -(9.81 m/s^2)).
Value MakeQuantity(double number, std::optional<ast::Unit> unit, std::string_view function,
                   const SourceLocation& where) {
  if (!std::isfinite(number)) {
    Fail(function, where, fmt::format("{} is not a finite number", number));
  }
  Node node;
  node.kind = ast::ExprKind::kNumber;
  node.number = std::fabs(number);
  node.text = fmt::format("{}", node.number);
  node.unit = std::move(unit);
  node.where = where;
  Value magnitude = Access::Make(std::move(node));
  if (!std::signbit(number)) return magnitude;
  return MakeUnary(std::move(magnitude), where);
}

// A row cannot start with a name: the text would read as a statement keyword.
bool StartsWithName(const Node& node) {
  switch (node.kind) {
    case ast::ExprKind::kPath:
    case ast::ExprKind::kCall:
    case ast::ExprKind::kBool:
      return true;
    case ast::ExprKind::kBinary:
    case ast::ExprKind::kArrow:
      return StartsWithName(Access::NodeOf(node.operands.at(0)));
    default:
      return false;
  }
}

}  // namespace

// --- Values -----------------------------------------------------------------------------------

std::shared_ptr<const Value::Node> Value::MakeNumber(double number, const SourceLocation& where) {
  return MakeQuantity(number, std::nullopt, "Value", where).node_;
}

std::shared_ptr<const Value::Node> Value::MakeBool(bool value, const SourceLocation& where) {
  auto node = std::make_shared<Node>();
  node->kind = ast::ExprKind::kBool;
  node->text = value ? "true" : "false";
  node->where = where;
  return node;
}

Value Q(double number, std::string_view unit, SourceLocation where) {
  return MakeQuantity(number, ParseUnit(unit, "Q", where), "Q", where);
}

Value Vector(std::initializer_list<Value> components, std::string_view unit, SourceLocation where) {
  if (components.size() < 2) Fail("Vector", where, "a vector has at least two components");
  Node node;
  node.kind = ast::ExprKind::kVector;
  node.operands.assign(components.begin(), components.end());
  node.unit = ParseUnit(unit, "Vector", where);
  node.where = where;
  return Access::Make(std::move(node));
}

Value V(Value x, Value y, Value z, std::string_view unit, SourceLocation where) {
  Node node;
  node.kind = ast::ExprKind::kVector;
  node.operands = {std::move(x), std::move(y), std::move(z)};
  node.unit = ParseUnit(unit, "V", where);
  node.where = where;
  return Access::Make(std::move(node));
}

Value Ref(std::string_view path, SourceLocation where) {
  Node node;
  node.kind = ast::ExprKind::kPath;
  node.path = SplitPath(path, "Ref", where);
  node.where = where;
  return Access::Make(std::move(node));
}

Value Str(std::string_view text, SourceLocation where) {
  if (text.find('\r') != std::string_view::npos) {
    Fail("Str", where, "a string cannot hold a carriage return");
  }
  Node node;
  node.kind = ast::ExprKind::kString;
  node.text = std::string(text);
  node.where = where;
  return Access::Make(std::move(node));
}

Value Call(std::string_view callee, std::initializer_list<Arg> arguments, SourceLocation where) {
  Node node;
  node.kind = ast::ExprKind::kCall;
  node.path = SplitPath(callee, "Call", where);
  for (const Arg& argument : arguments) {
    if (!argument.name.empty() && !IsIdentifier(argument.name)) {
      Fail("Call", where, fmt::format("argument name `{}` is not a name", argument.name));
    }
    node.arguments.push_back(argument);
  }
  node.where = where;
  return Access::Make(std::move(node));
}

Value Arrow(std::initializer_list<Value> chain, SourceLocation where) {
  if (chain.size() < 2) Fail("Arrow", where, "an arrow chain has at least two values");
  Node node;
  node.kind = ast::ExprKind::kArrow;
  for (const Value& value : chain) node.operands.push_back(Bracket(value, kSumPrecedence));
  node.where = where;
  return Access::Make(std::move(node));
}

Value Arrow(Value from, Value to, SourceLocation where) {
  return Arrow({std::move(from), std::move(to)}, where);
}

Value Table(std::string_view from, std::string_view to, SourceLocation where) {
  return Call("table", {Arrow(Ref(from, where), Ref(to, where), where)}, where);
}

Value Neg(Value operand, SourceLocation where) { return MakeUnary(std::move(operand), where); }

Value Pow(Value base, Value exponent, SourceLocation where) {
  Value power = MakeBinary('^', std::move(base), std::move(exponent));
  Node node = Access::NodeOf(power);
  node.where = where;
  return Access::Make(std::move(node));
}

Value Paren(Value inner, SourceLocation where) {
  Node node;
  node.kind = ast::ExprKind::kParen;
  node.operands.push_back(std::move(inner));
  node.where = where;
  return Access::Make(std::move(node));
}

Value operator+(Value left, Value right) {
  return MakeBinary('+', std::move(left), std::move(right));
}
Value operator-(Value left, Value right) {
  return MakeBinary('-', std::move(left), std::move(right));
}
Value operator*(Value left, Value right) {
  return MakeBinary('*', std::move(left), std::move(right));
}
Value operator/(Value left, Value right) {
  return MakeBinary('/', std::move(left), std::move(right));
}
Value operator-(Value operand) {
  const SourceLocation where = Access::NodeOf(operand).where;
  return MakeUnary(std::move(operand), where);
}

// --- From builder nodes to the AST ----------------------------------------------------------

namespace {

// Turns C++ call sites into ranges of the C++ source buffers in a SourceManager.
class Sites {
 public:
  explicit Sites(SourceManager& sources) : sources_(sources) {}

  SourceRange RangeOf(const SourceLocation& where) {
    const std::uint32_t line = where.line() == 0 ? 1 : where.line();
    const FileId file = FileFor(where.file_name(), line);
    const SourceBuffer& buffer = sources_.buffer(file);
    const std::uint32_t start = buffer.OffsetOf(line, 1);
    const std::string_view text = buffer.Line(line);
    const auto [begin, end] = SpanAt(text, where.column() == 0 ? 0 : where.column() - 1);
    return {file, start + begin, start + end};
  }

  FileId FileFor(const char* path, std::uint32_t line) {
    auto it = files_.find(path);
    if (it != files_.end() && sources_.buffer(it->second).line_count() >= line) return it->second;
    std::optional<FileId> file = sources_.Find(path);
    if (!file || sources_.buffer(*file).line_count() < line) file = sources_.Load(path);
    if (!file || sources_.buffer(*file).line_count() < line) {
      // The C++ file cannot be read (or is not the one compiled): empty lines keep the numbers.
      file = sources_.Add(path, std::string(std::max<std::uint32_t>(2 * line, 1024), '\n'));
    }
    files_[path] = *file;
    return *file;
  }

 private:
  // The call at a (0-based, byte) column of a line: GCC places a call at its `(`, Clang at the
  // start of the expression. Either way the span is the callee's name through the matching `)`
  // on the same line (or the rest of the line), or the token there (an implicitly converted
  // number under Clang).
  static std::pair<std::uint32_t, std::uint32_t> SpanAt(std::string_view text,
                                                        std::uint32_t column) {
    const auto size = static_cast<std::uint32_t>(text.size());
    if (column >= size) return {size, size};
    std::uint32_t begin = column;
    std::uint32_t open = column;
    if (text[column] == ')' || text[column] == '}') {
      // GCC places a constructor call `Scene scene(...)` at its closing bracket.
      const char close = text[column];
      const char opening = close == ')' ? '(' : '{';
      int depth = 0;
      bool quoted = false;
      for (std::uint32_t i = column + 1; i-- > 0;) {
        const char c = text[i];
        if (c == '"' && (i == 0 || text[i - 1] != '\\')) quoted = !quoted;
        if (quoted) continue;
        if (c == close) ++depth;
        if (c == opening && --depth == 0) {
          begin = i;
          while (begin > 0 && IsIdentifierOther(text[begin - 1])) --begin;
          return {begin, column + 1};
        }
      }
      return {column, column + 1};
    }
    if (text[column] != '(') {
      std::uint32_t i = column;
      if (text[i] == '-' || text[i] == '+') ++i;
      while (i < size && (IsIdentifierOther(text[i]) || text[i] == '.' || text[i] == ':')) ++i;
      if (i == size || text[i] != '(') return {begin, std::max(i, begin + 1)};
      open = i;
    } else {
      while (begin > 0 && (IsIdentifierOther(text[begin - 1]) || text[begin - 1] == ':')) --begin;
    }
    int depth = 0;
    for (std::uint32_t i = open; i < size; ++i) {
      const char c = text[i];
      if (c == '"' || c == '\'') {
        for (++i; i < size && text[i] != c; ++i) {
          if (text[i] == '\\') ++i;
        }
        continue;
      }
      if (c == '(') ++depth;
      if (c == ')' && --depth == 0) return {begin, i + 1};
    }
    std::uint32_t end = size;
    while (end > begin && (text[end - 1] == ' ' || text[end - 1] == '\t')) --end;
    return {begin, end};
  }

  SourceManager& sources_;
  std::map<std::string, FileId, std::less<>> files_;
};

ast::Expr MakeExpr(const Value& value, Sites* sites) {
  const Node& node = Access::NodeOf(value);
  ast::Expr expr;
  expr.kind = node.kind;
  expr.range = sites ? sites->RangeOf(node.where) : SourceRange{};
  expr.number = node.number;
  expr.text = node.text;
  expr.path = node.path;
  expr.op = node.op;
  if (node.unit) {
    expr.unit = node.unit;
    expr.unit->range = expr.range;
    for (ast::UnitFactor& factor : expr.unit->factors) factor.range = expr.range;
  }
  for (const Value& operand : node.operands) expr.operands.push_back(MakeExpr(operand, sites));
  for (const Arg& argument : node.arguments) {
    expr.arguments.push_back({argument.name, argument.name.empty() ? SourceRange{} : expr.range,
                              std::make_unique<ast::Expr>(MakeExpr(argument.value, sites))});
  }
  // Arithmetic made by C++ operators has no call of its own: it spans its operands.
  if (expr.kind == ast::ExprKind::kBinary && expr.operands.size() == 2) {
    const SourceRange& left = expr.operands[0].range;
    const SourceRange& right = expr.operands[1].range;
    if (left.file == right.file) expr.range = Join(left, right);
  }
  return expr;
}

ast::Statement MakeStatement(const Statement& source, Sites& sites) {
  ast::Statement statement;
  statement.kind = Access::Kind(source);
  statement.keyword = Access::Keyword(source);
  statement.range = sites.RangeOf(Access::Where(source));
  if (statement.kind == ast::StatementKind::kHeader) statement.keyword_range = statement.range;
  if (Access::Target(source)) statement.target = MakeExpr(*Access::Target(source), &sites);
  for (const auto& clause : Access::Clauses(source)) {
    statement.clauses.push_back(
        {clause.word, sites.RangeOf(clause.where), MakeExpr(clause.value, &sites)});
  }
  statement.has_value = Access::HasValue(source);
  for (const Value& value : Access::Values(source)) {
    statement.values.push_back(MakeExpr(value, &sites));
  }
  if (statement.kind == ast::StatementKind::kRow) {
    // A row's arrow spans the row, as the parser makes it.
    statement.values.at(0).range = statement.range;
  }
  if (Access::HasBlock(source)) {
    statement.block = std::make_unique<ast::Block>();
    statement.block->range = statement.range;
    bool previous_had_block = false;
    for (const auto& child : Access::Children(source)) {
      ast::Statement made = MakeStatement(*child, sites);
      // Blank lines around statements with blocks, so the formatted text reads well.
      const bool has_block = made.block != nullptr;
      made.blank_line_before =
          !statement.block->statements.empty() && (has_block || previous_had_block);
      previous_had_block = has_block;
      statement.block->statements.push_back(std::move(made));
    }
  }
  return statement;
}

}  // namespace

ast::Expr Value::ToExpr() const { return MakeExpr(*this, nullptr); }

// --- Statements -------------------------------------------------------------------------------

Statement::Statement(ast::StatementKind kind, std::string_view keyword, bool block,
                     const SourceLocation& where, const char* function)
    : kind_(kind), keyword_(keyword), block_(block), where_(where) {
  if (kind == ast::StatementKind::kHeader) CheckKeyword(keyword, function, where);
}

Statement::~Statement() = default;

Statement& Statement::AddChild(std::unique_ptr<Statement> child) {
  if (kind_ == ast::StatementKind::kRow) {
    Fail("Statement", where_, "a table row has no block");
  }
  children_.push_back(std::move(child));
  return *children_.back();
}

Statement& Statement::On(Value frame, SourceLocation where) {
  clauses_.push_back({"on", std::move(frame), where});
  return *this;
}

Statement& Statement::With(Value other, SourceLocation where) {
  clauses_.push_back({"with", std::move(other), where});
  return *this;
}

Statement& Statement::At(Value point, SourceLocation where) {
  clauses_.push_back({"at", std::move(point), where});
  return *this;
}

Statement& Statement::As(std::string_view name, SourceLocation where) {
  CheckName(name, "name", "As", where);
  clauses_.push_back({"as", Ref(name, where), where});
  return *this;
}

Statement& Statement::Filter(std::string_view filter_class, SourceLocation where) {
  CheckName(filter_class, "filter class", "Filter", where);
  clauses_.push_back({"filter", Ref(filter_class, where), where});
  return *this;
}

Statement& Statement::RelativeTo(Value frame, SourceLocation where) {
  clauses_.push_back({"relative_to", std::move(frame), where});
  return *this;
}

Statement& Statement::Is(Value value, SourceLocation where) {
  clauses_.push_back({":", std::move(value), where});
  return *this;
}

Statement& Statement::Equals(Value value) {
  has_value_ = true;
  values_.push_back(std::move(value));
  return *this;
}

Statement& Statement::Set(std::string_view attribute, Value value, SourceLocation where) {
  Attribute(attribute, std::move(value), where);
  return *this;
}

Statement& Statement::Set(std::string_view attribute, std::initializer_list<Value> values,
                          SourceLocation where) {
  if (values.size() == 0) Fail("Set", where, fmt::format("`{}` needs a value", attribute));
  Statement& child = Add(attribute, where);
  for (const Value& value : values) child.Equals(value);
  return *this;
}

Statement& Statement::Set(std::string_view attribute, std::string_view target, Value value,
                          SourceLocation where) {
  Add(attribute, target, where).Equals(std::move(value));
  return *this;
}

Statement& Statement::Row(Value from, Value to, SourceLocation where) {
  return Row({std::move(from), std::move(to)}, where);
}

Statement& Statement::Row(std::initializer_list<Value> values, SourceLocation where) {
  if (values.size() < 2) Fail("Row", where, "a row has at least two values: `x -> y`");
  Value arrow = Arrow(values, where);
  if (StartsWithName(Access::NodeOf(arrow))) {
    Fail("Row", where, "a row cannot start with a name; it would read as a statement");
  }
  auto row =
      std::unique_ptr<Statement>(new Statement(ast::StatementKind::kRow, {}, false, where, "Row"));
  row->has_value_ = false;
  row->values_.push_back(std::move(arrow));
  AddChild(std::move(row));
  return *this;
}

Statement& Statement::Param(std::string_view name, Value value, SourceLocation where) {
  Add("param", name, where).Equals(std::move(value));
  return *this;
}

Statement& Statement::Let(std::string_view name, Value value, SourceLocation where) {
  Add("let", name, where).Equals(std::move(value));
  return *this;
}

Statement& Statement::Import(std::string_view module, std::string_view alias,
                             SourceLocation where) {
  Statement& child = Add("import", module, where);
  if (!alias.empty()) child.As(alias, where);
  return *this;
}

Statement& Statement::Declare(std::string_view keyword, std::string_view name,
                              SourceLocation where) {
  return Declare(keyword, Ref(name, where), where);
}

Statement& Statement::Declare(std::string_view keyword, Value target, SourceLocation where) {
  const ast::ExprKind kind = Access::NodeOf(target).kind;
  if (kind != ast::ExprKind::kPath && kind != ast::ExprKind::kString) {
    Fail("Declare", where, "a statement's target is a name or a string");
  }
  Statement& child = Block(keyword, where);
  child.target_ = std::move(target);
  return child;
}

Statement& Statement::Block(std::string_view keyword, SourceLocation where) {
  return AddChild(std::unique_ptr<Statement>(
      new Statement(ast::StatementKind::kHeader, keyword, true, where, "Block")));
}

Statement& Statement::Add(std::string_view keyword, SourceLocation where) {
  return AddChild(std::unique_ptr<Statement>(
      new Statement(ast::StatementKind::kHeader, keyword, false, where, "Add")));
}

Statement& Statement::Add(std::string_view keyword, std::string_view target, SourceLocation where) {
  Statement& child = Add(keyword, where);
  child.target_ = Ref(target, where);
  return child;
}

Statement& Statement::Attribute(std::string_view attribute, Value value, SourceLocation where) {
  return Add(attribute, where).Equals(std::move(value));
}

Statement& Statement::Function(std::string_view name, Value value, SourceLocation where) {
  return Add("function", name, where).Equals(std::move(value));
}

Statement& Statement::Joint(std::string_view name, std::string_view type, std::string_view parent,
                            std::string_view child, SourceLocation where) {
  return Declare("joint", name, where)
      .Is(Call(type, {Arrow(Ref(parent, where), Ref(child, where), where)}, where), where);
}

// --- Scene ------------------------------------------------------------------------------------

Scene::Scene(SourceManager& sources, std::string_view title, SourceLocation where)
    : Statement(ast::StatementKind::kHeader, "scenario", true, where, "Scene"), sources_(sources) {
  target_ = Str(title, where);
}

ast::File Scene::Finish() const {
  Sites sites(sources_);
  ast::File file;
  ast::Statement scenario = MakeStatement(*this, sites);
  file.file = scenario.range.file;
  file.body.range = {file.file, 0,
                     static_cast<std::uint32_t>(sources_.buffer(file.file).text().size())};
  file.body.statements.push_back(std::move(scenario));
  return file;
}

}  // namespace sled::lang::build
