// The `sled` command-line program (README.md, The `sled` command): exit codes, where diagnostics
// go, `explain`, `fmt --check` and `--set`. Runs the built binary, whose path CMake gives
// (tests/compiler/sled_process.h).
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "lang/diagnostics/diagnostic.h"
#include "tests/compiler/sled_process.h"

namespace sled {
namespace {

namespace fs = std::filesystem;

using testing::ReadText;
using testing::SledResult;
using testing::WriteText;

const fs::path kRoot = testing::kSourceRoot;

using DriverTest = testing::SledProcessTest;

TEST_F(DriverTest, CheckOfACleanScenarioExitsZeroAndPrintsNothing) {
  const SledResult result = Sled({"check", "tests/golden/ok_belts.sled", "--diagnostics=compact"});
  EXPECT_EQ(result.exit_code, 0) << result.err;
  EXPECT_EQ(result.err, "");
  EXPECT_EQ(result.out, "");
}

TEST_F(DriverTest, CheckWithErrorsExitsOneWithDiagnosticsOnStandardError) {
  const SledResult result =
      Sled({"check", "tests/golden/fail_e0204_unknown_segment.sled", "--diagnostics=compact"});
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_NE(result.err.find("error[E0204]"), std::string::npos) << result.err;
  EXPECT_EQ(result.out, "");
  // The driver prints what the golden runner expects.
  EXPECT_EQ(result.err, ReadText(kRoot / "tests/golden/fail_e0204_unknown_segment.stderr"));
}

TEST_F(DriverTest, RichDiagnosticsAreTheDefaultAndEndWithASummary) {
  const SledResult result = Sled({"check", "tests/golden/rich_e0204.sled"});
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_EQ(result.err.rfind("error[E", 0), 0u) << result.err;
  EXPECT_NE(result.err.find(" --> tests/golden/rich_e0204.sled:"), std::string::npos) << result.err;
  EXPECT_NE(result.err.find("1 error, 0 warnings"), std::string::npos) << result.err;
}

TEST_F(DriverTest, WarningsAloneExitZero) {
  const SledResult result =
      Sled({"check", "tests/golden/fail_w0007_unused_parameter.sled", "--diagnostics=compact"});
  EXPECT_EQ(result.exit_code, 0);
  EXPECT_NE(result.err.find("warning[W0007]"), std::string::npos) << result.err;
}

TEST_F(DriverTest, UnknownCommandIsAUsageError) {
  const SledResult result = Sled({"frobnicate", "tests/golden/ok_belts.sled"});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.err.find("unknown command `frobnicate`"), std::string::npos) << result.err;
}

TEST_F(DriverTest, NoCommandIsAUsageError) {
  const SledResult result = Sled({});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.err.find("usage: sled"), std::string::npos) << result.err;
}

TEST_F(DriverTest, UnknownOptionIsAUsageError) {
  const SledResult result = Sled({"check", "--frobnicate", "tests/golden/ok_belts.sled"});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.err.find("unknown option `--frobnicate`"), std::string::npos) << result.err;
}

TEST_F(DriverTest, ExplainPrintsTheDocumentationPage) {
  const SledResult result = Sled({"explain", "E0204"});
  EXPECT_EQ(result.exit_code, 0) << result.err;
  EXPECT_EQ(result.out.rfind("# E0204", 0), 0u) << result.out;
  EXPECT_EQ(result.out, ReadText(kRoot / "docs/diagnostics/E0204.md"));
}

TEST_F(DriverTest, ExplainAcceptsLowercaseCodes) {
  const SledResult result = Sled({"explain", "w0006"});
  EXPECT_EQ(result.exit_code, 0) << result.err;
  EXPECT_EQ(result.out.rfind("# W0006", 0), 0u) << result.out;
}

TEST_F(DriverTest, ExplainHasAPageForEveryCode) {
  for (const lang::DiagnosticInfo& info : lang::AllDiagnostics()) {
    const SledResult result = Sled({"explain", std::string(info.code)});
    EXPECT_EQ(result.exit_code, 0) << info.code << ": " << result.err;
    EXPECT_EQ(result.out.rfind("# " + std::string(info.code) + ":", 0), 0u) << info.code;
  }
}

TEST_F(DriverTest, ExplainOfAnUnknownCodeIsAUsageError) {
  const SledResult result = Sled({"explain", "E9999"});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(result.out, "");
  EXPECT_NE(result.err.find("no diagnostic `E9999`"), std::string::npos) << result.err;
}

TEST_F(DriverTest, MissingFileReportsE0107) {
  const SledResult result =
      Sled({"check", "tests/golden/no_such_file.sled", "--diagnostics=compact"});
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_NE(result.err.find("error[E0107]"), std::string::npos) << result.err;
  EXPECT_NE(result.err.find("tests/golden/no_such_file.sled"), std::string::npos) << result.err;
}

TEST_F(DriverTest, AFolderGivenAsAFileReportsE0107ForEveryCommand) {
  // A folder opens as a stream and reads as empty text: it must not pass for an empty scenario.
  for (const char* command : {"check", "fmt", "run", "study"}) {
    const SledResult result = Sled({command, "tests/golden", "--diagnostics=compact"});
    EXPECT_EQ(result.exit_code, 1) << command << ": " << result.err;
    EXPECT_NE(result.err.find("error[E0107]: cannot read `tests/golden`: it is a folder"),
              std::string::npos)
        << command << ": " << result.err;
  }
}

