// Run-time faults, each with the exit status and the message it must give, and what must be on
// disk afterwards: a full disk (a small tmpfs) for the time series and for a checkpoint, a
// read-only folder, output paths that cannot be folders, SIGINT/SIGTERM/SIGHUP, two runs into
// one folder, an earlier run's leftovers, bad checkpoints, text and numbers that would break
// summary.json, and a run that fails numerically (its criteria are incomplete, never a pass).
//
// The tmpfs cases mount a file system (CI runs as root); where mounting is not permitted they
// are skipped with a message.
#include <signal.h>
#include <sys/mount.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <regex>
#include <string>
#include <thread>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/compiler/sled_process.h"
#include "tests/compiler/stiff_floor_scene.h"

namespace sled {
namespace {

namespace fs = std::filesystem;
using ::testing::ContainsRegex;
using ::testing::HasSubstr;
using ::testing::Not;
using testing::ReadText;
using testing::SledResult;
using testing::WriteText;

const fs::path kRoot = testing::kSourceRoot;
// The stiff floor fails at first touch with these settings (tests/compiler/stiff_floor_scene.h).
constexpr char kStiffSteps[] = "integrator dopri5 { tolerance = 1e-6  min_step = 0.1 ms }";

// The pendulum example with another end time: 2 s take about 0.03 s, 1000 s long enough to be
// interrupted.
std::string Pendulum(const std::string& end) {
  std::string text = ReadText(kRoot / "examples/pendulum.sled");
  const std::string time = "time { end = 2 s";
  text.replace(text.find(time), time.size(), "time { end = " + end);
  return text;
}

// Whether `text` parses as JSON.
bool ValidJson(const std::string& text) {
  return !nlohmann::json::parse(text, nullptr, false).is_discarded();
}

std::vector<std::string> Names(const fs::path& folder) {
  std::vector<std::string> names;
  std::error_code error;
  for (const auto& entry : fs::directory_iterator(folder, error)) {
    names.push_back(entry.path().filename().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

class RunFaults : public testing::SledProcessTest {
 protected:
  void TearDown() override {
    for (const fs::path& mount : mounts_) umount2(mount.c_str(), MNT_DETACH);
  }

  std::string Write(const std::string& name, const std::string& text) {
    const fs::path path = temp() / name;
    WriteText(path, text);
    return path.string();
  }
  std::string Out(const std::string& name) const { return (temp() / name).string(); }

  // A tmpfs of `size` at temp()/name, or the empty path when mounting is not permitted.
  fs::path Mount(const std::string& name, const std::string& options) {
    const fs::path path = temp() / name;
    fs::create_directories(path);
    if (mount("tmpfs", path.c_str(), "tmpfs", 0, options.c_str()) != 0) return {};
    mounts_.push_back(path);
    return path;
  }

  // Starts sled in the repository root with its output in `err_path`; returns its process id.
  pid_t Start(const std::vector<std::string>& args, const std::string& err_path) {
    const pid_t pid = fork();
    if (pid == 0) {
      if (chdir(kRoot.c_str()) != 0) _exit(127);
      FILE* err = std::freopen(err_path.c_str(), "w", stderr);
      FILE* out = std::freopen("/dev/null", "w", stdout);
      (void)err;
      (void)out;
      std::vector<std::string> words = {testing::SledBinary().string()};
      words.insert(words.end(), args.begin(), args.end());
      std::vector<char*> argv;
      for (std::string& word : words) argv.push_back(word.data());
      argv.push_back(nullptr);
      execv(argv[0], argv.data());
      _exit(127);
    }
    return pid;
  }

  // Waits until the run holds its folder (the folder exists and a row has been simulated: the
  // handlers are installed before the first row), at most 20 s.
  static void WaitUntilRunning(const fs::path& folder) {
    for (int i = 0; i < 2000 && !fs::exists(folder); ++i) {
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
  }

  static int ExitStatus(pid_t pid) {
    int status = 0;
    waitpid(pid, &status, 0);
    if (WIFSIGNALED(status)) return 1000 + WTERMSIG(status);  // killed: no handler
    return WEXITSTATUS(status);
  }

  // Interrupts a long run with `signal_number`; checks the exit status and what is on disk.
  void ExpectInterruptedBy(int signal_number, int exit_status, const std::string& name) {
    const std::string scene = Write("long.sled", Pendulum("1000 s"));
    const fs::path folder = Out("out");
    const std::string err = Out("err.txt");
    const pid_t pid = Start({"run", scene, "-o", folder.string()}, err);
    WaitUntilRunning(folder);
    ASSERT_EQ(kill(pid, signal_number), 0);
    EXPECT_EQ(ExitStatus(pid), exit_status) << ReadText(err);
    const std::string message = ReadText(err);
    EXPECT_THAT(message, HasSubstr("sled: interrupted by " + name + " at t = "));
    EXPECT_THAT(message, HasSubstr("(status \"interrupted\")"));
    const std::string summary = ReadText(folder / "summary.json");
    ASSERT_TRUE(ValidJson(summary)) << summary;
    const auto json = nlohmann::json::parse(summary);
    EXPECT_EQ(json["status"], "interrupted");
    EXPECT_EQ(json["interrupted"]["signal"], name);
    const double reached = json["stopped_at"];
    EXPECT_GT(reached, 0.0);
    EXPECT_LT(reached, 1000.0);
    // Every row up to the time reached, each complete.
    const std::string csv = ReadText(folder / "timeseries.csv");
    const long rows = std::count(csv.begin(), csv.end(), '\n') - 1;
    EXPECT_EQ(rows, json["rows"].get<long>());
    EXPECT_EQ(rows, std::lround(reached / 0.001) + 1);
    EXPECT_EQ(csv.back(), '\n');
  }

 private:
  std::vector<fs::path> mounts_;
};

#define SKIP_WITHOUT(mount) \
  if ((mount).empty()) GTEST_SKIP() << "mounting a tmpfs is not permitted here (not root?)"

TEST_F(RunFaults, AFullDiskForTheTimeSeriesNamesTheFileAndItsCause) {
  const fs::path disk = Mount("small", "size=64k");
  SKIP_WITHOUT(disk);
  const fs::path folder = disk / "out";
  const SledResult result = Sled({"run", Write("p.sled", Pendulum("2 s")), "-o", folder.string()});
  EXPECT_EQ(result.exit_code, 1) << result.err;
  EXPECT_THAT(result.err, HasSubstr("cannot write `" + (folder / "timeseries.csv").string() +
                                    "`: No space left on device"));
  EXPECT_THAT(result.err, HasSubstr("could not be written"));
  // No partial file under the name, no temporary left behind.
  EXPECT_FALSE(fs::exists(folder / "timeseries.csv"));
  for (const std::string& name : Names(folder))
    EXPECT_EQ(name.find(".sled-tmp"), std::string::npos);
  // summary.json (small) says what is missing.
  if (fs::exists(folder / "summary.json")) {
    const std::string summary = ReadText(folder / "summary.json");
    ASSERT_TRUE(ValidJson(summary)) << summary;
    EXPECT_THAT(summary, HasSubstr("timeseries.csv`: No space left on device"));
  }
}

TEST_F(RunFaults, AFullDiskForACheckpointStopsTheRunAndLeavesNoTruncatedCheckpoint) {
  const fs::path disk = Mount("small", "size=64k");
  SKIP_WITHOUT(disk);
  const fs::path folder = disk / "out";
  const SledResult result = Sled(
      {"run", Write("p.sled", Pendulum("2 s")), "-o", folder.string(), "--checkpoint-every", "1s"});
  EXPECT_EQ(result.exit_code, 1) << result.err;
  EXPECT_THAT(result.err,
              HasSubstr("cannot write `" + (folder / "checkpoint_1.000000s.bin").string() +
                        "`: No space left on device"));
  // Checkpoints are taken at the end of the first step past their time, with the rows so far.
  EXPECT_THAT(result.err, ContainsRegex("the run stopped at t = 1(\\.0[0-9]*)? s: an output "
                                        "could not be written"));
  EXPECT_FALSE(fs::exists(folder / "checkpoint_1.000000s.bin"));
  for (const std::string& name : Names(folder))
    EXPECT_EQ(name.find(".sled-tmp"), std::string::npos);
}

TEST_F(RunFaults, AReadOnlyFolderIsRefusedBeforeSimulating) {
  const fs::path disk = Mount("readonly", "size=64k");
  SKIP_WITHOUT(disk);
  fs::create_directories(disk / "out");
  ASSERT_EQ(mount("tmpfs", disk.c_str(), "tmpfs", MS_REMOUNT | MS_RDONLY, "size=64k"), 0);
  const SledResult result =
      Sled({"run", Write("long.sled", Pendulum("1000 s")), "-o", (disk / "out").string()});
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_THAT(result.err, HasSubstr("cannot write into the output folder `" +
                                    (disk / "out").string() + "`: Read-only file system"));
  EXPECT_THAT(result.err, Not(HasSubstr("rows")));  // nothing was simulated
}

TEST_F(RunFaults, AnOutputPathThatCannotBeAFolderIsRefusedBeforeSimulating) {
  const std::string scene = Write("long.sled", Pendulum("1000 s"));
  const std::string file = Write("file.txt", "a file");
  SledResult result = Sled({"run", scene, "-o", file});
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_THAT(result.err,
              HasSubstr("cannot write into `" + file + "`: it is a file, not a folder"));
  result = Sled({"run", scene, "-o", file + "/out"});
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_THAT(result.err,
              HasSubstr("cannot create the output folder `" + file + "/out`: Not a directory"));
  result = Sled({"run", scene, "-o", "/proc/sled-out"});
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_THAT(result.err, HasSubstr("cannot create the output folder `/proc/sled-out`"));
}

TEST_F(RunFaults, SigintWritesTheRowsSoFarAndExits130) {
  ExpectInterruptedBy(SIGINT, 130, "SIGINT");
}

TEST_F(RunFaults, SigtermWritesTheRowsSoFarAndExits143) {
  ExpectInterruptedBy(SIGTERM, 143, "SIGTERM");
}

TEST_F(RunFaults, SighupWritesTheRowsSoFarAndExits129) {
  ExpectInterruptedBy(SIGHUP, 129, "SIGHUP");
}

TEST_F(RunFaults, TheCriteriaOfAnInterruptedRunAreIncomplete) {
  // The flagship cut to 2 s of simulated time runs long enough to be interrupted.
  std::string text = ReadText(kRoot / "examples/frontal_sled.sled");
  const std::string time = "time { end = 200 ms";
  text.replace(text.find(time), time.size(), "time { end = 2000 ms");
  const std::string scene = Write("flagship.sled", text);
  const fs::path folder = Out("out");
  const std::string err = Out("err.txt");
  const pid_t pid = Start({"run", scene, "-o", folder.string()}, err);
  WaitUntilRunning(folder);
  kill(pid, SIGINT);
  const int status = ExitStatus(pid);
  ASSERT_EQ(status, 130) << ReadText(err);
  const auto json = nlohmann::json::parse(ReadText(folder / "summary.json"));
  ASSERT_FALSE(json["criteria"].empty());
  for (const auto& criterion : json["criteria"]) {
    if (criterion["value"].is_null()) continue;
    EXPECT_EQ(criterion["verdict"], "incomplete");
    EXPECT_TRUE(criterion["pass"].is_null());
  }
  EXPECT_THAT(ReadText(err), Not(HasSubstr(": pass")));
}

TEST_F(RunFaults, ASecondRunIntoTheSameFolderIsRefusedWhileTheFirstRuns) {
  const std::string scene = Write("long.sled", Pendulum("1000 s"));
  const fs::path folder = Out("out");
  const std::string err = Out("err.txt");
  const pid_t first = Start({"run", scene, "-o", folder.string()}, err);
  WaitUntilRunning(folder);
  const SledResult second = Sled({"run", Write("p.sled", Pendulum("2 s")), "-o", folder.string()});
  EXPECT_EQ(second.exit_code, 1);
  EXPECT_THAT(second.err, HasSubstr("is in use by another sled run"));
  kill(first, SIGINT);
  EXPECT_EQ(ExitStatus(first), 130);
  // The first run's rows are its own: times one output step apart from 0.
  const std::string csv = ReadText(folder / "timeseries.csv");
  EXPECT_TRUE(csv.starts_with("time [s],"));
  const long rows = std::count(csv.begin(), csv.end(), '\n') - 1;
  const auto json = nlohmann::json::parse(ReadText(folder / "summary.json"));
  EXPECT_EQ(rows, std::lround(json["stopped_at"].get<double>() / 0.001) + 1);
  // Once it is done, the folder is free again.
  EXPECT_EQ(Sled({"run", Write("p.sled", Pendulum("2 s")), "-o", folder.string()}).exit_code, 0);
}

TEST_F(RunFaults, AnEarlierRunsLeftoversAreRemovedAndNamed) {
  const std::string scene = Write("p.sled", Pendulum("2 s"));
  const fs::path folder = Out("out");
  ASSERT_EQ(Sled({"run", scene, "-o", folder.string(), "--report", "--format", "iso-mme",
                  "--dump-at", "0.5", "--checkpoint-every", "1s"})
                .exit_code,
            0);
  WriteText(folder / "timeseries_filtered.csv", "time [s],x\n0,1\n");  // as an older scene wrote
  WriteText(folder / "notes.txt", "the engineer's own notes");
  WriteText(folder / ".timeseries.csv.sled-tmp-99999", "a killed run's temporary file");
  const SledResult again = Sled({"run", scene, "-o", folder.string()});
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_THAT(again.err, HasSubstr("removed what an earlier run wrote in `" + folder.string() +
                                   "` and this one does not: checkpoint_1.000000s.bin, "
                                   "dump_0.5.txt, iso-mme/, report.html, "
                                   "timeseries_filtered.csv"));
  EXPECT_EQ(Names(folder), (std::vector<std::string>{"animation.glb", "notes.txt", "summary.json",
                                                     "timeseries.csv"}));
}

TEST_F(RunFaults, ResumingIntoTheCheckpointsOwnFolderKeepsTheCheckpoint) {
  const std::string scene = Write("p.sled", Pendulum("2 s"));
  const fs::path folder = Out("out");
  ASSERT_EQ(Sled({"run", scene, "-o", folder.string(), "--checkpoint-every", "1s"}).exit_code, 0);
  const std::string full = ReadText(folder / "timeseries.csv");
  const SledResult resumed = Sled({"run", scene, "-o", folder.string(), "--resume",
                                   (folder / "checkpoint_1.000000s.bin").string()});
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_TRUE(fs::exists(folder / "checkpoint_1.000000s.bin"));
  EXPECT_EQ(ReadText(folder / "timeseries.csv"), full);
}

TEST_F(RunFaults, BadCheckpointsAreRefusedWithTheReason) {
  const std::string scene = Write("p.sled", Pendulum("2 s"));
  ASSERT_EQ(Sled({"run", scene, "-o", Out("full"), "--checkpoint-every", "1s"}).exit_code, 0);
  const std::string good = ReadText(fs::path(Out("full")) / "checkpoint_1.000000s.bin");
  const std::string cut = Write("cut.bin", good.substr(0, good.size() / 2));
  const std::string empty = Write("empty.bin", "");
  const std::string text = Write("text.bin", "time [s],x\n0,1\n");
  std::string flipped_bytes = good;
  flipped_bytes[flipped_bytes.size() / 3] ^= 0x20;
  const std::string flipped = Write("flipped.bin", flipped_bytes);
  std::string other_text = Pendulum("2 s");
  other_text.replace(other_text.find("1.23 kg"), 7, "1.30 kg");  // another pendulum
  const std::string other = Write("other.sled", other_text);
  struct Case {
    std::vector<std::string> args;
    std::string message;
  };
  const std::vector<Case> cases = {
      {{"run", scene, "--resume", "/dev/zero"},
       "`/dev/zero` is not a checkpoint: it is not a regular file"},
      {{"run", scene, "--resume", temp().string()}, "is not a checkpoint: it is a folder"},
      {{"run", scene, "--resume", Out("missing.bin")}, "No such file or directory"},
      {{"run", scene, "--resume", empty}, "is not a sled checkpoint"},
      {{"run", scene, "--resume", text}, "is not a sled checkpoint"},
      {{"run", scene, "--resume", cut}, "truncated or damaged"},
      {{"run", scene, "--resume", flipped}, "truncated or damaged"},
      {{"run", other, "--resume", Out("full") + "/checkpoint_1.000000s.bin"},
       "is not the one the checkpoint was made from"},
  };
  for (const Case& c : cases) {
    std::vector<std::string> args = c.args;
    args.insert(args.end(), {"-o", Out("resumed")});
    const SledResult result = Sled(args);
    EXPECT_EQ(result.exit_code, 1) << c.args.back();
    EXPECT_THAT(result.err, HasSubstr(c.message)) << c.args.back();
    EXPECT_THAT(result.err, HasSubstr("cannot resume from")) << c.args.back();
  }
}

TEST_F(RunFaults, AnOverflowingStateGivesValidJsonWithNullAndANote) {
  const std::string scene = Write("far.sled", R"(scenario "far" {
  time { end = 10 ms  output_every = 1 ms }
  body b { segment s { mass = 1 kg  inertia = (1, 1, 1) kg*m^2 } }
  initial b { position = (0, 0, 0) m  velocity = (1e200, 0, 0) m/s }
  output { position b.s at (0, 0, 0) mm }
}
)");
  // Its kinetic energy overflows to inf, and the energy residual to nan.
  const SledResult result = Sled({"run", scene, "-o", Out("out")});
  const std::string summary = ReadText(fs::path(Out("out")) / "summary.json");
  ASSERT_TRUE(ValidJson(summary)) << summary;
  EXPECT_THAT(summary, HasSubstr("\"kinetic\": null"));
  EXPECT_THAT(summary, HasSubstr("`energy_balance.kinetic` was not finite (inf)"));
  EXPECT_THAT(summary, HasSubstr("and is written as null"));
}

TEST_F(RunFaults, ATitleThatIsNotUtf8IsRefusedBeforeItCanBreakTheJson) {
  const std::string scene = Write("latin1.sled",
                                  "scenario \"caf\xe9\" {\n"
                                  "  time { end = 10 ms  output_every = 1 ms }\n}\n");
  const SledResult result = Sled({"run", scene, "-o", Out("out"), "--diagnostics=compact"});
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_THAT(result.err, HasSubstr("error[E0105]: byte 0xE9 is not UTF-8"));
  EXPECT_FALSE(fs::exists(Out("out")));
}

TEST_F(RunFaults, AFolderNamedWithBytesThatAreNotUtf8StillGetsValidJson) {
  // File names are bytes on Linux; the failure's source line names the scene's path.
  const std::string scene = Write("stiff\xff.sled", testing::StiffFloor("1e12 N/m", kStiffSteps));
  const SledResult result = Sled({"run", scene, "-o", Out("out")});
  ASSERT_EQ(result.exit_code, 3) << result.err;
  const std::string summary = ReadText(fs::path(Out("out")) / "summary.json");
  EXPECT_TRUE(ValidJson(summary)) << summary;
  EXPECT_THAT(summary, HasSubstr("stiff\\ufffd.sled"));
}

TEST_F(RunFaults, ANumericalFailureGivesIncompleteCriteriaNeverAPass) {
  // Rows every 0.1 ms, as the head criteria's CFC 1000 needs.
  std::string text =
      testing::StiffFloor("1e12 N/m", kStiffSteps,
                          "acceleration ball.sphere at (0, 0, 0) mm\n"
                          "    criteria = hic15(ball.sphere), head_3ms(ball.sphere)");
  text.replace(text.find("output_every = 1 ms"), 19, "output_every = 0.1 ms");
  const std::string scene = Write("stiff.sled", text);
  const fs::path folder = Out("out");
  const SledResult result = Sled({"run", scene, "-o", folder.string(), "--report"});
  ASSERT_EQ(result.exit_code, 3) << result.err;
  EXPECT_THAT(result.err, HasSubstr("sled: the simulation failed at t = "));
  EXPECT_THAT(result.err, HasSubstr("hic15(ball.sphere) = "));
  EXPECT_THAT(result.err, HasSubstr("incomplete: over 0 ms to "));
  EXPECT_THAT(result.err, Not(HasSubstr(": pass")));
  const auto json = nlohmann::json::parse(ReadText(folder / "summary.json"));
  EXPECT_EQ(json["status"], "failed");
  for (const auto& criterion : json["criteria"]) {
    EXPECT_EQ(criterion["verdict"], "incomplete");
    EXPECT_TRUE(criterion["pass"].is_null());
    EXPECT_EQ(criterion["seen_until"], json["stopped_at"]);
  }
  const std::string page = ReadText(folder / "report.html");
  EXPECT_THAT(page, Not(HasSubstr("criteria within limits")));
  EXPECT_THAT(page, HasSubstr("criteria incomplete"));
}

TEST_F(RunFaults, AReportOf200000ColumnsTakesLinearTime) {
  // 200,000 channels of three rows: the reader was quadratic in the columns (past 20 s).
  const fs::path folder = Out("wide");
  fs::create_directories(folder);
  std::string header = "time [s]";
  std::string row;
  for (int c = 0; c < 200000; ++c) {
    header += ",b.s" + std::to_string(c) + ".position.x [m]";
    row += ",0.5";
  }
  WriteText(folder / "timeseries.csv",
            header + "\n0" + row + "\n0.001" + row + "\n0.002" + row + "\n");
  WriteText(folder / "summary.json",
            R"({"scenario": "wide", "status": "ok", "start_time": 0, "end_time": 0.002,
                "stopped_at": 0.002, "output_every": 0.001, "rows": 3, "channels": 200000,
                "criteria": [], "warnings": []})");
  const auto start = std::chrono::steady_clock::now();
  const SledResult result = Sled({"report", folder.string()});
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(result.exit_code, 0) << result.err;
  // Not a timing test: linear time is well under a second here, quadratic far past a minute.
  EXPECT_LT(seconds, 60.0);
}

}  // namespace
}  // namespace sled
