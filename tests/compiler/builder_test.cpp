// lang::build, the embedded C++ form of the language: a scene built in C++ gives the same AST and
// the same checked scenario as the same scene written as text; the built tree formats to text
// that parses back to it; and a mistake in the C++ is reported at the C++ line that made it.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "compiler/check/check.h"
#include "compiler/check/checked_scenario.h"
#include "lang/ast/ast.h"
#include "lang/builder/builder.h"
#include "lang/diagnostics/diagnostic.h"
#include "lang/diagnostics/render.h"
#include "lang/format/formatter.h"
#include "lang/source/source_manager.h"
#include "lang/syntax/parser.h"

namespace sled {
namespace {

namespace ast = lang::ast;
namespace build = lang::build;
using build::Arrow;
using build::Call;
using build::Q;
using build::Ref;
using build::Table;
using build::V;
using ::testing::HasSubstr;
using ::testing::IsEmpty;

// The scene of the comparison, as text. Keep in step with BuildFrontalSled below.
constexpr const char* kFrontalSledText = R"(scenario "frontal sled, belted occupant" {
  param speed = 56 km/h
  gravity = (0, 0, -9.81) m/s^2
  time { end = 200 ms  output_every = 0.1 ms }
  integrator auto { tolerance = 1e-5  max_step = 1 ms }

  body occupant {
    segment pelvis {
      mass = 11.7 kg
      inertia = (0.10, 0.09, 0.11) kg*m^2
      ellipsoid { semi_axes = (110, 170, 120) mm  center = (0, 0, 20) mm }
    }
    segment torso {
      mass = 2 * 8.5 kg
      inertia = (0.35, 0.30, 0.20) kg*m^2
      ellipsoid chest { semi_axes = (120, 180, 250) mm }
    }
    joint lumbar : ball(pelvis -> torso) {
      at pelvis = (0, 0, 120) mm
      at torso = (0, 0, -200) mm
      flexure = polynomial(0, 2.5 N*m/deg, 0.01 N*m/deg^2)
      stop = 45 deg
      viscous = 1.5 N*m*s/rad
    }
  }

  vehicle sled {
    motion = half_sine(delta_v = speed, duration = 100 ms, axis = -x)
  }

  plane seat_pan on sled { corners = (0, -250, 0) mm, (500, -250, 0) mm, (0, 250, 0) mm }

  function foam = table(deflection -> force) {
    0 mm -> 0 N
    25 mm -> 2 kN
    60 mm -> 12 kN
    energy_loss = 0.4
  }

  contact occupant.pelvis with seat_pan { force = foam  friction = 0.4 }

  belt lap on sled {
    path = (-200, -230, 50) mm -> occupant.pelvis -> (-200, 230, 50) mm
    force = table(strain -> force) { 0 -> 0 N  0.1 -> 8 kN }
    slack = 5 mm
  }

  initial occupant { position = (250, 0, 300) mm  velocity = (0, 0, 0) m/s }

  output {
    acceleration occupant.torso at (0, 0, 0) mm
    joint_torque occupant.lumbar
    contact_force occupant.pelvis with seat_pan
    belt_force lap
    criteria = chest_3ms(occupant.torso)
  }
}
)";

