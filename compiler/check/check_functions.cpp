// Functions as in CVS: constant, table and polynomial (degree up to five), with the unloading
// parameters of the force–deflection model; named or inline, checked against the signature each
// use expects (flexure: angle -> torque, contact force: deflection -> force, ...).
#include <algorithm>
#include <cmath>
#include <utility>

#include <fmt/format.h>

#include "compiler/check/context.h"

namespace sled::compiler::internal {
namespace {

constexpr int kMaxPolynomialDegree = 5;

std::string Signature(Dimension argument, Dimension result) {
  return fmt::format("{} -> {}", DescribeDimension(argument), DescribeDimension(result));
}

std::vector<std::string> QuantityNames() {
  std::vector<std::string> names;
  for (const QuantityName& name : AllQuantityNames()) names.emplace_back(name.name);
  return names;
}

}  // namespace

bool CheckContext::MatchSignature(FunctionId id, Dimension argument, Dimension result,
                                  SourceRange use) {
  if (id < 0 || static_cast<std::size_t>(id) >= scenario_.functions.size()) return false;
  if (!function_valid_.at(static_cast<std::size_t>(id))) return false;
  Function& function = scenario_.functions[static_cast<std::size_t>(id)];
  auto pending = pending_polynomials_.find(id);
  if (pending != pending_polynomials_.end() && !pending->second.resolved) {
    // The first use fixes the signature of a polynomial written without one.
    PendingPolynomial& polynomial = pending->second;
    polynomial.resolved = true;
    function.argument = argument;
    function.result = result;
    bool ok = true;
    for (std::size_t k = 0; k < polynomial.coefficients.size(); ++k) {
      const Value& coefficient = polynomial.coefficients[k];
      const Dimension wanted = result / argument.Pow(static_cast<int>(k));
      if (!(coefficient.dimension == wanted) && !IsBareZero(coefficient)) {
        auto diagnostic = lang::MakeDiagnostic(
            DiagnosticKind::kDimensionMismatch, polynomial.ranges[k],
            fmt::format("coefficient {} of {} should be {}, found {}", k,
                        function.name.empty() ? std::string("the polynomial")
                                              : fmt::format("`{}`", function.name),
                        DescribeDimension(wanted), DescribeDimension(coefficient.dimension)),
            "wrong dimension for this power");
        diagnostic.labels.push_back({use, "used here as " + Signature(argument, result), false});
        diagnostic.help = fmt::format(
            "coefficient k of a polynomial from {} has the dimension "
            "of the result divided by the argument to the power k",
            Signature(argument, result));
        diagnostics_.Consume(std::move(diagnostic));
        ok = false;
      }
      function.coefficients[k] = coefficient.components[0];
    }
    if (!ok) function_valid_[static_cast<std::size_t>(id)] = false;
    return ok;
  }
  const bool result_ok = function.result == result;
  const bool argument_ok =
      function.kind == Function::Kind::kConstant || function.argument == argument;
  if (result_ok && argument_ok) return true;
  // `function k = 80 kN/m` used where deflection -> force is needed: a slope, as it is inline.
  if (function.kind == Function::Kind::kConstant && !argument.IsDimensionless() &&
      function.result == result / argument) {
    function.kind = Function::Kind::kPolynomial;
    function.coefficients = {0.0, function.constant};
    function.argument = argument;
    function.result = result;
    return true;
  }
  auto diagnostic = lang::MakeDiagnostic(
      DiagnosticKind::kDimensionMismatch, use,
      fmt::format("function `{}` maps {}, but {} is needed here", function.name,
                  Signature(function.argument, function.result), Signature(argument, result)),
      "wrong kind of function");
  if (function.range.valid()) diagnostic.labels.push_back({function.range, "declared here", false});
  diagnostics_.Consume(std::move(diagnostic));
  return false;
}

std::optional<FunctionId> CheckContext::ExpectFunction(Scope& scope,
                                                       const ast::Statement& statement,
                                                       const ast::Expr& expr, Dimension argument,
                                                       Dimension result, std::string_view what) {
  if (expr.kind == ast::ExprKind::kPath) {
    // A parameter used as a constant function, or a named function.
    Entity* entity = Resolve(scope, expr, {EntityKind::kFunction, EntityKind::kParameter});
    if (!entity) return std::nullopt;
    if (entity->kind == EntityKind::kFunction) {
      if (statement.block) {
        Report(DiagnosticKind::kMalformedStatement, statement.block->range,
               "a block belongs to an inline table, not to a named function", "unexpected block",
               "rows follow a table: `function NAME = table(x -> y) { rows }`");
      }
      if (!MatchSignature(entity->index, argument, result, expr.range)) return std::nullopt;
      return entity->index;
    }
  }
  if (expr.kind == ast::ExprKind::kCall) {
    const int index = static_cast<int>(scenario_.functions.size());
    scenario_.functions.emplace_back();
    function_valid_.push_back(true);
    Function function;
    if (!BuildFunction(scope, statement, expr, std::make_pair(argument, result), function, index)) {
      function_valid_[static_cast<std::size_t>(index)] = false;
      scenario_.functions[static_cast<std::size_t>(index)] = std::move(function);
      return std::nullopt;
    }
    scenario_.functions[static_cast<std::size_t>(index)] = std::move(function);
    return index;
  }
  // A quantity: a constant of the result's dimension or the slope of a linear function.
  auto value = Evaluate(scope, expr);
  if (!value) return std::nullopt;
  if (value->components.size() != 1) {
    Report(DiagnosticKind::kWrongValueKind, expr.range,
           fmt::format("`{}` takes a function or a number, found a vector", what), "a vector",
           "give a function's name, a number with its unit, or constant/table/polynomial(...)");
    return std::nullopt;
  }
  Function function;
  function.argument = argument;
  function.result = result;
  function.range = expr.range;
  if (value->dimension == result || IsBareZero(*value)) {
    function.kind = Function::Kind::kConstant;
    function.constant = value->components[0];
  } else if (value->dimension == result / argument) {
    function.kind = Function::Kind::kPolynomial;
    function.coefficients = {0.0, value->components[0]};
  } else {
    const std::string slope =
        argument.IsDimensionless()
            ? std::string()
            : fmt::format(" or a slope {}", DescribeDimension(result / argument));
    Report(DiagnosticKind::kDimensionMismatch, expr.range,
           fmt::format("`{}` expects a function {}, a constant {}{}, found {}", what,
                       Signature(argument, result), DescribeDimension(result), slope,
                       DescribeDimension(value->dimension)),
           "wrong dimension", DimensionHelp(result / argument, value->dimension));
    return std::nullopt;
  }
  if (statement.block) {
    // `force = 50 kN/m { energy_loss = 0.5 }` keeps the unloading attributes.
    const BoundBlock bound = Bind(BlockKind::kTable, statement.block.get(), statement.range);
    if (!bound.rows.empty()) {
      Report(DiagnosticKind::kMisplacedStatement, bound.rows[0]->range,
             "table rows need `table(x -> y)`", "rows without a table",
             "put the rows in the block of `table(x -> y) { ... }`");
    }
    ReadUnloading(scope, bound, function);
  }
  scenario_.functions.push_back(std::move(function));
  function_valid_.push_back(true);
  return static_cast<FunctionId>(scenario_.functions.size() - 1);
}

void CheckContext::ReadUnloading(Scope& scope, const BoundBlock& bound, Function& function,
                                 int index) {
  function.energy_loss = ReadQuantity(scope, bound, BlockKind::kTable, "energy_loss").value_or(0);
  function.permanent_set =
      ReadQuantity(scope, bound, BlockKind::kTable, "permanent_set").value_or(0);
  function.unload_slope = ReadQuantity(scope, bound, BlockKind::kTable, "unload_slope");
  ReadAtbUnloading(scope, bound, function, index);
  if (!function.unload_slope) return;
  // A straight unloading line of the given slope decides both the permanent deflection and the
  // energy returned: a permanent set or an energy loss besides would contradict it.
  const std::pair<const char*, const ast::Statement*> others[] = {
      {"energy_loss", One(bound, "energy_loss")}, {"permanent_set", One(bound, "permanent_set")}};
  for (const auto& [other, given] : others) {
    if (given == nullptr) continue;
    Report(DiagnosticKind::kOverdeterminedUnloading, given->range,
           fmt::format("`{}` and `unload_slope` both describe the unloading line", other),
           "given with `unload_slope`",
           fmt::format("keep one: `unload_slope = s` unloads along a straight line of s times the "
                       "loading slope (its permanent set is 1 - 1/s of the largest deflection); "
                       "`{}` describes the curve otherwise",
                       other));
    function.unload_slope.reset();
  }
}

void CheckContext::RefuseUnloading(std::optional<FunctionId> id, const BoundBlock& bound,
                                   AttributeKey name, std::string_view element) {
  if (!id) return;
  const Function& function = scenario_.functions[static_cast<std::size_t>(*id)];
  std::string given;
  for (const auto& [attribute, value] :
       {std::pair{"energy_loss", function.energy_loss},
        std::pair{"permanent_set", function.permanent_set},
        std::pair{"unload_slope", function.unload_slope.value_or(0.0)},
        std::pair{"unloading", function.atb_unloading ? 1.0 : 0.0}}) {
    if (value != 0.0) given += fmt::format("{}`{}`", given.empty() ? "" : ", ", attribute);
  }
  if (given.empty()) return;
  const ast::Statement* statement = One(bound, name);
  Report(DiagnosticKind::kUnloadingNotApplied, statement ? statement->range : function.range,
         fmt::format("the `{}` of {} unloads as it loads; its function's {} would not apply",
                     name.view(), element, given),
         "a function with unloading",
         "give this element a function without unloading attributes (contacts, belts and joint "
         "torques unload by them)");
}

bool CheckContext::BuildFunction(Scope& scope, const ast::Statement& statement,
                                 const ast::Expr& call,
                                 std::optional<std::pair<Dimension, Dimension>> expected,
                                 Function& function, int index) {
  function.range = call.range;
  const std::string form = call.PathText();
  std::vector<const ast::Expr*> positional;
  for (const ast::Argument& argument : call.arguments) {
    if (!argument.name.empty()) {
      Report(DiagnosticKind::kUnknownArgument, argument.name_range,
             fmt::format("`{}` takes no named argument `{}`", form, argument.name),
             "unknown argument", "remove it; `sled explain E0209` lists what each form takes");
      return false;
    }
    positional.push_back(argument.value.get());
  }
  // A signature written as the first argument: table(deflection -> force).
  std::optional<std::pair<Dimension, Dimension>> signature;
  if (!positional.empty() && positional[0]->kind == ast::ExprKind::kArrow) {
    const ast::Expr& arrow = *positional[0];
    bool ok = arrow.operands.size() == 2;
    Dimension parts[2];
    for (std::size_t i = 0; ok && i < 2; ++i) {
      const ast::Expr& word = arrow.operands[i];
      const QuantityName* name = word.kind == ast::ExprKind::kPath && word.path.size() == 1
                                     ? FindQuantityName(word.path[0])
                                     : nullptr;
      if (!name) {
        Report(DiagnosticKind::kUnknownName, word.range,
               fmt::format("`{}` is not a quantity name", lang::ast::Dump(word)),
               "not a quantity name",
               word.kind == ast::ExprKind::kPath
                   ? lang::DidYouMean(word.PathText(), QuantityNames())
                   : "write two quantity names, as in `table(deflection -> force)`");
        return false;
      }
      parts[i] = name->dimension;
    }
    if (!ok) {
      Report(DiagnosticKind::kMalformedStatement, arrow.range,
             "a function signature has one argument and one result: `x -> y`", "not x -> y",
             "name the argument quantity, then the result: `deflection -> force`");
      return false;
    }
    signature = std::make_pair(parts[0], parts[1]);
    positional.erase(positional.begin());
    if (expected &&
        !(signature->first == expected->first && signature->second == expected->second)) {
      Report(DiagnosticKind::kDimensionMismatch, arrow.range,
             fmt::format("this function maps {}, but {} is needed here",
                         Signature(signature->first, signature->second),
                         Signature(expected->first, expected->second)),
             "wrong signature",
             "use a function whose argument and result have the dimensions needed here");
      return false;
    }
  }
  if (!signature) signature = expected;
  if (signature) {
    function.argument = signature->first;
    function.result = signature->second;
  }

  // Rows and unloading attributes live in the statement's block.
  BoundBlock bound;
  if (statement.block) bound = Bind(BlockKind::kTable, statement.block.get(), statement.range);
  ReadUnloading(scope, bound, function, index);
  if (form != "table" && !bound.rows.empty()) {
    Report(DiagnosticKind::kMisplacedStatement, bound.rows[0]->range,
           fmt::format("table rows given to `{}`", form), "rows need `table(x -> y)`",
           "only `table(x -> y)` takes rows; remove them");
    return false;
  }

  if (form == "constant") {
    function.kind = Function::Kind::kConstant;
    if (positional.size() != 1) {
      Report(DiagnosticKind::kMissingArgument, call.range,
             fmt::format("`constant` takes one value, found {}", positional.size()),
             "one value expected", "write `constant(50 N*m)`");
      return false;
    }
    auto value = Evaluate(scope, *positional[0]);
    if (!value) return false;
    if (value->components.size() != 1) {
      Report(DiagnosticKind::kWrongValueKind, positional[0]->range,
             "`constant` takes a number, found a vector", "a vector",
             "give one number with its unit: `constant(2 kN)`");
      return false;
    }
    if (signature && !(value->dimension == signature->second) && !IsBareZero(*value)) {
      Report(DiagnosticKind::kDimensionMismatch, positional[0]->range,
             fmt::format("the constant should be {}, found {}",
                         DescribeDimension(signature->second), DescribeDimension(value->dimension)),
             "wrong dimension", MismatchHelp(signature->second, value->dimension));
      return false;
    }
    if (!signature) function.result = value->dimension;
    function.constant = value->components[0];
    return true;
  }

  if (form == "table") {
    function.kind = Function::Kind::kTable;
    if (!signature || call.arguments.empty() ||
        call.arguments[0].value->kind != ast::ExprKind::kArrow) {
      Report(DiagnosticKind::kMissingArgument, call.range,
             "a table names its argument and result: `table(deflection -> force)`",
             "signature missing",
             "name the argument and result quantities, as in `table(deflection -> force)`");
      return false;
    }
    if (!positional.empty()) {
      Report(DiagnosticKind::kUnknownArgument, positional[0]->range,
             "`table` takes only its signature; rows go in the block after it", "extra argument",
             "move the rows into the block: `table(x -> y) { 0 mm -> 0 N  10 mm -> 1 kN }`");
      return false;
    }
    bool ok = true;
    for (const ast::Statement* row : bound.rows) {
      const ast::Expr& arrow = row->values.at(0);
      if (arrow.operands.size() != 2) {
        Report(DiagnosticKind::kMalformedStatement, arrow.range,
               fmt::format("a row of a table gives x -> y, found {} values", arrow.operands.size()),
               "not x -> y", "write each row as `x -> y`");
        ok = false;
        continue;
      }
      auto x = ExpectQuantity(scope, arrow.operands[0], function.argument, "table argument");
      auto y = ExpectQuantity(scope, arrow.operands[1], function.result, "table value");
      if (!x || !y) {
        ok = false;
        continue;
      }
      if (!function.points.empty() && !(*x > function.points.back()[0])) {
        Report(DiagnosticKind::kTableNotMonotone, arrow.operands[0].range,
               "table argument does not increase", "not above the previous row",
               "the rows of a table must be in strictly increasing order of the argument");
        ok = false;
        continue;
      }
      function.points.push_back({*x, *y});
    }
    if (ok && function.points.size() < 2) {
      Report(DiagnosticKind::kTableTooShort, call.range,
             fmt::format("a table needs at least two rows, found {}", function.points.size()),
             "too few rows", "add rows in a block: `{ 0 mm -> 0 N  10 mm -> 1 kN }`");
      ok = false;
    }
    return ok;
  }

  if (form == "polynomial") {
    function.kind = Function::Kind::kPolynomial;
    if (positional.empty()) {
      Report(DiagnosticKind::kMissingArgument, call.range,
             "a polynomial needs its coefficients: `polynomial(c0, c1, ...)`", "no coefficients",
             "give c0 up to c5, each with its unit: `polynomial(0 N, 50 N/mm)`");
      return false;
    }
    if (positional.size() > kMaxPolynomialDegree + 1) {
      Report(DiagnosticKind::kPolynomialDegree, positional[kMaxPolynomialDegree + 1]->range,
             fmt::format("a polynomial of degree {}; the largest allowed is {}",
                         positional.size() - 1, kMaxPolynomialDegree),
             "sixth coefficient", "CVS functions are polynomials of degree five at most");
      return false;
    }
    PendingPolynomial pending;
    bool ok = true;
    for (const ast::Expr* coefficient : positional) {
      auto value = Evaluate(scope, *coefficient);
      if (!value) {
        ok = false;
        continue;
      }
      if (value->components.size() != 1) {
        Report(DiagnosticKind::kWrongValueKind, coefficient->range,
               "a coefficient is a number, found a vector", "a vector",
               "each coefficient is one number with its unit");
        ok = false;
        continue;
      }
      pending.coefficients.push_back(*value);
      pending.ranges.push_back(coefficient->range);
    }
    if (!ok) return false;
    function.coefficients.assign(pending.coefficients.size(), 0.0);
    pending_polynomials_[index] = std::move(pending);
    if (signature) {
      // Resolve now against the known signature.
      scenario_.functions[static_cast<std::size_t>(index)] = function;
      const bool matched = MatchSignature(index, signature->first, signature->second, call.range);
      function = scenario_.functions[static_cast<std::size_t>(index)];
      return matched;
    }
    return true;
  }

  Report(DiagnosticKind::kInvalidEnumValue, call.range,
         fmt::format("unknown function form `{}`", form), "not a function form",
         lang::DidYouMean(form, {"constant", "table", "polynomial"}));
  return false;
}

void CheckContext::DefineFunction(Scope& scope, const ast::Statement& statement, int index) {
  Function function;
  function.name = scope.prefix + statement.target->PathText();
  const ast::Expr* value = statement.values.size() == 1 ? &statement.values[0] : nullptr;
  bool ok = false;
  if (!value) {
    Report(DiagnosticKind::kMalformedStatement, statement.range,
           "a function is declared as `function NAME = table(x -> y) { rows }`", "no single value",
           "give the function one value after `=`");
  } else if (value->kind == ast::ExprKind::kCall) {
    function_valid_[static_cast<std::size_t>(index)] = true;  // MatchSignature may need it
    ok = BuildFunction(scope, statement, *value, std::nullopt, function, index);
  } else {
    auto quantity = Evaluate(scope, *value);
    if (quantity && quantity->components.size() == 1) {
      function.kind = Function::Kind::kConstant;
      function.result = quantity->dimension;
      function.constant = quantity->components[0];
      ok = true;
    } else if (quantity) {
      Report(DiagnosticKind::kWrongValueKind, value->range,
             "a function is a number or constant/table/polynomial(...), found a vector", "a vector",
             "give a number with its unit, or constant/table/polynomial(...)");
    }
  }
  function.name = scope.prefix + statement.target->PathText();
  function.range = statement.target->range;
  scenario_.functions[static_cast<std::size_t>(index)] = std::move(function);
  function_valid_[static_cast<std::size_t>(index)] = ok;
}

}  // namespace sled::compiler::internal
