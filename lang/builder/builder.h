// The embedded C++ form of the language: a fluent builder that produces exactly the AST the parser
// produces for the equivalent .sled text, so the checker, the formatter and the runtime serve it
// like any other front end (docs/architecture.md, the stages).
//
//   using namespace sled::lang::build;
//   sled::lang::SourceManager sources;
//   Scene scene(sources, "frontal sled");                // scenario "frontal sled" {
//   scene.Param("speed", Q(56, "km/h"));                 //   param speed = 56 km/h
//   scene.Set("gravity", V(0, 0, -9.81, "m/s^2"));       //   gravity = (0, 0, -9.81) m/s^2
//   scene.Block("time").Set("end", Q(200, "ms"));        //   time { end = 200 ms }
//   scene.Declare("vehicle", "sled")                     //   vehicle sled {
//       .Set("motion",                                   //     motion = half_sine(
//            Call("half_sine",                           //       delta_v = speed,
//                 {{"delta_v", Ref("speed")},            //       duration = 100 ms,
//                  {"duration", Q(100, "ms")},           //       axis = -x)
//                  {"axis", -Ref("x")}}));               //   }
//   scene.Declare("plane", "seat_pan")                   //   plane seat_pan on sled {
//       .On(Ref("sled"))                                 //     corners = (0, -250, 0) mm, ...
//       .Set("corners", {V(0, -250, 0, "mm"), V(500, -250, 0, "mm"), V(0, 250, 0, "mm")});
//   scene.Function("foam", Table("deflection", "force")) //   function foam = table(...) {
//       .Row(Q(0, "mm"), Q(0, "N"))                      //     0 mm -> 0 N
//       .Row(Q(25, "mm"), Q(2, "kN"));                   //     25 mm -> 2 kN }
//   sled::lang::ast::File file = scene.Finish();
//
// Where the tree points. Every node's SourceRange is the C++ call that made it, taken from
// std::source_location: Finish() registers each C++ file with the SourceManager (read from disk
// by its compiled-in path, or, when it cannot be read, as a buffer of empty lines so line
// numbers still hold) and turns (line, column) into byte offsets. A diagnostic about a value
// therefore shows the line of the Q(...), V(...) or Ref(...) call that wrote it. GCC places a
// call at its `(`; Clang at the start of the whole expression, so a chain of calls on one object
// all point at the chain's first line (values keep their own lines with both compilers).
//
// Rules the builder keeps so that lang::Format prints text which parses back to the same tree:
// numbers are spelled in the shortest round-trip form and a negative number is a unary minus (as
// `-9.81 m/s^2` parses); units are split into factors as the grammar splits them (`*` and `/`,
// `^n`; a factor after `/` has a negative exponent; `*` after `/` multiplies again); operands
// that bind more loosely than their place allows get the parentheses (kParen) the text needs.
// A malformed unit, name or number is a programming error: std::invalid_argument naming the
// builder function and the C++ call site.
#pragma once

#include <cstdint>
#include <initializer_list>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>
#include <version>
#if __has_include(<source_location>)
#include <source_location>
#endif

#include "lang/ast/ast.h"
#include "lang/source/source_manager.h"

namespace sled::lang::build {

#if defined(__cpp_lib_source_location)
using SourceLocation = std::source_location;
#else
// Clang 14 with libstdc++ 12 lacks std::source_location (no __builtin_source_location); the
// older builtins give the same answer when used in a default argument.
class SourceLocation {
 public:
  static constexpr SourceLocation current(
      const char* file = __builtin_FILE(), const char* function = __builtin_FUNCTION(),
      std::uint_least32_t line = __builtin_LINE(),
      std::uint_least32_t column = __builtin_COLUMN()) noexcept {
    SourceLocation location;
    location.file_ = file;
    location.function_ = function;
    location.line_ = line;
    location.column_ = column;
    return location;
  }
  constexpr const char* file_name() const noexcept { return file_; }
  constexpr const char* function_name() const noexcept { return function_; }
  constexpr std::uint_least32_t line() const noexcept { return line_; }
  constexpr std::uint_least32_t column() const noexcept { return column_; }

