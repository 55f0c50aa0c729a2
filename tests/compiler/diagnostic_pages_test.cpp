// The pages of docs/diagnostics against the checker, so that `sled explain` never shows output
// the program no longer prints:
//   - where a page shows a ```sled example followed by "`sled check scene.sled ...` prints:" and
//     a ```text block, checking the example as scene.sled prints exactly that text;
//   - every ```sled block under "## How to fix" checks without errors and without the page's code.
// Set SLED_UPDATE_GOLDEN=1 to rewrite the printed blocks from what the checker says now; review
// the change with `git diff docs/diagnostics` before committing it.
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "compiler/check/check.h"
#include "compiler/sweep/design.h"
#include "lang/diagnostics/diagnostic.h"
#include "lang/diagnostics/render.h"
#include "lang/source/source_manager.h"

namespace sled::compiler {
namespace {

const std::filesystem::path kPages = std::filesystem::path(SLED_SOURCE_ROOT) / "docs/diagnostics";

// One ```sled example of a page, and what the page says checking it prints (if it says).
struct PageExample {
  int line = 0;  // of the example's first line of code
  std::string code;
  bool under_how_to_fix = false;
  bool imports_local_module = false;  // needs files the page only describes: not checked here
  std::vector<std::pair<std::string, std::string>> overrides;  // `--set 'NAME=VALUE'`
  std::vector<std::string> vary;  // `--vary 'TEXT'` of a `sled sweep ... --check` line
  bool shows_output = false;
  int output_first_line = 0;  // 0-based index of the printed block's first line in the page
  int output_line_count = 0;
  std::string output;
};

std::vector<std::string> Lines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) lines.push_back(line);
  return lines;
}

// The quoted arguments of one option (`--set 'NAME=VALUE'`) in a "`sled check ...` prints:" line.
std::vector<std::string> QuotedArguments(const std::string& command, const std::string& option) {
  std::vector<std::string> items;
  const std::string marker = option + " '";
  for (std::size_t at = command.find(marker); at != std::string::npos;
       at = command.find(marker, at + 1)) {
    const std::size_t begin = at + marker.size();
    const std::size_t end = command.find('\'', begin);
    items.push_back(command.substr(begin, end - begin));
  }
  return items;
}

std::vector<std::pair<std::string, std::string>> OverridesOf(const std::string& command) {
  std::vector<std::pair<std::string, std::string>> overrides;
  for (const std::string& item : QuotedArguments(command, "--set")) {
    const std::size_t equals = item.find('=');
    overrides.emplace_back(item.substr(0, equals), item.substr(equals + 1));
  }
  return overrides;
}

std::vector<PageExample> ExamplesOf(const std::vector<std::string>& lines) {
  std::vector<PageExample> examples;
  bool how_to_fix = false;
  bool awaiting_output = false;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const std::string& line = lines[i];
    if (line.rfind("## ", 0) == 0) how_to_fix = line == "## How to fix";
    if (line == "```sled") {
      PageExample example;
      example.line = static_cast<int>(i) + 2;
      example.under_how_to_fix = how_to_fix;
      for (++i; i < lines.size() && lines[i] != "```"; ++i) {
        example.code += lines[i] + '\n';
        const std::size_t word = lines[i].find_first_not_of(' ');
        if (word != std::string::npos && lines[i].compare(word, 7, "import ") == 0 &&
            lines[i].compare(word, 11, "import std.") != 0) {
          example.imports_local_module = true;
        }
      }
      examples.push_back(std::move(example));
      awaiting_output = false;
    } else if (!examples.empty() && line.size() >= 7 &&
               line.compare(line.size() - 7, 7, "prints:") == 0 &&
               (line == "prints:" || line.find("scene.sled") != std::string::npos)) {
      examples.back().overrides = OverridesOf(line);
      examples.back().vary = QuotedArguments(line, "--vary");
      awaiting_output = true;
    } else if (awaiting_output && line == "```text") {
      PageExample& example = examples.back();
      example.shows_output = true;
      example.output_first_line = static_cast<int>(i) + 1;
      for (++i; i < lines.size() && lines[i] != "```"; ++i) {
        example.output += lines[i] + '\n';
        ++example.output_line_count;
      }
      awaiting_output = false;
    }
  }
  return examples;
}

