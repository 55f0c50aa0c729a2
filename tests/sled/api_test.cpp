// The public API (sled/sled.h) as a program that embeds sled uses it: the three kinds of Source,
// the options, the diagnostics of every stage, and Simulate's sinks.
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "lang/builder/builder.h"
#include "sled/sled.h"
#include "tests/compiler/sled_process.h"

namespace sled {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using ::testing::IsEmpty;

const fs::path kRoot = SLED_SOURCE_ROOT;

// A ball dropped onto the floor: gravity, one contact, 50 output rows.
constexpr char kDrop[] = R"(scenario "drop" {
  gravity = (0, 0, -9.81) m/s^2
  time { end = 50 ms  output_every = 1 ms }
  plane floor { corners = (0, -1, 0) m, (1, -1, 0) m, (0, 1, 0) m }
  body ball {
    segment s {
      mass = 1 kg  inertia = (0.01, 0.01, 0.01) kg*m^2
      ellipsoid { semi_axes = (0.1, 0.1, 0.1) m }
    }
  }
  contact ball.s with floor { force = 10 kN/m }
  initial ball { position = (0, 0, 0.105) m }
  output { acceleration ball.s }
}
)";

CompileOptions InTree() {
  CompileOptions options;
  options.stdlib = (kRoot / "stdlib").string();
  return options;
}

TEST(Compile, TextCompilesToAModel) {
  const Compilation compiled = Compile(Source::Text(kDrop, "drop.sled"), InTree());
  ASSERT_TRUE(compiled.ok()) << compiled.Render();
  ASSERT_TRUE(compiled.has_model());
  EXPECT_EQ(compiled.model().title, "drop");
  EXPECT_EQ(compiled.model().nsegment(), 1u);
  ASSERT_NE(compiled.ast(), nullptr);
  EXPECT_TRUE(compiled.scenario().has_scenario);
  EXPECT_EQ(compiled.Render(), "");
}

TEST(Compile, FileCompilesTheFlagshipWithItsImports) {
  const Compilation compiled =
      Compile(Source::File((kRoot / "examples/frontal_sled.sled").string()), InTree());
  ASSERT_TRUE(compiled.ok()) << compiled.Render();
  EXPECT_GT(compiled.model().nsegment(), 10u);
}

TEST(Compile, ErrorsOfEveryStageAreDiagnosticsAndThereIsNoModel) {
  const Compilation compiled = Compile(Source::Text(R"(scenario "s" {
  time { end = 1 parsec }
  body b { segment s { mass = 1 kg  inertia = (1, 1, 1) kg*m^2 } }
  initial b { position = (0, 0, unknown) m }
}
)"),
                                       InTree());
  EXPECT_FALSE(compiled.ok());
  EXPECT_FALSE(compiled.has_model());
  EXPECT_GE(compiled.error_count(), 2);
  EXPECT_THAT(compiled.Render(), HasSubstr("scene.sled:2:"));
  EXPECT_THAT(compiled.Render(), HasSubstr("error[E0301]"));
  EXPECT_THROW((void)compiled.model(), std::logic_error);
  // Sorted by position: line 2 before line 4.
  const std::string compact = compiled.Render();
  EXPECT_LT(compact.find("scene.sled:2:"), compact.find("scene.sled:4:"));
}

TEST(Compile, AnUnreadableFileIsE0107) {
  const Compilation compiled = Compile(Source::File("/nonexistent/scene.sled"), InTree());
  EXPECT_FALSE(compiled.ok());
  EXPECT_EQ(compiled.ast(), nullptr);
  ASSERT_EQ(compiled.diagnostics().size(), 1u);
  EXPECT_EQ(compiled.diagnostics()[0].code(), "E0107");
}

TEST(Compile, WithoutLoweringAModuleIsNoErrorAndThereIsNoModel) {
  const std::string module = "body b { segment s { mass = 1 kg  inertia = (1, 1, 1) kg*m^2 } }\n";
  CompileOptions options = InTree();
  options.lower = false;
  const Compilation checked = Compile(Source::Text(module), options);
  EXPECT_TRUE(checked.ok()) << checked.Render();
  EXPECT_FALSE(checked.has_model());
  // Asked for a Model, the module has nothing to run.
  const Compilation lowered = Compile(Source::Text(module), InTree());
  EXPECT_FALSE(lowered.ok());
  EXPECT_THAT(lowered.Render(), HasSubstr("has no `scenario` to run"));
}

