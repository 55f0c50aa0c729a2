// The bad-input corpus (issue 15): every `fail_*.sled` of tests/golden, each a scenario a user
// could write that sled must refuse or warn about, run through the `sled` program as a user runs
// it. Each must give its exit status (1 with an error, 0 with warnings only), its code with the
// file, line and column, and exactly the diagnostics of its golden `.stderr`; `sled run` of an
// error must refuse it the same way before simulating and write no output folder. Designs of the
// E06xx files go through `sled sweep`, which refuses them before running anything.
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/compiler/sled_process.h"

namespace sled::testing {
namespace {

namespace fs = std::filesystem;

const fs::path kGolden = fs::path(SLED_SOURCE_ROOT) / "tests/golden";

struct CorpusFile {
  std::string stem;                   // fail_e0302_bare_vector_component
  std::string code;                   // E0302
  std::vector<std::string> settings;  // --set NAME=VALUE
  std::vector<std::string> design;    // --vary/--sample/--design arguments for sled sweep
};

// The `// sled-test:` directives at the top of the file (golden_test.cpp's format).
CorpusFile Read(const fs::path& path) {
  CorpusFile file;
  file.stem = path.stem().string();
  std::string code = file.stem.substr(5, 5);
  std::transform(code.begin(), code.end(), code.begin(),
                 [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  file.code = code;
  std::istringstream text(ReadText(path));
  const std::string directive = "// sled-test: ";
  for (std::string line; std::getline(text, line) && line.rfind("//", 0) == 0;) {
    if (line.rfind(directive, 0) != 0) continue;
    const std::string rest = line.substr(directive.size());
    const std::size_t space = rest.find(' ');
    const std::string option = rest.substr(0, space);
    std::string value = space == std::string::npos ? "" : rest.substr(space + 1);
    if (option == "--set") {
      file.settings.insert(file.settings.end(), {"--set", value});
    } else {
      if (option == "--design") value = "tests/golden/" + value;
      file.design.insert(file.design.end(), {option, value});
    }
  }
  return file;
}

std::vector<CorpusFile> Corpus() {
  std::vector<CorpusFile> files;
  for (const fs::directory_entry& entry : fs::directory_iterator(kGolden)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("fail_", 0) == 0 && entry.path().extension() == ".sled") {
      files.push_back(Read(entry.path()));
    }
  }
  std::sort(files.begin(), files.end(),
            [](const CorpusFile& a, const CorpusFile& b) { return a.stem < b.stem; });
  return files;
}

class BadInputCorpus : public SledProcessTest {};

TEST_F(BadInputCorpus, HoldsAtLeastAHundredScenarios) { EXPECT_GE(Corpus().size(), 100u); }

TEST_F(BadInputCorpus, EveryFileGivesItsExitStatusCodeAndMessage) {
  for (const CorpusFile& file : Corpus()) {
    SCOPED_TRACE(file.stem);
    const std::string path = "tests/golden/" + file.stem + ".sled";
    const bool error = file.code[0] == 'E';
    // PATH:LINE:COL: error[CODE] (or warning[CODE])
    // (an imported module's error is located in the module).
    const std::regex located(std::string("(^|\n)[^\n]+:[0-9]+:[0-9]+: ") +
                             (error ? "error" : "warning") + "\\[" + file.code + "\\]: ");
    if (!file.design.empty()) {
      std::vector<std::string> args = {"sweep", path};
      args.insert(args.end(), file.design.begin(), file.design.end());
      args.insert(args.end(), file.settings.begin(), file.settings.end());
      args.insert(args.end(), {"-o", (temp() / file.stem).string()});
      const SledResult result = Sled(args);
      EXPECT_EQ(result.exit_code, 1) << result.err;
      EXPECT_NE(result.err.find("[" + file.code + "]"), std::string::npos) << result.err;
      EXPECT_FALSE(fs::exists(temp() / file.stem / "runs" / "0000")) << "a run was started";
      continue;
    }
    std::vector<std::string> check = {"check", path, "--diagnostics=compact"};
    check.insert(check.end(), file.settings.begin(), file.settings.end());
    const SledResult checked = Sled(check);
    EXPECT_EQ(checked.exit_code, error ? 1 : 0) << checked.err;
    EXPECT_TRUE(std::regex_search(checked.err, located)) << checked.err;
    EXPECT_EQ(checked.err, ReadText(kGolden / (file.stem + ".stderr")));
    if (!error) continue;
    // The rich form names the code and gives a hint.
    std::vector<std::string> rich = {"check", path};
    rich.insert(rich.end(), file.settings.begin(), file.settings.end());
    const SledResult shown = Sled(rich);
    EXPECT_EQ(shown.exit_code, 1);
    EXPECT_NE(shown.err.find("error[" + file.code + "]"), std::string::npos) << shown.err;
    EXPECT_NE(shown.err.find("help"), std::string::npos) << shown.err;
    // `sled run` refuses it before simulating, and writes nothing.
    const fs::path folder = temp() / file.stem;
    std::vector<std::string> run = {"run", path, "-o", folder.string(), "--diagnostics=compact"};
    run.insert(run.end(), file.settings.begin(), file.settings.end());
    const SledResult ran = Sled(run);
    EXPECT_EQ(ran.exit_code, 1) << ran.err;
    EXPECT_TRUE(std::regex_search(ran.err, located)) << ran.err;
    EXPECT_FALSE(fs::exists(folder / "timeseries.csv"));
    EXPECT_FALSE(fs::exists(folder / "summary.json"));
  }
}

}  // namespace
}  // namespace sled::testing
