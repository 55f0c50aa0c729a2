// `sled run` end to end: the exit status, the files it writes, and a numerical failure that
// stops the run with status 3, names the segment and its line, and keeps the outputs so far.
#include <algorithm>
#include <filesystem>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "tests/compiler/sled_process.h"
#include "tests/compiler/stiff_floor_scene.h"

namespace sled {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using testing::ReadText;
using testing::SledResult;
using testing::StiffFloor;
using testing::WriteText;

using RunCommand = testing::SledProcessTest;

TEST_F(RunCommand, ReportWritesThePageBesideTheOutputs) {
  // `--report` makes the page from the files the run just wrote, as `sled report DIR` does.
  const fs::path out = temp() / "out";
  const SledResult result = Sled({"run", "examples/pendulum.sled", "-o", out.string(), "--report"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const std::string page = ReadText(out / "report.html");
  EXPECT_THAT(page, HasSubstr("<svg"));
  EXPECT_THAT(page, HasSubstr("pendulum"));
}

TEST_F(RunCommand, ThePendulumExampleRunsAndWritesItsOutputs) {
  const fs::path out = temp() / "out";
  const SledResult result = Sled({"run", "examples/pendulum.sled", "-o", out.string()});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const std::string csv = ReadText(out / "timeseries.csv");
  EXPECT_THAT(csv, HasSubstr("time [s],pendulum.lower.position.x [m]"));
  // 2 s at 1 ms: 2001 rows and the header.
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 2002);
  const std::string summary = ReadText(out / "summary.json");
  EXPECT_THAT(summary, HasSubstr("\"status\": \"ok\""));
  EXPECT_THAT(summary, HasSubstr("\"method\": \"dopri5\""));
  EXPECT_THAT(summary, HasSubstr("\"rejected_steps\""));
  EXPECT_THAT(summary, HasSubstr("\"error_estimate\""));
  EXPECT_THAT(summary, HasSubstr("\"wall_time_seconds\""));
}

TEST_F(RunCommand, ARunThatStartsLateKeepsItsLastRow) {
  // 0.1 s at 1 ms from t = 1e6 s: end - start is 0.1 s less rounding (about 1.2e-10 s), which
  // must not lose the row at the end (it gave 100 rows, not 101).
  WriteText(temp() / "late.sled", R"(scenario "late start" {
  time { start = 1e6 s  end = 1000000.1 s  output_every = 1 ms }
  body ball {
    segment sphere { mass = 1 kg  inertia = (0.001, 0.001, 0.001) kg*m^2 }
  }
  output { position ball.sphere }
}
)");
  const fs::path out = temp() / "out";
  const SledResult result = Sled({"run", (temp() / "late.sled").string(), "-o", out.string()});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const std::string csv = ReadText(out / "timeseries.csv");
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 102);  // the header and 101 rows
}

TEST_F(RunCommand, TheFlagshipRunsWithFiniteOutputs) {
  // Whatever the runtime simulates yet (it notes what it leaves out), the flagship, with and
  // without its driver airbag, runs its 200 ms and every value it writes is a number.
  for (const char* example : {"examples/frontal_sled.sled", "examples/frontal_sled_airbag.sled"}) {
    SCOPED_TRACE(example);
    const fs::path out = temp() / "out";
    const SledResult result = Sled({"run", example, "-o", out.string()});
    ASSERT_EQ(result.exit_code, 0) << result.err;
    const std::string csv = ReadText(out / "timeseries.csv");
    EXPECT_THAT(csv, HasSubstr("occupant.head.acceleration.x [m/s^2]"));
    EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 2002);  // 200 ms at 0.1 ms
    for (const char* bad : {"nan", "inf"}) EXPECT_THAT(csv, ::testing::Not(HasSubstr(bad)));
    EXPECT_THAT(ReadText(out / "summary.json"), HasSubstr("\"status\": \"ok\""));
  }
}