// The same scene in C++.
void BuildFrontalSled(build::Scene& scene) {
  scene.Param("speed", Q(56, "km/h"));
  scene.Set("gravity", V(0, 0, -9.81, "m/s^2"));
  scene.Block("time").Set("end", Q(200, "ms")).Set("output_every", Q(0.1, "ms"));
  scene.Declare("integrator", "auto").Set("tolerance", 1e-5).Set("max_step", Q(1, "ms"));

  auto& occupant = scene.Declare("body", "occupant");
  occupant.Declare("segment", "pelvis")
      .Set("mass", Q(11.7, "kg"))
      .Set("inertia", V(0.10, 0.09, 0.11, "kg*m^2"))
      .Block("ellipsoid")
      .Set("semi_axes", V(110, 170, 120, "mm"))
      .Set("center", V(0, 0, 20, "mm"));
  occupant.Declare("segment", "torso")
      .Set("mass", 2 * Q(8.5, "kg"))
      .Set("inertia", V(0.35, 0.30, 0.20, "kg*m^2"))
      .Declare("ellipsoid", "chest")
      .Set("semi_axes", V(120, 180, 250, "mm"));
  occupant.Joint("lumbar", "ball", "pelvis", "torso")
      .Set("at", "pelvis", V(0, 0, 120, "mm"))
      .Set("at", "torso", V(0, 0, -200, "mm"))
      .Set("flexure", Call("polynomial", {0, Q(2.5, "N*m/deg"), Q(0.01, "N*m/deg^2")}))
      .Set("stop", Q(45, "deg"))
      .Set("viscous", Q(1.5, "N*m*s/rad"));

  scene.Declare("vehicle", "sled")
      .Set("motion",
           Call("half_sine",
                {{"delta_v", Ref("speed")}, {"duration", Q(100, "ms")}, {"axis", -Ref("x")}}));
  scene.Declare("plane", "seat_pan")
      .On(Ref("sled"))
      .Set("corners", {V(0, -250, 0, "mm"), V(500, -250, 0, "mm"), V(0, 250, 0, "mm")});
  scene.Function("foam", Table("deflection", "force"))
      .Row(Q(0, "mm"), Q(0, "N"))
      .Row(Q(25, "mm"), Q(2, "kN"))
      .Row(Q(60, "mm"), Q(12, "kN"))
      .Set("energy_loss", 0.4);
  scene.Declare("contact", Ref("occupant.pelvis"))
      .With(Ref("seat_pan"))
      .Set("force", Ref("foam"))
      .Set("friction", 0.4);

  auto& lap = scene.Declare("belt", "lap").On(Ref("sled"));
  lap.Set("path", Arrow({V(-200, -230, 50, "mm"), Ref("occupant.pelvis"), V(-200, 230, 50, "mm")}));
  lap.Attribute("force", Table("strain", "force")).Row(0, Q(0, "N")).Row(0.1, Q(8, "kN"));
  lap.Set("slack", Q(5, "mm"));

  scene.Declare("initial", "occupant")
      .Set("position", V(250, 0, 300, "mm"))
      .Set("velocity", V(0, 0, 0, "m/s"));
  auto& output = scene.Block("output");
  output.Add("acceleration", "occupant.torso").At(V(0, 0, 0, "mm"));
  output.Add("joint_torque", "occupant.lumbar");
  output.Add("contact_force", "occupant.pelvis").With(Ref("seat_pan"));
  output.Add("belt_force", "lap");
  output.Set("criteria", Call("chest_3ms", {Ref("occupant.torso")}));
}

// The stdlib folder of this tree, so the check does not depend on $SLED_STDLIB.
compiler::CheckOptions CheckOptionsFor(lang::DiagnosticCollector& diagnostics) {
  compiler::CheckOptions options;
  options.diagnostics = &diagnostics;
  options.stdlib_root = std::string(SLED_SOURCE_ROOT) + "/stdlib";
  return options;
}

ast::File ParseOrFail(lang::SourceManager& sources, const std::string& path, std::string text) {
  const lang::FileId file = sources.Add(path, std::move(text));
  lang::DiagnosticCollector diagnostics;
  lang::ParseOptions options;
  options.diagnostics = &diagnostics;
  ast::File tree = lang::Parse(sources, file, options);
  for (const lang::Diagnostic& diagnostic : diagnostics.diagnostics()) {
    ADD_FAILURE() << lang::RenderRich(sources, diagnostic);
  }
  return tree;
}

std::string RenderAll(const lang::SourceManager& sources,
                      const lang::DiagnosticCollector& diagnostics) {
  std::string out;
  for (const lang::Diagnostic& diagnostic : diagnostics.diagnostics()) {
    out += lang::RenderRich(sources, diagnostic);
  }
  return out;
}

// Calls `visit` on every range of the tree.
void ForEachRange(const ast::Expr& expr,
                  const std::function<void(const lang::SourceRange&)>& visit) {
  visit(expr.range);
  if (expr.unit) {
    visit(expr.unit->range);
    for (const ast::UnitFactor& factor : expr.unit->factors) visit(factor.range);
  }
  for (const ast::Expr& operand : expr.operands) ForEachRange(operand, visit);
  for (const ast::Argument& argument : expr.arguments) {
    if (!argument.name.empty()) visit(argument.name_range);
    ForEachRange(*argument.value, visit);
  }
}

void ForEachRange(const ast::Block& block,
                  const std::function<void(const lang::SourceRange&)>& visit) {
  visit(block.range);
  for (const ast::Statement& statement : block.statements) {
    visit(statement.range);
    if (statement.kind == ast::StatementKind::kHeader) visit(statement.keyword_range);
    if (statement.target) ForEachRange(*statement.target, visit);
    for (const ast::Clause& clause : statement.clauses) {
      visit(clause.word_range);
      ForEachRange(clause.value, visit);
    }
    for (const ast::Expr& value : statement.values) ForEachRange(value, visit);
    if (statement.block) ForEachRange(*statement.block, visit);
  }
}

