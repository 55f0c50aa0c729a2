// `sled run --dump-at T,...` writes the complete state at each time, read from the dense output: a
// ball in free fall (no drag) is where the parabola puts it at times between the output rows, and
// the rows are those of a run without dumps;
// the flagship's printout lists every kind of force element, and its joint torque at an output
// time is the one timeseries.csv holds. Bad option values are usage errors (exit 2).
#include <cmath>
#include <filesystem>
#include <regex>
#include <string>

#include <fmt/format.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "tests/compiler/csv_table.h"
#include "tests/compiler/flagship_scene.h"
#include "tests/compiler/sled_process.h"

namespace sled {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using testing::ReadText;
using testing::SledResult;
using testing::WriteText;

using DumpAt = testing::SledProcessTest;

constexpr const char* kFreeFall = R"(scenario "free fall" {
  gravity = (0, 0, -9.81) m/s^2
  time { end = 50 ms  output_every = 10 ms }
  body ball {
    segment core { mass = 1 kg  inertia = (0.01, 0.01, 0.01) kg*m^2 }
  }
  initial ball { position = (0, 0, 1) m  velocity = (2, 0, 3) m/s }
  output { position ball.core at (0, 0, 0) mm }
}
)";

// The three numbers after `label` ... `= (` in a printout section.
std::vector<double> Triple(const std::string& text, const std::string& label) {
  std::smatch match;
  const std::regex pattern(label + R"([^\n]*= \(([-0-9.e+]+), ([-0-9.e+]+), ([-0-9.e+]+)\))");
  if (!std::regex_search(text, match, pattern)) return {};
  return {std::stod(match[1]), std::stod(match[2]), std::stod(match[3])};
}

TEST_F(DumpAt, TheFreeFallIsPrintedExactlyAtTimesBetweenTheRows) {
  WriteText(temp() / "fall.sled", kFreeFall);
  const fs::path out = temp() / "out";
  const SledResult result = Sled(
      {"run", (temp() / "fall.sled").string(), "-o", out.string(), "--dump-at", "0.0123,20ms,0"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  for (const double t : {0.0, 0.0123, 0.02}) {
    const fs::path file = out / fmt::format("dump_{}.txt", t);
    ASSERT_TRUE(fs::exists(file)) << file;
    const std::string dump = ReadText(file);
    EXPECT_THAT(dump, HasSubstr(fmt::format("complete state at t = {} s", t)));
    const std::string segment = dump.substr(dump.find("== segments"));
    const std::vector<double> p = Triple(segment, "position");
    const std::vector<double> v = Triple(segment, "velocity");
    const std::vector<double> a = Triple(segment, "acceleration");
    ASSERT_EQ(p.size(), 3u) << dump;
    EXPECT_NEAR(p[0], 2 * t, 1e-8);
    EXPECT_NEAR(p[1], 0.0, 1e-12);
    EXPECT_NEAR(p[2], 1 + 3 * t - 0.5 * 9.81 * t * t, 1e-8);
    EXPECT_NEAR(v[0], 2.0, 1e-8);
    EXPECT_NEAR(v[2], 3 - 9.81 * t, 1e-8);
    EXPECT_NEAR(a[2], -9.81, 1e-8);
    EXPECT_THAT(dump, HasSubstr("== generalized coordinates: nq = 7, nv = 6"));
  }
  // The rows stay where they were: a dump adds no row and no step.
  EXPECT_EQ(testing::ReadCsv(out / "timeseries.csv").rows.size(), 6u);
  const fs::path plain = temp() / "plain";
  ASSERT_EQ(Sled({"run", (temp() / "fall.sled").string(), "-o", plain.string()}).exit_code, 0);
  EXPECT_EQ(ReadText(out / "timeseries.csv"), ReadText(plain / "timeseries.csv"));
}

TEST_F(DumpAt, TheFlagshipPrintoutHoldsEveryForceElement) {
  WriteText(temp() / "flagship.sled", testing::FlagshipScene("10 ms"));
  const fs::path out = temp() / "out";
  const SledResult result =
      Sled({"run", (temp() / "flagship.sled").string(), "-o", out.string(), "--dump-at", "8ms"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const std::string dump = ReadText(out / "dump_0.008.txt");
  for (const char* section :
       {"== generalized coordinates", "== vehicles", "== segments", "== joints", "== contacts",
        "== belts", "occupant.neck_upper (", "occupant.pelvis with", "three_point.lap",
        "span 1: tension", "force on the first anchor", "flexure, twist"}) {
    EXPECT_THAT(dump, HasSubstr(section));
  }
  // The neck torque at 8 ms (an output row) is timeseries.csv's.
  const testing::CsvTable csv = testing::ReadCsv(out / "timeseries.csv");
  const std::size_t column = csv.Column("occupant.neck_upper.joint_torque.x [N*m]");
  ASSERT_LT(column, csv.names.size());
  const std::string joint = dump.substr(dump.find("occupant.neck_upper ("));
  const std::vector<double> torque = Triple(joint, "torque");
  ASSERT_EQ(torque.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_NEAR(torque[i], csv.rows[80][column + i], 1e-6 * (1 + std::abs(torque[i])));
  }
}

TEST_F(DumpAt, BadOptionValuesAreUsageErrors) {
  WriteText(temp() / "fall.sled", kFreeFall);
  const std::string file = (temp() / "fall.sled").string();
  const std::string out = (temp() / "out").string();
  struct Case {
    std::vector<std::string> args;
    const char* message;
  };
  const Case cases[] = {
      {{"--dump-at", "soon"}, "`soon` is not a time"},
      {{"--dump-at", "0.01,-1"}, "`-1` is not a time"},
      {{"--dump-at", "3 h"}, "`3 h` is not a time"},
      {{"--dump-at", "0.2"}, "0.2 s is outside the run, which goes from 0 s to 0.05 s"},
      {{"--dump-at"}, "`--dump-at` needs a value"},
      {{"--format", "xml"}, "unknown format `xml`; write csv or iso-mme"},
  };
  for (const Case& c : cases) {
    std::vector<std::string> args = {"run", file, "-o", out};
    args.insert(args.end(), c.args.begin(), c.args.end());
    const SledResult result = Sled(args);
    EXPECT_EQ(result.exit_code, 2) << c.message;
    EXPECT_THAT(result.err, HasSubstr(c.message));
  }
}

}  // namespace
}  // namespace sled
