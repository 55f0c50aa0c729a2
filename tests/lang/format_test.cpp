#include "lang/format/formatter.h"

#include <algorithm>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "lang/ast/ast.h"
#include "lang/ast/make_expr.h"
#include "lang/diagnostics/diagnostic.h"
#include "lang/source/source_manager.h"
#include "lang/syntax/parser.h"

namespace sled::lang {
namespace {

// Parses `text`, failing the test on any diagnostic.
ast::File ParseClean(const std::string& text) {
  SourceManager sources;
  DiagnosticCollector diagnostics;
  const FileId id = sources.Add("test.sled", text);
  ast::File file = Parse(sources, id, {&diagnostics});
  EXPECT_TRUE(diagnostics.diagnostics().empty())
      << "input does not parse cleanly:\n"
      << text << "\nfirst diagnostic: " << diagnostics.diagnostics().front().message;
  return file;
}

std::string FormatText(const std::string& text) { return Format(ParseClean(text)); }

ast::Expr ParseValueClean(const std::string& text) {
  SourceManager sources;
  DiagnosticCollector diagnostics;
  const FileId id = sources.Add("value.sled", text);
  std::optional<ast::Expr> value = ParseValue(sources, id, {&diagnostics});
  EXPECT_TRUE(value.has_value()) << text;
  EXPECT_FALSE(diagnostics.has_errors()) << text;
  return value ? std::move(*value) : ast::Expr();
}

// Every comment text in the tree, in reading order of the tree walk.
void CollectComments(const ast::Block& block, std::vector<std::string>& out) {
  for (const ast::Statement& statement : block.statements) {
    for (const ast::Comment& comment : statement.leading_comments) out.push_back(comment.text);
    if (statement.block) CollectComments(*statement.block, out);
    if (statement.trailing_comment) out.push_back(statement.trailing_comment->text);
  }
  for (const ast::Comment& comment : block.closing_comments) out.push_back(comment.text);
}

std::vector<std::string> SortedComments(const ast::File& file) {
  std::vector<std::string> out;
  CollectComments(file.body, out);
  std::sort(out.begin(), out.end());
  return out;
}

// Inputs that together use every statement and expression form of the grammar.
const std::vector<std::string>& Corpus() {
  static const std::vector<std::string> corpus = {
      // The design document's scenario, in the forms the grammar accepts.
      R"(// examples/frontal_sled.sled
scenario "frontal sled, belted occupant, 56 km/h" {
  import std.humans.male50 as occupant
  import std.pulses.half_sine

  gravity = (0, 0, -9.81) m/s^2
  time { end = 200 ms  output_every = 0.1 ms }
  integrator exponential { tolerance = 1e-5  max_step = 1 ms }

  vehicle sled {
    motion = half_sine(delta_v = 56 km/h, duration = 100 ms, axis = -x)
  }

  plane seat_pan on sled { corners = (0, -250, 0) mm, (500, -250, 0) mm, (0, 250, 0) mm }

  function foam = table(deflection -> force) {
    0 mm -> 0 N
    25 mm -> 2 kN
    60 mm -> 12 kN
    unload slope = 0.2  permanent_set = 0.3
  }

  contact occupant.pelvis with seat_pan { force = foam  friction = 0.4 }

  belt lap on sled {
    path = (-200, -230, 50) mm -> occupant.pelvis -> (-200, 230, 50) mm
    force = table(strain -> force) { 0 -> 0 N  0.1 -> 8 kN }
    slack = 5 mm
  }

  initial occupant { position = (250, 0, 300) mm  velocity = (0, 0, 0) m/s }

  output {
    acceleration occupant.head at (0, 0, 0) mm
    joint_torque occupant.neck
    contact_force occupant.pelvis with seat_pan
    criteria = hic15(occupant.head), chest_3ms(occupant.upper_torso)
  }
}
)",
      R"(// stdlib/humans/male50.sled (excerpt)
body male50 {
  segment pelvis {
    mass = 11.7 kg
    inertia = (0.10, 0.09, 0.11) kg*m^2
    ellipsoid = (110, 170, 120) mm
    at = (0, 0, 20) mm
  }
  joint lumbar : ball(pelvis -> abdomen) {
    at pelvis = (0, 0, 120) mm   at abdomen = (0, 0, -80) mm
    flexure = polynomial(0, 2.5 N*m/deg)
    viscous = 1.5 N*m*s/rad
  }
  joint knee_r : pin(upper_leg_r -> lower_leg_r) { axis = (0, 1, 0) }
}
)",
      // Expressions: arithmetic, precedence, parentheses, powers, unary minus, booleans,
      // strings, calls with named and positional arguments, trailing commas, arrows.
      "param speed = 56 km/h\n"
      "param a = 2*speed+1 km/h; param b = -(speed - 3 km/h) / 2\n"
      "param c = 2^-3 ^ 2 * - - x.y.z\n"
      "param d = (1 + 2) * (3 - (4 / 5))\n"
      "flag = true, false\n"
      "label \"quoted \\\"name\\\" with \\\\ and \\t tab\\nnewline\"\n"
      "f = g(1, h(2, k = 3 m), name = \"n\",)\n"
      "v = (1, 2, 3,) m/s, (a + b, -c, d ^ 2)\n"
      "chain = a -> b -> (c -> d) -> -1\n"
      "e = f()\n",
      // Units: products, quotients, powers, negative exponents, exponents in the number.
      "u1 = 1e-5 s\nu2 = 2.5E+3 N*m/deg\nu3 = 9.81 m/s^2\nu4 = 3 s^-1\nu5 = 1 kg*m^2/s^2\n"
      "u6 = 4 m*s^-2\nu7 = 5 N/m*s\nu8 = 7. mm\nu9 = 5 m ^ 2\n",
      // Statement shapes: keyword only, target, string target, every clause word, `:` clause,
      // values with and without blocks, empty blocks, nested blocks, `;` and shared lines.
      "output\n"
      "output {}\n"
      "output { }\n"
      "a { b { c { d = 1 } } }\n"
      "x on y with z at (1, 2, 3) mm as w : q(r) = 1, 2 { inner = 3; other = 4 }\n"
      "s \"target\" { }\n"
      "t = 1; u = 2;; v = 3\n"
      "rows = table(x -> y) { -1 -> 2  (1 + 2) -> 3 -> 4\n  0.5 mm -> -2 kN }\n",
      // Comments everywhere.
      "// file header\n"
      "a = 1  // trailing\n"
      "\n"
      "\n"
      "\n"
      "// leading of b\n"
      "// second line\n"
      "b {  // inside after brace\n"
      "  c = 2\n"
      "  // closing of b's block\n"
      "}  // trailing after brace\n"
      "e { // only a comment\n"
      "}\n"
      "// file end\n"
      "//no space\n",
  };
  return corpus;
}

