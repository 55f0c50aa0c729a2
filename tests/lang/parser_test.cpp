// lang::Parse over the grammar of lang/syntax/grammar.h: every expression form, units, statement
// separation, comments, rows and clauses; the parse errors (code and line:column) and recovery;
// the renderers of lang/diagnostics and the line tables of lang/source.
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

// --- Diagnostics rendering --------------------------------------------------------------------

// A diagnostic of a registered kind on a known piece of a buffer.
Diagnostic UnknownUnitAt(FileId file, std::uint32_t begin, std::uint32_t end) {
  Diagnostic diagnostic = MakeDiagnostic(DiagnosticKind::kUnknownUnit, {file, begin, end},
                                         "unknown unit `kgg`", "not a unit sled knows");
  diagnostic.help = "did you mean `kg`?";
  return diagnostic;
}

TEST(RenderDiagnostic, CompactFormIsPathLineColumnSeverityCodeMessage) {
  SourceManager sources;
  const FileId file = sources.Add("scenes/a.sled", "x = 1\nmass = 11.7 kgg\n");
  Diagnostic diagnostic =
      MakeDiagnostic(DiagnosticKind::kSyntaxError, {file, 18, 21}, "expected `=`, found `kgg`");
  EXPECT_EQ(RenderCompact(sources, diagnostic),
            "scenes/a.sled:2:13: error[E0101]: expected `=`, found `kgg`");
  diagnostic.help = "remove it";
  EXPECT_EQ(RenderCompact(sources, diagnostic),
            "scenes/a.sled:2:13: error[E0101]: expected `=`, found `kgg` (help: remove it)");
}

TEST(RenderDiagnostic, CompactFormOfWarningsAndLocationFreeDiagnostics) {
  SourceManager sources;
  const FileId file = sources.Add("a.sled", "function f = 1\n");
  Diagnostic warning =
      MakeDiagnostic(DiagnosticKind::kUnusedFunction, {file, 9, 10}, "function `f` is unused");
  EXPECT_EQ(RenderCompact(sources, warning), "a.sled:1:10: warning[W0001]: function `f` is unused");
  Diagnostic nowhere;
  nowhere.kind = DiagnosticKind::kFileUnreadable;
  nowhere.message = "cannot read `missing.sled`";
  EXPECT_EQ(RenderCompact(sources, nowhere), "sled: error[E0107]: cannot read `missing.sled`");
}

TEST(RenderDiagnostic, CompactFormShowsCardColumnsWhenAsked) {
  SourceManager sources;
  const FileId file = sources.Add("deck.ain", "A.1 CARD  12.5  x\n");
  Diagnostic diagnostic =
      MakeDiagnostic(DiagnosticKind::kSyntaxError, {file, 10, 14}, "not a number");
  diagnostic.show_column_range = true;
  EXPECT_EQ(RenderCompact(sources, diagnostic), "deck.ain:1:11-14: error[E0101]: not a number");
}

TEST(RenderDiagnostic, RichFormShowsTheLineCaretsLabelAndHelp) {
  SourceManager sources;
  const FileId file = sources.Add("a.sled", "x = 1\nmass = 11.7 kgg\n");
  Diagnostic diagnostic = UnknownUnitAt(file, 18, 21);
  diagnostic.notes.push_back("units are case-sensitive");
  EXPECT_EQ(RenderRich(sources, diagnostic),
            "error[E0301]: unknown unit `kgg`\n"
            " --> a.sled:2:13\n"
            "  |\n"
            "2 | mass = 11.7 kgg\n"
            "  |             ^^^ not a unit sled knows\n"
            "  = note: units are case-sensitive\n"
            "  = help: did you mean `kg`?\n");
}

TEST(RenderDiagnostic, RichFormWidensTheGutterAndDrawsSecondaryLabels) {
  std::string text;
  for (int i = 1; i <= 9; ++i) text += "a = 1\n";
  text += "b = 2 mm\n";  // line 10
  SourceManager sources;
  const FileId file = sources.Add("a.sled", text);
  Diagnostic diagnostic = MakeDiagnostic(DiagnosticKind::kDuplicateName, {file, 0, 1},
                                         "`a` is declared twice", "first here");
  diagnostic.labels.push_back({{file, 54, 55}, "b is here", false});
  EXPECT_EQ(RenderRich(sources, diagnostic),
            "error[E0202]: `a` is declared twice\n"
            "  --> a.sled:1:1\n"
            "   |\n"
            " 1 | a = 1\n"
            "   | ^ first here\n"
            "10 | b = 2 mm\n"
            "   | - b is here\n");
}

