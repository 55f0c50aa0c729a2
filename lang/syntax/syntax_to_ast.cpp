#include "lang/syntax/syntax_to_ast.h"

#include <charconv>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

namespace sled::lang::syntax {
namespace {

class Converter {
 public:
  Converter(std::string_view text, FileId file, DiagnosticConsumer& diagnostics)
      : text_(text), file_(file), diagnostics_(diagnostics) {}

  SourceRange Range(const Node& node) const { return {file_, node.begin, node.end}; }
  std::string_view Text(const Node& node) const {
    return text_.substr(node.begin, node.end - node.begin);
  }

  void ConvertBlockItems(const Node& parent, ast::Block& block) {
    for (const auto& child : parent.children) {
      if (child->type == NodeType::kHeader) block.statements.push_back(ConvertHeader(*child));
      if (child->type == NodeType::kRow) block.statements.push_back(ConvertRow(*child));
    }
  }

  std::unique_ptr<ast::Block> ConvertBlock(const Node& node) {
    auto block = std::make_unique<ast::Block>();
    block->range = Range(node);
    block->one_line = Text(node).find('\n') == std::string_view::npos;
    ConvertBlockItems(node, *block);
    return block;
  }

  ast::Statement ConvertRow(const Node& node) {
    ast::Statement statement;
    statement.kind = ast::StatementKind::kRow;
    statement.range = Range(node);
    // The row's children are sums; the row itself is the arrow chain.
    ast::Expr arrow;
    arrow.kind = ast::ExprKind::kArrow;
    arrow.range = Range(node);
    for (const auto& child : node.children) arrow.operands.push_back(ConvertExpr(*child));
    statement.values.push_back(std::move(arrow));
    return statement;
  }

  ast::Statement ConvertHeader(const Node& node) {
    ast::Statement statement;
    statement.range = Range(node);
    for (const auto& child : node.children) {
      switch (child->type) {
        case NodeType::kKeyword:
          statement.keyword = std::string(Text(*child));
          statement.keyword_range = Range(*child);
          break;
        case NodeType::kTarget:
          statement.target = ConvertExpr(*child->children.at(0));
          break;
        case NodeType::kWordClause: {
          ast::Clause clause;
          clause.word = std::string(Text(*child->children.at(0)));
          clause.word_range = Range(*child->children.at(0));
          clause.value = ConvertExpr(*child->children.at(1));
          statement.clauses.push_back(std::move(clause));
          break;
        }
        case NodeType::kColonClause: {
          ast::Clause clause;
          clause.word = ":";
          clause.word_range = {file_, child->begin, child->begin + 1};
          clause.value = ConvertExpr(*child->children.at(0));
          statement.clauses.push_back(std::move(clause));
          break;
        }
        case NodeType::kStatementValue:
          statement.has_value = true;
          statement.values.push_back(ConvertExpr(*child->children.at(0)));
          break;
        case NodeType::kBlock:
          statement.block = ConvertBlock(*child);
          break;
        default:
          break;
      }
    }
    return statement;
  }