TEST(FormatTest, IsIdempotentOnTheCorpus) {
  for (const std::string& input : Corpus()) {
    const std::string once = FormatText(input);
    const std::string twice = FormatText(once);
    EXPECT_EQ(twice, once) << "input:\n" << input;
  }
}

TEST(FormatTest, RoundTripsTheTree) {
  for (const std::string& input : Corpus()) {
    const ast::File original = ParseClean(input);
    const std::string formatted = Format(original);
    const ast::File reparsed = ParseClean(formatted);
    EXPECT_EQ(ast::Dump(reparsed), ast::Dump(original)) << "formatted:\n" << formatted;
  }
}

TEST(FormatTest, KeepsEveryComment) {
  for (const std::string& input : Corpus()) {
    const ast::File original = ParseClean(input);
    const ast::File reparsed = ParseClean(Format(original));
    EXPECT_EQ(SortedComments(reparsed), SortedComments(original)) << "input:\n" << input;
  }
}

TEST(FormatTest, OutputEndsWithOneNewlineAndHasNoTrailingBlanks) {
  for (const std::string& input : Corpus()) {
    const std::string formatted = FormatText(input);
    ASSERT_FALSE(formatted.empty());
    EXPECT_EQ(formatted.back(), '\n');
    EXPECT_NE(formatted.substr(formatted.size() - 2), "\n\n");
    EXPECT_EQ(formatted.find(" \n"), std::string::npos) << formatted;
    EXPECT_EQ(formatted.find("\n\n\n"), std::string::npos) << formatted;
    EXPECT_NE(formatted.front(), '\n');
  }
}

