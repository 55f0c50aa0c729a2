// The formatter over every real file in the tree: examples/, stdlib/, docs' examples are parsed,
// printed and parsed again; the trees must be equal and a second formatting must change nothing
// (issue 2: parse(print(ast)) == ast for every file in examples/ and stdlib/).
#include <filesystem>
#include <initializer_list>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "lang/ast/ast.h"
#include "lang/format/formatter.h"
#include "lang/syntax/parser.h"

namespace sled::lang {
namespace {

std::vector<std::string> CorpusFiles(std::initializer_list<const char*> folders = {
                                         "examples", "stdlib", "tests/golden"}) {
  std::vector<std::string> files;
  for (const char* folder : folders) {
    const std::filesystem::path root = std::filesystem::path(SLED_SOURCE_ROOT) / folder;
    std::error_code error;
    for (auto it = std::filesystem::recursive_directory_iterator(root, error);
         !error && it != std::filesystem::recursive_directory_iterator(); it.increment(error)) {
      if (it->path().extension() == ".sled") files.push_back(it->path().string());
    }
  }
  return files;
}

struct Parsed {
  ast::File file;
  int errors = 0;
};

Parsed ParseText(const std::string& path, const std::string& text) {
  SourceManager sources;
  const FileId id = sources.Add(path, text);
  DiagnosticCollector diagnostics;
  ParseOptions options;
  options.diagnostics = &diagnostics;
  Parsed parsed{Parse(sources, id, options), diagnostics.error_count()};
  return parsed;
}

// The formatter's promise for text that parses cleanly: its output parses cleanly to the same
// tree, and formatting that again changes nothing. Returns what broke, or "" (also for text
// with syntax errors, which the promise does not cover).
std::string BrokenPromise(const std::string& path, const std::string& text) {
  const Parsed original = ParseText(path, text);
  if (original.errors > 0) return "";
  const std::string formatted = Format(original.file);
  const Parsed reparsed = ParseText(path + " (formatted)", formatted);
  const char* broken = reparsed.errors > 0 ? "formats to text with syntax errors"
                       : ast::Dump(reparsed.file) != ast::Dump(original.file)
                           ? "formats to text that parses to a different tree"
                       : Format(reparsed.file) != formatted ? "formats differently a second time"
                                                            : nullptr;
  if (!broken) return "";
  return path + " " + broken + ":\n--- text ---\n" + text + "\n--- formatted ---\n" + formatted;
}

TEST(FormatCorpus, EveryFileRoundTripsThroughTheFormatter) {
  const std::vector<std::string> files = CorpusFiles();
  ASSERT_FALSE(files.empty()) << "no .sled files found under " << SLED_SOURCE_ROOT;
  int checked = 0;
  for (const std::string& path : files) {
    auto text = ReadFile(path);
    ASSERT_TRUE(text.has_value()) << path;
    if (ParseText(path, *text).errors > 0) continue;  // files that test syntax errors
    EXPECT_EQ(BrokenPromise(path, *text), "");
    ++checked;
  }
  EXPECT_GT(checked, 0);
}

// What the parser fuzzer finds first: one character of a real file changed. Every deletion of
// one character of an example, and every separator put in place of or before one, that still
// parses must keep the promise (found this way: `positi;n` joined into `positi  n`, a target,
// and `(a,)` printed as the parenthesised `(a)`).
TEST(FormatCorpus, EverySingleSeparatorEditOfAnExampleKeepsThePromise) {
  const std::string path = std::string(SLED_SOURCE_ROOT) + "/examples/pendulum.sled";
  const auto text = ReadFile(path);
  ASSERT_TRUE(text.has_value()) << path;
  int broken = 0;
  const auto check = [&](const std::string& edited) {
    const std::string problem = BrokenPromise(path + " (edited)", edited);
    if (!problem.empty() && ++broken <= 3) ADD_FAILURE() << problem;
  };
  for (std::size_t i = 0; i < text->size(); ++i) {
    check(std::string(*text).erase(i, 1));
    for (const char separator : {';', ',', '\n', ' '}) {
      check(std::string(*text).insert(i, 1, separator));
      if ((*text)[i] != separator) check(std::string(*text).replace(i, 1, 1, separator));
    }
  }
  EXPECT_EQ(broken, 0);
}

TEST(FormatCorpus, ExamplesAndTheStandardLibraryAreInCanonicalForm) {
  // What users copy from should be what `sled fmt` writes: `sled fmt --check` passes on them.
  int checked = 0;
  for (const std::string& path : CorpusFiles({"examples", "stdlib"})) {
    auto text = ReadFile(path);
    ASSERT_TRUE(text.has_value()) << path;
    const Parsed parsed = ParseText(path, *text);
    ASSERT_EQ(parsed.errors, 0) << path;
    EXPECT_EQ(Format(parsed.file), *text) << path << " is not in canonical form; run sled fmt";
    ++checked;
  }
  EXPECT_GT(checked, 20);
}

}  // namespace
}  // namespace sled::lang
