// The documentation and the shipped .sled files against the checker:
//   - every ```sled block of docs/language.md and docs/tutorial.md is a complete file that checks
//     with no errors and no warnings, and every ```sled-fail block reports at least one error;
//   - every .sled file under examples/ and stdlib/ checks with no errors and no warnings;
//   - docs/language.md names every block attribute and declaration of the schema, every output
//     request, criterion, function quantity name and unit.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "compiler/check/check.h"
#include "compiler/check/schema.h"
#include "compiler/units/unit_table.h"
#include "lang/diagnostics/diagnostic.h"
#include "lang/diagnostics/render.h"
#include "lang/source/source_manager.h"
#include "lang/syntax/parser.h"

namespace sled::compiler {
namespace {

const std::string kRoot = SLED_SOURCE_ROOT;

// One fenced code block of a Markdown file.
struct Block {
  std::string file;  // relative to the repository root, for messages
  int line = 0;      // 1-based line of the first line of code (after the fence)
  bool expect_failure = false;
  std::string text;
};

std::string ReadOrFail(const std::string& path) {
  auto text = lang::ReadFile(path);
  EXPECT_TRUE(text.has_value()) << "cannot read " << path;
  return text.value_or("");
}

// The ```sled and ```sled-fail blocks of a Markdown file. Other fences (```sh, ```text, plain)
// are skipped; a fence is closed by a line that is only ``` (leading blanks allowed).
std::vector<Block> ExtractBlocks(const std::string& relative) {
  std::vector<Block> blocks;
  std::istringstream in(ReadOrFail(kRoot + "/" + relative));
  std::string line;
  int number = 0;
  bool in_fence = false;
  bool wanted = false;
  Block current;
  auto trim = [](const std::string& s) {
    const auto begin = s.find_first_not_of(" \t\r");
    const auto end = s.find_last_not_of(" \t\r");
    return begin == std::string::npos ? std::string() : s.substr(begin, end - begin + 1);
  };
  while (std::getline(in, line)) {
    ++number;
    const std::string trimmed = trim(line);
    if (!in_fence) {
      if (trimmed.rfind("```", 0) == 0) {
        in_fence = true;
        const std::string info = trim(trimmed.substr(3));
        wanted = info == "sled" || info == "sled-fail";
        current = Block{relative, number + 1, info == "sled-fail", ""};
      }
      continue;
    }
    if (trimmed == "```") {
      in_fence = false;
      if (wanted) blocks.push_back(current);
      continue;
    }
    if (wanted) current.text += line + "\n";
  }
  EXPECT_FALSE(in_fence) << relative << ": a code fence is never closed";
  return blocks;
}

// The result of checking one text: the diagnostics rendered compactly, with counts.
struct Outcome {
  int errors = 0;
  int warnings = 0;
  std::string report;
};

// Parses and checks `text` as the file `path` (imports relative to its folder resolve there).
// `first_line` maps diagnostics in the text back to the Markdown file's lines.
Outcome CheckText(const std::string& path, std::string text, const std::string& shown_as = "",
                  int first_line = 1) {
  lang::SourceManager sources;
  lang::DiagnosticCollector collector;
  const lang::FileId id = sources.Add(path, std::move(text));
  lang::ParseOptions parse_options;
  parse_options.diagnostics = &collector;
  const lang::ast::File file = lang::Parse(sources, id, parse_options);
  CheckOptions options;
  options.diagnostics = &collector;
  options.stdlib_root = kRoot + "/stdlib";
  Check(sources, file, options);
  collector.SortByPosition();
  Outcome outcome{collector.error_count(), collector.warning_count(), ""};
  for (const lang::Diagnostic& diagnostic : collector.diagnostics()) {
    const lang::SourceRange* range = diagnostic.primary_range();
    if (!shown_as.empty() && range && range->file == id) {
      const lang::LineColumn at = sources.buffer(id).Locate(range->begin);
      outcome.report += fmt::format("  {}:{}:{}: {}[{}]: {}\n", shown_as,
                                    first_line + static_cast<int>(at.line) - 1, at.column,
                                    lang::SeverityName(diagnostic.severity), diagnostic.code(),
                                    diagnostic.message);
    } else {
      outcome.report += "  " + lang::RenderCompact(sources, diagnostic) + "\n";
    }
  }
  return outcome;
}

void CheckDocumentBlocks(const std::string& relative, std::size_t minimum_blocks) {
  const std::vector<Block> blocks = ExtractBlocks(relative);
  EXPECT_GE(blocks.size(), minimum_blocks)
      << relative << ": fewer ```sled blocks than expected; is the fence syntax intact?";
  for (const Block& block : blocks) {
    // A path inside docs/, so that relative imports resolve from the docs folder.
    const std::string path = fmt::format("{}/{}.block{}.sled", kRoot, relative, block.line);
    const Outcome outcome = CheckText(path, block.text, relative, block.line);
    if (block.expect_failure) {
      EXPECT_GE(outcome.errors, 1)
          << relative << ":" << block.line << ": a ```sled-fail block checked without errors\n"
          << outcome.report;
    } else {
      EXPECT_EQ(outcome.errors + outcome.warnings, 0)
          << relative << ":" << block.line << ": a ```sled block has " << outcome.errors
          << " errors and " << outcome.warnings << " warnings\n"
          << outcome.report;
    }
  }
}

TEST(DocsExamples, LanguageReferenceBlocksCheckAsMarked) {
  CheckDocumentBlocks("docs/language.md", 30);
}

TEST(DocsExamples, TutorialBlocksCheckAsMarked) { CheckDocumentBlocks("docs/tutorial.md", 6); }

TEST(DocsExamples, TutorialEndsWithTheFlagshipExample) {
  // The tutorial's last scenario is examples/frontal_sled.sled (from `scenario` on), so the two
  // cannot drift apart.
  const std::vector<Block> blocks = ExtractBlocks("docs/tutorial.md");
  ASSERT_FALSE(blocks.empty());
  const std::string example = ReadOrFail(kRoot + "/examples/frontal_sled.sled");
  const std::size_t start = example.find("scenario \"");
  ASSERT_NE(start, std::string::npos);
  EXPECT_NE(blocks.back().text.find(example.substr(start)), std::string::npos)
      << "docs/tutorial.md:" << blocks.back().line
      << ": the last block differs from examples/frontal_sled.sled";
}

TEST(DocsExamples, ExtractorReadsFencesAndLines) {
  // The extractor itself: a failure here would let broken docs pass unnoticed.
  const std::vector<Block> blocks = ExtractBlocks("docs/language.md");
  ASSERT_FALSE(blocks.empty());
  const bool has_fail =
      std::any_of(blocks.begin(), blocks.end(), [](const Block& b) { return b.expect_failure; });
  EXPECT_TRUE(has_fail) << "docs/language.md has no ```sled-fail block";
  const std::string text = ReadOrFail(kRoot + "/docs/language.md");
  std::istringstream in(text);
  std::string line;
  std::vector<std::string> lines;
  while (std::getline(in, line)) lines.push_back(line);
  for (const Block& block : blocks) {
    ASSERT_GE(block.line, 2);
    ASSERT_LE(static_cast<std::size_t>(block.line), lines.size());
    EXPECT_EQ(lines[static_cast<std::size_t>(block.line) - 2].rfind("```sled", 0), 0u)
        << "docs/language.md:" << block.line << ": the block does not follow a ```sled fence";
  }
}

// Every .sled file under a folder, sorted.
std::vector<std::filesystem::path> SledFilesUnder(const std::string& folder) {
  std::vector<std::filesystem::path> files;
  std::error_code error;
  for (auto it = std::filesystem::recursive_directory_iterator(folder, error);
       !error && it != std::filesystem::recursive_directory_iterator(); it.increment(error)) {
    if (it->is_regular_file() && it->path().extension() == ".sled") files.push_back(it->path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

TEST(ExamplesAndStdlib, EveryFileChecksWithoutErrorsOrWarnings) {
  std::set<std::string> seen;
  for (const std::string folder : {"examples", "stdlib"}) {
    for (const std::filesystem::path& file : SledFilesUnder((kRoot + "/").append(folder))) {
      const std::string relative = std::filesystem::relative(file, kRoot).generic_string();
      seen.insert(relative);
      const Outcome outcome = CheckText(file.string(), ReadOrFail(file.string()));
      // The numerics suite's initial overlap starts its ball 5 cm into its floor on purpose: it
      // must get exactly that warning (W0004).
      if (relative == "examples/numerics/initial_overlap.sled") {
        EXPECT_EQ(outcome.errors, 0) << outcome.report;
        EXPECT_EQ(outcome.warnings, 1) << outcome.report;
        EXPECT_NE(outcome.report.find("W0004"), std::string::npos) << outcome.report;
        continue;
      }
      EXPECT_EQ(outcome.errors + outcome.warnings, 0)
          << relative << ": " << outcome.errors << " errors and " << outcome.warnings
          << " warnings\n"
          << outcome.report;
    }
  }
  // The files the documentation and README promise.
  for (const char* expected :
       {"examples/frontal_sled.sled", "examples/frontal_sled_airbag.sled", "examples/pendulum.sled",
        "examples/pedestrian.sled", "examples/ejection_seat.sled", "examples/four_bar.sled",
        "stdlib/humans/male50.sled", "stdlib/vehicles/midsize_driver.sled",
        "stdlib/pulses/ncap_56kmh.sled", "stdlib/pulses/r16_50kmh.sled",
        "stdlib/pulses/r44_50kmh.sled"}) {
    EXPECT_TRUE(seen.count(expected)) << expected << " is missing";
  }
}

TEST(ExamplesAndStdlib, EveryExampleHasAReadmeLine) {
  const std::string readme = ReadOrFail(kRoot + "/examples/README.md");
  for (const std::filesystem::path& file : SledFilesUnder(kRoot + "/examples")) {
    // Linked by its path under examples/: `(pendulum.sled)`, `(legacy/x.sled)`.
    const std::string name = std::filesystem::relative(file, kRoot + "/examples").generic_string();
    EXPECT_NE(readme.find("(" + name + ")"), std::string::npos)
        << "examples/README.md has no line for " << name;
  }
}

TEST(DocsReference, NamesEverySchemaWordOutputCriterionQuantityAndUnit) {
  const std::string text = ReadOrFail(kRoot + "/docs/language.md");
  auto mentioned = [&](std::string_view word) {
    return text.find(fmt::format("`{}`", word)) != std::string::npos;
  };
  std::vector<std::string> missing;
  for (const BlockSpec& spec : AllBlockSpecs()) {
    for (const AttributeSpec& attribute : spec.attributes) {
      if (!mentioned(attribute.name)) {
        missing.push_back(
            fmt::format("attribute `{}` of {}", attribute.name, BlockName(spec.kind)));
      }
    }
    for (const DeclarationSpec& declaration : spec.declarations) {
      if (!mentioned(declaration.keyword)) {
        missing.push_back(
            fmt::format("declaration `{}` in {}", declaration.keyword, BlockName(spec.kind)));
      }
    }
  }
  for (const OutputSpec& output : AllOutputSpecs()) {
    if (!mentioned(output.keyword)) missing.push_back(fmt::format("output `{}`", output.keyword));
  }
  for (const CriterionSpec& criterion : AllCriterionSpecs()) {
    if (!mentioned(criterion.name)) {
      missing.push_back(fmt::format("criterion `{}`", criterion.name));
    }
  }
  for (const QuantityName& quantity : AllQuantityNames()) {
    if (!mentioned(quantity.name)) {
      missing.push_back(fmt::format("function quantity `{}`", quantity.name));
    }
  }
  for (const UnitInfo& unit : AllUnits()) {
    if (!mentioned(unit.symbol)) missing.push_back(fmt::format("unit `{}`", unit.symbol));
  }
  std::string list;
  for (const std::string& item : missing) list += "  " + item + "\n";
  EXPECT_TRUE(missing.empty()) << "docs/language.md does not mention (in backquotes):\n" << list;
}

}  // namespace
}  // namespace sled::compiler