TEST(FormatTest, PlacesCommentsAndCollapsesBlankLines) {
  const std::string input = Corpus().back();
  EXPECT_EQ(FormatText(input),
            "// file header\n"
            "a = 1  // trailing\n"
            "\n"
            "// leading of b\n"
            "// second line\n"
            "b {\n"
            "  // inside after brace\n"
            "  c = 2\n"
            "  // closing of b's block\n"
            "}  // trailing after brace\n"
            "e {\n"
            "  // only a comment\n"
            "}\n"
            "// file end\n"
            "//no space\n");
}

TEST(FormatTest, DropsBlankLinesAtTheStartOfABlockAndTheFile) {
  EXPECT_EQ(FormatText("\n\n\nx {\n\n\n  a = 1\n\n  b = 2\n\n}\n\n\n"),
            "x {\n"
            "  a = 1\n"
            "\n"
            "  b = 2\n"
            "}\n");
}

TEST(FormatTest, SplitsSharedLinesAndSemicolons) {
  EXPECT_EQ(FormatText("time {\n  end = 200 ms  output_every = 0.1 ms\n}\nt = 1; u = 2;; v = 3\n"),
            "time {\n"
            "  end = 200 ms\n"
            "  output_every = 0.1 ms\n"
            "}\n"
            "t = 1\n"
            "u = 2\n"
            "v = 3\n");
}

TEST(FormatTest, KeepsABlockWrittenOnOneLineOnOneLine) {
  // Statements two spaces apart, one space inside the braces, a trailing comment after them.
  EXPECT_EQ(FormatText("time {end=200 ms;output_every=0.1 ms}  // short\n"
                       "ellipsoid { semi_axes = (1,2,3) mm }\n"),
            "time { end = 200 ms  output_every = 0.1 ms }  // short\n"
            "ellipsoid { semi_axes = (1, 2, 3) mm }\n");
}

TEST(FormatTest, BreaksAOneLineBlockThatCannotStayOnOneLine) {
  // Past the column limit, around a comment, or around a block that is not empty.
  const std::string long_values = "a { b = " + std::string(90, 'x') + "  c = 1 }\n";
  EXPECT_EQ(FormatText(long_values), "a {\n  b = " + std::string(90, 'x') + "\n  c = 1\n}\n");
  EXPECT_EQ(FormatText("a { b = 1  // why\n}\n"), "a {\n  b = 1  // why\n}\n");
  EXPECT_EQ(FormatText("a { b { c = 1 }  d = 2 }\n"), "a {\n  b { c = 1 }\n  d = 2\n}\n");
  // Or where the next statement would read as part of the value before it (fuzzer finding:
  // `end = 100 ;ms` joined by spaces is `end = 100 ms`), or a row starts with a minus.
  EXPECT_EQ(FormatText("a { b = 100 ;ms }\n"), "a {\n  b = 100\n  ms\n}\n");
  EXPECT_EQ(FormatText("t { 0 -> 5;-1 -> 2 }\n"), "t {\n  0 -> 5\n  -1 -> 2\n}\n");
  EXPECT_EQ(FormatText("a { b = 1 m  output x }\n"), "a {\n  b = 1 m\n  output x\n}\n");
  // Or after a statement with neither value nor block, whose next name would read as its target
  // or clause (fuzzer finding: `positi;n = 1` joined by spaces is `positi n = 1`).
  EXPECT_EQ(FormatText("a { positi;n = 1 }\n"), "a {\n  positi\n  n = 1\n}\n");
  EXPECT_EQ(FormatText("a { b c;d = 1 }\n"), "a {\n  b c\n  d = 1\n}\n");
  // An empty block ends its statement, so the next may follow it.
  EXPECT_EQ(FormatText("a { c {};d = 2 }\n"), "a { c {}  d = 2 }\n");
}

TEST(FormatTest, KeepsTheCommaOfAOneElementVector) {
  // `(b,)` is a vector of one element and `(b)` a parenthesised value; with a unit the comma
  // is not needed (a finding of a sweep of single-character edits of the examples).
  EXPECT_EQ(FormatText("a = (b ,)\nc = (1 ,) mm\nd = (1)\n"), "a = (b,)\nc = (1) mm\nd = (1)\n");
}

