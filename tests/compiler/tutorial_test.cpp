// docs/tutorial.md tested as written: each command it shows runs in a folder of its own with the
// files the tutorial has the reader save (its ```sled blocks), and what sled prints is compared
// with what the tutorial shows: the diagnostics line for line (their line and column numbers
// included), the order of the lines of a run, which files a run writes and where the options of
// its last section put their results.
#include <filesystem>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/compiler/sled_process.h"

namespace sled {
namespace {

namespace fs = std::filesystem;
using testing::ReadText;
using testing::SledResult;
using testing::WriteText;

using Tutorial = testing::SledProcessTest;

// A fenced block of the tutorial: its info word (sh, text, sled, sled-fail) and its text.
struct Fence {
  std::string info;
  std::string text;
};

std::vector<Fence> TutorialFences() {
  std::vector<Fence> fences;
  std::istringstream in(ReadText(testing::kSourceRoot / "docs" / "tutorial.md"));
  std::string line;
  Fence* open = nullptr;
  while (std::getline(in, line)) {
    if (line.rfind("```", 0) != 0) {
      if (open) open->text += line + "\n";
    } else if (open) {
      open = nullptr;
    } else {
      fences.push_back({line.substr(3), ""});
      open = &fences.back();
    }
  }
  return fences;
}

// The first fence of `info` whose text holds `marker`, and the fence after it.
struct Found {
  const Fence* fence = nullptr;
  const Fence* next = nullptr;
};
Found Find(const std::vector<Fence>& fences, const std::string& info, const std::string& marker) {
  for (std::size_t i = 0; i < fences.size(); ++i) {
    if (fences[i].info == info && fences[i].text.find(marker) != std::string::npos) {
      return {&fences[i], i + 1 < fences.size() ? &fences[i + 1] : nullptr};
    }
  }
  ADD_FAILURE() << "docs/tutorial.md has no ```" << info << " block with `" << marker << "`";
  return {};
}

std::vector<std::string> Lines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// A line the tutorial shows as a pattern: its numbers stand for any number, and `...` for
// anything.
std::regex Shown(const std::string& line) {
  static const std::regex kSpecial(R"([.^$|()\[\]{}*+?\\])");
  std::string pattern = std::regex_replace(line, kSpecial, R"(\$&)");
  pattern = std::regex_replace(pattern, std::regex(R"(\\\.\\\.\\\.)"), ".*");
  pattern =
      std::regex_replace(pattern, std::regex(R"([0-9]+(\\\.[0-9]+)?(e[-+][0-9]+)?)"), "[-+0-9.e]+");
  return std::regex(pattern);
}

// Every line the tutorial shows (but a lone `...`) matches a printed line, in the same order.
void ExpectLinesInOrder(const std::string& shown, const std::string& printed) {
  const std::vector<std::string> actual = Lines(printed);
  std::size_t at = 0;
  for (const std::string& line : Lines(shown)) {
    if (line.find_first_not_of(" .") == std::string::npos) continue;
    const std::regex pattern = Shown(line);
    while (at < actual.size() && !std::regex_match(actual[at], pattern)) ++at;
    EXPECT_LT(at, actual.size()) << "the tutorial shows\n  " << line
                                 << "\nwhich sled does not print at this place in\n"
                                 << printed;
    if (at == actual.size()) return;
    ++at;
  }
}

TEST_F(Tutorial, TheFlagshipChecksCleanAsSection1Says) {
  const SledResult result = Sled({"check", "examples/frontal_sled.sled"});
  EXPECT_EQ(result.exit_code, 0);
  EXPECT_EQ(result.out + result.err, "");
}

TEST_F(Tutorial, TheFirstPendulumGivesTheDiagnosticsSection3Shows) {
  const std::vector<Fence> fences = TutorialFences();
  const Found file = Find(fences, "sled-fail", "My first scenario");
  const Found command = Find(fences, "sh", "sled check pendulum.sled");
  ASSERT_TRUE(file.fence && command.next && command.next->info == "text");
  WriteText(temp() / "pendulum.sled", file.fence->text);
  const SledResult rich = Sled({"check", "pendulum.sled"}, temp());
  EXPECT_EQ(rich.exit_code, 1);
  EXPECT_EQ(rich.err, command.next->text);
  const Found compact = Find(fences, "text", "pendulum.sled:7:14: error[E0302]");
  ASSERT_TRUE(compact.fence);
  const SledResult lines = Sled({"check", "pendulum.sled", "--diagnostics=compact"}, temp());
  EXPECT_EQ(Lines(lines.err).at(0) + "\n", compact.fence->text);
}

// The ```sled block holding `marker`, saved as `file`, checks clean with the `--set`s shown.
TEST_F(Tutorial, TheStudyValuesOfSections4And7AreSetFromTheCommandLine) {
  const std::vector<Fence> fences = TutorialFences();
  const struct {
    const char* marker;
    const char* file;
    std::vector<std::string> sets;
  } cases[] = {
      {"param length = 400 mm", "pendulum.sled", {"length=600 mm"}},
      {"scenario \"sled, unbelted\"", "sled.sled", {"speed=50 km/h", "pulse=80 ms"}},
  };
  for (const auto& c : cases) {
    const Found block = Find(fences, "sled", c.marker);
    ASSERT_TRUE(block.fence) << c.marker;
    WriteText(temp() / c.file, block.fence->text);
    std::vector<std::string> args = {"check", c.file};
    for (const std::string& set : c.sets) args.insert(args.end(), {"--set", set});
    const SledResult result = Sled(args, temp());
    EXPECT_EQ(result.exit_code, 0) << c.file << "\n" << result.err;
    EXPECT_EQ(result.err, "") << c.file;
  }
}

TEST_F(Tutorial, AMisplacedOccupantGivesTheWarningSection5Shows) {
  const std::vector<Fence> fences = TutorialFences();
  const Found file = Find(fences, "sled", "A 50th-percentile male sitting on a rigid seat pan");
  const Found warning = Find(fences, "text", "warning[W0004]");
  ASSERT_TRUE(file.fence && warning.fence);
  // "With `position = (0, 0, 120) mm`":
  std::string scene = file.fence->text;
  const std::string placed = "position = (0, 0, 150) mm";
  ASSERT_NE(scene.find(placed), std::string::npos);
  scene.replace(scene.find(placed), placed.size(), "position = (0, 0, 120) mm");
  WriteText(temp() / "seat.sled", scene);
  const SledResult result = Sled({"check", "seat.sled"}, temp());
  EXPECT_EQ(result.exit_code, 0);
  EXPECT_EQ(result.err, warning.fence->text);
}

// Section 9: `sled run examples/frontal_sled.sled -o out`, then the options it suggests. The
// flagship runs as the tutorial's reader runs it, from a folder holding examples/.
TEST_F(Tutorial, TheRunOfSection9PrintsAndWritesWhatItShows) {
  const std::vector<Fence> fences = TutorialFences();
  const Found command = Find(fences, "sh", "sled run examples/frontal_sled.sled -o out");
  const Found printed = Find(fences, "text", "rows to `out`");
  ASSERT_TRUE(command.fence && printed.fence);
  fs::create_directories(temp() / "examples");
  fs::copy_file(testing::kSourceRoot / "examples" / "frontal_sled.sled",
                temp() / "examples" / "frontal_sled.sled");
  // The command as shown, with the options its last paragraph suggests ("`--format iso-mme`
  // adds an ISO-MME data set, `--dump-at 80ms` writes every state variable and force at 80 ms to
  // out/dump_0.08.txt, `--report` writes out/report.html, `--checkpoint-every 50ms` writes
  // checkpoints"), in one run: they add lines of their own, and the lines shown keep their order.
  const SledResult run =
      Sled({"run", "examples/frontal_sled.sled", "-o", "out", "--format", "iso-mme", "--dump-at",
            "80ms", "--checkpoint-every", "50ms", "--report"},
           temp());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  ExpectLinesInOrder(printed.fence->text, run.err);
  for (const char* file : {"timeseries.csv", "timeseries_filtered.csv", "summary.json",
                           "animation.glb", "iso-mme/frontal_sled.mme", "dump_0.08.txt",
                           "report.html", "checkpoint_0.050000s.bin", "checkpoint_0.100000s.bin"}) {
    EXPECT_TRUE(fs::exists(temp() / "out" / file)) << file;
  }
  const SledResult resumed = Sled({"run", "examples/frontal_sled.sled", "-o", "later", "--resume",
                                   "out/checkpoint_0.100000s.bin"},
                                  temp());
  EXPECT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_TRUE(fs::exists(temp() / "later" / "timeseries.csv"));
}

}  // namespace
}  // namespace sled