struct Checked {
  std::string compact;  // every diagnostic, one line each, sorted by position
  int errors = 0;
  std::vector<std::string> codes;
};

Checked CheckAsScene(const PageExample& example) {
  lang::SourceManager sources;
  const lang::FileId file = sources.Add("scene.sled", example.code);
  lang::DiagnosticCollector collector;
  CheckOptions options;
  options.diagnostics = &collector;
  options.stdlib_root = std::string(SLED_SOURCE_ROOT) + "/stdlib";
  options.overrides = example.overrides;
  const CheckedScenario scene = ParseAndCheck(sources, file, options);
  if (!example.vary.empty() && !collector.has_errors()) {
    // `sled sweep scene.sled --vary '...' --check`: the design, built against the scene.
    DesignRequest request;
    for (const std::string& vary : example.vary)
      request.vary.push_back(sources.Add("--vary", vary));
    for (const auto& [name, value] : example.overrides) request.fixed.push_back(name);
    BuildDesign(sources, request, scene, collector);
  }
  collector.SortByPosition();
  Checked checked;
  checked.errors = collector.error_count();
  for (const lang::Diagnostic& diagnostic : collector.diagnostics()) {
    checked.compact += lang::RenderCompact(sources, diagnostic) + '\n';
    checked.codes.emplace_back(diagnostic.code());
  }
  return checked;
}

std::vector<std::filesystem::path> Pages() {
  std::vector<std::filesystem::path> pages;
  for (const auto& entry : std::filesystem::directory_iterator(kPages)) {
    const std::string name = entry.path().filename().string();
    if (entry.path().extension() == ".md" && name != "README.md") pages.push_back(entry.path());
  }
  std::sort(pages.begin(), pages.end());
  return pages;
}

TEST(DiagnosticPages, PrintedOutputIsWhatTheCheckerPrints) {
  const bool update = std::getenv("SLED_UPDATE_GOLDEN") != nullptr;
  int compared = 0;
  for (const std::filesystem::path& page : Pages()) {
    std::ifstream in(page);
    std::stringstream text;
    text << in.rdbuf();
    std::vector<std::string> lines = Lines(text.str());
    bool changed = false;
    const std::vector<PageExample> examples = ExamplesOf(lines);
    // Last to first, so that replacing a printed block leaves the earlier blocks' lines in place.
    for (auto it = examples.rbegin(); it != examples.rend(); ++it) {
      const PageExample& example = *it;
      if (!example.shows_output || example.imports_local_module) continue;
      ++compared;
      const Checked checked = CheckAsScene(example);
      if (update && checked.compact != example.output) {
        std::vector<std::string> replacement = Lines(checked.compact);
        lines.erase(lines.begin() + example.output_first_line,
                    lines.begin() + example.output_first_line + example.output_line_count);
        lines.insert(lines.begin() + example.output_first_line, replacement.begin(),
                     replacement.end());
        changed = true;
        continue;
      }
      EXPECT_EQ(checked.compact, example.output)
          << page.filename().string() << ":" << example.line
          << ": the page shows other output than the checker prints";
    }
    if (changed) {
      std::ofstream out(page);
      for (const std::string& line : lines) out << line << '\n';
    }
  }
  EXPECT_GT(compared, 50);
}

TEST(DiagnosticPages, HowToFixExamplesCheckWithoutThePageCode) {
  int checked_examples = 0;
  for (const std::filesystem::path& page : Pages()) {
    const std::string code = page.stem().string();
    std::ifstream in(page);
    std::stringstream text;
    text << in.rdbuf();
    for (const PageExample& example : ExamplesOf(Lines(text.str()))) {
      if (!example.under_how_to_fix || example.imports_local_module) continue;
      ++checked_examples;
      const Checked checked = CheckAsScene(example);
      EXPECT_EQ(checked.errors, 0) << page.filename().string() << ":" << example.line << ":\n"
                                   << checked.compact;
      EXPECT_EQ(std::count(checked.codes.begin(), checked.codes.end(), code), 0)
          << page.filename().string() << ":" << example.line << ": the fix still reports " << code
          << ":\n"
          << checked.compact;
    }
  }
  EXPECT_GT(checked_examples, 40);
}

}  // namespace
}  // namespace sled::compiler