TEST(FormatTest, PutsEachTableRowOnItsOwnLine) {
  EXPECT_EQ(FormatText("belt lap {\n"
                       "force = table(strain -> force) {\n 0 -> 0 N  0.1 -> 8 kN\n}\n"
                       "}\n"),
            "belt lap {\n"
            "  force = table(strain -> force) {\n"
            "    0 -> 0 N\n"
            "    0.1 -> 8 kN\n"
            "  }\n"
            "}\n");
  // A table written on one line stays so.
  EXPECT_EQ(FormatText("f = table(strain -> force) { 0 -> 0 N  0.1 -> 8 kN }\n"),
            "f = table(strain -> force) { 0 -> 0 N  0.1 -> 8 kN }\n");
}

TEST(FormatTest, IndentsNestedBlocksAndPrintsEmptyBlocksOnOneLine) {
  EXPECT_EQ(FormatText("a {\n b {\n c {   }\n }\n d { }\n}"),
            "a {\n"
            "  b {\n"
            "    c {}\n"
            "  }\n"
            "  d {}\n"
            "}\n");
  EXPECT_EQ(FormatText("a { b { c {   } } d { } }"),
            "a {\n"
            "  b { c {} }\n"
            "  d {}\n"
            "}\n");
}

TEST(FormatTest, PrintsHeadersWithTargetsAndClauses) {
  EXPECT_EQ(FormatText("joint   lumbar:ball(pelvis->abdomen){\nat pelvis=(0,0,120)mm}\n"
                       "import std.humans.male50   as occupant\n"
                       "scenario \"s\" on a with b at (1,2,3) mm as c = 1,2\n"),
            "joint lumbar : ball(pelvis -> abdomen) {\n"
            "  at pelvis = (0, 0, 120) mm\n"
            "}\n"
            "import std.humans.male50 as occupant\n"
            "scenario \"s\" on a with b at (1, 2, 3) mm as c = 1, 2\n");
}

TEST(FormatTest, KeepsNumberSpellingsAndUnitFactorOrder) {
  EXPECT_EQ(FormatText("a = 1e-5\nb = 2.50E+3 N*m/deg\nc = (0,0,-9.81) m/s^2\nd = 56 km/h\n"
                       "e = 0.10 kg*m^2\nf = 1 N*m*s/rad\ng = 5 N/m*s\n"),
            "a = 1e-5\n"
            "b = 2.50E+3 N*m/deg\n"
            "c = (0, 0, -9.81) m/s^2\n"
            "d = 56 km/h\n"
            "e = 0.10 kg*m^2\n"
            "f = 1 N*m*s/rad\n"
            "g = 5 N/m*s\n");
}

TEST(FormatTest, WritesNegativeUnitExponents) {
  // A leading negative exponent cannot become `1/s`; later ones become `/`.
  EXPECT_EQ(FormatText("a = 3 s^-1\nb = 4 m*s^-2\nc = 2 s^-1*m\nd = 1 m/s^-2\n"),
            "a = 3 s^-1\n"
            "b = 4 m/s^2\n"
            "c = 2 s^-1*m\n"
            "d = 1 m*s^2\n");
}

TEST(FormatTest, SpacesOperatorsButNotPowersOrUnaryMinus) {
  EXPECT_EQ(FormatText("a = 2*b+c/d-e^2\nb = - x\nc = 2^-3\nd = a--b\ne = (a+b)*(c)\n"
                       "f = a->b->-c\n"),
            "a = 2 * b + c / d - e^2\n"
            "b = -x\n"
            "c = 2^-3\n"
            "d = a - -b\n"
            "e = (a + b) * (c)\n"
            "f = a -> b -> -c\n");
}

TEST(FormatTest, SpacesAPowerOfAQuantityWithAUnit) {
  // `2 m^2` would be two square metres: the power of `2 m` keeps its spaces.
  EXPECT_EQ(FormatText("a = 2 m ^ 2\nb = (2 m)^2\nc = x^2 m\n"),
            "a = 2 m ^ 2\nb = (2 m)^2\nc = x^2 m\n");
}

TEST(FormatTest, PrintsCallsVectorsAndTrailingCommas) {
  EXPECT_EQ(FormatText("m = half_sine( delta_v=56 km/h ,duration = 100 ms,axis=-x, )\n"
                       "v = ( 1 ,2, 3, ) mm\nn = f()\n"),
            "m = half_sine(delta_v = 56 km/h, duration = 100 ms, axis = -x)\n"
            "v = (1, 2, 3) mm\n"
            "n = f()\n");
}

TEST(FormatTest, ReescapesStrings) {
  const std::string input = R"(name "a \"quoted\" \\ back\tslash\nline")"
                            "\n";
  EXPECT_EQ(FormatText(input), input);
}