TEST(Compile, OverridesSetParameters) {
  const std::string scene = R"(scenario "s" {
  param drop_height = 1 m
  time { end = 10 ms  output_every = 1 ms }
  body b { segment s { mass = 1 kg  inertia = (1, 1, 1) kg*m^2 } }
  initial b { position = (0, 0, drop_height) }
}
)";
  CompileOptions options = InTree();
  options.overrides = {{"drop_height", "250 mm"}};
  const Compilation compiled = Compile(Source::Text(scene), options);
  ASSERT_TRUE(compiled.ok()) << compiled.Render();
  const runtime::Model& model = compiled.model();
  ASSERT_GE(model.q0.size(), 3);
  EXPECT_DOUBLE_EQ(model.q0[2], 0.25);
}

TEST(Compile, LoweringNotesAreRegisteredDiagnostics) {
  // The arm hangs 2 m above the floor and reaches 0.15 m: the Model leaves its contact out.
  const Compilation compiled = Compile(Source::Text(R"(scenario "s" {
  time { end = 10 ms  output_every = 1 ms }
  plane floor { corners = (0, -1, 0) m, (1, -1, 0) m, (0, 1, 0) m }
  body arm {
    segment upper {
      mass = 1 kg  inertia = (0.01, 0.01, 0.01) kg*m^2
      ellipsoid { semi_axes = (0.05, 0.05, 0.05) m  center = (0, 0, 0.1) m }
    }
  }
  constraint shoulder : fixed_point(ground -> arm.upper) {
    at ground = (0, 0, 2) m  at arm.upper = (0, 0, 0.2) m
  }
  contact arm.upper with floor { force = 10 kN/m }
  initial arm { position = (0, 0, 1.8) m }
}
)"),
                                       InTree());
  ASSERT_TRUE(compiled.ok()) << compiled.Render();
  ASSERT_EQ(compiled.diagnostics().size(), 1u);
  EXPECT_EQ(compiled.diagnostics()[0].code(), "N0401");
  EXPECT_EQ(compiled.diagnostics()[0].severity, lang::Severity::kNote);
  EXPECT_THAT(compiled.Notes(),
              ::testing::ElementsAre(HasSubstr("note[N0401]: contact between `arm.upper`")));
}

TEST(Compile, ABuiltTreeCompilesWithDiagnosticsInTheCppFile) {
  namespace build = lang::build;
  auto built = [](bool misspelt) {
    auto sources = std::make_unique<lang::SourceManager>();
    build::Scene scene(*sources, "built");
    scene.Block("time").Set("end", build::Q(10, "ms")).Set("output_every", build::Q(1, "ms"));
    scene.Declare("body", "b")
        .Declare("segment", "s")
        .Set("mass", build::Q(1, "kg"))
        .Set("inertia", build::V(1, 1, 1, "kg*m^2"));
    if (misspelt) scene.Declare("initial", "bb").Set("position", build::V(0, 0, 1, "m"));
    return Compile(Source::Tree(std::move(sources), scene.Finish()), InTree());
  };
  const Compilation compiled = built(false);
  ASSERT_TRUE(compiled.ok()) << compiled.Render();
  EXPECT_EQ(compiled.model().title, "built");
  const Compilation misspelt = built(true);
  EXPECT_FALSE(misspelt.ok());
  EXPECT_THAT(misspelt.Render(), HasSubstr("api_test.cpp:"));
  EXPECT_THAT(misspelt.Render(), HasSubstr("error[E0204]"));
}

TEST(Compile, ModulePathFindsImportsOutsideTheScenesFolder) {
  testing::TempFolder library;
  ASSERT_FALSE(library.path().empty());
  fs::create_directories(library.path() / "parts");
  testing::WriteText(library.path() / "parts" / "dummy.sled",
                     "body dummy { segment s { mass = 2 kg  inertia = (1, 1, 1) kg*m^2 } }\n");
  const std::string scene = R"(scenario "s" {
  import parts.dummy as d
  time { end = 10 ms  output_every = 1 ms }
}
)";
  // Without the folder the import is E0203; with it, the module is found there.
  const Compilation missing = Compile(Source::Text(scene), InTree());
  EXPECT_THAT(missing.Render(), HasSubstr("error[E0203]"));
  CompileOptions options = InTree();
  options.module_path = {library.path().string()};
  const Compilation found = Compile(Source::Text(scene), options);
  ASSERT_TRUE(found.ok()) << found.Render();
  EXPECT_DOUBLE_EQ(found.model().segment_mass[0], 2.0);
  // $SLED_PATH adds the same folder.
  ASSERT_EQ(setenv("SLED_PATH", ("/nonexistent:" + library.path().string()).c_str(), 1), 0);
  const Compilation from_environment = Compile(Source::Text(scene), InTree());
  unsetenv("SLED_PATH");
  EXPECT_TRUE(from_environment.ok()) << from_environment.Render();
}