TEST(RenderDiagnostic, RichFormAlignsCaretsUnderUtf8AndTabs) {
  SourceManager sources;
  const FileId file = sources.Add("a.sled", "\tname = \"Müller\" kgg\n");
  const std::uint32_t begin =
      static_cast<std::uint32_t>(std::string("\tname = \"Müller\" ").size());
  Diagnostic diagnostic = UnknownUnitAt(file, begin, begin + 3);
  EXPECT_EQ(RenderRich(sources, diagnostic),
            "error[E0301]: unknown unit `kgg`\n"
            " --> a.sled:1:18\n"
            "  |\n"
            "1 |  name = \"Müller\" kgg\n"
            "  |                  ^^^ not a unit sled knows\n"
            "  = help: did you mean `kg`?\n");
}

TEST(RenderDiagnostic, RichFormOfALongUtf8LineShowsAWindowWithAlignedCarets) {
  // 5,000 two-byte characters (past the source's 4 KB column blocks), a tab, the label, more.
  std::string before;
  for (int i = 0; i < 5000; ++i) before += "ü";
  const std::string text = before + "\tkgg" + std::string(300, 'x') + "\n";
  SourceManager sources;
  const FileId file = sources.Add("a.sled", text);
  const auto begin = static_cast<std::uint32_t>(before.size() + 1);
  Diagnostic diagnostic = UnknownUnitAt(file, begin, begin + 3);
  std::string window = "...";
  for (int i = 0; i < 39; ++i) window += "ü";
  window += " kgg" + std::string(77, 'x') + "...";  // 120 characters in all
  EXPECT_EQ(RenderRich(sources, diagnostic),
            "error[E0301]: unknown unit `kgg`\n"
            " --> a.sled:1:5002\n"
            "  |\n"
            "1 | " +
                window +
                "\n"
                "  | " +
                std::string(43, ' ') +
                "^^^ not a unit sled knows\n"
                "  = help: did you mean `kg`?\n");
}

TEST(RenderDiagnostic, RichFormOfAnEmptyRangeAtTheEndOfALineShowsOneCaret) {
  SourceManager sources;
  const FileId file = sources.Add("a.sled", "title = \"abc\n");
  Diagnostic diagnostic =
      MakeDiagnostic(DiagnosticKind::kUnclosedDelimiter, {file, 12, 12}, "string is not closed");
  EXPECT_EQ(RenderRich(sources, diagnostic),
            "error[E0102]: string is not closed\n"
            " --> a.sled:1:13\n"
            "  |\n"
            "1 | title = \"abc\n"
            "  |             ^\n");
}

TEST(RenderDiagnostic, RichFormInColorWrapsTheHeadingInEscapes) {
  SourceManager sources;
  const FileId file = sources.Add("a.sled", "mass = 1 kgg\n");
  const std::string colored =
      RenderRich(sources, UnknownUnitAt(file, 9, 12), RenderOptions{.color = true});
  EXPECT_THAT(colored, HasSubstr("\x1b[1;31merror[E0301]\x1b[0m"));
  EXPECT_EQ(RenderRich(sources, UnknownUnitAt(file, 9, 12)).find('\x1b'), std::string::npos);
}

TEST(RenderDiagnostic, EveryParseErrorRendersInBothForms) {
  auto parsed = ParseText("a = (1,\nb 2\n}\nc = \"x\né = 1e999\n");
  ASSERT_TRUE(parsed->diagnostics.has_errors());
  for (const Diagnostic& diagnostic : parsed->diagnostics.diagnostics()) {
    EXPECT_THAT(RenderCompact(parsed->sources, diagnostic), HasSubstr("test.sled:"));
    EXPECT_THAT(RenderRich(parsed->sources, diagnostic), HasSubstr(" --> test.sled:"));
  }
}

// --- Diagnostic registry and suggestions ------------------------------------------------------