TEST(FormatTest, KeepsATrailingCommentAfterTheClosingBrace) {
  EXPECT_EQ(FormatText("x {\n a = 1 }  // after\ny {} // empty\n"),
            "x {\n"
            "  a = 1\n"
            "}  // after\n"
            "y {}  // empty\n");
}

TEST(FormatTest, KeepsACommentInsideAValueList) {
  // A comment inside a statement's value becomes a leading comment of what follows it.
  const std::string input = "a = 1, // one\n  2\nb = 3\n";
  const std::string formatted = FormatText(input);
  EXPECT_EQ(formatted, "a = 1, 2\n// one\nb = 3\n");
  EXPECT_EQ(FormatText(formatted), formatted);
}

TEST(FormatTest, WrapsLongValueListsAfterCommas) {
  std::string input = "plane seat_pan on sled {\n  corners = ";
  for (int i = 0; i < 8; ++i) {
    if (i > 0) input += ", ";
    input += "(" + std::to_string(i * 100) + ", -250, 0) mm";
  }
  input += "  // corners\n}\n";
  const ast::File original = ParseClean(input);
  const std::string formatted = Format(original);
  EXPECT_EQ(formatted,
            "plane seat_pan on sled {\n"
            "  corners = (0, -250, 0) mm, (100, -250, 0) mm, (200, -250, 0) mm, (300, -250, 0) "
            "mm,\n"
            "      (400, -250, 0) mm, (500, -250, 0) mm, (600, -250, 0) mm, (700, -250, 0) mm  "
            "// corners\n"
            "}\n");
  EXPECT_EQ(ast::Dump(ParseClean(formatted)), ast::Dump(original));
  EXPECT_EQ(FormatText(formatted), formatted);
}

TEST(FormatTest, WrappedLinesStayWithinTheColumnLimit) {
  std::string input = "x {\n  y {\n    values = ";
  for (int i = 0; i < 60; ++i) {
    if (i > 0) input += ", ";
    input += std::to_string(i * 1001) + " N*m";
  }
  // A unit cannot end the line before `{`, so the last value has none.
  input += ", 0 {\n      0 -> 1\n    }\n  }\n}\n";
  const ast::File original = ParseClean(input);
  const std::string formatted = Format(original);
  std::size_t start = 0;
  int lines = 0;
  while (start < formatted.size()) {
    const std::size_t end = formatted.find('\n', start);
    EXPECT_LE(end - start, 100u) << formatted.substr(start, end - start);
    start = end + 1;
    ++lines;
  }
  EXPECT_GT(lines, 8);
  EXPECT_NE(formatted.find(" N*m,\n        9009 N*m, "), std::string::npos) << formatted;
  EXPECT_NE(formatted.find(", 0 {\n      0 -> 1\n"), std::string::npos) << formatted;
  EXPECT_EQ(ast::Dump(ParseClean(formatted)), ast::Dump(original));
  EXPECT_EQ(FormatText(formatted), formatted);
}

TEST(FormatTest, DoesNotWrapASingleLongValue) {
  const std::string input =
      "s \"" + std::string(120, 'x') + "\" = \"" + std::string(30, 'y') + "\"\n";
  EXPECT_EQ(FormatText(input), input);
}

TEST(FormatTest, FormatsAnEmptyFileAsEmpty) {
  EXPECT_EQ(FormatText(""), "");
  EXPECT_EQ(FormatText("\n\n  \n"), "");
  EXPECT_EQ(FormatText("// only\n\n"), "// only\n");
}

TEST(FormatTest, AcceptsWindowsLineEndings) {
  EXPECT_EQ(FormatText("a = 1  // one\r\nb {\r\n  c = 2\r\n}\r\n"),
            "a = 1  // one\n"
            "b {\n"
            "  c = 2\n"
            "}\n");
}

TEST(FormatExprTest, PrintsParsedValuesCanonically) {
  EXPECT_EQ(Format(ParseValueClean("(0,0,-9.81)m/s^2")), "(0, 0, -9.81) m/s^2");
  EXPECT_EQ(Format(ParseValueClean("table(a->b)")), "table(a -> b)");
  EXPECT_EQ(Format(ParseValueClean("-(1+2)*3^-x")), "-(1 + 2) * 3^-x");
  EXPECT_EQ(Format(ParseValueClean("\"a\\\"b\"")), "\"a\\\"b\"");
}

