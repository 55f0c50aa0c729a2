// The everyday command line: `--help` on every command, `sled --version`, options of one command
// refused by another, an empty `-o`, and progress on a terminal only.
#include <regex>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "tests/compiler/sled_process.h"

namespace sled {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;
using testing::SledResult;

using CommandLine = testing::SledProcessTest;

const std::vector<std::string> kCommands = {"check", "fmt",     "run",     "report",
                                            "study", "convert", "explain", "lsp"};

// The option names a help page lists: each line of its options section that starts with `-`.
std::vector<std::string> ListedOptions(const std::string& help) {
  std::vector<std::string> options;
  const std::regex option(R"(^  (-[-a-zA-Z]+)(, (--[-a-z]+))?)");
  std::size_t start = 0;
  while (start < help.size()) {
    const std::size_t end = std::min(help.find('\n', start), help.size());
    const std::string line = help.substr(start, end - start);
    std::smatch match;
    if (std::regex_search(line, match, option)) {
      options.push_back(match[1]);
      if (match[3].matched) options.push_back(match[3]);
    }
    start = end + 1;
  }
  return options;
}

TEST_F(CommandLine, TheOverviewListsEveryCommand) {
  const SledResult result = Sled({"--help"});
  EXPECT_EQ(result.exit_code, 0);
  EXPECT_THAT(result.out, HasSubstr("usage: sled <command>"));
  for (const std::string& command : kCommands) {
    EXPECT_THAT(result.out, HasSubstr("\n  " + command + " ")) << command;
  }
}

TEST_F(CommandLine, EveryCommandHasHelpWithItsOptionsAndExamples) {
  for (const std::string& command : kCommands) {
    for (const char* spelling : {"--help", "-h"}) {
      const SledResult result = Sled({command, spelling});
      EXPECT_EQ(result.exit_code, 0) << command << ": " << result.err;
      EXPECT_EQ(result.err, "") << command;
      EXPECT_EQ(result.out.rfind("usage: sled " + command, 0), 0u) << result.out;
      EXPECT_THAT(result.out, HasSubstr("\nexamples:\n  sled " + command)) << command;
      EXPECT_THAT(result.out, HasSubstr("Exit status")) << command;
    }
    // `sled help COMMAND` is the same page.
    EXPECT_EQ(Sled({"help", command}).out, Sled({command, "--help"}).out) << command;
  }
}

TEST_F(CommandLine, EveryListedOptionIsTakenAndNoOtherIs) {
  for (const std::string& command : kCommands) {
    const std::string help = Sled({command, "--help"}).out;
    const std::vector<std::string> options = ListedOptions(help);
    for (const std::string& option : options) {
      // Followed by --help, an option the command takes prints the help (its value, if any,
      // is the word `--help`, which is refused with a message that is not "takes no option").
      const SledResult result = Sled({command, option, "--help"});
      EXPECT_THAT(result.err, Not(HasSubstr("takes no option"))) << command << " " << option;
      EXPECT_THAT(result.err, Not(HasSubstr("unknown option"))) << command << " " << option;
    }
  }
  // `run` writes into a folder; `check` does not, and says so rather than ignore it.
  const SledResult check = Sled({"check", "examples/pendulum.sled", "-o", "out"});
  EXPECT_EQ(check.exit_code, 2);
  EXPECT_THAT(check.err, HasSubstr("`sled check` takes no option `-o`"));
  EXPECT_THAT(check.err, HasSubstr("`sled check --help` lists its options"));
  const SledResult report = Sled({"report", "out", "--set", "a=1"});
  EXPECT_EQ(report.exit_code, 2);
  EXPECT_THAT(report.err, HasSubstr("`sled report` takes no option `--set`"));
}

TEST_F(CommandLine, AnUnknownCommandSuggestsTheClosestOne) {
  const SledResult result = Sled({"rn", "examples/pendulum.sled"});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_THAT(result.err, HasSubstr("unknown command `rn`"));
  EXPECT_THAT(result.err, HasSubstr("`run`"));
}

TEST_F(CommandLine, VersionPrintsTheVersionAndTheCommit) {
  for (const char* spelling : {"--version", "-V", "version"}) {
    const SledResult result = Sled({spelling});
    EXPECT_EQ(result.exit_code, 0) << spelling;
    EXPECT_TRUE(std::regex_match(
        result.out,
        std::regex(R"(sled \d+\.\d+\.\d+ \(commit ([0-9a-f]{12}(\+modified)?|unknown)\)\n)")))
        << result.out;
  }
}

TEST_F(CommandLine, AnEmptyOutputFolderIsAUsageErrorNotTheDefault) {
  // `-o "$OUT"` with OUT unset would otherwise write into pendulum-out unasked.
  for (const char* command : {"run", "study", "report", "convert"}) {
    const SledResult result = Sled({command, "examples/pendulum.sled", "-o", ""});
    EXPECT_EQ(result.exit_code, 2) << command;
    EXPECT_THAT(result.err, HasSubstr("`-o` needs a")) << command;
  }
}

TEST_F(CommandLine, ProgressShowsOnATerminalAndNotWhenPiped) {
  const std::string out = (temp() / "run").string();
  const SledResult piped = Sled({"run", "examples/pendulum.sled", "-o", out});
  EXPECT_EQ(piped.exit_code, 0) << piped.err;
  EXPECT_THAT(piped.err, Not(HasSubstr("simulating")));
  EXPECT_THAT(piped.err, Not(HasSubstr("\r")));
  // script(1) gives the run a terminal; its transcript holds what the terminal showed.
  const std::string transcript = (temp() / "typescript").string();
  const std::string command =
      "cd " + testing::Quote(testing::kSourceRoot.string()) + " && script -qec " +
      testing::Quote(testing::Quote(testing::SledBinary().string()) +
                     " run examples/pendulum.sled -o " + testing::Quote(out + "2")) +
      " " + testing::Quote(transcript) + " >/dev/null 2>&1 </dev/null";
  if (std::system("command -v script >/dev/null 2>&1") != 0) {
    GTEST_SKIP() << "script(1) (util-linux) is not installed: no terminal to test with";
  }
  ASSERT_EQ(std::system(command.c_str()), 0);
  const std::string shown = testing::ReadText(transcript);
  EXPECT_THAT(shown, HasSubstr("simulating: 100 %"));
  EXPECT_THAT(shown, HasSubstr("rows to"));
}

}  // namespace
}  // namespace sled