 private:
  const char* file_ = "";
  const char* function_ = "";
  std::uint_least32_t line_ = 0;
  std::uint_least32_t column_ = 0;
};
#endif

// An expression: a number, quantity, vector, name, string, boolean, call or arithmetic. Values
// are immutable and cheap to copy, so one can be reused (`auto pelvis = Ref("occupant.pelvis")`).
// A C++ number or bool converts implicitly: `Set("friction", 0.4)`, `Set("impulse", true)`.
class Value {
 public:
  template <typename T>
  requires(std::is_arithmetic_v<T> && !std::is_same_v<T, char>)
      Value(T number,  // NOLINT(google-explicit-constructor): implicit on purpose
            SourceLocation where = SourceLocation::current())
      : node_(std::is_same_v<T, bool> ? MakeBool(number != T{}, where)
                                      : MakeNumber(static_cast<double>(number), where)) {}

  // The expression with invalid ranges (no SourceManager is involved): for tests and messages.
  ast::Expr ToExpr() const;

  struct Node;  // defined in builder.cpp

 private:
  explicit Value(std::shared_ptr<const Node> node) : node_(std::move(node)) {}
  static std::shared_ptr<const Node> MakeNumber(double number, const SourceLocation& where);
  static std::shared_ptr<const Node> MakeBool(bool value, const SourceLocation& where);

  std::shared_ptr<const Node> node_;
  friend class Access;
};

// An argument of a call: positional (`0`, `Q(2.5, "N*m/deg")`) or named (`{"delta_v", v}`).
struct Arg {
  Arg(Value positional)  // NOLINT(google-explicit-constructor): implicit on purpose
      : value(std::move(positional)) {}
  template <typename T>
  requires(std::is_arithmetic_v<T> && !std::is_same_v<T, char>)
      Arg(T number,  // NOLINT(google-explicit-constructor): implicit on purpose
          SourceLocation where = SourceLocation::current())
      : value(number, where) {}
  Arg(std::string_view argument_name, Value named) : name(argument_name), value(std::move(named)) {}

  std::string name;  // empty for a positional argument
  Value value;
};

// --- Values -----------------------------------------------------------------------------------

// A number with a unit: Q(56, "km/h") is `56 km/h`; an empty unit gives a bare number.
Value Q(double number, std::string_view unit, SourceLocation where = SourceLocation::current());
// A three-component vector with an optional unit: V(0, 0, -9.81, "m/s^2").
Value V(Value x, Value y, Value z, std::string_view unit = {},
        SourceLocation where = SourceLocation::current());
// A vector of any length (two or more components): Vector({1, 2}, "mm") is `(1, 2) mm`.
Value Vector(std::initializer_list<Value> components, std::string_view unit = {},
             SourceLocation where = SourceLocation::current());
// A dotted name: Ref("occupant.pelvis").
Value Ref(std::string_view path, SourceLocation where = SourceLocation::current());
// A string: Str("frontal sled").
Value Str(std::string_view text, SourceLocation where = SourceLocation::current());
// A call: Call("half_sine", {{"delta_v", Ref("speed")}, {"duration", Q(100, "ms")}}) or
// Call("polynomial", {0, Q(2.5, "N*m/deg")}).
Value Call(std::string_view callee, std::initializer_list<Arg> arguments = {},
           SourceLocation where = SourceLocation::current());
// An arrow chain: Arrow({V(-200, -230, 50, "mm"), Ref("occupant.pelvis"), V(...)}).
Value Arrow(std::initializer_list<Value> chain, SourceLocation where = SourceLocation::current());
Value Arrow(Value from, Value to, SourceLocation where = SourceLocation::current());
// `table(from -> to)`: the head of a table function whose rows follow.
Value Table(std::string_view from, std::string_view to,
            SourceLocation where = SourceLocation::current());
// `-operand`, `base ^ exponent` and `(inner)`.
Value Neg(Value operand, SourceLocation where = SourceLocation::current());
Value Pow(Value base, Value exponent, SourceLocation where = SourceLocation::current());
Value Paren(Value inner, SourceLocation where = SourceLocation::current());
// Arithmetic; the node points at its operands.
Value operator+(Value left, Value right);
Value operator-(Value left, Value right);
Value operator*(Value left, Value right);
Value operator/(Value left, Value right);
Value operator-(Value operand);

// --- Statements -------------------------------------------------------------------------------

// One statement `keyword [target] [clause...] [= value, ...] [{ ... }]`, or a table row. Methods
// that describe this statement (clauses, Equals) and those that add a simple child to its block
// (Set, Row, Param, Let, Import) return *this, so they chain; those that add a child which has
// children of its own (Declare, Block, Add, Attribute, Function, Joint) return the child.
// References stay valid as long as the Scene lives.
class Statement {
 public:
  Statement(const Statement&) = delete;
  Statement& operator=(const Statement&) = delete;
  virtual ~Statement();