TEST_F(DriverTest, AnEndlessFileIsE0107NotReadUntilMemoryRunsOut) {
  // /dev/zero never ends; sled stops reading at 256 MiB.
  for (const std::string command : {"check", "fmt", "run", "convert"}) {
    std::vector<std::string> args = {command, "/dev/zero", "--diagnostics=compact"};
    if (command == "convert") args.push_back("--deck=ain");
    const SledResult result = Sled(args);
    EXPECT_EQ(result.exit_code, 1) << command << ": " << result.err;
    EXPECT_NE(result.err.find("error[E0107]: cannot read `/dev/zero`: it is larger than 256 MiB"),
              std::string::npos)
        << command << ": " << result.err;
  }
}

TEST_F(DriverTest, RunningAModuleWithoutAScenarioIsAnInputError) {
  // stdlib modules check clean but hold nothing to simulate.
  const fs::path module = temp() / "module.sled";
  WriteText(module, "let seat_height = 300 mm\n");
  for (const char* command : {"run", "study"}) {
    const SledResult result =
        Sled({command, module.string(), "-o", (temp() / "out").string(), "--diagnostics=compact"});
    EXPECT_EQ(result.exit_code, 1) << command << ": " << result.err;
    EXPECT_NE(result.err.find("module.sled:1:1: error[E0206]: `" + module.string() +
                              "` has no `scenario` to run"),
              std::string::npos)
        << command << ": " << result.err;
  }
}

TEST_F(DriverTest, FmtReplacesTheFileBehindALinkAndKeepsItsPermissions) {
  // fmt writes a temporary file and renames it over the original, so a failed write cannot
  // leave a half-written scenario; the rename must not replace a link or widen permissions.
  const fs::path file = temp() / "scene.sled";
  const fs::path link = temp() / "link.sled";
  WriteText(file, "let a = 2*b\n");
  fs::permissions(file, fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
  fs::create_symlink(file, link);
  const SledResult result = Sled({"fmt", link.string()});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_TRUE(fs::is_symlink(link));
  EXPECT_EQ(ReadText(file), "let a = 2 * b\n");
  EXPECT_EQ(fs::status(file).permissions() & fs::perms::all,
            fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
  for (const auto& entry : fs::directory_iterator(temp())) {
    EXPECT_EQ(entry.path().string().find(".sled-tmp"), std::string::npos) << entry.path();
  }
}

TEST_F(DriverTest, FmtCheckAcceptsAFormattedFile) {
  // Format a copy first: whatever the formatter writes must then pass `--check` (idempotence).
  const fs::path copy = temp() / "formatted.sled";
  fs::copy_file(kRoot / "tests/golden/ok_joints.sled", copy);
  const SledResult formatted = Sled({"fmt", copy.string()});
  ASSERT_EQ(formatted.exit_code, 0) << formatted.err;
  const std::string text = ReadText(copy);
  const SledResult result = Sled({"fmt", "--check", copy.string()});
  EXPECT_EQ(result.exit_code, 0) << result.out << result.err;
  EXPECT_EQ(ReadText(copy), text);
}

TEST_F(DriverTest, FmtCheckRejectsABadlyFormattedFileWithoutChangingIt) {
  const fs::path copy = temp() / "messy.sled";
  const std::string messy =
      "scenario   \"messy\"{\n"
      "time{end=100 ms   output_every=1 ms}\n"
      "        param speed=56 km/h\n"
      "  vehicle sled { motion = half_sine(delta_v=speed,duration=100 ms,axis=-x) }\n"
      "}\n";
  WriteText(copy, messy);
  const SledResult result = Sled({"fmt", "--check", copy.string()});
  EXPECT_EQ(result.exit_code, 1) << result.out << result.err;
  EXPECT_NE(result.out.find("would be reformatted"), std::string::npos) << result.out;
  EXPECT_EQ(ReadText(copy), messy);
  // Without --check the file is rewritten, and then passes the check.
  EXPECT_EQ(Sled({"fmt", copy.string()}).exit_code, 0);
  EXPECT_NE(ReadText(copy), messy);
  EXPECT_EQ(Sled({"fmt", "--check", copy.string()}).exit_code, 0);
}

TEST_F(DriverTest, SetOverridesADeclaredParameter) {
  const SledResult result = Sled({"check", "tests/golden/ok_units_conversion.sled", "--set",
                                  "speed=40 km/h", "--diagnostics=compact", "--dump-checked"});
  EXPECT_EQ(result.exit_code, 0) << result.err;
  EXPECT_EQ(result.err, "");
  // 40 km/h is 11.11 m/s, where the file's own 30 mph is 13.4112 m/s.
  EXPECT_NE(result.out.find("delta_v 11.11111111111111"), std::string::npos) << result.out;
}

TEST_F(DriverTest, SetOfAnUndeclaredParameterReportsE0213) {
  const SledResult result = Sled({"check", "tests/golden/ok_units_conversion.sled", "--set",
                                  "nosuch=1", "--diagnostics=compact"});
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_NE(result.err.find("error[E0213]"), std::string::npos) << result.err;
  EXPECT_NE(result.err.find("`--set nosuch`"), std::string::npos) << result.err;
}

TEST_F(DriverTest, SetWithoutEqualsIsAUsageError) {
  const SledResult result =
      Sled({"check", "tests/golden/ok_units_conversion.sled", "--set", "speed"});
  EXPECT_EQ(result.exit_code, 2);
}

}  // namespace
}  // namespace sled
