// `sled sweep` end to end on a small scene: a ball dropped on a floor whose stiffness the design
// varies, one value too stiff for the integrator's minimum step (that run fails numerically and
// is recorded, not fatal). Runs are compared byte for byte across worker counts and against
// `sled run` itself; resuming runs only what did not finish.
#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "tests/compiler/csv_table.h"
#include "tests/compiler/sled_process.h"
#include "tests/compiler/stiff_floor_scene.h"

namespace sled {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using testing::ReadText;
using testing::SledResult;
using testing::WriteText;

class SweepCommand : public testing::SledProcessTest {
 protected:
  // The stiff-floor scene with its stiffness a `param`.
  fs::path Scene() {
    const fs::path path = temp() / "floor.sled";
    WriteText(path,
              testing::StiffFloor("stiffness",
                                  "integrator dopri5 { tolerance = tolerance  min_step = 0.1 ms }\n"
                                  "  param stiffness = 1e5 N/m\n  param tolerance = 1e-6"));
    return path;
  }
  SledResult Sweep(const fs::path& out, std::vector<std::string> extra) {
    std::vector<std::string> args = {"sweep", Scene().string(), "-o", out.string()};
    args.insert(args.end(), extra.begin(), extra.end());
    return Sled(args);
  }
};

const std::vector<std::string> kDesign = {"--vary", "stiffness=1e4,1e5,1e12 N/m"};

TEST_F(SweepCommand, RecordsEveryRunAndAFailureIsNotFatal) {
  const fs::path out = temp() / "sweep";
  std::vector<std::string> args = kDesign;
  args.insert(args.end(), {"--jobs", "2"});
  const SledResult result = Sweep(out, args);
  EXPECT_EQ(result.exit_code, 3) << result.err;  // one run failed
  const std::string csv = ReadText(out / "sweep.csv");
  EXPECT_THAT(csv, HasSubstr("run,folder,stiffness [N/m],status"));
  EXPECT_THAT(csv, HasSubstr("0,runs/0000,10000,done,0,"));
  EXPECT_THAT(csv, HasSubstr("1,runs/0001,100000,done,0,"));
  EXPECT_THAT(csv, HasSubstr("2,runs/0002,1000000000000,failed,3,"));
  EXPECT_THAT(csv, HasSubstr("peak ball.sphere.position.z [m]"));
  EXPECT_THAT(ReadText(out / "sweep.html"), HasSubstr("<svg"));
  EXPECT_TRUE(fs::exists(out / "runs/0002/timeseries.csv"));  // kept up to the failure
  EXPECT_THAT(ReadText(out / "runs/0002/run.log"), HasSubstr("failed"));
}

TEST_F(SweepCommand, RunsAreBitIdenticalWhateverTheWorkerCountAndToSledRun) {
  const fs::path serial = temp() / "serial";
  const fs::path parallel = temp() / "parallel";
  std::vector<std::string> args = {"--vary", "stiffness=1e4..1e5 N/m count 4", "--jobs"};
  Sweep(serial, [&] {
    auto a = args;
    a.push_back("1");
    return a;
  }());
  Sweep(parallel, [&] {
    auto a = args;
    a.push_back("2");
    return a;
  }());
  for (const char* run : {"runs/0000", "runs/0001", "runs/0002", "runs/0003"}) {
    const std::string a = ReadText(serial / run / "timeseries.csv");
    ASSERT_FALSE(a.empty()) << run;
    EXPECT_EQ(a, ReadText(parallel / run / "timeseries.csv")) << run;
  }
  const SledResult alone = Sled(
      {"run", Scene().string(), "-o", (temp() / "alone").string(), "--set", "stiffness=70000 N/m"});
  ASSERT_EQ(alone.exit_code, 0) << alone.err;
  EXPECT_EQ(ReadText(temp() / "alone/timeseries.csv"),
            ReadText(serial / "runs/0002/timeseries.csv"));
}

TEST_F(SweepCommand, AResumedSweepRunsOnlyWhatDidNotFinish) {
  const fs::path out = temp() / "sweep";
  ASSERT_EQ(Sweep(out, {"--vary", "stiffness=1e4,2e4,3e4 N/m"}).exit_code, 0);
  // Run 1 as an interrupted sweep leaves it: no status. Run 0 is marked to see it is kept.
  fs::remove(out / "runs/0001/status.json");
  WriteText(out / "runs/0000/run.log", "kept\n");
  const SledResult resumed = Sweep(out, {"--vary", "stiffness=1e4,2e4,3e4 N/m"});
  EXPECT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_THAT(resumed.err, HasSubstr("resuming"));
  EXPECT_THAT(resumed.err, HasSubstr("[3/3] runs/0001 done"));
  EXPECT_EQ(ReadText(out / "runs/0000/run.log"), "kept\n");
  EXPECT_TRUE(fs::exists(out / "runs/0001/status.json"));
  // `resume DIR` reads the design from the folder.
  fs::remove(out / "runs/0002/status.json");
  const SledResult again = Sled({"sweep", "resume", out.string()});
  EXPECT_EQ(again.exit_code, 0) << again.err;
  EXPECT_THAT(again.err, HasSubstr("runs/0002 done"));
}

TEST_F(SweepCommand, AnInterruptedSweepKeepsWhatFinishedAndResumes) {
  // Four flagship runs of 200 ms, one at a time; SIGTERM once the first has finished.
  const fs::path out = temp() / "sweep";
  const std::vector<std::string> args = {
      testing::SledBinary().string(),
      "sweep",
      (testing::kSourceRoot / "examples/frontal_sled.sled").string(),
      "-o",
      out.string(),
      "--vary",
      "speed=40..64 km/h step 8",
      "--jobs",
      "1"};
  const pid_t pid = fork();
  if (pid == 0) {
    const int null = open("/dev/null", O_WRONLY);
    dup2(null, STDERR_FILENO);
    std::vector<char*> argv;
    for (const std::string& arg : args) argv.push_back(const_cast<char*>(arg.c_str()));
    argv.push_back(nullptr);
    execv(argv[0], argv.data());
    _exit(127);
  }
  ASSERT_GT(pid, 0);
  for (int i = 0; i < 6000 && !fs::exists(out / "runs/0000/status.json"); ++i) usleep(5000);
  kill(pid, SIGTERM);
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 130);
  EXPECT_TRUE(fs::exists(out / "runs/0000/status.json"));
  EXPECT_FALSE(fs::exists(out / "runs/0003/status.json"));
  EXPECT_THAT(ReadText(out / "sweep.csv"), HasSubstr("not run"));
  const SledResult resumed = Sled({"sweep", "resume", out.string()});
  EXPECT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_THAT(resumed.err, ::testing::Not(HasSubstr("runs/0000 done")));
  EXPECT_THAT(resumed.err, HasSubstr("runs/0003 done"));
}