  ast::Expr ConvertExpr(const Node& node) {
    const DepthGuard guard(expression_depth_, 1);
    ast::Expr expr;
    expr.range = Range(node);
    switch (node.type) {
      case NodeType::kArrow:
      case NodeType::kSum:
      case NodeType::kProduct:
        if (node.children.size() == 1) return ConvertExpr(*node.children[0]);
        if (node.type == NodeType::kArrow) {
          expr.kind = ast::ExprKind::kArrow;
          for (const auto& child : node.children) expr.operands.push_back(ConvertExpr(*child));
          return expr;
        }
        return ConvertLeftAssociative(node);
      case NodeType::kPower:
        if (node.children.size() == 1) return ConvertExpr(*node.children[0]);
        expr.kind = ast::ExprKind::kBinary;
        expr.op = '^';
        expr.operands.push_back(ConvertExpr(*node.children.at(0)));
        expr.operands.push_back(ConvertExpr(*node.children.at(2)));
        return expr;
      case NodeType::kNegate:
        expr.kind = ast::ExprKind::kUnary;
        expr.op = '-';
        expr.operands.push_back(ConvertExpr(*node.children.at(1)));
        return expr;
      case NodeType::kQuantity:
        expr = ConvertNumber(*node.children.at(0));
        expr.range = Range(node);
        if (node.children.size() > 1) expr.unit = ConvertUnit(*node.children[1]);
        return expr;
      case NodeType::kVector: {
        bool trailing_comma = false;
        for (const auto& child : node.children) {
          if (child->type == NodeType::kUnit) {
            expr.unit = ConvertUnit(*child);
          } else if (child->type == NodeType::kTupleComma) {
            trailing_comma = true;
          } else {
            expr.operands.push_back(ConvertExpr(*child));
          }
        }
        const bool parenthesised = expr.operands.size() == 1 && !trailing_comma && !expr.unit;
        expr.kind = parenthesised ? ast::ExprKind::kParen : ast::ExprKind::kVector;
        return expr;
      }
      case NodeType::kCall:
        expr.kind = ast::ExprKind::kCall;
        for (const auto& child : node.children) {
          if (child->type == NodeType::kPath) {
            expr.path = SplitPath(Text(*child));
          } else if (child->type == NodeType::kNamedArgument) {
            ast::Argument argument;
            argument.name = std::string(Text(*child->children.at(0)));
            argument.name_range = Range(*child->children.at(0));
            argument.value = std::make_unique<ast::Expr>(ConvertExpr(*child->children.at(1)));
            expr.arguments.push_back(std::move(argument));
          } else if (child->type == NodeType::kPositionalArgument) {
            ast::Argument argument;
            argument.value = std::make_unique<ast::Expr>(ConvertExpr(*child->children.at(0)));
            expr.arguments.push_back(std::move(argument));
          }
        }
        return expr;
      case NodeType::kPath:
        expr.kind = ast::ExprKind::kPath;
        expr.path = SplitPath(Text(node));
        return expr;
      case NodeType::kString:
        expr.kind = ast::ExprKind::kString;
        expr.text = Unescape(Text(node).substr(1, node.end - node.begin - 2));
        return expr;
      case NodeType::kBoolean:
        expr.kind = ast::ExprKind::kBool;
        expr.text = std::string(Text(node));
        return expr;
      case NodeType::kStatementValue:
      case NodeType::kPositionalArgument:
        return ConvertExpr(*node.children.at(0));
      default:
        throw std::logic_error(fmt::format("lang::Parse: unexpected syntax node {} at byte {}",
                                           static_cast<int>(node.type), node.begin));
    }
  }

 private:
  // The deepest expression tree the conversion builds. The grammar limits nesting, but a chain
  // `a + b + c ...` becomes a tree as deep as the chain is long, and every later pass (checker,
  // formatter, destructor) walks expressions recursively.
  static constexpr int kMaxExpressionDepth = 1000;

  struct DepthGuard {
    DepthGuard(int& depth, int by) : depth_(depth), by_(by) { depth_ += by_; }
    ~DepthGuard() { depth_ -= by_; }
    DepthGuard(const DepthGuard&) = delete;
    DepthGuard& operator=(const DepthGuard&) = delete;
    int& depth_;
    int by_;
  };

  // a op b op c ... as ((a op b) op c).
  ast::Expr ConvertLeftAssociative(const Node& node) {
    const int operators = static_cast<int>(node.children.size() / 2);
    if (expression_depth_ + operators > kMaxExpressionDepth) {
      diagnostics_.Consume([&] {
        auto d = MakeDiagnostic(
            DiagnosticKind::kNestingTooDeep, {file_, node.begin, node.begin + 1},
            fmt::format("an expression is more than {} operations deep", kMaxExpressionDepth),
            fmt::format("{} operations chained here", operators));
        d.help = "split the expression into several `let`s";
        return d;
      }());
      ast::Expr nothing;  // a number the checker skips, as for an out-of-range number
      nothing.kind = ast::ExprKind::kNumber;
      nothing.range = Range(node);
      nothing.text = std::string(Text(node));
      nothing.number = std::numeric_limits<double>::quiet_NaN();
      return nothing;
    }
    const DepthGuard chain(expression_depth_, operators);
    ast::Expr left = ConvertExpr(*node.children.at(0));
    for (std::size_t i = 1; i + 1 < node.children.size(); i += 2) {
      ast::Expr combined;
      combined.kind = ast::ExprKind::kBinary;
      combined.op = Text(*node.children[i]).at(0);
      combined.range = {file_, node.begin, node.children[i + 1]->end};
      combined.operands.push_back(std::move(left));
      combined.operands.push_back(ConvertExpr(*node.children[i + 1]));
      left = std::move(combined);
    }
    return left;
  }