TEST(DiagnosticRegistry, CodesAreUniqueAndFindable) {
  std::vector<std::string_view> codes;
  for (const DiagnosticInfo& info : AllDiagnostics()) {
    EXPECT_EQ(std::count(codes.begin(), codes.end(), info.code), 0) << info.code;
    codes.push_back(info.code);
    EXPECT_EQ(FindDiagnosticByCode(info.code), info.kind);
    EXPECT_EQ(InfoOf(info.kind).code, info.code);
    EXPECT_EQ(info.code[0] == 'W', info.severity == Severity::kWarning) << info.code;
  }
  EXPECT_FALSE(FindDiagnosticByCode("E9999").has_value());
}

TEST(DiagnosticCollector, CountsBySeverityAndSortsByPosition) {
  DiagnosticCollector collector;
  const FileId file{1};
  collector.Consume(MakeDiagnostic(DiagnosticKind::kUnknownName, {file, 30, 31}, "late"));
  collector.Consume(MakeDiagnostic(DiagnosticKind::kUnusedFunction, {file, 5, 6}, "early"));
  collector.Consume(MakeDiagnostic(DiagnosticKind::kUnknownUnit, {file, 30, 32}, "late too"));
  EXPECT_EQ(collector.error_count(), 2);
  EXPECT_EQ(collector.warning_count(), 1);
  collector.SortByPosition();
  std::vector<std::string> order;
  for (const Diagnostic& d : collector.diagnostics()) order.push_back(d.message);
  EXPECT_THAT(order, ElementsAre("early", "late", "late too"));
  collector.Clear();
  EXPECT_FALSE(collector.has_errors());
  EXPECT_THAT(collector.diagnostics(), IsEmpty());
}

TEST(DidYouMean, SuggestsTheClosestCandidateWithinAThirdOfTheLength) {
  const std::vector<std::string> attributes = {"friction", "force", "damping", "mass"};
  EXPECT_EQ(ClosestMatch("frictoin", attributes), "friction");
  EXPECT_EQ(ClosestMatch("forse", attributes), "force");
  EXPECT_EQ(ClosestMatch("mas", attributes), "mass");
  EXPECT_EQ(ClosestMatch("stiffness", attributes), std::nullopt);
  EXPECT_EQ(ClosestMatch("mass", attributes), std::nullopt);  // an exact match needs no hint
  EXPECT_EQ(ClosestMatch("x", {}), std::nullopt);
  EXPECT_EQ(DidYouMean("kgg", {"kg", "g", "m"}), "did you mean `kg`?");
  EXPECT_EQ(DidYouMean("qq", {"kg", "g", "m"}), "one of: `kg`, `g`, `m`");
  EXPECT_EQ(DidYouMean("qq", {"kg"}), "the only choice here is `kg`");
  EXPECT_EQ(DidYouMean("qq", {"a", "b", "c", "d", "e", "f", "g", "h", "i"}), "");
  EXPECT_EQ(DidYouMean("qq", {}), "");
}

TEST(DidYouMean, SuggestedNamesReadBackEveryFormItWrites) {
  using V = std::vector<std::string>;
  EXPECT_EQ(SuggestedNames(DidYouMean("kgg", {"kg", "g", "m"})), V{"kg"});
  EXPECT_EQ(SuggestedNames(DidYouMean("qq", {"kg", "g", "m"})), (V{"kg", "g", "m"}));
  EXPECT_EQ(SuggestedNames(DidYouMean("qq", {"kg"})), V{"kg"});
  // A longer hint that starts the same way suggests its first name only.
  EXPECT_EQ(SuggestedNames("did you mean `knee_r`, the joint from `a` to `b`?"), V{"knee_r"});
  EXPECT_EQ(SuggestedNames("write the unit after the number, such as `5 mm`"), V{});
  EXPECT_EQ(SuggestedNames(""), V{});
}

TEST(DidYouMean, CountsTwoSwappedLettersAsOneEdit) {
  // "widht" is two substitutions from "width" but one swap; a third of five letters allows one.
  EXPECT_EQ(ClosestMatch("widht", {"width", "depth"}), "width");
  EXPECT_EQ(ClosestMatch("plevis", {"pelvis", "thorax"}), "pelvis");
  EXPECT_EQ(ClosestMatch("tdiwh", {"width"}), std::nullopt);  // a swap is of neighbours only
}