TEST(BuilderScene, GivesTheParsersTreeAndTheSameCheckedScenario) {
  lang::SourceManager sources;
  build::Scene scene(sources, "frontal sled, belted occupant");
  BuildFrontalSled(scene);
  const ast::File built = scene.Finish();
  const ast::File parsed = ParseOrFail(sources, "frontal_sled.sled", kFrontalSledText);
  ASSERT_FALSE(ast::Dump(parsed).empty());
  EXPECT_EQ(ast::Dump(built), ast::Dump(parsed));

  lang::DiagnosticCollector built_diagnostics;
  const compiler::CheckedScenario from_built =
      compiler::Check(sources, built, CheckOptionsFor(built_diagnostics));
  lang::DiagnosticCollector parsed_diagnostics;
  const compiler::CheckedScenario from_parsed =
      compiler::Check(sources, parsed, CheckOptionsFor(parsed_diagnostics));
  EXPECT_THAT(built_diagnostics.diagnostics(), IsEmpty()) << RenderAll(sources, built_diagnostics);
  EXPECT_THAT(parsed_diagnostics.diagnostics(), IsEmpty())
      << RenderAll(sources, parsed_diagnostics);
  EXPECT_EQ(compiler::Dump(from_built), compiler::Dump(from_parsed));
  // The comparison means something: the scene has every part the checker was asked about.
  EXPECT_EQ(from_built.segments.size(), 2u);
  EXPECT_EQ(from_built.ellipsoids.size(), 2u);
  EXPECT_EQ(from_built.joints.size(), 1u);
  EXPECT_EQ(from_built.contacts.size(), 1u);
  EXPECT_EQ(from_built.belts.size(), 1u);
  EXPECT_EQ(from_built.outputs.size(), 4u);
  EXPECT_EQ(from_built.criteria.size(), 1u);
}

TEST(BuilderScene, EveryRangePointsIntoThisFile) {
  lang::SourceManager sources;
  build::Scene scene(sources, "frontal sled, belted occupant");
  BuildFrontalSled(scene);
  const ast::File built = scene.Finish();
  ASSERT_TRUE(built.file.value != 0);
  EXPECT_EQ(sources.buffer(built.file).path(), __FILE__);
  int count = 0;
  ForEachRange(built.body, [&](const lang::SourceRange& range) {
    ++count;
    EXPECT_EQ(range.file, built.file);
    EXPECT_FALSE(sources.Text(range).empty());
  });
  EXPECT_GT(count, 100);
  // The scenario statement is the line that constructed the Scene.
  const std::uint32_t line = __LINE__ + 1;
  build::Scene second(sources, "another");
  const ast::File other = second.Finish();
  EXPECT_EQ(other.file, built.file) << "the C++ file is registered once";
  const lang::SourceRange& range = other.body.statements.at(0).range;
  EXPECT_EQ(sources.buffer(range.file).Locate(range.begin).line, line);
  EXPECT_THAT(std::string(sources.Text(range)), HasSubstr("second(sources, \"another\")"));
}

TEST(BuilderFormat, FormattedTextParsesBackToTheSameTree) {
  lang::SourceManager sources;
  build::Scene scene(sources, "frontal sled, belted occupant");
  scene.Import("std.humans.male50", "occupant");
  scene.Let("half", Q(250, "mm") / 2);
  scene.Set("title", build::Str("quote \" and \\ and tab\t"));
  scene.Set("mirror", true);
  BuildFrontalSled(scene);
  const ast::File built = scene.Finish();
  const std::string text = lang::Format(built);
  const ast::File reparsed = ParseOrFail(sources, "formatted.sled", text);
  EXPECT_EQ(ast::Dump(reparsed), ast::Dump(built)) << text;
  EXPECT_EQ(lang::Format(reparsed), text) << "formatting the reparsed tree changes nothing";
  EXPECT_THAT(text, HasSubstr("  import std.humans.male50 as occupant\n"));
  EXPECT_THAT(text, HasSubstr("gravity = (0, 0, -9.81) m/s^2\n"));
  EXPECT_THAT(text, HasSubstr("flexure = polynomial(0, 2.5 N*m/deg, 0.01 N*m/deg^2)\n"));
  EXPECT_THAT(text, HasSubstr("tolerance = 1e-05\n"));
}