  // Header clauses, kept in call order: `on sled`, `with seat_pan`, `at (0, 0, 0) mm`,
  // `as occupant`, and `: ball(pelvis -> torso)` (Is).
  Statement& On(Value frame, SourceLocation where = SourceLocation::current());
  Statement& With(Value other, SourceLocation where = SourceLocation::current());
  Statement& At(Value point, SourceLocation where = SourceLocation::current());
  Statement& As(std::string_view name, SourceLocation where = SourceLocation::current());
  // `filter cfc1000` on an output request.
  Statement& Filter(std::string_view filter_class,
                    SourceLocation where = SourceLocation::current());
  // `relative_to sled` on a segment output request: the quantity relative to a frame, in its axes.
  Statement& RelativeTo(Value frame, SourceLocation where = SourceLocation::current());
  Statement& Is(Value value, SourceLocation where = SourceLocation::current());
  // `= value` (call again for `= a, b, c`).
  Statement& Equals(Value value);

  // `attribute = value`, `attribute = a, b, c` and `attribute target = value` (at pelvis = ...).
  Statement& Set(std::string_view attribute, Value value,
                 SourceLocation where = SourceLocation::current());
  Statement& Set(std::string_view attribute, std::initializer_list<Value> values,
                 SourceLocation where = SourceLocation::current());
  Statement& Set(std::string_view attribute, std::string_view target, Value value,
                 SourceLocation where = SourceLocation::current());
  // A table row `from -> to` or `a -> b -> c`; the first value may not start with a name.
  Statement& Row(Value from, Value to, SourceLocation where = SourceLocation::current());
  Statement& Row(std::initializer_list<Value> values,
                 SourceLocation where = SourceLocation::current());
  // `param name = value`, `let name = value`, `import module [as alias]`.
  Statement& Param(std::string_view name, Value value,
                   SourceLocation where = SourceLocation::current());
  Statement& Let(std::string_view name, Value value,
                 SourceLocation where = SourceLocation::current());
  Statement& Import(std::string_view module, std::string_view alias = {},
                    SourceLocation where = SourceLocation::current());

  // `keyword name { }`: a declaration with a block (a dotted name becomes a path).
  Statement& Declare(std::string_view keyword, std::string_view name,
                     SourceLocation where = SourceLocation::current());
  // `keyword target { }` with a path or string target: Declare("contact", Ref("occupant.head")).
  Statement& Declare(std::string_view keyword, Value target,
                     SourceLocation where = SourceLocation::current());
  // `keyword { }`: time, output, ...
  Statement& Block(std::string_view keyword, SourceLocation where = SourceLocation::current());
  // `keyword [target]` without a block (it gets one when children are added): output requests.
  Statement& Add(std::string_view keyword, SourceLocation where = SourceLocation::current());
  Statement& Add(std::string_view keyword, std::string_view target,
                 SourceLocation where = SourceLocation::current());
  // `attribute = value`, returned so rows or unloading attributes can follow:
  // Attribute("force", Table("strain", "force")).Row(0, Q(0, "N")).Row(0.1, Q(8, "kN")).
  Statement& Attribute(std::string_view attribute, Value value,
                       SourceLocation where = SourceLocation::current());
  // `function name = value`, returned for its rows.
  Statement& Function(std::string_view name, Value value,
                      SourceLocation where = SourceLocation::current());
  // `joint name : type(parent -> child) { }`.
  Statement& Joint(std::string_view name, std::string_view type, std::string_view parent,
                   std::string_view child, SourceLocation where = SourceLocation::current());

 protected:
  Statement(ast::StatementKind kind, std::string_view keyword, bool block,
            const SourceLocation& where, const char* function);

  struct Clause {
    std::string word;
    Value value;
    SourceLocation where;
  };

  Statement& AddChild(std::unique_ptr<Statement> child);

  ast::StatementKind kind_;
  std::string keyword_;
  std::optional<Value> target_;
  std::vector<Clause> clauses_;
  bool has_value_ = false;
  std::vector<Value> values_;
  bool block_ = false;
  std::vector<std::unique_ptr<Statement>> children_;
  SourceLocation where_;

  friend class Access;
};

// A scenario: `scenario "title" { ... }` in a file of its own. Finish() produces the AST; it may
// be called again after more statements are added.
class Scene : public Statement {
 public:
  Scene(SourceManager& sources, std::string_view title,
        SourceLocation where = SourceLocation::current());

  // The file's AST. Its FileId is the C++ file that constructed the Scene; buffers for the C++
  // files are added to the SourceManager on first use.
  ast::File Finish() const;

 private:
  SourceManager& sources_;
};

}  // namespace sled::lang::build
