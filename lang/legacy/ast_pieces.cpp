// The pieces of the scenario tree the deck mapping builds: numbers with the deck's units,
// vectors, paths, calls, statements, card comments and names from deck labels.
#include "lang/legacy/ast_pieces.h"

#include <cctype>
#include <cmath>
#include <memory>

#include <fmt/format.h>

#include "lang/ast/make_expr.h"

namespace sled::lang::legacy::mapping {

// --- Building the tree --------------------------------------------------------------------

ast::Unit MakeUnit(std::string_view text) {
  ast::Unit unit;
  int sign = 1;
  std::size_t i = 0;
  while (i < text.size()) {
    std::size_t end = text.find_first_of("*/", i);
    if (end == std::string_view::npos) end = text.size();
    std::string_view factor = text.substr(i, end - i);
    int exponent = 1;
    const std::size_t caret = factor.find('^');
    if (caret != std::string_view::npos) {
      exponent = std::stoi(std::string(factor.substr(caret + 1)));
      factor = factor.substr(0, caret);
    }
    unit.factors.push_back({std::string(factor), sign * exponent, {}});
    if (end < text.size()) sign = text[end] == '/' ? -1 : 1;
    i = end + 1;
  }
  return unit;
}

ast::Expr Number(double value, std::string_view unit) {
  ast::Expr expr;
  expr.kind = ast::ExprKind::kNumber;
  expr.number = value == 0 ? 0.0 : value;  // never print `-0`
  if (!unit.empty()) expr.unit = MakeUnit(unit);
  return expr;
}

ast::Expr Vector(const Vec3& v, std::string_view unit) {
  ast::Expr expr;
  expr.kind = ast::ExprKind::kVector;
  for (const double c : v) expr.operands.push_back(Number(c));
  if (!unit.empty()) expr.unit = MakeUnit(unit);
  return expr;
}

ast::Expr Path(const std::string& dotted) {
  ast::Expr expr;
  expr.kind = ast::ExprKind::kPath;
  std::size_t start = 0;
  while (true) {
    const std::size_t dot = dotted.find('.', start);
    expr.path.push_back(dotted.substr(start, dot - start));
    if (dot == std::string::npos) break;
    start = dot + 1;
  }
  return expr;
}

ast::Expr String(std::string text) {
  ast::Expr expr;
  expr.kind = ast::ExprKind::kString;
  expr.text = std::move(text);
  return expr;
}

ast::Expr Boolean(bool value) {
  ast::Expr expr;
  expr.kind = ast::ExprKind::kBool;
  expr.text = value ? "true" : "false";
  return expr;
}

ast::Expr Call(std::string callee, std::vector<std::pair<std::string, ast::Expr>> arguments) {
  ast::Expr expr;
  expr.kind = ast::ExprKind::kCall;
  expr.path.push_back(std::move(callee));
  for (auto& argument : arguments) {
    expr.arguments.push_back(
        {std::move(argument.first), {}, std::make_unique<ast::Expr>(std::move(argument.second))});
  }
  return expr;
}

ast::Statement Attribute(std::string keyword, ast::Expr value) {
  ast::Statement statement;
  statement.keyword = std::move(keyword);
  statement.has_value = true;
  statement.values.push_back(std::move(value));
  return statement;
}

ast::Statement Declaration(std::string keyword, ast::Expr target, std::string comment) {
  ast::Statement statement;
  statement.keyword = std::move(keyword);
  statement.target = std::move(target);
  statement.block = std::make_unique<ast::Block>();
  if (!comment.empty()) statement.leading_comments.push_back({" " + std::move(comment), {}, false});
  return statement;
}

void Add(ast::Statement& parent, ast::Statement child) {
  parent.block->statements.push_back(std::move(child));
}

ast::Statement Row(ast::Expr from, ast::Expr to) {
  ast::Statement row;
  row.kind = ast::StatementKind::kRow;
  std::vector<ast::Expr> chain;
  chain.push_back(std::move(from));
  chain.push_back(std::move(to));
  row.values.push_back(ast::MakeArrow(std::move(chain)));
  return row;
}

std::string CardComment(std::string_view card, std::uint32_t line) {
  return fmt::format("card {}, line {}", card, line);
}

bool IsZero(const Vec3& v) { return v[0] == 0 && v[1] == 0 && v[2] == 0; }

// The cosine and sine of an angle in degrees, exact at multiples of 90 degrees (a vehicle pitched
// -90 degrees moves along z, not along z plus 1e-17 of x).
std::optional<double> ExactCos(double degrees) {
  const double quarters = degrees / 90;
  if (quarters != std::floor(quarters) || std::fabs(quarters) > 1e6) return std::nullopt;
  static constexpr double kCos[] = {1, 0, -1, 0};
  return kCos[static_cast<int>(std::fmod(std::fmod(quarters, 4) + 4, 4))];
}
double CosDegrees(double degrees) {
  return ExactCos(degrees).value_or(std::cos(degrees * (std::numbers::pi / 180)));
}
double SinDegrees(double degrees) {
  return ExactCos(degrees - 90).value_or(std::sin(degrees * (std::numbers::pi / 180)));
}
Vec3 TurnedX(double yaw, double pitch) {
  return {CosDegrees(yaw) * CosDegrees(pitch), SinDegrees(yaw) * CosDegrees(pitch),
          -SinDegrees(pitch)};
}

// --- Names --------------------------------------------------------------------------------

// A deck label as a sled name: lower case, words joined by `_`, never a word the grammar or the
// frames reserve, unique among `taken`. A name something else already has takes the `kind` of
// what it names (a function titled like a plane, `knee_bolster`, becomes `knee_bolster_force`),
// and a number only if that is taken too.
std::string NameOf(std::string_view label, std::string_view fallback, std::set<std::string>& taken,
                   std::string_view kind) {
  std::string name;
  for (const char c : label) {
    if (std::isalnum(static_cast<unsigned char>(c))) {
      name += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    } else if (!name.empty() && name.back() != '_') {
      name += '_';
    }
  }
  while (!name.empty() && name.back() == '_') name.pop_back();
  if (name.size() > 24) name.resize(24);
  while (!name.empty() && name.back() == '_') name.pop_back();
  static const std::set<std::string> kReserved = {
      "at", "on", "with", "as",      "filter", "true",     "false",       "ground",      "x",
      "y",  "z",  "body", "segment", "joint",  "function", "relative_to", "expressed_in"};
  if (name.empty()) name = std::string(fallback);
  if (std::isdigit(static_cast<unsigned char>(name[0]))) name = std::string(fallback) + "_" + name;
  if (kReserved.count(name) != 0) name += "_";
  if (taken.count(name) != 0 && !kind.empty()) {
    while (name.back() == '_') name.pop_back();
    name += "_" + std::string(kind);
  }
  std::string unique = name;
  for (int n = 2; taken.count(unique) != 0; ++n) unique = fmt::format("{}_{}", name, n);
  taken.insert(unique);
  return unique;
}

}  // namespace sled::lang::legacy::mapping