TEST_F(SweepCommand, AnotherDesignOrAChangedSceneIsNotMixedIn) {
  const fs::path out = temp() / "sweep";
  ASSERT_EQ(Sweep(out, {"--vary", "stiffness=1e4,2e4 N/m"}).exit_code, 0);
  SledResult other = Sweep(out, {"--vary", "stiffness=1e4,5e4 N/m"});
  EXPECT_EQ(other.exit_code, 1);
  EXPECT_THAT(other.err, HasSubstr("--restart"));
  other = Sweep(out, {"--vary", "stiffness=1e4,5e4 N/m", "--restart"});
  EXPECT_EQ(other.exit_code, 0) << other.err;
  WriteText(temp() / "floor.sled", ReadText(temp() / "floor.sled") + "// changed\n");
  const SledResult changed = Sled({"sweep", "resume", out.string()});
  EXPECT_EQ(changed.exit_code, 1);
  EXPECT_THAT(changed.err, HasSubstr("changed since"));
  // A folder of something else is never written into.
  fs::create_directories(temp() / "mine");
  WriteText(temp() / "mine/notes.txt", "mine");
  EXPECT_EQ(Sweep(temp() / "mine", {"--vary", "stiffness=1e4 N/m"}).exit_code, 1);
}

TEST_F(SweepCommand, BadDesignsAreErrorsBeforeAnyRun) {
  const fs::path out = temp() / "sweep";
  SledResult result = Sweep(out, {"--vary", "stiffness=1..3 kg", "--diagnostics=compact"});
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_THAT(result.err, HasSubstr("--vary:1:16: error[E0603]"));
  EXPECT_FALSE(fs::exists(out));
  // A value the scene refuses (a negative tolerance) is found at check time, run by run.
  result = Sweep(out, {"--vary", "tolerance=-1e-6,1e-6", "--diagnostics=compact"});
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_THAT(result.err, HasSubstr("does not check at run 0"));
  EXPECT_FALSE(fs::exists(out));
  // Checked over two workers, the points are counted and the first that fails is the one shown.
  result = Sweep(
      out, {"--vary", "tolerance=1e-6,-1e-6,-2e-6,1e-5", "--jobs", "2", "--diagnostics=compact"});
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_THAT(result.err, HasSubstr("does not check at run 1 of the design (tolerance = -1e-06)"));
  EXPECT_THAT(result.err, HasSubstr("2 of 4 runs of the design do not check"));
  EXPECT_FALSE(fs::exists(out));
  result = Sled({"sweep", Scene().string()});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_THAT(result.err, HasSubstr("needs a design"));
}

TEST_F(SweepCommand, CheckPrintsTheDesignAndSamplingIsReproducible) {
  const fs::path out = temp() / "sweep";
  SledResult lhs = Sweep(
      out, {"--vary", "stiffness=1e4..1e5 N/m", "--sample", "lhs=5", "--seed", "3", "--check"});
  EXPECT_EQ(lhs.exit_code, 0) << lhs.err;
  EXPECT_EQ(std::count(lhs.out.begin(), lhs.out.end(), '\n'), 6);
  EXPECT_EQ(Sweep(out, {"--vary", "stiffness=1e4..1e5 N/m", "--sample", "lhs=5", "--seed", "3",
                        "--check"})
                .out,
            lhs.out);
  EXPECT_FALSE(fs::exists(out));
}

TEST_F(SweepCommand, RunsADesignFromACsvFile) {
  WriteText(temp() / "points.csv", "# stiffness only\nstiffness [kN/m]\n10\n20\n");
  const fs::path out = temp() / "sweep";
  const SledResult result = Sweep(out, {"--design", (temp() / "points.csv").string()});
  EXPECT_EQ(result.exit_code, 0) << result.err;
  EXPECT_THAT(ReadText(out / "sweep.csv"), HasSubstr("1,runs/0001,20,done"));
  EXPECT_THAT(ReadText(out / "runs/0001/run.log"), ::testing::Not(HasSubstr("error")));
}

}  // namespace
}  // namespace sled