TEST_F(RunCommand, ANumericalFailureExitsWithThreeAndKeepsTheOutputs) {
  // A massless segment that nothing holds: its articulated inertia is singular.
  WriteText(temp() / "broken.sled", R"(scenario "singular" {
  time { end = 10 ms  output_every = 1 ms }
  body b {
    segment heavy { mass = 1 kg  inertia = (1, 1, 1) kg*m^2 }
    segment ghost { mass = 0 kg  singular = true }
    joint j : ball(heavy -> ghost) { at heavy = (0, 0, 0) mm  at ghost = (0, 0, 0) mm }
  }
  output { position b.heavy }
}
)");
  const fs::path out = temp() / "out";
  const SledResult result = Sled({"run", (temp() / "broken.sled").string(), "-o", out.string()});
  EXPECT_EQ(result.exit_code, 3) << result.err;
  EXPECT_THAT(result.err, HasSubstr("failed at t = 0"));
  EXPECT_THAT(result.err, HasSubstr("b.ghost"));
  EXPECT_THAT(result.err, HasSubstr("broken.sled:5:"));
  EXPECT_TRUE(fs::exists(out / "timeseries.csv"));
  EXPECT_THAT(ReadText(out / "summary.json"), HasSubstr("\"status\": \"failed\""));
}

// A ball dropped 20 mm onto a floor whose contact stiffness is `stiffness`, with `integrator`.
TEST_F(RunCommand, AFailureAtTheMinimumStepNamesTheSegmentWhoseErrorIsLargest) {
  // A contact far too stiff for a 0.1 ms minimum step: the error test fails at first touch
  // (after 20 mm of free fall, t = 63.9 ms), and the state the error is in is the ball's.
  WriteText(temp() / "stiff.sled",
            StiffFloor("1e12 N/m", "integrator dopri5 { tolerance = 1e-6  min_step = 0.1 ms }"));
  const fs::path out = temp() / "out";
  const SledResult result = Sled({"run", (temp() / "stiff.sled").string(), "-o", out.string()});
  EXPECT_EQ(result.exit_code, 3) << result.err;
  EXPECT_THAT(result.err, HasSubstr("failed at t = 0.063"));
  EXPECT_THAT(result.err, HasSubstr("in `ball.sphere`: the error test failed at the minimum step"));
  EXPECT_THAT(result.err, HasSubstr("stiff.sled:6:"));
  const std::string csv = ReadText(out / "timeseries.csv");
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 65);  // the header and 0 to 63 ms
}

TEST_F(RunCommand, APowerThatOverflowsNamesTheSegment) {
  // A stiffness of 1e300 N/m: the contact force stays finite, its power does not.
  WriteText(temp() / "overflow.sled", StiffFloor("1e300 N/m", "integrator dopri5 {}"));
  const fs::path out = temp() / "out";
  const SledResult result = Sled({"run", (temp() / "overflow.sled").string(), "-o", out.string()});
  EXPECT_EQ(result.exit_code, 3) << result.err;
  EXPECT_THAT(result.err,
              HasSubstr("in `ball.sphere`: the power the forces deliver to it is not finite"));
  EXPECT_THAT(result.err, HasSubstr("overflow.sled:6:"));
  EXPECT_TRUE(fs::exists(out / "timeseries.csv"));
}

TEST_F(RunCommand, AFailureInAConstraintNamesItsLine) {
  // A spring whose damping of 1e300 N*s/m pulls a body along a sliding constraint: the
  // constraint forces that hold it overflow at the start.
  WriteText(temp() / "slider.sled", R"(scenario "slider" {
  time { end = 100 ms  output_every = 1 ms }
  body b { segment s { mass = 1 kg  inertia = (0.01, 0.01, 0.01) kg*m^2 } }
  spring k : b.s -> ground {
    at b.s = (0, 0, 0) mm
    at ground = (0, 0, 500) mm
    stiffness = 20 kN/m
    damping = 1e300 N*s/m
    free_length = 400 mm
  }
  constraint rail : sliding(ground -> b.s) {
    at ground = (0, 0, 0) mm
    at b.s = (0, 0, 0) mm
    axis = (0, 0, 1)
  }
  output { position b.s }
}
)");
  const fs::path out = temp() / "out";
  const SledResult result = Sled({"run", (temp() / "slider.sled").string(), "-o", out.string()});
  EXPECT_EQ(result.exit_code, 3) << result.err;
  EXPECT_THAT(result.err, HasSubstr("failed at t = 0 s in `rail`"));
  EXPECT_THAT(result.err, HasSubstr("slider.sled:11:"));
  EXPECT_TRUE(fs::exists(out / "timeseries.csv"));
}

TEST_F(RunCommand, InputErrorsExitWithOne) {
  WriteText(temp() / "bad.sled", "scenario \"x\" { time { end = 1 kg  output_every = 1 ms } }\n");
  const SledResult result =
      Sled({"run", (temp() / "bad.sled").string(), "-o", (temp() / "out").string()});
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_THAT(result.err, HasSubstr("E0302"));
}

}  // namespace
}  // namespace sled