// Counts what a sink sees.
class CountingSink : public RunSink {
 public:
  void OnRow(const runtime::Model&, const runtime::Data&) override { ++rows; }
  void OnStop(const runtime::Model&, const runtime::Data& data) override {
    stops.push_back(data.time);
  }
  bool OnEnd(const runtime::Model&, const RunResult& result, std::string* error) override {
    ended_with_rows = result.series.rows();
    if (fail) *error = "could not keep it";
    return !fail;
  }
  int rows = 0;
  std::vector<double> stops;
  std::size_t ended_with_rows = 0;
  bool fail = false;
};

TEST(Simulate, SinksSeeEveryRowTheStopsAndTheEnd) {
  const Compilation compiled = Compile(Source::Text(kDrop), InTree());
  ASSERT_TRUE(compiled.ok()) << compiled.Render();
  CountingSink first;
  CountingSink second;
  second.fail = true;
  SimulateOptions options;
  options.stop_times = {0.0125, 0.03};
  int progress_calls = 0;
  options.progress = [&](double) { ++progress_calls; };
  const RunResult result = Simulate(compiled.model(), options, {&first, &second});
  ASSERT_FALSE(result.failed()) << DescribeFailure(compiled.model(), result.summary.failure);
  EXPECT_EQ(result.series.rows(), 51u);
  EXPECT_EQ(first.rows, 51);
  EXPECT_EQ(second.rows, 51);
  EXPECT_THAT(first.stops, ::testing::ElementsAre(0.0125, 0.03));
  EXPECT_EQ(first.ended_with_rows, 51u);
  EXPECT_EQ(progress_calls, 50);
  EXPECT_THAT(result.sink_errors, ::testing::ElementsAre("could not keep it"));
  EXPECT_THAT(result.series.names, ::testing::Contains(HasSubstr("ball.s.acceleration.z")));
}

TEST(Simulate, TheOutputFolderHoldsWhatSledRunWrites) {
  const Compilation compiled = Compile(Source::Text(kDrop), InTree());
  ASSERT_TRUE(compiled.ok()) << compiled.Render();
  testing::TempFolder out;
  ASSERT_FALSE(out.path().empty());
  OutputFolderOptions folder_options;
  folder_options.directory = out.path().string();
  OutputFolder folder(compiled.model(), folder_options);
  SimulateOptions options;
  options.stop_times = {0.02};
  const RunResult result = Simulate(compiled.model(), options, {&folder});
  EXPECT_THAT(result.sink_errors, IsEmpty());
  for (const char* file : {"timeseries.csv", "summary.json", "animation.glb"}) {
    EXPECT_TRUE(fs::exists(out.path() / file)) << file;
  }
  EXPECT_EQ(folder.dumps_written().size(), 1u);
  EXPECT_THAT(folder.dump_errors(), IsEmpty());
  // An output folder that is not there: OnEnd says which file it could not write.
  OutputFolderOptions missing;
  missing.directory = (out.path() / "not" / "there").string();
  OutputFolder nowhere(compiled.model(), missing);
  const RunResult lost = Simulate(compiled.model(), {}, {&nowhere});
  ASSERT_EQ(lost.sink_errors.size(), 1u);
  EXPECT_THAT(lost.sink_errors[0], HasSubstr("timeseries.csv"));
}

TEST(Simulate, CheckpointStepMustBeAMultipleOfTheOutputStep) {
  const Compilation compiled = Compile(Source::Text(kDrop), InTree());
  ASSERT_TRUE(compiled.ok()) << compiled.Render();
  EXPECT_EQ(CheckpointStepError(compiled.model(), 0.005), "");
  EXPECT_THAT(CheckpointStepError(compiled.model(), 0.0015), HasSubstr("not a multiple"));
  EXPECT_THAT(CheckpointStepError(compiled.model(), 0.0), HasSubstr("not a multiple"));
}

}  // namespace
}  // namespace sled