// --- Sources ----------------------------------------------------------------------------------

TEST(SourceBuffer, LocateCountsLinesAndColumnsFromOne) {
  const SourceBuffer buffer("a.sled", "ab\ncd\n\nef");
  EXPECT_EQ(buffer.line_count(), 4u);
  const auto at = [&](std::uint32_t offset) {
    const LineColumn place = buffer.Locate(offset);
    return fmt::format("{}:{}", place.line, place.column);
  };
  EXPECT_EQ(at(0), "1:1");
  EXPECT_EQ(at(2), "1:3");  // the newline itself belongs to its line
  EXPECT_EQ(at(3), "2:1");
  EXPECT_EQ(at(6), "3:1");
  EXPECT_EQ(at(8), "4:2");
  EXPECT_EQ(at(9), "4:3");     // end of buffer
  EXPECT_EQ(at(1000), "4:3");  // clamped
}

TEST(SourceBuffer, LocateCountsUtf8CharactersNotBytes) {
  const SourceBuffer buffer("a.sled", "é = \"µ€𝄞\" x\n");
  EXPECT_EQ(buffer.Locate(2).column, 2u);  // the space after é
  // Bytes: é 0-1, ` = "` 2-5, µ 6-7, € 8-10, 𝄞 11-14, `"` 15, space 16, x 17.
  EXPECT_EQ(buffer.Locate(15).column, 9u);   // the closing quote
  EXPECT_EQ(buffer.Locate(17).column, 11u);  // x
  EXPECT_EQ(buffer.OffsetOf(1, 11), 17u);
  EXPECT_EQ(buffer.OffsetOf(1, 8), 11u);
}

TEST(SourceBuffer, CrlfLinesEndBeforeTheCarriageReturn) {
  const SourceBuffer buffer("a.sled", "x = 1\r\nmass 11.7 kg\r\n");
  EXPECT_EQ(buffer.Line(1), "x = 1");
  EXPECT_EQ(buffer.Line(2), "mass 11.7 kg");
  EXPECT_EQ(buffer.Locate(7).line, 2u);
  EXPECT_EQ(buffer.Locate(7).column, 1u);
  EXPECT_EQ(buffer.Locate(12).column, 6u);
  EXPECT_EQ(buffer.OffsetOf(2, 6), 12u);
  EXPECT_EQ(buffer.Line(99), "");
}

TEST(SourceBuffer, ParseErrorsInCrlfFilesHaveTheRightColumn) {
  auto parsed = ParseText("x = 1\r\nmass 11.7 kg\r\n");
  EXPECT_THAT(parsed->Problems(), ElementsAre("E0101@2:6"));
}

TEST(SourceManager, AddsFindsAndSlicesBuffers) {
  SourceManager sources;
  const FileId a = sources.Add("a.sled", "alpha");
  const FileId b = sources.Add("b.sled", "beta");
  EXPECT_NE(a.value, b.value);
  EXPECT_EQ(sources.Find("b.sled"), b);
  EXPECT_FALSE(sources.Find("c.sled").has_value());
  EXPECT_EQ(sources.Text({b, 1, 3}), "et");
  EXPECT_EQ(sources.Text({}), "");
  EXPECT_EQ(sources.buffer(a).path(), "a.sled");
  EXPECT_THROW(sources.buffer(FileId{}), std::logic_error);
  EXPECT_FALSE(sources.Load("/nonexistent/sled/file.sled").has_value());
}

TEST(SourceRange, JoinCoversBothAndPrecedesOrdersByFileThenOffset) {
  const SourceRange a{FileId{1}, 4, 8};
  const SourceRange b{FileId{1}, 2, 5};
  EXPECT_EQ(Join(a, b), (SourceRange{FileId{1}, 2, 8}));
  EXPECT_EQ(Join(SourceRange{}, a), a);
  EXPECT_TRUE(Precedes(b, a));
  EXPECT_FALSE(Precedes(a, b));
  EXPECT_TRUE(Precedes(SourceRange{FileId{1}, 9, 9}, SourceRange{FileId{2}, 0, 1}));
}

}  // namespace
}  // namespace sled::lang

namespace sled::lang {
namespace {

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
