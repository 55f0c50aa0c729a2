// Values: binding a block's attributes to the schema, evaluating expressions with units and
// parameters, and reading typed attributes (quantities, vectors, functions).
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "compiler/check/context.h"
#include "compiler/units/unit_table.h"

namespace sled::compiler::internal {
namespace {

std::string Article(std::string_view word) {
  return (!word.empty() && std::string_view("aeiou").find(word[0]) != std::string_view::npos)
             ? fmt::format("an `{}`", word)
             : fmt::format("a `{}`", word);
}

// The schema's entry for attribute `name` of a `kind` block. A key of another kind of block
// would always read as absent: a checker bug, not a user error.
const AttributeSpec* SpecOfKey(BlockKind kind, AttributeKey name) {
  const AttributeSpec* spec = FindAttribute(kind, name);
  if (!spec) {
    throw std::logic_error(fmt::format("checker: `{}` is not an attribute of {} blocks",
                                       name.view(), BlockName(kind)));
  }
  return spec;
}

}  // namespace

CheckContext::BoundBlock CheckContext::Bind(BlockKind kind, const ast::Block* block,
                                            SourceRange owner_range) {
  BoundBlock bound;
  const std::string block_name(BlockName(kind));
  std::vector<std::string> misspellings;  // attributes the unknown keywords were probably meant as
  if (block) {
    for (const ast::Statement& statement : block->statements) {
      if (statement.kind == ast::StatementKind::kRow) {
        if (kind == BlockKind::kTable) {
          bound.rows.push_back(&statement);
        } else {
          Report(DiagnosticKind::kMisplacedStatement, statement.range,
                 fmt::format("a table row is not allowed in {} block", Article(block_name)),
                 "rows belong to a table",
                 "rows follow `= table(x -> y)`, as in `force = table(deflection -> force) { "
                 "0 mm -> 0 N  10 mm -> 1 kN }`");
        }
        continue;
      }
      const std::string& keyword = statement.keyword;
      const bool is_output = kind == BlockKind::kOutput && FindOutput(keyword);
      if (FindDeclaration(kind, keyword) || is_output) {
        bound.declarations.push_back(&statement);
        continue;
      }
      const AttributeSpec* spec = FindAttribute(kind, keyword);
      if (!spec && keyword == "scenario" && kind == BlockKind::kModule) {
        Report(DiagnosticKind::kMultipleScenarios, statement.keyword_range,
               "a module cannot hold a scenario", "scenario in a module",
               "a file with a scenario is a scene; import modules from it, not the other way");
        continue;
      }
      if (!spec) {
        const std::vector<BlockKind> elsewhere = BlocksAllowing(keyword);
        if (!elsewhere.empty()) {
          std::string places;
          for (std::size_t i = 0; i < elsewhere.size() && i < 4; ++i) {
            if (i > 0)
              places += i + 1 == std::min<std::size_t>(elsewhere.size(), 4) ? " or " : ", ";
            places += fmt::format("`{}`", BlockName(elsewhere[i]));
          }
          Report(DiagnosticKind::kMisplacedStatement, statement.keyword_range,
                 fmt::format("`{}` is not allowed in {} block", keyword, Article(block_name)),
                 "not allowed here", fmt::format("`{}` belongs in {} blocks", keyword, places));
        } else {
          const auto closest = lang::ClosestMatch(keyword, KeywordsOf(kind));
          if (closest) misspellings.push_back(*closest);
          Report(DiagnosticKind::kUnknownStatement, statement.keyword_range,
                 fmt::format("unknown {} `{}` in {} block",
                             kind == BlockKind::kOutput ? "output request" : "attribute", keyword,
                             Article(block_name)),
                 "unknown here", lang::DidYouMean(keyword, KeywordsOf(kind)));
        }
        continue;
      }
      // An attribute is `name = value`; `at` and `axes` also name a frame: `at pelvis = ...`.
      const bool wants_target = spec->name == "at" || spec->name == "axes";
      const bool takes_rows =
          spec->type == ValueType::kFunction || spec->type == ValueType::kMotion;
      if (!statement.has_value || (statement.target.has_value() != wants_target) ||
          !statement.clauses.empty() || (statement.block && !takes_rows)) {
        Report(DiagnosticKind::kMalformedStatement, statement.range,
               fmt::format("`{}` is an attribute: write `{}`", keyword,
                           wants_target ? fmt::format("{} SEGMENT = value", keyword)
                                        : fmt::format("{} = value", keyword)),
               "not an attribute statement", "remove what follows the value");
        continue;
      }
      auto& list = bound.attributes[keyword];
      if (!list.empty() && !spec->repeatable) {
        auto diagnostic = lang::MakeDiagnostic(
            DiagnosticKind::kDuplicateAttribute, statement.keyword_range,
            fmt::format("`{}` is given twice in {} block", keyword, Article(block_name)),
            "given again here");
        diagnostic.labels.push_back({list.front()->keyword_range, "first given here", false});
        diagnostic.help = "remove one of them";
        diagnostics_.Consume(std::move(diagnostic));
        continue;
      }
      list.push_back(&statement);
    }
  }
  // Missing required attributes; not reported when a syntax error may have eaten them, nor when
  // a misspelt attribute already stands for it (`mas = 1 kg`).
  if (!block || !block->had_syntax_errors) {
    for (const AttributeSpec& spec : SpecOf(kind).attributes) {
      const bool misspelt =
          std::find(misspellings.begin(), misspellings.end(), spec.name) != misspellings.end();
      if (spec.required && !misspelt && !bound.attributes.count(std::string(spec.name))) {
        Report(DiagnosticKind::kMissingAttribute, owner_range,
               fmt::format("{} block needs `{}`", Article(block_name), spec.name),
               fmt::format("no `{}` given", spec.name),
               fmt::format("add `{} = ...`: {}", spec.name, spec.doc));
      }
    }
  }
  return bound;
}

const ast::Statement* CheckContext::One(const BoundBlock& bound, AttributeKey name) const {
  auto it = bound.attributes.find(std::string(name.view()));
  return it == bound.attributes.end() || it->second.empty() ? nullptr : it->second.front();
}

const ast::Expr* CheckContext::ValueOf(const BoundBlock& bound, AttributeKey name) {
  const ast::Statement* statement = One(bound, name);
  return statement ? SingleValue(*statement) : nullptr;
}

const ast::Expr* CheckContext::SingleValue(const ast::Statement& statement) {
  if (statement.values.size() != 1) {
    Report(
        DiagnosticKind::kWrongValueKind,
        statement.values.size() > 1 ? statement.values[1].range : statement.range,
        fmt::format("`{}` takes one value, found {}", statement.keyword, statement.values.size()),
        "extra value", "remove the extra values, or write a vector in parentheses: `(x, y, z) mm`");
    return nullptr;
  }
  return &statement.values[0];
}

std::optional<Value> CheckContext::ValueOf(Parameter& parameter) {
  if (parameter.state == Parameter::State::kPending) {
    parameter.state = Parameter::State::kEvaluating;
    const ast::Expr& definition =
        parameter.override_expr ? *parameter.override_expr : *parameter.expr;
    auto value = Evaluate(*parameter.scope, definition);
    if (value && parameter.override_expr && !OverrideFits(parameter, *value)) value.reset();
    if (parameter.state == Parameter::State::kFailed || !value) {
      parameter.state = Parameter::State::kFailed;
      return std::nullopt;
    }
    parameter.value = *value;
    parameter.state = Parameter::State::kDone;
  }
  if (parameter.state == Parameter::State::kFailed) return std::nullopt;
  return parameter.value;
}

bool CheckContext::OverrideFits(Parameter& parameter, const Value& value) {
  // `--set speed=40` for `param speed = 56 km/h` would run at 40 m/s: the value from the
  // command line must have the dimension and the shape of the one it replaces (a bare 0 fits).
  const auto declared = Evaluate(*parameter.scope, *parameter.expr);
  if (!declared) return true;  // its own errors are reported; the override stands alone
  const SourceRange range = parameter.override_expr->range;
  const bool vector = declared->components.size() == 3;
  if (value.components.size() != declared->components.size()) {
    auto diagnostic =
        lang::MakeDiagnostic(DiagnosticKind::kWrongValueKind, range,
                             fmt::format("`--set {}` gives {}, but `{}` is {}", parameter.name,
                                         vector ? "one number" : "a vector", parameter.name,
                                         vector ? "a vector" : "one number"),
                             "not the shape of the declared value");
    diagnostic.labels.push_back({parameter.range, "declared here", false});
    diagnostic.help =
        vector ? fmt::format("write a vector: --set \"{}=(x, y, z) unit\"", parameter.name)
               : fmt::format("write one number with its unit: --set \"{}=...\"", parameter.name);
    diagnostics_.Consume(std::move(diagnostic));
    return false;
  }
  if (value.dimension == declared->dimension || IsBareZero(value)) return true;
  auto diagnostic =
      lang::MakeDiagnostic(DiagnosticKind::kDimensionMismatch, range,
                           fmt::format("`--set {}` gives {}, but `{}` is declared as {}",
                                       parameter.name, DescribeDimension(value.dimension),
                                       parameter.name, DescribeDimension(declared->dimension)),
                           value.bare ? "no unit" : "wrong dimension");
  diagnostic.labels.push_back({parameter.range, "declared here", false});
  diagnostic.help = value.bare ? fmt::format("give the unit: --set \"{}=... {}\"", parameter.name,
                                             SiUnitSymbol(declared->dimension))
                               : DimensionHelp(declared->dimension, value.dimension);
  diagnostics_.Consume(std::move(diagnostic));
  return false;
}

void CheckContext::EvaluateParameters() {
  // In the order of declaration, so that a long chain of `let`s, each using the one before,
  // is evaluated one link at a time, not by recursing from its last link to its first. One that
  // nothing uses is still checked: a wrong dimension in it is a mistake the checker can find.
  for (std::size_t i = 0; i < parameters_.size(); ++i) ValueOf(*parameters_[i]);
}

std::optional<Value> CheckContext::Evaluate(Scope& scope, const ast::Expr& expr) {
  // A value defined through later definitions (`let a = b + 1` before `let b = ...`) recurses
  // through them; a generated chain of thousands would overflow the stack.
  if (evaluation_depth_ >= kMaxEvaluationDepth) return ReportEvaluationTooDeep(expr);
  ++evaluation_depth_;
  auto value = EvaluateNested(scope, expr);
  --evaluation_depth_;
  return value;
}

// Only the recursion lives here; what each kind of value needs (and every diagnostic, whose
// strings would make each level's stack frame large) is in the functions it calls.
std::optional<Value> CheckContext::EvaluateNested(Scope& scope, const ast::Expr& expr) {
  switch (expr.kind) {
    case ast::ExprKind::kNumber:
      return EvaluateNumber(expr);
    case ast::ExprKind::kVector:
      return EvaluateVector(scope, expr);
    case ast::ExprKind::kPath:
      return EvaluatePath(scope, expr);
    case ast::ExprKind::kParen:
      return Evaluate(scope, expr.operands.at(0));
    case ast::ExprKind::kUnary: {
      auto operand = Evaluate(scope, expr.operands.at(0));
      if (!operand) return std::nullopt;
      for (double& component : operand->components) component = -component;
      return operand;
    }
    case ast::ExprKind::kBinary: {
      auto left = Evaluate(scope, expr.operands.at(0));
      auto right = Evaluate(scope, expr.operands.at(1));
      if (!left || !right) return std::nullopt;
      return Combine(expr, *left, *right);
    }
    case ast::ExprKind::kCall:
    case ast::ExprKind::kString:
    case ast::ExprKind::kBool:
    case ast::ExprKind::kArrow:
      return ReportNotAQuantity(expr);
  }
  return std::nullopt;
}

std::optional<Value> CheckContext::ReportEvaluationTooDeep(const ast::Expr& expr) {
  // Once: the rest of such a chain would report it again from each of its links.
  if (evaluation_too_deep_) return std::nullopt;
  evaluation_too_deep_ = true;
  Report(DiagnosticKind::kNestingTooDeep, expr.range,
         fmt::format("this value is defined through more than {} nested definitions and "
                     "operations",
                     kMaxEvaluationDepth),
         "too deep here", "declare each `let` before the `let`s that use it");
  return std::nullopt;
}

std::optional<Value> CheckContext::ReportNotAQuantity(const ast::Expr& expr) {
  Report(DiagnosticKind::kWrongValueKind, expr.range,
         fmt::format("expected a number or a vector, found {}",
                     expr.kind == ast::ExprKind::kCall     ? "a call"
                     : expr.kind == ast::ExprKind::kString ? "a string"
                     : expr.kind == ast::ExprKind::kBool   ? "`" + expr.text + "`"
                                                           : "an arrow chain"),
         "not a quantity", "write a number with its unit, or a vector `(x, y, z) unit`");
  return std::nullopt;
}

std::optional<Value> CheckContext::EvaluateNumber(const ast::Expr& expr) {
  // The parser marks a number it could not read as NaN, after reporting it.
  if (std::isnan(expr.number)) return std::nullopt;
  Value value{{expr.number}, dim::kDimensionless, true};
  if (expr.unit) {
    auto unit = ResolveUnit(*expr.unit, diagnostics_);
    if (!unit) return std::nullopt;
    value.components[0] *= unit->scale_to_si;
    value.dimension = unit->dimension;
    value.bare = false;
  }
  return value;
}

std::optional<Value> CheckContext::EvaluateVector(Scope& scope, const ast::Expr& expr) {
  if (expr.operands.size() == 1 && expr.unit) {
    // `(40 + 2) kg`: a parenthesised number with a unit.
    auto inner = Evaluate(scope, expr.operands[0]);
    auto unit = ResolveUnit(*expr.unit, diagnostics_);
    if (!inner || !unit) return std::nullopt;
    if (!inner->bare) {
      Report(DiagnosticKind::kDimensionMismatch, expr.operands[0].range,
             "the value in parentheses has its own unit and a unit follows", "unit given twice",
             "write the unit once");
      return std::nullopt;
    }
    for (double& component : inner->components) component *= unit->scale_to_si;
    inner->dimension = unit->dimension;
    inner->bare = false;
    return inner;
  }
  if (expr.operands.size() != 3) {
    Report(DiagnosticKind::kWrongVectorSize, expr.range,
           fmt::format("a vector has three components, found {}", expr.operands.size()),
           "not three components", "write (x, y, z)");
    return std::nullopt;
  }
  Value value{{}, dim::kDimensionless, true};
  std::optional<Dimension> common;
  bool failed = false;
  std::vector<const ast::Expr*> bare_numbers;  // components without a unit other than 0
  for (const ast::Expr& operand : expr.operands) {
    auto component = Evaluate(scope, operand);
    if (!component) {
      failed = true;
      continue;
    }
    if (component->components.size() != 1) {
      Report(DiagnosticKind::kWrongValueKind, operand.range, "a vector component must be a number",
             "a vector inside a vector", "write each component as one number");
      failed = true;
      continue;
    }
    if (expr.unit && !component->bare) {
      Report(DiagnosticKind::kDimensionMismatch, operand.range,
             "a component has its own unit and the vector has one too", "unit given twice",
             "write the unit once, after the closing parenthesis");
      failed = true;
      continue;
    }
    const bool zero = component->bare && component->components[0] == 0.0;
    if (component->bare && !zero) bare_numbers.push_back(&operand);
    if (!component->bare || !zero) {
      if (common && !(*common == component->dimension) && !component->bare) {
        Report(DiagnosticKind::kDimensionMismatch, operand.range,
               fmt::format("vector components have different dimensions: {}",
                           DescribeMismatch(*common, component->dimension)),
               "differs from the first component",
               "give every component the same dimension, or write the unit once after `)`");
        failed = true;
      }
      if (!component->bare) common = component->dimension;
      value.bare = value.bare && component->bare;
    }
    value.components.push_back(component->components[0]);
  }
  if (!expr.unit && common && !common->IsDimensionless()) {
    // `(0 mm, 0 mm, 150)` is not 150 m: a number without a unit beside components with one.
    for (const ast::Expr* operand : bare_numbers) {
      Report(DiagnosticKind::kDimensionMismatch, operand->range,
             fmt::format("this component has no unit, but the others are {}",
                         DescribeDimension(*common)),
             "no unit",
             fmt::format("give it a unit of {}, or write the unit once after `)`; only a bare 0 "
                         "stands for any dimension",
                         DescribeDimension(*common)));
      failed = true;
    }
  }
  if (failed) return std::nullopt;
  if (expr.unit) {
    auto unit = ResolveUnit(*expr.unit, diagnostics_);
    if (!unit) return std::nullopt;
    for (double& component : value.components) component *= unit->scale_to_si;
    value.dimension = unit->dimension;
    value.bare = false;
  } else if (common) {
    value.dimension = *common;
  }
  return value;
}

std::optional<Value> CheckContext::EvaluatePath(Scope& scope, const ast::Expr& expr) {
  Entity* entity = Resolve(scope, expr, {EntityKind::kParameter});
  if (!entity) return std::nullopt;
  Parameter& parameter = *parameters_.at(static_cast<std::size_t>(entity->index));
  if (parameter.state == Parameter::State::kEvaluating) return ReportCycle(expr, parameter);
  return ValueOf(parameter);
}

std::optional<Value> CheckContext::ReportCycle(const ast::Expr& expr, Parameter& parameter) {
  Report(DiagnosticKind::kCyclicDefinition, expr.range,
         fmt::format("`{}` is defined in terms of itself", parameter.name),
         "used in its own definition", "break the cycle with a literal value");
  parameter.state = Parameter::State::kFailed;
  return std::nullopt;
}

std::optional<Value> CheckContext::Combine(const ast::Expr& expr, const Value& left,
                                           const Value& right) {
  const bool left_vector = left.components.size() == 3;
  const bool right_vector = right.components.size() == 3;
  Value result;
  result.bare = left.bare && right.bare;
  if (expr.op == '+' || expr.op == '-') {
    if (left_vector != right_vector) {
      Report(DiagnosticKind::kWrongValueKind, expr.range, "cannot add a vector and a number",
             "vector and number", "add a vector to a vector, a number to a number");
      return std::nullopt;
    }
    const bool left_zero = IsBareZero(left);
    const bool right_zero = IsBareZero(right);
    if (!(left.dimension == right.dimension) && !left_zero && !right_zero) {
      Report(DiagnosticKind::kIncompatibleArithmetic, expr.range,
             fmt::format("cannot {} {}", expr.op == '+' ? "add" : "subtract",
                         DescribeMismatch(left.dimension, right.dimension)),
             "dimensions differ",
             MismatchHelp(left.dimension, right.dimension).empty()
                 ? "both sides of `+` and `-` need the same dimension; check their units"
                 : MismatchHelp(left.dimension, right.dimension));
      return std::nullopt;
    }
    result.dimension = left_zero ? right.dimension : left.dimension;
    result.components = left.components;
    for (std::size_t i = 0; i < result.components.size(); ++i) {
      result.components[i] += expr.op == '+' ? right.components[i] : -right.components[i];
    }
    return result;
  }
  if (expr.op == '*' || expr.op == '/') {
    if (left_vector && right_vector) {
      Report(DiagnosticKind::kWrongValueKind, expr.range, "cannot multiply or divide two vectors",
             "two vectors", "multiply or divide a vector by a number");
      return std::nullopt;
    }
    if (expr.op == '/' && right_vector) {
      Report(DiagnosticKind::kWrongValueKind, expr.range, "cannot divide by a vector",
             "vector divisor", "divide a vector by a number");
      return std::nullopt;
    }
    const Value& vector_side = right_vector ? right : left;
    const double scalar = right_vector ? left.components[0] : right.components[0];
    if (expr.op == '/' && scalar == 0.0) {
      Report(DiagnosticKind::kDivisionByZero, expr.operands[1].range,
             "division by zero in a constant expression", "this is zero",
             "the divisor evaluates to zero; check the value and the names it uses");
      return std::nullopt;
    }
    result.dimension =
        expr.op == '*' ? left.dimension * right.dimension : left.dimension / right.dimension;
    result.components = vector_side.components;
    if (&vector_side == &left) {
      for (double& c : result.components) c = expr.op == '*' ? c * scalar : c / scalar;
    } else {
      for (double& c : result.components) c *= scalar;
    }
    return result;
  }
  // '^': a scalar raised to a dimensionless constant power.
  if (left_vector || right_vector || !right.dimension.IsDimensionless()) {
    Report(DiagnosticKind::kInvalidExponent, expr.range,
           "a power needs a number base and a dimensionless exponent", "invalid power",
           "raise a number to a plain-number exponent, as in `length^2`");
    return std::nullopt;
  }
  const ArithmeticResult power = Power(Quantity{left.components[0], left.dimension},
                                       Quantity{right.components[0], right.dimension});
  if (!power.ok()) {
    Report(power.status == ArithmeticStatus::kDivisionByZero ? DiagnosticKind::kDivisionByZero
                                                             : DiagnosticKind::kInvalidExponent,
           expr.range,
           power.status == ArithmeticStatus::kDivisionByZero
               ? "zero raised to a negative power"
               : "a quantity with a unit can only be raised to a whole power up to 9",
           "invalid power",
           power.status == ArithmeticStatus::kDivisionByZero
               ? "a negative power of zero is infinite; check the base"
               : "raise a quantity with a unit to a whole number from -9 to 9; a plain "
                 "number may take any power");
    return std::nullopt;
  }
  result.components = {power.quantity.value};
  result.dimension = power.quantity.dimension;
  return result;
}

namespace {

// A bare zero fits any dimension; other bare numbers fit only where no unit is expected.
bool FitsDimension(const Value& value, Dimension expected) {
  return value.dimension == expected || IsBareZero(value);
}

}  // namespace

std::optional<double> CheckContext::ExpectQuantity(Scope& scope, const ast::Expr& expr,
                                                   Dimension dimension, std::string_view what) {
  auto value = Evaluate(scope, expr);
  if (!value) return std::nullopt;
  if (value->components.size() != 1) {
    Report(DiagnosticKind::kWrongValueKind, expr.range,
           fmt::format("`{}` takes one number, found a vector", what), "a vector",
           fmt::format("expected {}", DescribeDimension(dimension)));
    return std::nullopt;
  }
  if (!FitsDimension(*value, dimension)) {
    Report(DiagnosticKind::kDimensionMismatch, expr.range,
           fmt::format("`{}` expects {}, found {}", what, DescribeDimension(dimension),
                       DescribeDimension(value->dimension)),
           value->bare ? "no unit" : "wrong dimension", DimensionHelp(dimension, value->dimension));
    return std::nullopt;
  }
  if (!std::isfinite(value->components[0])) {
    Report(DiagnosticKind::kInvalidNumber, expr.range,
           fmt::format("`{}` evaluates to a value that is not finite", what), "overflows",
           "the value passes 1e308 in SI units; check its units and the names it uses");
    return std::nullopt;
  }
  return value->components[0];
}

std::optional<Vec3> CheckContext::ExpectVector(Scope& scope, const ast::Expr& expr,
                                               Dimension dimension, std::string_view what) {
  auto value = Evaluate(scope, expr);
  if (!value) return std::nullopt;
  if (value->components.size() != 3) {
    Report(DiagnosticKind::kWrongValueKind, expr.range,
           fmt::format("`{}` takes a vector (x, y, z), found one number", what), "one number",
           fmt::format("write ({0}, {0}, {0}) with a unit of {1}", "...",
                       DescribeDimension(dimension)));
    return std::nullopt;
  }
  if (!FitsDimension(*value, dimension)) {
    Report(DiagnosticKind::kDimensionMismatch, expr.range,
           fmt::format("`{}` expects {}, found {}", what, DescribeDimension(dimension),
                       DescribeDimension(value->dimension)),
           value->bare ? "no unit" : "wrong dimension", DimensionHelp(dimension, value->dimension));
    return std::nullopt;
  }
  for (double component : value->components) {
    if (!std::isfinite(component)) {
      Report(DiagnosticKind::kInvalidNumber, expr.range,
             fmt::format("`{}` has a component that is not finite", what), "overflows",
             "the value passes 1e308 in SI units; check its units and the names it uses");
      return std::nullopt;
    }
  }
  return Vec3{value->components[0], value->components[1], value->components[2]};
}

std::optional<bool> CheckContext::ExpectBool(const ast::Expr& expr, std::string_view what) {
  if (expr.kind != ast::ExprKind::kBool) {
    Report(DiagnosticKind::kWrongValueKind, expr.range,
           fmt::format("`{}` is `true` or `false`", what), "not a boolean",
           "write `true` or `false`");
    return std::nullopt;
  }
  return expr.text == "true";
}

std::optional<Vec3> CheckContext::ExpectDirection(Scope& scope, const ast::Expr& expr,
                                                  std::string_view what) {
  // Axis words: x, -x, y, -y, z, -z.
  const ast::Expr* word = &expr;
  double sign = 1.0;
  if (expr.kind == ast::ExprKind::kUnary && expr.operands.at(0).kind == ast::ExprKind::kPath) {
    word = &expr.operands[0];
    sign = -1.0;
  }
  if (word->kind == ast::ExprKind::kPath && word->path.size() == 1 &&
      (word->path[0] == "x" || word->path[0] == "y" || word->path[0] == "z")) {
    Vec3 axis{0, 0, 0};
    axis[static_cast<std::size_t>(word->path[0][0] - 'x')] = sign;
    return axis;
  }
  auto vector = ExpectVector(scope, expr, dim::kDimensionless, what);
  if (!vector) return std::nullopt;
  // hypot, not the root of the sum of squares: (1e300, 1e300, 0) is a direction too, and its
  // squares would overflow to a length of infinity and a direction of zero.
  const double length = std::hypot((*vector)[0], (*vector)[1], (*vector)[2]);
  if (!(length > 1e-12)) {
    Report(DiagnosticKind::kZeroVector, expr.range,
           fmt::format("`{}` is a direction and cannot be zero", what), "zero length",
           "give a direction such as (0, 1, 0) or the word y");
    return std::nullopt;
  }
  return Vec3{(*vector)[0] / length, (*vector)[1] / length, (*vector)[2] / length};
}

bool CheckContext::CheckRange(const AttributeSpec& spec, double value, SourceRange range) {
  const bool below = spec.min_exclusive ? !(value > spec.min) : !(value >= spec.min);
  const bool above = !(value <= spec.max);
  if (!below && !above) return true;
  const std::string unit = SiUnitSymbol(spec.dimension);
  const auto bound = [&](double x) {
    return unit.empty() ? fmt::format("{:g}", x) : fmt::format("{:g} {}", x, unit);
  };
  std::string rule;
  if (std::isinf(spec.max)) {
    rule = spec.min_exclusive ? fmt::format("greater than {}", bound(spec.min))
                              : fmt::format("at least {}", bound(spec.min));
  } else if (std::isinf(spec.min)) {
    rule = fmt::format("at most {}", bound(spec.max));
  } else {
    rule = fmt::format("{} {} and {}", spec.min_exclusive ? "above" : "between", bound(spec.min),
                       bound(spec.max));
  }
  DiagnosticKind kind = DiagnosticKind::kValueOutOfRange;
  if (spec.name == "mass") kind = DiagnosticKind::kNonPositiveMass;
  Report(kind, range,
         fmt::format(
             "`{}` is {}, but it must be {}", spec.name,
             unit.empty() ? fmt::format("{:g}", value) : fmt::format("{:g} {}", value, unit), rule),
         "out of range", std::string(spec.doc));
  return false;
}

std::optional<double> CheckContext::ReadQuantity(Scope& scope, const BoundBlock& bound,
                                                 BlockKind kind, AttributeKey name) {
  return ReadQuantity(scope, bound, kind, name, SpecOfKey(kind, name)->dimension);
}

std::optional<double> CheckContext::ReadQuantity(Scope& scope, const BoundBlock& bound,
                                                 BlockKind kind, AttributeKey name,
                                                 Dimension dimension) {
  const AttributeSpec* spec = SpecOfKey(kind, name);
  const ast::Expr* expr = ValueOf(bound, name);
  if (!expr) return std::nullopt;
  auto value = ExpectQuantity(scope, *expr, dimension, name);
  if (value && !CheckRange(*spec, *value, expr->range)) return std::nullopt;
  return value;
}

std::optional<Vec3> CheckContext::ReadVector(Scope& scope, const BoundBlock& bound, BlockKind kind,
                                             AttributeKey name) {
  const AttributeSpec* spec = SpecOfKey(kind, name);
  const ast::Expr* expr = ValueOf(bound, name);
  if (!expr) return std::nullopt;
  if (spec->dimension == dim::kDimensionless && name.view() == "axis") {
    return ExpectDirection(scope, *expr, name);
  }
  return ExpectVector(scope, *expr, spec->dimension, name);
}

std::optional<bool> CheckContext::ReadBool(const BoundBlock& bound, AttributeKey name) {
  const ast::Expr* expr = ValueOf(bound, name);
  if (!expr) return std::nullopt;
  return ExpectBool(*expr, name);
}

std::optional<FunctionId> CheckContext::ReadFunction(Scope& scope, const BoundBlock& bound,
                                                     BlockKind kind, AttributeKey name) {
  const AttributeSpec* spec = SpecOfKey(kind, name);
  return ReadFunction(scope, bound, kind, name, spec->argument, spec->dimension);
}

std::optional<FunctionId> CheckContext::ReadFunction(Scope& scope, const BoundBlock& bound,
                                                     BlockKind kind, AttributeKey name,
                                                     Dimension argument, Dimension result) {
  (void)SpecOfKey(kind, name);  // throws for an attribute `kind` does not have (a checker bug)
  const ast::Statement* statement = One(bound, name);
  if (!statement) return std::nullopt;
  const ast::Expr* expr = SingleValue(*statement);
  if (!expr) return std::nullopt;
  return ExpectFunction(scope, *statement, *expr, argument, result, name);
}

}  // namespace sled::compiler::internal