ast::Expr Number(double value, std::string text = {}) {
  ast::Expr expr;
  expr.kind = ast::ExprKind::kNumber;
  expr.number = value;
  expr.text = std::move(text);
  return expr;
}

ast::Expr Name(std::string name) {
  ast::Expr expr;
  expr.kind = ast::ExprKind::kPath;
  expr.path = {std::move(name)};
  return expr;
}

ast::Expr Arrow(ast::Expr a, ast::Expr b) {
  std::vector<ast::Expr> chain;
  chain.push_back(std::move(a));
  chain.push_back(std::move(b));
  return ast::MakeArrow(std::move(chain));
}

// Removes the paren nodes the formatter had to add, so a synthetic tree compares to its
// reparsed text.
ast::Expr StripParens(const ast::Expr& expr) {
  if (expr.kind == ast::ExprKind::kParen) return StripParens(expr.operands.at(0));
  ast::Expr copy = expr;
  for (ast::Expr& operand : copy.operands) operand = StripParens(operand);
  for (ast::Argument& argument : copy.arguments) {
    if (argument.value) argument.value = std::make_unique<ast::Expr>(StripParens(*argument.value));
  }
  return copy;
}

TEST(FormatExprTest, AddsParenthesesASyntheticTreeNeeds) {
  const std::vector<std::pair<ast::Expr, std::string>> cases = [] {
    std::vector<std::pair<ast::Expr, std::string>> out;
    out.emplace_back(ast::MakeBinary('*', ast::MakeBinary('+', Name("a"), Name("b")), Name("c")),
                     "(a + b) * c");
    out.emplace_back(ast::MakeBinary('-', Name("a"), ast::MakeBinary('-', Name("b"), Name("c"))),
                     "a - (b - c)");
    out.emplace_back(ast::MakeBinary('-', ast::MakeBinary('-', Name("a"), Name("b")), Name("c")),
                     "a - b - c");
    out.emplace_back(ast::MakeBinary('^', ast::MakeBinary('^', Name("a"), Name("b")), Name("c")),
                     "(a^b)^c");
    out.emplace_back(ast::MakeBinary('^', Name("a"), ast::MakeBinary('^', Name("b"), Name("c"))),
                     "a^b^c");
    out.emplace_back(ast::MakeBinary('^', ast::MakeNegation(Name("a")), Name("b")), "(-a)^b");
    out.emplace_back(ast::MakeBinary('^', Name("a"), ast::MakeNegation(Name("b"))), "a^-b");
    out.emplace_back(ast::MakeNegation(ast::MakeBinary('+', Name("a"), Name("b"))), "-(a + b)");
    out.emplace_back(ast::MakeBinary('*', Name("a"), Arrow(Name("b"), Name("c"))), "a * (b -> c)");
    out.emplace_back(Arrow(Arrow(Name("a"), Name("b")), Name("c")), "(a -> b) -> c");
    out.emplace_back(Number(0.1), "0.1");
    out.emplace_back(Number(1.5e-7), "1.5e-07");
    out.emplace_back(Number(3, "03.50e+1x"), "3");
    return out;
  }();
  for (const auto& [expr, text] : cases) {
    EXPECT_EQ(Format(expr), text);
    const ast::Expr reparsed = ParseValueClean(Format(expr));
    EXPECT_EQ(ast::Dump(StripParens(reparsed)), ast::Dump(StripParens(expr))) << text;
  }
}

TEST(FormatExprTest, SignsANegativeNumberWithoutSpellingAsUnaryMinus) {
  // It reads back as unary minus on a positive number: the same value, not the same tree.
  EXPECT_EQ(Format(Number(-2)), "-2");
  EXPECT_EQ(Format(ast::MakeBinary('^', Number(-2), Number(2, "2"))), "(-2)^2");
  EXPECT_EQ(Format(ast::MakeBinary('-', Name("a"), Number(-2))), "a - -2");
}

TEST(FormatExprTest, EscapesStringsItCannotHoldVerbatim) {
  ast::Expr expr;
  expr.kind = ast::ExprKind::kString;
  expr.text = "tab\there \"q\" back\\slash\r\nnext";
  EXPECT_EQ(Format(expr), R"("tab\there \"q\" back\\slash\nnext")");
}

}  // namespace
}  // namespace sled::lang
