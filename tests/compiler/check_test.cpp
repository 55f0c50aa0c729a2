// The checker's rules, one behaviour per test: names, units, physical validity, topology, imports,
// parameters and lints. Values are compared with independent conversions, not with earlier output.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "compiler/check/check.h"
#include "lang/diagnostics/render.h"
#include "lang/syntax/parser.h"
#include "tests/compiler/sled_process.h"

namespace sled::compiler {
namespace {

using ::testing::Contains;
using ::testing::HasSubstr;
using ::testing::IsEmpty;

struct Result {
  CheckedScenario scenario;
  std::vector<std::string> codes;     // "E0302@3:10"
  std::vector<std::string> messages;  // compact renderings
  std::vector<lang::Diagnostic> diagnostics;
  int errors = 0;
  int warnings = 0;
};

Result CheckText(const std::string& text, CheckOptions options = {},
                 const std::string& path = "test.sled") {
  lang::SourceManager sources;
  const lang::FileId file = sources.Add(path, text);
  lang::DiagnosticCollector collector;
  options.diagnostics = &collector;
  if (options.stdlib_root.empty()) options.stdlib_root = std::string(SLED_SOURCE_ROOT) + "/stdlib";
  Result result;
  result.scenario = ParseAndCheck(sources, file, options);
  collector.SortByPosition();
  for (const auto& d : collector.diagnostics()) {
    const lang::SourceRange* range = d.primary_range();
    const auto at = range && range->valid() ? sources.buffer(range->file).Locate(range->begin)
                                            : lang::LineColumn{};
    result.codes.push_back(fmt::format("{}@{}:{}", d.code(), at.line, at.column));
    result.messages.push_back(lang::RenderCompact(sources, d));
    result.diagnostics.push_back(d);
  }
  result.errors = collector.error_count();
  result.warnings = collector.warning_count();
  return result;
}

// A minimal valid scene around the given scenario statements.
std::string Scene(const std::string& body) {
  return "scenario \"t\" {\n  time { end = 100 ms  output_every = 1 ms }\n" + body + "\n}\n";
}

const std::string kTwoSegments = R"(
  body b {
    segment s1 { mass = 2 kg  inertia = (0.1, 0.1, 0.1) kg*m^2 }
    segment s2 { mass = 1 kg  inertia = (0.1, 0.1, 0.1) kg*m^2 }
    joint j : pin(s1 -> s2) { at s1 = (0, 0, -100) mm  at s2 = (0, 0, 100) mm  axis = y }
  })";

TEST(CheckUnits, ConvertsEveryValueToSi) {
  const Result r = CheckText(Scene(R"(
  body b {
    segment s {
      mass = 22 lb
      inertia = (1, 2, 2.5) slug*ft^2
      principal_axes = (90, 0, 0) deg
      ellipsoid { semi_axes = (4, 5, 6) in }
    }
  })"));
  ASSERT_EQ(r.errors, 0) << fmt::format("{}", fmt::join(r.messages, "\n"));
  const Segment& s = r.scenario.segments.at(0);
  EXPECT_DOUBLE_EQ(s.mass, 22 * 0.45359237);
  const double slug_ft2 = 14.593902937206364 * 0.3048 * 0.3048;
  EXPECT_NEAR(s.inertia[1], 2 * slug_ft2, 1e-12);
  EXPECT_NEAR(s.principal_axes[0], std::numbers::pi / 2, 1e-15);
  EXPECT_NEAR(r.scenario.ellipsoids.at(0).semi_axes[2], 6 * 0.0254, 1e-15);
  EXPECT_NEAR(r.scenario.run.end, 0.1, 1e-15);
}

TEST(CheckUnits, WrongDimensionNamesTheExpectedAndTheFound) {
  const Result r = CheckText(Scene(R"(
  body b { segment s { mass = 5 m  inertia = (0.1, 0.1, 0.1) kg*m^2 } })"));
  ASSERT_THAT(r.codes, Contains("E0302@4:31"));
  EXPECT_THAT(r.messages[0], HasSubstr("mass [kg]"));
  EXPECT_THAT(r.messages[0], HasSubstr("length [m]"));
}

TEST(CheckUnits, ABareNumberWhereAUnitBelongsIsAnError) {
  const Result r = CheckText(Scene(kTwoSegments + "\n  gravity = (0, 0, -9.81)"));
  EXPECT_THAT(r.codes, Contains(HasSubstr("E0302")));
}

TEST(CheckUnits, ArithmeticWithParametersAndLets) {
  const Result r = CheckText(Scene(R"(
  param height = 1.5 m
  let half = height / 2 + 250 mm
  body b {
    segment s { mass = 1 kg  inertia = (0.1, 0.1, 0.1) kg*m^2 }
  }
  initial b { position = (0 m, 0 m, half) })"));
  ASSERT_EQ(r.errors, 0) << fmt::format("{}", fmt::join(r.messages, "\n"));
  ASSERT_EQ(r.scenario.initial_conditions.size(), 1u);
  EXPECT_DOUBLE_EQ((*r.scenario.initial_conditions[0].position)[2], 1.0);
}

// 20,000 lets, each the one before plus a kilogram: evaluated in the order they are declared,
// so a use of the last does not recurse through all of them (it overflowed the stack).
TEST(CheckUnits, ALongChainOfLetsIsEvaluatedInOrder) {
  constexpr int kLinks = 20000;
  std::string lets = "  let x0 = 1 kg\n";
  for (int i = 1; i < kLinks; ++i) lets += fmt::format("  let x{} = x{} + 1 kg\n", i, i - 1);
  const Result r = CheckText(Scene(lets + fmt::format(R"(
  body b {{
    segment s {{ mass = x{}  inertia = (0.1, 0.1, 0.1) kg*m^2 }}
  }})",
                                                      kLinks - 1)));
  ASSERT_EQ(r.errors, 0) << fmt::format("{}", fmt::join(r.messages, "\n"));
  ASSERT_EQ(r.scenario.segments.size(), 1u);
  EXPECT_DOUBLE_EQ(r.scenario.segments[0].mass, kLinks);
}

// The same chain declared backwards makes each let wait on a later one; past 2,500 levels of
// evaluation it is E0106, reported once, where the limit was reached.
TEST(CheckUnits, AChainOfLaterLetsTooDeepToEvaluateIsE0106Once) {
  constexpr int kLinks = 20000;
  std::string lets;
  for (int i = 0; i < kLinks; ++i) lets += fmt::format("  let x{} = x{} + 1 kg\n", i, i + 1);
  lets += fmt::format("  let x{} = 1 kg\n", kLinks);
  const Result r = CheckText(Scene(lets));
  EXPECT_EQ(r.errors, 1) << fmt::format("{}", fmt::join(r.messages, "\n"));
  EXPECT_THAT(r.messages, Contains(HasSubstr("error[E0106]: this value is defined through more "
                                             "than 2500 nested definitions")));
}

TEST(CheckUnits, AddingALengthToATimeIsAnError) {
  const Result r =
      CheckText(Scene("  let x = 5 mm + 2 s\n  body b { segment s { mass = x  "
                      "inertia = (1, 1, 1) kg*m^2 } }"));
  EXPECT_THAT(r.codes, Contains("E0303@3:11"));
}

TEST(CheckUnits, ParameterDefinedInTermsOfItselfIsReported) {
  const Result r =
      CheckText(Scene("  let a = b + 1 m\n  let b = a\n  body z { segment s { "
                      "mass = 1 kg  inertia = (1, 1, 1) kg*m^2 } }\n  initial z { "
                      "position = (a, 0 m, 0 m) }"));
  EXPECT_GE(r.errors, 1);
}

TEST(CheckUnits, OverrideReplacesAParameter) {
  CheckOptions options;
  options.overrides = {{"speed", "40 km/h"}};
  const Result r = CheckText(Scene(R"(
  param speed = 56 km/h
  vehicle v { motion = half_sine(delta_v = speed, duration = 100 ms) })"),
                             options);
  ASSERT_EQ(r.errors, 0) << fmt::format("{}", fmt::join(r.messages, "\n"));
  EXPECT_NEAR(r.scenario.vehicles.at(0).motion.delta_v, 40 / 3.6, 1e-12);
}

TEST(CheckUnits, OverrideOfAnUnknownParameterIsAnError) {
  CheckOptions options;
  options.overrides = {{"sped", "40 km/h"}};
  const Result r = CheckText(Scene("  param speed = 56 km/h\n  vehicle v { motion = "
                                   "half_sine(delta_v = speed, duration = 100 ms) }"),
                             options);
  ASSERT_THAT(r.codes, Contains(HasSubstr("E0213")));
  EXPECT_THAT(fmt::format("{}", fmt::join(r.messages, "\n")), HasSubstr("`speed`"));
}

TEST(CheckNames, UnknownAttributeSuggestsTheClosestName) {
  const Result r =
      CheckText(Scene("  body b { segment s { mas = 1 kg  inertia = (1, 1, 1) "
                      "kg*m^2 } }"));
  ASSERT_THAT(r.codes, Contains("E0201@3:24"));
  // The misspelt `mas` is not also reported as a missing `mass`.
  EXPECT_THAT(r.codes, ::testing::Not(Contains(HasSubstr("E0206"))));
  EXPECT_THAT(fmt::format("{}", fmt::join(r.messages, "\n")), HasSubstr("did you mean `mass`?"));
}

TEST(CheckNames, AttributeOfAnotherBlockIsMisplaced) {
  const Result r =
      CheckText(Scene("  body b { segment s { mass = 1 kg  inertia = (1, 1, 1) "
                      "kg*m^2  viscous = 1 N*m*s/rad } }"));
  EXPECT_THAT(r.codes, Contains(HasSubstr("E0211")));
}

TEST(CheckNames, UnknownSegmentInAJointSuggestsTheClosest) {
  const Result r = CheckText(Scene(R"(
  body b {
    segment torso { mass = 2 kg  inertia = (0.1, 0.1, 0.1) kg*m^2 }
    segment head { mass = 1 kg  inertia = (0.1, 0.1, 0.1) kg*m^2 }
    joint neck : ball(torso2 -> head) { at torso = (0, 0, 0) mm  at head = (0, 0, 0) mm }
  })"));
  ASSERT_THAT(r.codes, Contains("E0204@7:23"));
  EXPECT_EQ(r.errors, 1) << "no cascade of not-reached segments";
  EXPECT_THAT(fmt::format("{}", fmt::join(r.messages, "\n")), HasSubstr("did you mean `torso`?"));
}

TEST(CheckNames, DuplicateNamesPointAtBothDeclarations) {
  const Result r = CheckText(Scene(R"(
  body b {
    segment s { mass = 2 kg  inertia = (0.1, 0.1, 0.1) kg*m^2 }
    segment s { mass = 1 kg  inertia = (0.1, 0.1, 0.1) kg*m^2 }
  })"));
  ASSERT_THAT(r.codes, Contains("E0202@6:13"));
  EXPECT_EQ(r.errors, 1);
  const auto& d = r.diagnostics.at(0);
  ASSERT_EQ(d.labels.size(), 2u);
}

TEST(CheckNames, MissingRequiredAttributeIsNotReportedAfterASyntaxError) {
  const Result r =
      CheckText(Scene("  body b { segment s { mass = = 1 kg  inertia = (1, 1, 1) "
                      "kg*m^2 } }"));
  EXPECT_THAT(r.codes, Contains(HasSubstr("E0101")));
  EXPECT_THAT(r.codes, ::testing::Not(Contains(HasSubstr("E0206"))));
}

TEST(CheckNames, ManyErrorsAreReportedInOneRunInSourceOrder) {
  const Result r = CheckText(Scene(R"(
  body b {
    segment a { mass = -1 kg  inertia = (0.1, 0.1, 0.1) kg*m^2 }
    segment c { mass = 1 kg  inertia = (1, 0.1, 0.1) kg*m^2 }
    segment d { mass = 1 kg  inertia = (0.1, 0.1, 0.1) kg*m^2  colour = 3 }
    joint j1 : ball(a -> c) { at a = (0, 0, 0) mm  at c = (0, 0, 0) mm }
    joint j2 : ball(a -> d) { at a = (0, 0, 0) mm  at d = (0, 0, 0) mm  flexure = 5 N }
  })"));
  ASSERT_EQ(r.codes.size(), 4u) << fmt::format("{}", fmt::join(r.messages, "\n"));
  EXPECT_EQ(r.codes[0], "E0401@5:24");
  EXPECT_EQ(r.codes[1], "E0402@6:40");
  EXPECT_EQ(r.codes[2], "E0201@7:64");
  EXPECT_EQ(r.codes[3], "E0302@9:83");
}

TEST(CheckModel, PrincipalMomentsMustSatisfyTheTriangleInequality) {
  const Result ok =
      CheckText(Scene("  body b { segment s { mass = 1 kg  inertia = (1, 1, 2) "
                      "kg*m^2 } }"));
  EXPECT_EQ(ok.errors, 0);  // a flat body: equality holds
  const Result bad =
      CheckText(Scene("  body b { segment s { mass = 1 kg  inertia = (1, 1, 2.1) "
                      "kg*m^2 } }"));
  EXPECT_THAT(bad.codes, Contains(HasSubstr("E0402")));
}

TEST(CheckModel, SingularSegmentsMustBeMassless) {
  const Result ok = CheckText(Scene("  body b { segment s { mass = 0 kg  singular = true } }"));
  EXPECT_EQ(ok.errors, 0) << fmt::format("{}", fmt::join(ok.messages, "\n"));
  const Result bad =
      CheckText(Scene("  body b { segment s { mass = 0 kg  inertia = (1, 1, 1) "
                      "kg*m^2 } }"));
  EXPECT_THAT(bad.codes, Contains(HasSubstr("E0401")));
}

TEST(CheckModel, TablesMustIncreaseAndHaveTwoRows) {
  const Result r = CheckText(Scene(R"(
  function f = table(deflection -> force) {
    0 mm -> 0 N
    20 mm -> 1 kN
    10 mm -> 2 kN
  }
  function g = table(deflection -> force) { 0 mm -> 0 N }
  function h = polynomial(1 N, 1 N/m, 1 N/m^2, 1 N/m^3, 1 N/m^4, 1 N/m^5, 1 N/m^6))"));
  EXPECT_THAT(r.codes, Contains("E0407@7:5"));
  EXPECT_THAT(r.codes, Contains(HasSubstr("E0413")));
  EXPECT_THAT(r.codes, Contains(HasSubstr("E0408")));
}

TEST(CheckModel, PolynomialCoefficientsFollowTheSignatureOfTheirUse) {
  const Result r = CheckText(Scene(kTwoSegments.substr(0, kTwoSegments.size() - 4) +
                                   "    joint k : ball(s2 -> s3) { at s2 = (0, 0, 0) mm  at s3 = "
                                   "(0, 0, 0) mm  flexure = polynomial(0, 2 N*m/deg, 3 N) }\n"
                                   "    segment s3 { mass = 1 kg  inertia = (1, 1, 1) kg*m^2 }\n"
                                   "  }"));
  // The third coefficient of angle -> torque must be N*m/rad^2, not N.
  EXPECT_THAT(r.codes, Contains(HasSubstr("E0302")));
}

TEST(CheckModel, FrictionAndRestitutionAreInRange) {
  const Result r = CheckText(Scene(kTwoSegments + R"(
  plane p { corners = (0, 0, 0) m, (1, 0, 0) m, (0, 1, 0) m }
  contact b.s1 with p { force = 1 kN/mm  friction = -0.1  restitution = 1.5 })"));
  EXPECT_EQ(std::count_if(r.codes.begin(), r.codes.end(),
                          [](const std::string& c) { return c.starts_with("E0409"); }),
            2);
}

TEST(CheckModel, ADirectionOfHugeComponentsIsStillADirection) {
  // The squares of 1e300 overflow; the axis is (1, 1, 0) / sqrt(2) all the same.
  std::string scene = kTwoSegments;
  scene.replace(scene.find("axis = y"), 8, "axis = (1e300, 1e300, 0)");
  const Result r = CheckText(Scene(scene));
  ASSERT_EQ(r.errors, 0) << fmt::format("{}", fmt::join(r.messages, "\n"));
  const Vec3& axis = r.scenario.joints.at(0).axis;
  EXPECT_NEAR(axis[0], std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(axis[1], std::sqrt(0.5), 1e-15);
  EXPECT_EQ(axis[2], 0.0);
}

TEST(CheckModel, APlaneWhoseAreaOverflowsIsOutOfRange) {
  const Result r = CheckText(Scene(kTwoSegments + R"(
  plane floor { corners = (-1e300, -1e300, 0) m, (1e300, -1e300, 0) m, (-1e300, 1e300, 0) m })"));
  EXPECT_THAT(r.codes, Contains(HasSubstr("E0409")));
  EXPECT_THAT(r.messages,
              Contains(HasSubstr("are so far apart that its area (2e+300 by 2e+300 m)")));
}

TEST(CheckTopology, ASegmentWithTwoParentJointsIsReported) {
  const Result r = CheckText(Scene(kTwoSegments.substr(0, kTwoSegments.size() - 4) +
                                   "    segment s3 { mass = 1 kg  inertia = (1, 1, 1) kg*m^2 }\n"
                                   "    joint k : ball(s3 -> s2) { at s3 = (0, 0, 0) mm  at s2 = "
                                   "(0, 0, 0) mm }\n  }"));
  EXPECT_THAT(r.codes, Contains(HasSubstr("E0404")));
}

TEST(CheckTopology, AClosedLoopOfJointsIsReported) {
  const Result r = CheckText(Scene(R"(
  body b {
    segment a { mass = 1 kg  inertia = (1, 1, 1) kg*m^2 }
    segment c { mass = 1 kg  inertia = (1, 1, 1) kg*m^2 }
    segment d { mass = 1 kg  inertia = (1, 1, 1) kg*m^2 }
    joint j1 : ball(a -> c) { at a = (0, 0, 0) mm  at c = (0, 0, 0) mm }
    joint j2 : ball(c -> d) { at c = (0, 0, 0) mm  at d = (0, 0, 0) mm }
    joint j3 : ball(d -> a) { at d = (0, 0, 0) mm  at a = (0, 0, 0) mm }
  })"));
  // d -> a makes a the child of j3 although a is the root; the loop itself closes at j3.
  EXPECT_GE(r.errors, 1);
  EXPECT_THAT(r.codes, Contains(::testing::AnyOf(HasSubstr("E0406"), HasSubstr("E0405"))));
}

TEST(CheckTopology, ASegmentNoJointReachesIsReported) {
  const Result r = CheckText(Scene(kTwoSegments.substr(0, kTwoSegments.size() - 4) +
                                   "    segment lost { mass = 1 kg  inertia = (1, 1, 1) kg*m^2 "
                                   "}\n  }"));
  EXPECT_THAT(r.codes, Contains(HasSubstr("E0405")));
  EXPECT_THAT(fmt::format("{}", fmt::join(r.messages, "\n")), HasSubstr("null"));
}

TEST(CheckTopology, ANullJointStartsAnotherReferenceSegment) {
  const Result r = CheckText(Scene(kTwoSegments.substr(0, kTwoSegments.size() - 4) +
                                   "    segment free { mass = 1 kg  inertia = (1, 1, 1) kg*m^2 }\n"
                                   "    joint n : null(s1 -> free)\n  }"));
  ASSERT_EQ(r.errors, 0) << fmt::format("{}", fmt::join(r.messages, "\n"));
  EXPECT_EQ(r.scenario.bodies.at(0).reference_segments.size(), 2u);
}

TEST(CheckImports, TheStandardOccupantImportsUnderItsAlias) {
  const Result r =
      CheckText(Scene("  import std.humans.male50 as occupant\n  initial occupant "
                      "{ position = (0, 0, 1) m }"));
  ASSERT_EQ(r.errors, 0) << fmt::format("{}", fmt::join(r.messages, "\n"));
  ASSERT_EQ(r.scenario.bodies.size(), 1u);
  EXPECT_EQ(r.scenario.bodies[0].name, "occupant");
  EXPECT_EQ(r.scenario.segments.size(), 15u);
  double mass = 0;
  for (const Segment& s : r.scenario.segments) mass += s.mass;
  EXPECT_NEAR(mass, 78.0, 1.0);  // the 50th-percentile male of crash-conventions.md §4
}

TEST(CheckImports, TwoImportsOfOneBodyAreTwoInstances) {
  const Result r =
      CheckText(Scene("  import std.humans.male50 as driver\n  import "
                      "std.humans.male50 as passenger"));
  ASSERT_EQ(r.errors, 0) << fmt::format("{}", fmt::join(r.messages, "\n"));
  EXPECT_EQ(r.scenario.bodies.size(), 2u);
  EXPECT_EQ(r.scenario.segments.size(), 30u);
}

TEST(CheckImports, UnknownModuleSuggestsTheClosest) {
  const Result r = CheckText(Scene("  import std.humans.male5 as occupant"));
  ASSERT_THAT(r.codes, Contains(HasSubstr("E0203")));
  EXPECT_THAT(fmt::format("{}", fmt::join(r.messages, "\n")),
              HasSubstr("did you mean `std.humans.male50`?"));
}

TEST(CheckImports, ACycleOfImportsIsReported) {
  const sled::testing::TempFolder temp;
  const std::filesystem::path& folder = temp.path();
  std::ofstream(folder / "a.sled") << "import b\n";
  std::ofstream(folder / "b.sled") << "import a\n";
  const Result r = CheckText("import a\n", {}, (folder / "main.sled").string());
  EXPECT_THAT(r.codes, Contains(HasSubstr("E0208")));
}

TEST(CheckLints, ContactBetweenSurfacesOfOneFrameCanNeverTouch) {
  const Result r = CheckText(Scene(R"(
  vehicle v { motion = half_sine(delta_v = 10 km/h, duration = 50 ms) }
  plane p on v { corners = (0, 0, 0) m, (1, 0, 0) m, (0, 1, 0) m }
  ellipsoid e on v { semi_axes = (0.1, 0.1, 0.1) m  center = (0.5, 0.5, 1) m }
  contact e with p { force = 1 kN/mm })"));
  EXPECT_THAT(r.codes, Contains(HasSubstr("W0003")));
  EXPECT_EQ(r.errors, 0);
}

TEST(CheckLints, AnEllipsoidStartingInsideAPlaneIsReportedWithItsDepth) {
  const Result r = CheckText(Scene(R"(
  body b { segment s { mass = 1 kg  inertia = (1, 1, 1) kg*m^2
                       ellipsoid { semi_axes = (100, 100, 100) mm } } }
  initial b { position = (500, 500, 70) mm }
  plane floor { corners = (0, 0, 0) m, (1, 0, 0) m, (0, 1, 0) m }
  contact b.s with floor { force = 1 kN/mm })"));
  ASSERT_THAT(r.codes, Contains(HasSubstr("W0004")));
  EXPECT_THAT(fmt::format("{}", fmt::join(r.messages, "\n")), HasSubstr("30.0 mm inside"));
}

TEST(CheckLints, MaxStepTooLongForTheStiffestContact) {
  // k = 1e6 N/m against 1 kg: period 2*pi*sqrt(1e-6) s = 6.28 ms; a tenth is 0.63 ms.
  const std::string scene = R"(
  body b { segment s { mass = 1 kg  inertia = (1, 1, 1) kg*m^2
                       ellipsoid { semi_axes = (100, 100, 100) mm } } }
  initial b { position = (500, 500, 200) mm }
  plane floor { corners = (0, 0, 0) m, (1, 0, 0) m, (0, 1, 0) m }
  contact b.s with floor { force = 1 kN/mm })";
  const Result slow = CheckText(Scene("  integrator dopri5 { max_step = 1 ms }" + scene));
  EXPECT_THAT(slow.codes, Contains(HasSubstr("W0006")));
  const Result fine = CheckText(Scene("  integrator dopri5 { max_step = 0.5 ms }" + scene));
  EXPECT_THAT(fine.codes, ::testing::Not(Contains(HasSubstr("W0006"))));
}

TEST(CheckLints, UnusedFunctionsAndParametersAreReported) {
  const Result r = CheckText(Scene("  param unused = 3 m\n  function spare = constant(5 N)"));
  EXPECT_THAT(r.codes, Contains(HasSubstr("W0001")));
  EXPECT_THAT(r.codes, Contains(HasSubstr("W0007")));
  EXPECT_EQ(r.errors, 0);
}

TEST(CheckLints, AnOutputOfAContactNobodyDeclaredIsReported) {
  const Result r = CheckText(Scene(kTwoSegments + R"(
  plane p { corners = (0, 0, 0) m, (1, 0, 0) m, (0, 1, 0) m }
  output { contact_force b.s1 with p })"));
  EXPECT_THAT(r.codes, Contains(HasSubstr("W0005")));
}

TEST(CheckRun, ATimeBlockIsRequired) {
  const Result r = CheckText("scenario \"x\" { gravity = (0, 0, -1) g }\n");
  EXPECT_THAT(r.codes, Contains("E0206@1:1"));
}

TEST(CheckRun, OutputStepLongerThanTheRunIsReported) {
  const Result r = CheckText("scenario \"x\" { time { end = 10 ms  output_every = 20 ms } }\n");
  EXPECT_THAT(r.codes, Contains(HasSubstr("E0412")));
}

TEST(CheckOutputs, FilterClassesAndTheFilterStandard) {
  const Result r = CheckText(Scene(kTwoSegments + R"(
  output {
    filter_standard = iso_6487
    acceleration b.s1 filter cfc180
    acceleration b.s2 filter none as raw
    joint_force b.j filter cfc600
    criteria = hic15(b.s1)
  })"));
  ASSERT_EQ(r.errors, 0) << ::testing::PrintToString(r.messages);
  ASSERT_EQ(r.scenario.outputs.size(), 3u);
  EXPECT_EQ(r.scenario.outputs[0].filter_class, 180);
  EXPECT_EQ(r.scenario.outputs[1].filter_class, 0);
  EXPECT_EQ(r.scenario.outputs[2].filter_class, 600);
  EXPECT_TRUE(r.scenario.outputs[0].iso_filter);
  ASSERT_EQ(r.scenario.criteria.size(), 1u);
  EXPECT_TRUE(r.scenario.criteria[0].iso_filter);
}

TEST(CheckOutputs, AnUnknownFilterClassOrStandardIsReported) {
  const Result r = CheckText(Scene(kTwoSegments + R"(
  output {
    filter_standard = iso6487
    acceleration b.s1 filter cfc100
  })"));
  EXPECT_EQ(r.errors, 2);
  EXPECT_THAT(r.messages, Contains(HasSubstr("`cfc60`, `cfc180`, `cfc600` or `cfc1000`")));
  EXPECT_THAT(r.messages, Contains(HasSubstr("`filter_standard` is `sae_j211` or `iso_6487`")));
}

// --- Load cases: overriding an imported body's joints, seating by the H-point, trapezoids by
// delta-v, and criteria with the scene's own limits.

const Joint& NamedJoint(const CheckedScenario& scenario, const std::string& name) {
  for (const Joint& joint : scenario.joints) {
    if (joint.name == name) return joint;
  }
  throw std::runtime_error("no joint " + name);
}

TEST(CheckOverride, ChangesOnlyWhatItStatesOfAnImportedJoint) {
  const Result plain = CheckText(Scene("  import std.humans.male50 as occupant"));
  const Result r = CheckText(Scene(R"(
  import std.humans.male50 as occupant
  function stiff = table(angle -> torque) { 0 deg -> 0 N*m  30 deg -> 60 N*m }
  override occupant.neck_upper { nutation = stiff  viscous = 3 N*m*s/rad  stop = 40 deg }
  override occupant.elbow_l { locked = true })"));
  ASSERT_EQ(r.errors + r.warnings, 0) << fmt::format("{}", fmt::join(r.messages, "\n"));
  const Joint& before = NamedJoint(plain.scenario, "occupant.neck_upper");
  const Joint& neck = NamedJoint(r.scenario, "occupant.neck_upper");
  EXPECT_DOUBLE_EQ(neck.viscous, 3.0);
  ASSERT_TRUE(neck.stop.has_value());
  EXPECT_NEAR(*neck.stop, 40.0 * std::numbers::pi / 180.0, 1e-12);
  ASSERT_GE(neck.nutation, 0);
  EXPECT_EQ(r.scenario.functions[static_cast<std::size_t>(neck.nutation)].points.size(), 2u);
  // What the override does not state stays the body's.
  EXPECT_EQ(neck.precession >= 0, before.precession >= 0);
  EXPECT_EQ(neck.spin >= 0, before.spin >= 0);
  EXPECT_EQ(neck.twist_stop, before.twist_stop);
  EXPECT_EQ(neck.location_in_parent, before.location_in_parent);
  EXPECT_EQ(NamedJoint(r.scenario, "occupant.elbow_l").locked_axes, 7u);
  EXPECT_EQ(NamedJoint(r.scenario, "occupant.elbow_r").locked_axes,
            NamedJoint(plain.scenario, "occupant.elbow_r").locked_axes);
}

TEST(CheckOverride, ChecksEachValueAsTheJointWould) {
  const Result r = CheckText(Scene(R"(
  import std.humans.male50 as occupant
  override occupant.knee_l { twist = 2 N*m/deg }
  override occupant.knee_r { viscous = 2 kg }
  override occupant.pelvis { viscous = 1 N*m*s/rad }
  override occupant.hip_l { at occupant.pelvis = (0, 0, 0) mm })"));
  EXPECT_THAT(r.codes, Contains(HasSubstr("E0211@5:30")));  // twist on a pin joint
  EXPECT_THAT(r.codes, Contains(HasSubstr("E0302@6:40")));  // wrong dimension
  EXPECT_THAT(r.codes, Contains(HasSubstr("E0205@7:12")));  // a segment, not a joint
  EXPECT_THAT(r.codes, Contains(HasSubstr("E0211@8:29")));  // geometry is not overridable
}

TEST(CheckHPoint, SeatsTheBodyByItsHPoint) {
  const Result r = CheckText(Scene(R"(
  import std.humans.male50 as occupant
  initial occupant { h_point = (100, 0, 200) mm  orientation = (0, -20, 0) deg })"));
  ASSERT_EQ(r.errors, 0) << fmt::format("{}", fmt::join(r.messages, "\n"));
  ASSERT_EQ(r.scenario.initial_conditions.size(), 1u);
  const auto& position = r.scenario.initial_conditions[0].position;
  ASSERT_TRUE(position.has_value());
  // The pelvis centre of mass is 57 mm above the H-point along the pelvis's z, pitched -20 deg:
  // R_y(-20 deg) (0, 0, 0.057) = (-0.057 sin 20 deg, 0, 0.057 cos 20 deg).
  const double pitch = 20.0 * std::numbers::pi / 180.0;
  EXPECT_NEAR((*position)[0], 0.100 - 0.057 * std::sin(pitch), 1e-12);
  EXPECT_NEAR((*position)[1], 0.0, 1e-12);
  EXPECT_NEAR((*position)[2], 0.200 + 0.057 * std::cos(pitch), 1e-12);
}

TEST(CheckHPoint, NeedsABodyWithOneAndNoPosition) {
  const Result r = CheckText(Scene(kTwoSegments + R"(
  import std.humans.male50 as occupant
  initial b { h_point = (0, 0, 0) mm }
  initial occupant { h_point = (0, 0, 0) mm  position = (0, 0, 0) mm })"));
  EXPECT_THAT(r.codes, Contains(HasSubstr("E0206@10:15")));
  EXPECT_THAT(r.codes, Contains(HasSubstr("E0207@11:22")));
}

TEST(CheckCriteria, AScenesOwnLimitComesWithItsStandard) {
  const Result r = CheckText(Scene(R"(
  import std.humans.male50 as occupant
  output {
    criteria = hic15(occupant.head, limit = 1000, standard = "GTR 9"),
      head_3ms(occupant.head, limit = 72 g, standard = "Euro NCAP"),
      nkm(occupant.neck_upper)
  })"));
  ASSERT_EQ(r.errors, 0) << fmt::format("{}", fmt::join(r.messages, "\n"));
  ASSERT_EQ(r.scenario.criteria.size(), 3u);
  EXPECT_EQ(r.scenario.criteria[0].limit, 1000.0);
  EXPECT_EQ(r.scenario.criteria[0].standard, "GTR 9");
  EXPECT_NEAR(*r.scenario.criteria[1].limit, 72 * 9.80665, 1e-9);
  EXPECT_FALSE(r.scenario.criteria[2].limit.has_value());
  const Result bad = CheckText(Scene(R"(
  import std.humans.male50 as occupant
  output {
    criteria = hic15(occupant.head, limit = 1000), hic36(occupant.head, limit = 5 N,
      standard = "x"), nij(occupant.neck_upper, standard = "y")
  })"));
  EXPECT_THAT(bad.codes, Contains(HasSubstr("E0210@6:16")));
  EXPECT_THAT(bad.codes, Contains(HasSubstr("E0302@6:81")));
  EXPECT_THAT(bad.codes, Contains(HasSubstr("E0210@7:24")));
}

TEST(CheckCriteria, NicAndTtiNeedTheirSecondInput) {
  const Result r = CheckText(Scene(R"(
  import std.humans.male50 as occupant
  output {
    criteria = nic(occupant.head, t1 = occupant.neck_lower, limit = 20 m^2/s^2,
      standard = "x"), tti(occupant.thorax, spine = occupant.abdomen, limit = 90 g,
      standard = "FMVSS 214, two-door")
  })"));
  ASSERT_EQ(r.errors, 0) << fmt::format("{}", fmt::join(r.messages, "\n"));
  ASSERT_EQ(r.scenario.criteria.size(), 2u);
  EXPECT_EQ(r.scenario.criteria[0].limit, 20.0);
  EXPECT_GE(r.scenario.criteria[0].second, 0);
  EXPECT_NEAR(*r.scenario.criteria[1].limit, 90 * 9.80665, 1e-9);
  const Result bad = CheckText(Scene(R"(
  import std.humans.male50 as occupant
  output {
    criteria = nic(occupant.head), tti(occupant.thorax, t1 = occupant.neck_lower),
      nic(occupant.head, t1 = occupant.abdomen), tibia_index(occupant.knee_l, spine = occupant.head)
  })"));
  EXPECT_THAT(bad.codes, Contains(HasSubstr("E0210@6:16")));
  EXPECT_THAT(bad.codes, Contains(HasSubstr("E0209@6:57")));
  EXPECT_EQ(bad.scenario.criteria.size(), 0u);
}

}  // namespace
}  // namespace sled::compiler