TEST(BuilderFormat, ArithmeticGetsTheParenthesesTheTextNeeds) {
  const build::Value a = Q(1, "m");
  const build::Value b = Q(2, "m");
  const std::vector<build::Value> values = {
      (a + b) * 3,
      a - (b - a),
      a - b - a,
      -(a + b),
      build::Pow(a, 2),
      build::Pow(-a, 2),
      build::Pow(a, -2),
      build::Pow(a + b, 2),
      a / (b * 2),
      Arrow(a, Arrow(a, b)),
      build::Neg(Q(-5, "s")),
      build::Paren(a) * 2,
      V(a + b, -3, Arrow(1, 2)),
  };
  for (const build::Value& value : values) {
    const ast::Expr expr = value.ToExpr();
    const std::string text = lang::Format(expr);
    lang::SourceManager sources;
    const lang::FileId file = sources.Add("value", text);
    lang::DiagnosticCollector diagnostics;
    lang::ParseOptions options;
    options.diagnostics = &diagnostics;
    const auto parsed = lang::ParseValue(sources, file, options);
    ASSERT_TRUE(parsed.has_value()) << text;
    EXPECT_EQ(ast::Dump(*parsed), ast::Dump(expr)) << text;
  }
  EXPECT_EQ(lang::Format(((a + b) * 3).ToExpr()), "(1 m + 2 m) * 3");
  EXPECT_EQ(lang::Format(build::Pow(-a, 2).ToExpr()), "(-1 m)^2");
}

TEST(BuilderValues, UnitsAndNumbersAreWhatTheParserMakes) {
  const std::vector<std::string> units = {"kg",   "m/s^2",  "N*m/deg", "N*m*s/rad", "N/m*s",
                                          "s^-1", "kg*m^2", "km/h",    "kg/m^-3",   "N*m/deg^2"};
  const std::vector<double> numbers = {0, 1, 0.1, 9.81, 1e-5, 2.5e20, 123456.789, 1.0 / 3.0};
  for (const std::string& unit : units) {
    for (const double number : numbers) {
      const ast::Expr built = Q(number, unit).ToExpr();
      const std::string text = fmt::format("{} {}", number, unit);
      lang::SourceManager sources;
      const lang::FileId file = sources.Add("value", text);
      lang::DiagnosticCollector diagnostics;
      lang::ParseOptions options;
      options.diagnostics = &diagnostics;
      const auto parsed = lang::ParseValue(sources, file, options);
      ASSERT_TRUE(parsed.has_value()) << text;
      EXPECT_EQ(ast::Dump(built), ast::Dump(*parsed)) << text;
      EXPECT_EQ(built.text, parsed->text) << "the spelling is the shortest round trip";
      EXPECT_EQ(built.number, parsed->number);
    }
  }
  EXPECT_EQ(ast::Dump(Q(-9.81, "m/s^2").ToExpr()), "(- (num 9.81 [m s^-2]))");
  EXPECT_EQ(ast::Dump(build::Value(true).ToExpr()), "(bool true)");
  EXPECT_EQ(ast::Dump(build::Value(3).ToExpr()), "(num 3)");
}

TEST(BuilderValues, MalformedInputIsAProgrammingErrorNamingTheCallSite) {
  const std::string here = fmt::format("{}:{}", __FILE__, __LINE__ + 2);
  try {
    (void)Q(1, "m/");
    FAIL() << "a malformed unit was accepted";
  } catch (const std::invalid_argument& error) {
    EXPECT_THAT(error.what(), HasSubstr("sled::lang::build::Q: malformed unit `m/`"));
    EXPECT_THAT(error.what(), HasSubstr(here));
  }
  for (const char* unit : {"m s", "m^", "*m", "m^x", "2m", "m.s", "on", "N*m/"}) {
    EXPECT_THROW((void)Q(1, unit), std::invalid_argument) << unit;
  }
  EXPECT_THROW((void)Ref("occupant..pelvis"), std::invalid_argument);
  EXPECT_THROW((void)Ref("with"), std::invalid_argument);
  EXPECT_THROW((void)Ref("2x"), std::invalid_argument);
  EXPECT_THROW((void)Q(std::numeric_limits<double>::infinity(), "m"), std::invalid_argument);
  EXPECT_THROW((void)build::Vector({1}), std::invalid_argument);
  lang::SourceManager sources;
  build::Scene scene(sources, "errors");
  EXPECT_THROW(scene.Set("true", 1), std::invalid_argument);
  EXPECT_THROW(scene.Declare("contact", Q(1, "m")), std::invalid_argument);
  EXPECT_THROW(scene.Row(Ref("x"), 1), std::invalid_argument) << "would read as a statement";
  EXPECT_NO_THROW(scene.Row(-Ref("x"), 1));
}

