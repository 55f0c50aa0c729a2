// `sled run` end to end: the exit status, the files it writes, and a numerical failure that
// stops the run with status 3, names the segment and its line, and keeps the outputs so far.
#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <fmt/format.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

fs::path SledBinary() {
  std::error_code error;
  const fs::path self = fs::read_symlink("/proc/self/exe", error);
  return (self.parent_path().parent_path() / "compiler" / "driver" / "sled").lexically_normal();
}

struct Outcome {
  int status = -1;
  std::string stderr_text;
};

Outcome RunSled(const std::string& arguments) {
  const fs::path log = fs::temp_directory_path() / "sled_run_command_test.log";
  const std::string command =
      fmt::format("'{}' {} 2>'{}'", SledBinary().string(), arguments, log.string());
  const int raw = std::system(command.c_str());
  Outcome outcome;
  outcome.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  std::ifstream in(log);
  std::stringstream text;
  text << in.rdbuf();
  outcome.stderr_text = text.str();
  return outcome;
}

std::string ReadAll(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(RunCommand, ThePendulumExampleRunsAndWritesItsOutputs) {
  const fs::path out = fs::temp_directory_path() / "sled_run_pendulum";
  fs::remove_all(out);
  const Outcome outcome = RunSled(
      fmt::format("run '{}/examples/pendulum.sled' -o '{}'", SLED_SOURCE_ROOT, out.string()));
  ASSERT_EQ(outcome.status, 0) << outcome.stderr_text;
  const std::string csv = ReadAll(out / "timeseries.csv");
  EXPECT_THAT(csv, HasSubstr("time [s],pendulum.lower.position.x [m]"));
  // 2 s at 1 ms: 2001 rows and the header.
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 2002);
  const std::string summary = ReadAll(out / "summary.json");
  EXPECT_THAT(summary, HasSubstr("\"status\": \"ok\""));
  EXPECT_THAT(summary, HasSubstr("\"method\": \"dopri5\""));
  EXPECT_THAT(summary, HasSubstr("\"rejected_steps\""));
  EXPECT_THAT(summary, HasSubstr("\"error_estimate\""));
  EXPECT_THAT(summary, HasSubstr("\"wall_time_seconds\""));
  fs::remove_all(out);
}

TEST(RunCommand, ANumericalFailureExitsWithThreeAndKeepsTheOutputs) {
  // A massless segment that nothing holds: its articulated inertia is singular.
  const fs::path dir = fs::temp_directory_path() / "sled_run_failure";
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "broken.sled") << R"(scenario "singular" {
  time { end = 10 ms  output_every = 1 ms }
  body b {
    segment heavy { mass = 1 kg  inertia = (1, 1, 1) kg*m^2 }
    segment ghost { mass = 0 kg  singular = true }
    joint j : ball(heavy -> ghost) { at heavy = (0, 0, 0) mm  at ghost = (0, 0, 0) mm }
  }
  output { position b.heavy }
}
)";
  const Outcome outcome = RunSled(
      fmt::format("run '{}' -o '{}'", (dir / "broken.sled").string(), (dir / "out").string()));
  EXPECT_EQ(outcome.status, 3) << outcome.stderr_text;
  EXPECT_THAT(outcome.stderr_text, HasSubstr("failed at t = 0"));
  EXPECT_THAT(outcome.stderr_text, HasSubstr("b.ghost"));
  EXPECT_THAT(outcome.stderr_text, HasSubstr("broken.sled:5:"));
  EXPECT_TRUE(fs::exists(dir / "out" / "timeseries.csv"));
  EXPECT_THAT(ReadAll(dir / "out" / "summary.json"), HasSubstr("\"status\": \"failed\""));
  fs::remove_all(dir);
}

TEST(RunCommand, InputErrorsExitWithOne) {
  const fs::path dir = fs::temp_directory_path() / "sled_run_input_error";
  fs::create_directories(dir);
  std::ofstream(dir / "bad.sled")
      << "scenario \"x\" { time { end = 1 kg  output_every = 1 ms } }\n";
  const Outcome outcome =
      RunSled(fmt::format("run '{}' -o '{}'", (dir / "bad.sled").string(), (dir / "out").string()));
  EXPECT_EQ(outcome.status, 1);
  EXPECT_THAT(outcome.stderr_text, HasSubstr("E0302"));
  fs::remove_all(dir);
}

}  // namespace