  ast::Expr ConvertNumber(const Node& node) {
    ast::Expr expr;
    expr.kind = ast::ExprKind::kNumber;
    expr.range = Range(node);
    expr.text = std::string(Text(node));
    const char* first = expr.text.data();
    const char* last = first + expr.text.size();
    auto [end, error] = std::from_chars(first, last, expr.number);
    if (error != std::errc() || end != last || !std::isfinite(expr.number)) {
      diagnostics_.Consume([&] {
        auto d = MakeDiagnostic(DiagnosticKind::kInvalidNumber, Range(node),
                                fmt::format("number `{}` is out of range", expr.text),
                                "not representable as a double");
        d.help = "numbers must lie within about 1e-308 to 1e308 in magnitude";
        return d;
      }());
      expr.number = std::numeric_limits<double>::quiet_NaN();  // the checker skips it
    }
    return expr;
  }

  ast::Unit ConvertUnit(const Node& node) {
    ast::Unit unit;
    unit.range = Range(node);
    int sign = 1;
    for (const auto& child : node.children) {
      if (child->type == NodeType::kUnitDivide) {
        sign = -1;
      } else if (child->type == NodeType::kUnitSymbol) {
        unit.factors.push_back({std::string(Text(*child)), sign, Range(*child)});
        // `*` after `/` multiplies again: N/m*s is N*s/m, as in arithmetic.
        sign = 1;
      } else if (child->type == NodeType::kUnitPower) {
        const std::string_view digits = Text(*child).substr(1);
        int exponent = 0;
        const bool negative = !digits.empty() && digits[0] == '-';
        const std::string_view magnitude = negative ? digits.substr(1) : digits;
        auto [end, error] =
            std::from_chars(magnitude.data(), magnitude.data() + magnitude.size(), exponent);
        if (error != std::errc() || end != magnitude.data() + magnitude.size()) exponent = 1000;
        if (negative) exponent = -exponent;
        auto& factor = unit.factors.back();
        factor.exponent *= exponent;
        factor.range.end = child->end;
      }
    }
    return unit;
  }

  static std::vector<std::string> SplitPath(std::string_view text) {
    std::vector<std::string> parts;
    std::size_t start = 0;
    while (true) {
      const std::size_t dot = text.find('.', start);
      parts.emplace_back(text.substr(start, dot - start));
      if (dot == std::string_view::npos) break;
      start = dot + 1;
    }
    return parts;
  }

  static std::string Unescape(std::string_view raw) {
    std::string out;
    for (std::size_t i = 0; i < raw.size(); ++i) {
      if (raw[i] == '\\' && i + 1 < raw.size()) {
        ++i;
        out += raw[i] == 'n' ? '\n' : raw[i] == 't' ? '\t' : raw[i];
      } else {
        out += raw[i];
      }
    }
    return out;
  }

  std::string_view text_;
  FileId file_;
  DiagnosticConsumer& diagnostics_;
  int expression_depth_ = 0;
};

}  // namespace

void ConvertFile(const Node& root, std::string_view text, FileId file,
                 DiagnosticConsumer& diagnostics, ast::Block& body) {
  Converter(text, file, diagnostics).ConvertBlockItems(root, body);
}

ast::Expr ConvertValue(const Node& value, std::string_view text, FileId file,
                       DiagnosticConsumer& diagnostics) {
  return Converter(text, file, diagnostics).ConvertExpr(value);
}

}  // namespace sled::lang::syntax