// Finds the one diagnostic of a kind, or fails.
const lang::Diagnostic* FindKind(const lang::DiagnosticCollector& diagnostics,
                                 lang::DiagnosticKind kind) {
  for (const lang::Diagnostic& diagnostic : diagnostics.diagnostics()) {
    if (diagnostic.kind == kind) return &diagnostic;
  }
  return nullptr;
}

// A scene with a body of one segment, `torso`; the caller adds the rest and the mistake.
build::Statement& MinimalScene(build::Scene& scene) {
  scene.Block("time").Set("end", Q(100, "ms")).Set("output_every", Q(1, "ms"));
  auto& body = scene.Declare("body", "occupant");
  body.Declare("segment", "torso")
      .Set("mass", Q(30, "kg"))
      .Set("inertia", V(0.3, 0.3, 0.2, "kg*m^2"));
  return body;
}

TEST(BuilderDiagnostics, AWrongUnitIsReportedAtTheCppLine) {
  lang::SourceManager sources;
  build::Scene scene(sources, "mistakes");
  build::Statement& body = MinimalScene(scene);
  auto& pelvis = body.Declare("segment", "pelvis");
  pelvis.Set("inertia", V(0.1, 0.09, 0.11, "kg*m^2"));
  const std::uint32_t mass_line = __LINE__ + 1;
  pelvis.Set("mass", Q(11.7, "m"));  // metres, not kilograms
  body.Joint("lumbar", "ball", "pelvis", "torso")
      .Set("at", "pelvis", V(0, 0, 120, "mm"))
      .Set("at", "torso", V(0, 0, -200, "mm"));
  const ast::File file = scene.Finish();

  lang::DiagnosticCollector diagnostics;
  (void)compiler::Check(sources, file, CheckOptionsFor(diagnostics));
  const lang::Diagnostic* wrong_unit =
      FindKind(diagnostics, lang::DiagnosticKind::kDimensionMismatch);
  ASSERT_NE(wrong_unit, nullptr) << RenderAll(sources, diagnostics);
  const lang::SourceRange& range = *wrong_unit->primary_range();
  EXPECT_EQ(sources.buffer(range.file).path(), __FILE__);
  EXPECT_EQ(sources.buffer(range.file).Locate(range.begin).line, mass_line);
  EXPECT_EQ(sources.Text(range), "Q(11.7, \"m\")");
  const std::string rendered = lang::RenderRich(sources, *wrong_unit);
  EXPECT_THAT(rendered, HasSubstr(fmt::format("{}:{}:", __FILE__, mass_line)));
  EXPECT_THAT(rendered,
              HasSubstr("pelvis.Set(\"mass\", Q(11.7, \"m\"));  // metres, not kilograms"));
}

TEST(BuilderDiagnostics, AnUnknownSegmentIsReportedAtTheCppLine) {
  lang::SourceManager sources;
  build::Scene scene(sources, "mistakes");
  build::Statement& body = MinimalScene(scene);
  body.Declare("segment", "pelvis")
      .Set("mass", Q(11.7, "kg"))
      .Set("inertia", V(0.1, 0.09, 0.11, "kg*m^2"));
  const std::uint32_t joint_line = __LINE__ + 1;
  auto& joint = body.Joint("lumbar", "ball", "pelvis", "torsoo");
  joint.Set("at", "pelvis", V(0, 0, 120, "mm")).Set("at", "torso", V(0, 0, -200, "mm"));
  const ast::File file = scene.Finish();

  lang::DiagnosticCollector diagnostics;
  (void)compiler::Check(sources, file, CheckOptionsFor(diagnostics));
  const lang::Diagnostic* unknown = FindKind(diagnostics, lang::DiagnosticKind::kUnknownName);
  ASSERT_NE(unknown, nullptr) << RenderAll(sources, diagnostics);
  EXPECT_THAT(unknown->message, HasSubstr("torsoo"));
  const lang::SourceRange& range = *unknown->primary_range();
  EXPECT_EQ(sources.buffer(range.file).path(), __FILE__);
  EXPECT_EQ(sources.buffer(range.file).Locate(range.begin).line, joint_line);
  const std::string rendered = lang::RenderRich(sources, *unknown);
  EXPECT_THAT(rendered, HasSubstr("body.Joint(\"lumbar\", \"ball\", \"pelvis\", \"torsoo\");"));
  EXPECT_THAT(rendered, HasSubstr("did you mean `torso`?"));
}

}  // namespace
}  // namespace sled
