// lang::Parse over the grammar of lang/syntax/grammar.h: every expression form, units, statement
// separation, comments, rows and clauses; the parse errors (code and line:column), their
// rendering and recovery. The renderers, the registry and the source tables themselves are tested
// in diagnostics_test.cpp.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "lang/ast/ast.h"
#include "lang/diagnostics/diagnostic.h"
#include "lang/diagnostics/render.h"
#include "lang/source/source_manager.h"
#include "lang/syntax/parser.h"

namespace sled::lang {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::IsEmpty;

// One parse: the buffer, what was reported and the tree.
struct Parsed {
  SourceManager sources;
  FileId file;
  DiagnosticCollector diagnostics;
  ast::File tree;

  const ast::Block& body() const { return tree.body; }
  const ast::Statement& statement(std::size_t i) const { return tree.body.statements.at(i); }
  const ast::Expr& value(std::size_t i) const { return statement(i).values.at(0); }
  std::string Text(const SourceRange& range) const { return std::string(sources.Text(range)); }

  // "CODE@LINE:COLUMN" of every diagnostic, in report order.
  std::vector<std::string> Problems() const {
    std::vector<std::string> out;
    for (const Diagnostic& diagnostic : diagnostics.diagnostics()) {
      const SourceRange* range = diagnostic.primary_range();
      const LineColumn at = sources.buffer(range->file).Locate(range->begin);
      out.push_back(fmt::format("{}@{}:{}", diagnostic.code(), at.line, at.column));
    }
    return out;
  }
  std::string Dump() const { return ast::Dump(tree); }
};

std::unique_ptr<Parsed> ParseText(std::string text, int max_depth = 64) {
  auto parsed = std::make_unique<Parsed>();
  parsed->file = parsed->sources.Add("test.sled", std::move(text));
  ParseOptions options;
  options.diagnostics = &parsed->diagnostics;
  options.max_depth = max_depth;
  parsed->tree = Parse(parsed->sources, parsed->file, options);
  return parsed;
}

// Parses text that must be clean and returns the dump of its first statement's first value.
std::string DumpValue(const std::string& text) {
  auto parsed = ParseText(text);
  EXPECT_THAT(parsed->Problems(), IsEmpty()) << text;
  if (parsed->body().statements.empty() || parsed->statement(0).values.empty()) return "<none>";
  return ast::Dump(parsed->value(0));
}

// --- Expressions ------------------------------------------------------------------------------

TEST(ParseExpression, NumberWithUnitKeepsValueSpellingAndUnit) {
  auto parsed = ParseText("mass = 11.7 kg\n");
  ASSERT_THAT(parsed->Problems(), IsEmpty());
  const ast::Expr& mass = parsed->value(0);
  EXPECT_EQ(mass.kind, ast::ExprKind::kNumber);
  EXPECT_DOUBLE_EQ(mass.number, 11.7);
  EXPECT_EQ(mass.text, "11.7");
  ASSERT_TRUE(mass.unit.has_value());
  ASSERT_EQ(mass.unit->factors.size(), 1u);
  EXPECT_EQ(mass.unit->factors[0].symbol, "kg");
  EXPECT_EQ(mass.unit->factors[0].exponent, 1);
  EXPECT_EQ(parsed->Text(mass.range), "11.7 kg");
}

TEST(ParseExpression, NumbersTakeExponentsInEitherCase) {
  auto parsed = ParseText("a = 1e-5\nb = 2.5E+3\nc = 7.\n");
  ASSERT_THAT(parsed->Problems(), IsEmpty());
  EXPECT_DOUBLE_EQ(parsed->value(0).number, 1e-5);
  EXPECT_EQ(parsed->value(0).text, "1e-5");
  EXPECT_DOUBLE_EQ(parsed->value(1).number, 2500.0);
  EXPECT_DOUBLE_EQ(parsed->value(2).number, 7.0);
  EXPECT_FALSE(parsed->value(0).unit.has_value());
}

TEST(ParseExpression, VectorTakesOneUnitForAllComponents) {
  EXPECT_EQ(DumpValue("gravity = (0, 0, -9.81) m/s^2"),
            "(vec (num 0) (num 0) (- (num 9.81)) [m s^-2])");
}

TEST(ParseExpression, VectorMayBreakAfterCommasAndEndWithAComma) {
  EXPECT_EQ(DumpValue("y = (1,\n     2,\n     3,) mm\n"), "(vec (num 1) (num 2) (num 3) [mm])");
  EXPECT_EQ(DumpValue("y = (1, 2\n  , 3)\n"), "(vec (num 1) (num 2) (num 3))");
}

TEST(ParseExpression, DottedPathIsSplitIntoParts) {
  auto parsed = ParseText("force = occupant.pelvis.front\n");
  ASSERT_THAT(parsed->Problems(), IsEmpty());
  EXPECT_EQ(parsed->value(0).kind, ast::ExprKind::kPath);
  EXPECT_THAT(parsed->value(0).path, ElementsAre("occupant", "pelvis", "front"));
  EXPECT_EQ(parsed->value(0).PathText(), "occupant.pelvis.front");
}

TEST(ParseExpression, StringEscapesAreDecoded) {
  auto parsed = ParseText(R"(title = "a \"b\"\n\tc\\")");
  ASSERT_THAT(parsed->Problems(), IsEmpty());
  EXPECT_EQ(parsed->value(0).kind, ast::ExprKind::kString);
  EXPECT_EQ(parsed->value(0).text, "a \"b\"\n\tc\\");
}

TEST(ParseExpression, BooleansAreReservedWords) {
  auto parsed = ParseText("mirror = true\nsettle = false\n");
  ASSERT_THAT(parsed->Problems(), IsEmpty());
  EXPECT_EQ(parsed->value(0).kind, ast::ExprKind::kBool);
  EXPECT_EQ(parsed->value(0).text, "true");
  EXPECT_EQ(parsed->value(1).text, "false");
}

TEST(ParseExpression, CallTakesNamedAndPositionalArguments) {
  auto parsed = ParseText("motion = half_sine(delta_v = 56 km/h, duration = 100 ms, axis = -x)\n");
  ASSERT_THAT(parsed->Problems(), IsEmpty());
  const ast::Expr& call = parsed->value(0);
  EXPECT_EQ(call.kind, ast::ExprKind::kCall);
  EXPECT_EQ(call.PathText(), "half_sine");
  ASSERT_EQ(call.arguments.size(), 3u);
  EXPECT_EQ(call.arguments[0].name, "delta_v");
  EXPECT_EQ(parsed->Text(call.arguments[0].name_range), "delta_v");
  EXPECT_EQ(ast::Dump(*call.arguments[0].value), "(num 56 [km h^-1])");
  EXPECT_EQ(ast::Dump(*call.arguments[2].value), "(- (path x))");
  EXPECT_EQ(DumpValue("flexure = polynomial(0, 2.5 N*m/deg)"),
            "(call polynomial (num 0) (num 2.5 [N m deg^-1]))");
}

TEST(ParseExpression, CallArgumentsMaySpanLinesWithATrailingComma) {
  EXPECT_EQ(DumpValue("z = std.f(\n  a = 1,\n  2,\n)\n"), "(call std.f a=(num 1) (num 2))");
  EXPECT_EQ(DumpValue("z = f()"), "(call f)");
}

TEST(ParseExpression, ProductsBindTighterThanSumsAndBothAssociateLeft) {
  EXPECT_EQ(DumpValue("a = 1 + 2 * 3 - 4 / 5"),
            "(- (+ (num 1) (* (num 2) (num 3))) (/ (num 4) (num 5)))");
  EXPECT_EQ(DumpValue("a = 8 / 4 / 2"), "(/ (/ (num 8) (num 4)) (num 2))");
}

TEST(ParseExpression, PowerAssociatesRightAndBindsTighterThanNegation) {
  EXPECT_EQ(DumpValue("c = 2^3^2"), "(^ (num 2) (^ (num 3) (num 2)))");
  EXPECT_EQ(DumpValue("b = -x ^ 2"), "(- (^ (path x) (num 2)))");
}

TEST(ParseExpression, NegationNestsAfterABinaryMinus) {
  EXPECT_EQ(DumpValue("u = 1 - -2"), "(- (num 1) (- (num 2)))");
}

TEST(ParseExpression, ParenthesesAreKeptForTheFormatter) {
  EXPECT_EQ(DumpValue("d = (1 + 2) * 3"), "(* (paren (+ (num 1) (num 2))) (num 3))");
  EXPECT_EQ(DumpValue("t = -(1 + 2)"), "(- (paren (+ (num 1) (num 2))))");
}

TEST(ParseExpression, ArrowChainsHoldEveryStep) {
  EXPECT_EQ(DumpValue("path = (-200, -230, 50) mm -> occupant.pelvis -> (-200, 230, 50) mm"),
            "(-> (vec (- (num 200)) (- (num 230)) (num 50) [mm]) (path occupant.pelvis) "
            "(vec (- (num 200)) (num 230) (num 50) [mm]))");
}

TEST(ParseExpression, ValueContinuesOnTheNextLineAfterAnOperator) {
  EXPECT_EQ(DumpValue("x = 1 +\n  2\n"), "(+ (num 1) (num 2))");
  EXPECT_EQ(DumpValue("x = a ->\n  b\n"), "(-> (path a) (path b))");
}

TEST(ParseExpression, CommaSeparatesSeveralValues) {
  auto parsed = ParseText("corners = (0, -250, 0) mm, (500, -250, 0) mm,\n  (0, 250, 0) mm\n");
  ASSERT_THAT(parsed->Problems(), IsEmpty());
  ASSERT_EQ(parsed->statement(0).values.size(), 3u);
  EXPECT_TRUE(parsed->statement(0).has_value);
}

TEST(ParseValue, ParsesOneValueForSetOverrides) {
  SourceManager sources;
  DiagnosticCollector diagnostics;
  ParseOptions options;
  options.diagnostics = &diagnostics;
  auto value = ParseValue(sources, sources.Add("--set", " 56 km/h "), options);
  ASSERT_TRUE(value.has_value());
  EXPECT_EQ(ast::Dump(*value), "(num 56 [km h^-1])");
  EXPECT_FALSE(diagnostics.has_errors());
}

TEST(ParseValue, ReportsTextThatIsNotOneValue) {
  SourceManager sources;
  DiagnosticCollector diagnostics;
  ParseOptions options;
  options.diagnostics = &diagnostics;
  EXPECT_FALSE(ParseValue(sources, sources.Add("--set", "56 km/h )"), options).has_value());
  ASSERT_EQ(diagnostics.error_count(), 1);
  EXPECT_EQ(diagnostics.diagnostics()[0].code(), "E0101");
}

// --- Units ------------------------------------------------------------------------------------

TEST(ParseUnit, PowersAndDivisionGiveSignedExponents) {
  EXPECT_EQ(DumpValue("i = 0.1 kg*m^2"), "(num 0.1 [kg m^2])");
  EXPECT_EQ(DumpValue("a = 9.81 m/s^2"), "(num 9.81 [m s^-2])");
  EXPECT_EQ(DumpValue("w = 1 m^-2"), "(num 1 [m^-2])");
  EXPECT_EQ(DumpValue("m = 3 kg*m^2/s^-2"), "(num 3 [kg m^2 s^2])");
  EXPECT_EQ(DumpValue("v = 1.5 N*m*s/rad"), "(num 1.5 [N m s rad^-1])");
}

TEST(ParseUnit, DivisionAppliesToTheNextFactorOnly) {
  EXPECT_EQ(DumpValue("k = 1 N/m*s"), "(num 1 [N m^-1 s])");
}

TEST(ParseUnit, FactorRangeCoversSymbolAndPower) {
  auto parsed = ParseText("a = 9.81 m/s^2\n");
  ASSERT_THAT(parsed->Problems(), IsEmpty());
  const ast::Unit& unit = *parsed->value(0).unit;
  ASSERT_EQ(unit.factors.size(), 2u);
  EXPECT_EQ(parsed->Text(unit.factors[0].range), "m");
  EXPECT_EQ(parsed->Text(unit.factors[1].range), "s^2");
  EXPECT_EQ(parsed->Text(unit.range), "m/s^2");
}

TEST(ParseUnit, UnitWordFollowedByEqualsStartsTheNextStatement) {
  auto parsed = ParseText("x = 1 m y = 2\n");
  ASSERT_THAT(parsed->Problems(), IsEmpty());
  EXPECT_EQ(parsed->Dump(), "(x = (num 1 [m]))\n(y = (num 2))\n");
}

// --- Statements -------------------------------------------------------------------------------

TEST(ParseStatement, HeaderHasKeywordTargetClausesValueAndBlock) {
  auto parsed = ParseText(
      "plane seat_pan on sled { corners = (0, -250, 0) mm }\n"
      "contact occupant.pelvis with seat_pan { friction = 0.4 }\n"
      "import std.humans.male50 as occupant\n"
      "acceleration occupant.head at (0, 0, 0) mm\n"
      "joint lumbar : ball(pelvis -> abdomen) { viscous = 1.5 N*m*s/rad }\n"
      "scenario \"frontal sled, 56 km/h\" { }\n");
  ASSERT_THAT(parsed->Problems(), IsEmpty());
  ASSERT_EQ(parsed->body().statements.size(), 6u);

  const ast::Statement& plane = parsed->statement(0);
  EXPECT_EQ(plane.kind, ast::StatementKind::kHeader);
  EXPECT_EQ(plane.keyword, "plane");
  EXPECT_EQ(parsed->Text(plane.keyword_range), "plane");
  ASSERT_TRUE(plane.target.has_value());
  EXPECT_EQ(plane.target->PathText(), "seat_pan");
  ASSERT_NE(plane.FindClause("on"), nullptr);
  EXPECT_EQ(plane.FindClause("on")->value.PathText(), "sled");
  EXPECT_EQ(parsed->Text(plane.FindClause("on")->word_range), "on");
  EXPECT_FALSE(plane.has_value);
  ASSERT_NE(plane.block, nullptr);
  EXPECT_EQ(plane.block->statements.size(), 1u);
  EXPECT_EQ(parsed->Text(plane.block->range), "{ corners = (0, -250, 0) mm }");
  EXPECT_EQ(parsed->Text(plane.range), "plane seat_pan on sled { corners = (0, -250, 0) mm }");

  EXPECT_EQ(parsed->statement(1).FindClause("with")->value.PathText(), "seat_pan");
  EXPECT_EQ(parsed->statement(2).FindClause("as")->value.PathText(), "occupant");
  EXPECT_EQ(ast::Dump(parsed->statement(3).FindClause("at")->value),
            "(vec (num 0) (num 0) (num 0) [mm])");
  const ast::Clause* kind = parsed->statement(4).FindClause(":");
  ASSERT_NE(kind, nullptr);
  EXPECT_EQ(ast::Dump(kind->value), "(call ball (-> (path pelvis) (path abdomen)))");
  EXPECT_EQ(parsed->statement(5).target->kind, ast::ExprKind::kString);
  EXPECT_EQ(parsed->statement(5).target->text, "frontal sled, 56 km/h");
  EXPECT_EQ(parsed->statement(0).FindClause("with"), nullptr);
}

TEST(ParseStatement, KeywordWithTargetAndValue) {
  auto parsed = ParseText("at pelvis = (0, 0, 120) mm\nparam speed = 56 km/h\n");
  ASSERT_THAT(parsed->Problems(), IsEmpty());
  EXPECT_EQ(parsed->Dump(),
            "(at target=(path pelvis) = (vec (num 0) (num 0) (num 120) [mm]))\n"
            "(param target=(path speed) = (num 56 [km h^-1]))\n");
}

TEST(ParseStatement, TwoStatementsMayShareALineAfterAValue) {
  auto parsed = ParseText("time { end = 200 ms  output_every = 0.1 ms }\n");
  ASSERT_THAT(parsed->Problems(), IsEmpty());
  EXPECT_EQ(parsed->Dump(),
            "(time {\n  (end = (num 200 [ms]))\n  (output_every = (num 0.1 [ms]))\n})\n");
}

TEST(ParseStatement, StatementMayFollowABlockOnItsLine) {
  auto parsed = ParseText("a { b = 1 } c = 2\n");
  ASSERT_THAT(parsed->Problems(), IsEmpty());
  EXPECT_EQ(parsed->Dump(), "(a {\n  (b = (num 1))\n})\n(c = (num 2))\n");
}

TEST(ParseStatement, SemicolonSeparatesStatements) {
  auto parsed = ParseText("a = 1; b = 2;; c = 3;\n");
  ASSERT_THAT(parsed->Problems(), IsEmpty());
  EXPECT_EQ(parsed->Dump(), "(a = (num 1))\n(b = (num 2))\n(c = (num 3))\n");
}

TEST(ParseStatement, KeywordAloneIsAStatement) {
  auto parsed = ParseText("settle\noutput { hic }\n");
  ASSERT_THAT(parsed->Problems(), IsEmpty());
  EXPECT_EQ(parsed->Dump(), "(settle)\n(output {\n  (hic)\n})\n");
}

TEST(ParseStatement, TableRowsAreTheAttributeBlock) {
  auto parsed = ParseText(
      "function foam = table(deflection -> force) {\n"
      "  0 mm -> 0 N\n"
      "  25 mm -> 2 kN\n"
      "  -1 mm -> -2 N\n"
      "  (1, 2) mm -> 3\n"
      "  0 -> 1 -> 2\n"
      "  unload slope = 0.2  permanent_set = 0.3\n"
      "}\n"
      "force = table(strain -> force) { 0 -> 0 N  0.1 -> 8 kN }\n");
  ASSERT_THAT(parsed->Problems(), IsEmpty());
  const ast::Block& rows = *parsed->statement(0).block;
  ASSERT_EQ(rows.statements.size(), 7u);
  EXPECT_EQ(rows.statements[0].kind, ast::StatementKind::kRow);
  EXPECT_EQ(rows.statements[0].values.at(0).kind, ast::ExprKind::kArrow);
  EXPECT_EQ(rows.statements[0].values.at(0).operands.size(), 2u);
  EXPECT_EQ(parsed->Text(rows.statements[1].range), "25 mm -> 2 kN");
  EXPECT_EQ(ast::Dump(rows.statements[2].values.at(0)), "(-> (- (num 1 [mm])) (- (num 2 [N])))");
  EXPECT_EQ(ast::Dump(rows.statements[3].values.at(0)), "(-> (vec (num 1) (num 2) [mm]) (num 3))");
  EXPECT_EQ(rows.statements[4].values.at(0).operands.size(), 3u);
  EXPECT_EQ(rows.statements[5].kind, ast::StatementKind::kHeader);
  EXPECT_EQ(rows.statements[5].keyword, "unload");
  EXPECT_EQ(rows.statements[6].keyword, "permanent_set");

  const ast::Block& inline_rows = *parsed->statement(1).block;
  ASSERT_EQ(inline_rows.statements.size(), 2u);
  EXPECT_EQ(ast::Dump(inline_rows.statements[1].values.at(0)), "(-> (num 0.1) (num 8 [kN]))");
}

TEST(ParseStatement, NestedBlocksNest) {
  auto parsed = ParseText("body male50 {\n  segment pelvis {\n    mass = 11.7 kg\n  }\n}\n");
  ASSERT_THAT(parsed->Problems(), IsEmpty());
  const ast::Statement& segment = parsed->statement(0).block->statements.at(0);
  EXPECT_EQ(segment.keyword, "segment");
  EXPECT_EQ(segment.block->statements.at(0).keyword, "mass");
  EXPECT_FALSE(parsed->statement(0).block->had_syntax_errors);
}

TEST(ParseStatement, EmptyFilesAndByteOrderMarkAndCrlfParseCleanly) {
  EXPECT_THAT(ParseText("")->Problems(), IsEmpty());
  EXPECT_THAT(ParseText("\n\n  \n")->Problems(), IsEmpty());
  auto parsed = ParseText("\xEF\xBB\xBFx = 1\r\ny = \"a\"\r\n// c\r\nz { w = 2 }\r\n");
  ASSERT_THAT(parsed->Problems(), IsEmpty());
  EXPECT_EQ(parsed->Dump(), "(x = (num 1))\n(y = (str \"a\"))\n(z {\n  (w = (num 2))\n})\n");
}

// --- Comments ---------------------------------------------------------------------------------

TEST(ParseComment, CommentsAreKeptAsTriviaOnTheirStatements) {
  auto parsed = ParseText(
      "// leads x\n"
      "x = 1 +\n"
      "  2 // trails x\n"
      "\n"
      "// leads b\n"
      "b {\n"
      "  c = 3\n"
      "  // closes b\n"
      "}\n");
  ASSERT_THAT(parsed->Problems(), IsEmpty());
  ASSERT_EQ(parsed->body().statements.size(), 2u);
  const ast::Statement& x = parsed->statement(0);
  ASSERT_EQ(x.leading_comments.size(), 1u);
  EXPECT_EQ(x.leading_comments[0].text, " leads x");
  ASSERT_TRUE(x.trailing_comment.has_value());
  EXPECT_EQ(x.trailing_comment->text, " trails x");
  EXPECT_EQ(parsed->Text(x.trailing_comment->range), "// trails x");
  EXPECT_EQ(ast::Dump(x.values.at(0)), "(+ (num 1) (num 2))");
  EXPECT_FALSE(x.blank_line_before);

  const ast::Statement& b = parsed->statement(1);
  ASSERT_EQ(b.leading_comments.size(), 1u);
  // The blank line is before b's leading comment, not between the comment and b.
  EXPECT_TRUE(b.leading_comments[0].blank_line_before);
  EXPECT_FALSE(b.blank_line_before);
  EXPECT_EQ(b.leading_comments[0].text, " leads b");
  ASSERT_EQ(b.block->closing_comments.size(), 1u);
  EXPECT_EQ(b.block->closing_comments[0].text, " closes b");
}

TEST(ParseComment, CommentEndsAStatementAndMayHoldAnything) {
  auto parsed = ParseText("x = 5 mm// { ( \" é\ny = 2 //\n");
  ASSERT_THAT(parsed->Problems(), IsEmpty());
  EXPECT_EQ(parsed->Dump(), "(x = (num 5 [mm]))\n(y = (num 2))\n");
}

// --- Errors and recovery ----------------------------------------------------------------------

TEST(ParseError, MissingEqualsIsReportedAtTheValue) {
  auto parsed = ParseText("segment pelvis {\n  mass 11.7 kg\n}\n");
  EXPECT_THAT(parsed->Problems(), ElementsAre("E0101@2:8"));
  const Diagnostic& diagnostic = parsed->diagnostics.diagnostics().at(0);
  EXPECT_THAT(diagnostic.message, HasSubstr("`=`"));
  EXPECT_THAT(diagnostic.message, HasSubstr("found `11.7`"));
  EXPECT_EQ(parsed->Text(*diagnostic.primary_range()), "11.7");
  EXPECT_EQ(diagnostic.severity, Severity::kError);
}

TEST(ParseError, UnclosedStringIsReportedAtTheEndOfItsLine) {
  auto parsed = ParseText("title = \"abc\nx = 1\n");
  EXPECT_THAT(parsed->Problems(), ElementsAre("E0102@1:13"));
  // Recovery resumes on the next line.
  EXPECT_EQ(parsed->Dump(), "(x = (num 1))\n");
}

TEST(ParseError, StrayClosingBraceIsReportedAndSkipped) {
  auto parsed = ParseText("x = 1\n  }\ny = 2\n");
  EXPECT_THAT(parsed->Problems(), ElementsAre("E0103@2:3"));
  EXPECT_EQ(parsed->Dump(), "(x = (num 1))\n(y = (num 2))\n");
}

TEST(ParseError, UnclosedBlockIsReportedAtItsBrace) {
  auto parsed = ParseText("a = 1\nbody b {\n  c = 2\n");
  EXPECT_THAT(parsed->Problems(), ElementsAre("E0102@2:8"));
}

TEST(ParseError, NumberOutOfRangeIsReportedAtTheNumber) {
  auto parsed = ParseText("x = 1\nspeed = 1e999 m/s\n");
  EXPECT_THAT(parsed->Problems(), ElementsAre("E0104@2:9"));
  EXPECT_EQ(parsed->Text(*parsed->diagnostics.diagnostics()[0].primary_range()), "1e999");
  // Too small is out of range too: the help promises magnitudes of about 1e-308 to 1e308.
  EXPECT_THAT(ParseText("x = -1e-999\n")->Problems(), ElementsAre("E0104@1:6"));
  EXPECT_THAT(ParseText("x = 1.7e308\n")->Problems(), IsEmpty());
}

TEST(ParseError, NonAsciiCharacterIsReportedWithItsCodePoint) {
  auto parsed = ParseText("x = 1 m\né = 2\n");
  EXPECT_THAT(parsed->Problems(), ElementsAre("E0105@2:1"));
  EXPECT_THAT(parsed->diagnostics.diagnostics()[0].message, HasSubstr("U+00E9"));
  // The primary range covers the whole UTF-8 sequence.
  EXPECT_EQ(parsed->Text(*parsed->diagnostics.diagnostics()[0].primary_range()), "é");
}

TEST(ParseError, NonAsciiCharacterAfterAValueCountsColumnsInCharacters) {
  auto parsed = ParseText("name = \"Müller\" µm\n");
  EXPECT_THAT(parsed->Problems(), ElementsAre("E0105@1:17"));
}

TEST(ParseError, ControlCharacterIsAnInvalidCharacter) {
  auto parsed = ParseText(std::string("x = 1\n\x01y = 2\n"));
  EXPECT_THAT(parsed->Problems(), ElementsAre("E0105@2:1"));
}

TEST(ParseError, DeepParenthesesReportNestingInsteadOfCrashing) {
  const std::string text = "x = " + std::string(1000, '(') + "1" + std::string(1000, ')') + "\n";
  auto parsed = ParseText(text, 64);
  // Each parenthesis opens a value and a unary operand: depth 64 allows 32 of them.
  EXPECT_THAT(parsed->Problems(), ElementsAre(fmt::format("E0106@1:{}", 4 + 32 + 1)));
  EXPECT_TRUE(parsed->body().had_syntax_errors);
}

TEST(ParseError, DeepBlocksAndNegationsReportNestingInsteadOfCrashing) {
  std::string blocks;
  for (int i = 0; i < 1000; ++i) blocks += "a {";
  blocks += std::string(1000, '}');
  auto parsed = ParseText(blocks);
  ASSERT_EQ(parsed->diagnostics.error_count(), 1);
  EXPECT_EQ(parsed->diagnostics.diagnostics()[0].code(), "E0106");

  auto negations = ParseText("x = " + std::string(100000, '-') + "1\n");
  ASSERT_EQ(negations->diagnostics.error_count(), 1);
  EXPECT_EQ(negations->diagnostics.diagnostics()[0].code(), "E0106");
}

TEST(ParseError, NestedParenthesesDoNotMakeTheParserBacktrackExponentially) {
  // A vector and a parenthesized value both start with `(` and a value. A parser that parses
  // that value once per alternative takes 2^depth steps (the fuzzer found it): 20 levels took
  // half a second, 30 would take minutes. Well within the nesting limit, this must take
  // microseconds; the bound guards against exponential time, it is not a benchmark.
  for (const std::string& close : {std::string(20, ')'), std::string()}) {
    const std::string text = "x = " + std::string(20, '(') + "1" + close + "\n";
    const auto start = std::chrono::steady_clock::now();
    auto parsed = ParseText(text);
    const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
    EXPECT_LT(elapsed.count(), 0.1) << text;
    EXPECT_EQ(parsed->diagnostics.has_errors(), close.empty()) << text;
  }
}

TEST(ParseError, SeveralErrorsAreReportedInOrderAndGoodStatementsKept) {
  auto parsed = ParseText(
      "a = 1\n"
      "b 2\n"
      "c = (1, 2\n"
      "d = 3 kg\n"
      "e = \"open\n"
      "f = 1e999\n"
      "g = 5\n");
  EXPECT_THAT(parsed->Problems(),
              ElementsAre("E0101@2:3", "E0101@3:10", "E0102@5:10", "E0104@6:5"));
  EXPECT_EQ(parsed->Dump(), "(a = (num 1))\n(d = (num 3 [kg]))\n(f = (num nan))\n(g = (num 5))\n");
}

TEST(ParseError, ErrorsAreReportedInSourceOrderWhicheverStepFoundThem) {
  // The out-of-range number is found while building the tree, after the grammar's errors.
  auto parsed = ParseText("a = 1e999\nb 2\nc = 1e999\n");
  EXPECT_THAT(parsed->Problems(), ElementsAre("E0104@1:5", "E0101@2:3", "E0104@3:5"));
}

TEST(ParseError, BrokenStatementWithABlockIsSkippedWhole) {
  auto parsed = ParseText(
      "x = 1\n"
      "body b oops oops {\n"
      "  segment s { mass = 1 kg }\n"
      "  y = 2\n"
      "}\n"
      "z = 3\n");
  EXPECT_THAT(parsed->Problems(), ElementsAre("E0101@2:8"));
  // Neither the block's statements nor its `}` surface as statements or errors of their own.
  EXPECT_EQ(parsed->Dump(), "(x = (num 1))\n(z = (num 3))\n");
}

TEST(ParseError, BlockWithASkippedStatementIsMarked) {
  auto parsed = ParseText(
      "body b {\n"
      "  segment s { mass = 1 kg }\n"
      "  joint j oops 4\n"
      "  x = 2\n"
      "}\n"
      "other { y = 1 }\n");
  EXPECT_THAT(parsed->Problems(), ElementsAre("E0101@3:11"));
  const ast::Block& body = *parsed->statement(0).block;
  EXPECT_TRUE(body.had_syntax_errors);
  ASSERT_EQ(body.statements.size(), 2u);  // segment and x survive, joint is skipped
  EXPECT_EQ(body.statements[1].keyword, "x");
  EXPECT_FALSE(body.statements[0].block->had_syntax_errors);
  EXPECT_FALSE(parsed->statement(1).block->had_syntax_errors);
}

TEST(ParseError, CleanFileHasNoBlockMarked) {
  auto parsed = ParseText("body b {\n  segment s { mass = 1 kg }\n}\n");
  ASSERT_THAT(parsed->Problems(), IsEmpty());
  EXPECT_FALSE(parsed->body().had_syntax_errors);
  EXPECT_FALSE(parsed->statement(0).block->had_syntax_errors);
}

TEST(ParseError, BlockCommentIsNotAComment) {
  auto parsed = ParseText("x = 1 m\ny = 2 /* hi */\n");
  EXPECT_THAT(parsed->Problems(), ElementsAre("E0101@2:7"));
}

TEST(ParseError, OperatorWithoutOperandIsReportedNotThrown) {
  // `x = 2 ^` once escaped as std::out_of_range from building the tree (found by the fuzzer).
  for (const char* text : {"x = 1 *\n", "x = 1 +\n", "x = 1 /", "x = 1 ->\n", "x = 2 ^\n",
                           "x = 2 ^", "x = 2 ^ // c\n", "x = 2 ^ 3 ^\n", "a { e = 2 ^ }\n"}) {
    std::unique_ptr<Parsed> parsed;
    ASSERT_NO_THROW(parsed = ParseText(text)) << text;
    ASSERT_EQ(parsed->diagnostics.error_count(), 1) << text;
    EXPECT_EQ(parsed->diagnostics.diagnostics()[0].code(), "E0101") << text;
    EXPECT_EQ(parsed->Problems()[0].substr(0, 7), "E0101@1") << text;
  }
}

TEST(ParseError, ParseRequiresADiagnosticConsumer) {
  SourceManager sources;
  const FileId file = sources.Add("x.sled", "x = 1\n");
  EXPECT_THROW(Parse(sources, file, ParseOptions{}), std::logic_error);
}

TEST(RenderDiagnostic, EveryParseErrorRendersInBothForms) {
  auto parsed = ParseText("a = (1,\nb 2\n}\nc = \"x\né = 1e999\n");
  ASSERT_TRUE(parsed->diagnostics.has_errors());
  for (const Diagnostic& diagnostic : parsed->diagnostics.diagnostics()) {
    EXPECT_THAT(RenderCompact(parsed->sources, diagnostic), HasSubstr("test.sled:"));
    EXPECT_THAT(RenderRich(parsed->sources, diagnostic), HasSubstr(" --> test.sled:"));
  }
}

TEST(SourceBuffer, ParseErrorsInCrlfFilesHaveTheRightColumn) {
  auto parsed = ParseText("x = 1\r\nmass 11.7 kg\r\n");
  EXPECT_THAT(parsed->Problems(), ElementsAre("E0101@2:6"));
}

// Found by the check fuzzer: `^` matched, its operand did not, and the operator's node stayed in
// the tree, so building the AST read past the end of a node's children.
TEST(ParseRegression, AnOperatorWhoseOperandFailsLeavesNoNodeBehind) {
  SourceManager sources;
  const FileId file = sources.Add("regression.sled", "x = a ^ 0.5end\ny = (b ^ ) + 1\n");
  DiagnosticCollector diagnostics;
  ParseOptions options;
  options.diagnostics = &diagnostics;
  const ast::File parsed = Parse(sources, file, options);
  EXPECT_TRUE(diagnostics.has_errors());
  EXPECT_NO_THROW((void)ast::Dump(parsed));
}

}  // namespace
}  // namespace sled::lang
