// Golden tests of the front end (docs/architecture.md, recipes): every file in tests/golden is
// parsed and checked as `sled check` would, and what comes out is compared with the expected file
// next to it.
//
//   fail_<code>_<what>.sled  ->  <name>.stderr    compact diagnostics, sorted by position; the
//                                                  file must report <code> (an error for E codes)
//   ok_<what>.sled           ->  <name>.checked   compiler::Dump of the checked scenario; the
//                                                  file must check without any diagnostic
//   rich_<what>.sled         ->  <name>.rendered  lang::RenderRich output, without color
//   note_<code>_<what>.sled  ->  <name>.stderr    compact diagnostics of the whole sled::Compile
//                                                  (lowering included); must report the note
//                                                  <code> and no error
//
// Paths in the messages are relative to the repository root: the test runs with the working
// directory there and loads each file under its repository-relative path, so imports resolve
// relative to tests/golden as they do for `sled check tests/golden/x.sled`.
//
// A leading comment `// sled-test: --set NAME=VALUE` passes a parameter override to the checker;
// `// sled-test: --vary TEXT` (and `--sample lhs=N`, `--design FILE.csv`) builds a sweep design
// after the check, for the E06xx codes.
//
// Set SLED_UPDATE_GOLDEN=1 to write the expected files instead of comparing with them; review the
// change with `git diff tests/golden` before committing it.
#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "compiler/check/check.h"
#include "compiler/check/checked_scenario.h"
#include "compiler/sweep/design.h"
#include "lang/diagnostics/diagnostic.h"
#include "lang/diagnostics/render.h"
#include "lang/source/source_manager.h"
#include "lang/syntax/parser.h"
#include "sled/compile.h"
#include "tests/compiler/sled_process.h"

namespace sled::compiler {
namespace {

namespace fs = std::filesystem;
using sled::testing::WorkingDirectory;

const fs::path kRoot = SLED_SOURCE_ROOT;
constexpr std::string_view kGoldenFolder = "tests/golden";
constexpr std::string_view kDirective = "// sled-test:";

bool UpdateRequested() {
  const char* update = std::getenv("SLED_UPDATE_GOLDEN");
  return update != nullptr && std::string_view(update) == "1";
}

std::optional<std::string> ReadText(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

void WriteText(const fs::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << text;
  ASSERT_TRUE(out.good()) << "cannot write " << path;
}

bool StartsWith(std::string_view text, std::string_view prefix) {
  return text.substr(0, prefix.size()) == prefix;
}

std::string Upper(std::string text) {
  for (char& c : text) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return text;
}

// The golden inputs, by file name, in a stable order.
std::vector<std::string> GoldenFiles() {
  std::vector<std::string> names;
  std::error_code error;
  for (const auto& entry : fs::directory_iterator(kRoot / kGoldenFolder, error)) {
    if (!entry.is_regular_file() || entry.path().extension() != ".sled") continue;
    const std::string name = entry.path().filename().string();
    if (StartsWith(name, "fail_") || StartsWith(name, "ok_") || StartsWith(name, "rich_") ||
        StartsWith(name, "note_")) {
      names.push_back(name);
    }
  }
  std::sort(names.begin(), names.end());
  return names;
}

// The `// sled-test:` lines at the top of a golden file: `--set NAME=VALUE` overrides, and a
// sweep design (`--vary TEXT`, `--sample lhs=N`, `--design FILE` beside the golden file) that
// is built after the check, as `sled sweep --check` does.
struct Directives {
  std::vector<std::pair<std::string, std::string>> overrides;
  std::vector<std::string> vary;
  std::string design_file;
  Sampling sampling = Sampling::kNone;
  int samples = 0;
  bool has_design() const { return !vary.empty() || !design_file.empty(); }
};

Directives DirectivesIn(const std::string& text) {
  Directives directives;
  std::istringstream lines(text);
  std::string line;
  while (std::getline(lines, line) && StartsWith(line, "//")) {
    if (!StartsWith(line, kDirective)) continue;
    std::string_view rest = std::string_view(line).substr(kDirective.size());
    while (!rest.empty() && rest.front() == ' ') rest.remove_prefix(1);
    auto take = [&](std::string_view option) {
      if (!StartsWith(rest, option)) return false;
      rest.remove_prefix(option.size());
      return true;
    };
    if (take("--vary ")) {
      directives.vary.emplace_back(rest);
    } else if (take("--design ")) {
      directives.design_file = std::string(rest);
    } else if (take("--sample ")) {
      directives.sampling =
          StartsWith(rest, "sobol=") ? Sampling::kSobol : Sampling::kLatinHypercube;
      directives.samples = std::stoi(std::string(rest.substr(rest.find('=') + 1)));
    } else if (take("--set ")) {
      const std::size_t equals = rest.find('=');
      if (equals == std::string_view::npos) {
        ADD_FAILURE() << "write `// sled-test: --set NAME=VALUE`: " << line;
        continue;
      }
      directives.overrides.emplace_back(std::string(rest.substr(0, equals)),
                                        std::string(rest.substr(equals + 1)));
    } else {
      ADD_FAILURE() << "unknown sled-test directive: " << line;
    }
  }
  return directives;
}

// One file through the front end, as `sled check` runs it.
struct Outcome {
  lang::SourceManager sources;
  lang::DiagnosticCollector diagnostics;
  CheckedScenario scenario;

  std::string Compact() const {
    std::string out;
    for (const lang::Diagnostic& d : diagnostics.diagnostics()) {
      out += lang::RenderCompact(sources, d) + "\n";
    }
    return out;
  }
  std::string Rich() const {
    std::string out;
    for (const lang::Diagnostic& d : diagnostics.diagnostics()) {
      out += lang::RenderRich(sources, d, lang::RenderOptions{false}) + "\n";
    }
    return out;
  }
  bool Reports(std::string_view code) const {
    return std::any_of(diagnostics.diagnostics().begin(), diagnostics.diagnostics().end(),
                       [&](const lang::Diagnostic& d) { return d.code() == code; });
  }
};

std::unique_ptr<Outcome> CheckGolden(const std::string& relative_path, const std::string& text) {
  auto outcome = std::make_unique<Outcome>();
  // The checked file must be the first buffer: lints only report on the file being checked.
  const lang::FileId file = outcome->sources.Add(relative_path, text);
  lang::ParseOptions parse_options;
  parse_options.diagnostics = &outcome->diagnostics;
  const lang::ast::File ast = lang::Parse(outcome->sources, file, parse_options);
  CheckOptions check_options;
  check_options.diagnostics = &outcome->diagnostics;
  check_options.stdlib_root = (kRoot / "stdlib").string();
  const Directives directives = DirectivesIn(text);
  check_options.overrides = directives.overrides;
  outcome->scenario = Check(outcome->sources, ast, check_options);
  if (directives.has_design() && !outcome->diagnostics.has_errors()) {
    DesignRequest request;
    for (const std::string& vary : directives.vary) {
      request.vary.push_back(outcome->sources.Add("--vary", vary));
    }
    if (!directives.design_file.empty()) {
      const std::string path = std::string(kGoldenFolder) + "/" + directives.design_file;
      request.csv = outcome->sources.Load(path);
      EXPECT_TRUE(request.csv.has_value()) << "cannot read " << path;
    }
    request.sampling = directives.sampling;
    request.samples = directives.samples;
    for (const auto& [name, value] : directives.overrides) request.fixed.push_back(name);
    BuildDesign(outcome->sources, request, outcome->scenario, outcome->diagnostics);
  }
  outcome->diagnostics.SortByPosition();
  return outcome;
}

// One file through sled::Compile, lowering included, as `sled run` compiles it.
std::string CompileGolden(const std::string& relative_path, const std::string& text,
                          bool* has_errors) {
  CompileOptions options;
  options.stdlib = (kRoot / "stdlib").string();
  options.overrides = DirectivesIn(text).overrides;
  const Compilation compiled = Compile(Source::Text(text, relative_path), options);
  *has_errors = !compiled.ok();
  return compiled.Render(lang::DiagnosticStyle::kCompact);
}

// The first line where two texts differ, to make a failure readable.
std::string FirstDifference(const std::string& actual, const std::string& expected) {
  std::istringstream a(actual);
  std::istringstream e(expected);
  std::string line_a;
  std::string line_e;
  for (int line = 1;; ++line) {
    const bool more_a = static_cast<bool>(std::getline(a, line_a));
    const bool more_e = static_cast<bool>(std::getline(e, line_e));
    if (!more_a && !more_e) return "the texts differ only in their final newline";
    if (!more_a) line_a = "<end>";
    if (!more_e) line_e = "<end>";
    if (line_a != line_e || !more_a || !more_e) {
      std::ostringstream difference;
      difference << "first difference at line " << line << ":\n  actual:   " << line_a
                 << "\n  expected: " << line_e;
      return difference.str();
    }
  }
}

// Compares with the expected file, or writes it when updating.
void ExpectMatchesFile(const std::string& actual, const fs::path& expected_path) {
  if (UpdateRequested()) {
    WriteText(expected_path, actual);
    return;
  }
  const std::optional<std::string> expected = ReadText(expected_path);
  ASSERT_TRUE(expected.has_value())
      << "missing " << expected_path << "; run with SLED_UPDATE_GOLDEN=1 to create it";
  EXPECT_EQ(actual, *expected) << expected_path.filename().string() << ": "
                               << FirstDifference(actual, *expected)
                               << "\n(run with SLED_UPDATE_GOLDEN=1 to accept the new output)";
}

class GoldenTest : public ::testing::TestWithParam<std::string> {};

TEST_P(GoldenTest, MatchesExpectedOutput) {
  const std::string name = GetParam();
  const std::string stem = name.substr(0, name.size() - std::string_view(".sled").size());
  const std::string relative = std::string(kGoldenFolder) + "/" + name;
  const fs::path folder = kRoot / kGoldenFolder;
  WorkingDirectory at_root(kRoot);

  const std::optional<std::string> text = ReadText(kRoot / relative);
  ASSERT_TRUE(text.has_value()) << "cannot read " << relative;
  // fail_<code>_<what> and note_<code>_<what>: the code is the second part of the name.
  std::string code;
  std::optional<lang::DiagnosticKind> kind;
  if (StartsWith(name, "fail_") || StartsWith(name, "note_")) {
    const std::size_t end = name.find('_', 5);
    ASSERT_NE(end, std::string::npos)
        << name << ": name it " << name.substr(0, 5) << "<code>_<what>.sled";
    code = Upper(name.substr(5, end - 5));
    kind = lang::FindDiagnosticByCode(code);
    ASSERT_TRUE(kind.has_value()) << name << ": `" << code << "` is not a registered code";
  }
  if (StartsWith(name, "note_")) {
    // The whole compile reports the note, and no error.
    EXPECT_EQ(lang::InfoOf(*kind).severity, lang::Severity::kNote) << name;
    bool has_errors = false;
    const std::string compact = CompileGolden(relative, *text, &has_errors);
    EXPECT_FALSE(has_errors) << name << " reports errors:\n" << compact;
    EXPECT_NE(compact.find("[" + code + "]"), std::string::npos)
        << name << " does not report " << code << ":\n"
        << compact;
    ExpectMatchesFile(compact, folder / (stem + ".stderr"));
    return;
  }
  const auto outcome = CheckGolden(relative, *text);

  if (StartsWith(name, "fail_")) {
    EXPECT_TRUE(outcome->Reports(code)) << name << " does not report " << code << ":\n"
                                        << outcome->Compact();
    if (lang::InfoOf(*kind).severity == lang::Severity::kError) {
      EXPECT_TRUE(outcome->diagnostics.has_errors()) << name << " reports no error";
    } else {
      EXPECT_GT(outcome->diagnostics.warning_count(), 0) << name << " reports no warning";
    }
    ExpectMatchesFile(outcome->Compact(), folder / (stem + ".stderr"));
  } else if (StartsWith(name, "ok_")) {
    EXPECT_EQ(outcome->diagnostics.diagnostics().size(), 0u) << name << " must check clean:\n"
                                                             << outcome->Compact();
    ExpectMatchesFile(Dump(outcome->scenario), folder / (stem + ".checked"));
  } else {
    EXPECT_TRUE(outcome->diagnostics.has_errors()) << name << " reports no error";
    ExpectMatchesFile(outcome->Rich(), folder / (stem + ".rendered"));
  }
}

std::string TestNameOf(const ::testing::TestParamInfo<std::string>& info) {
  std::string name = info.param.substr(0, info.param.size() - std::string_view(".sled").size());
  for (char& c : name) {
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  }
  return name;
}

INSTANTIATE_TEST_SUITE_P(Golden, GoldenTest, ::testing::ValuesIn(GoldenFiles()), TestNameOf);

// --- Coverage: every code has a golden test and a documentation page -------------------------

// Codes that need no golden file: E0107 (an unreadable file, tested through the driver), the
// legacy-deck codes E05xx and W05xx, which have their own tests
// (tests/legacy/legacy_reader_test.cpp), and W0010, which the run reports, not the checker
// (tests/verification/contact_tunnel_test.cpp).
bool ExemptFromGolden(std::string_view code) {
  return code == "E0107" || code == "W0010" || StartsWith(code, "E05") || StartsWith(code, "W05");
}

std::string AllExpectedDiagnostics() {
  std::string all;
  std::error_code error;
  for (const auto& entry : fs::directory_iterator(kRoot / kGoldenFolder, error)) {
    const std::string extension = entry.path().extension().string();
    if (extension == ".stderr" || extension == ".rendered") {
      all += ReadText(entry.path()).value_or("");
    }
  }
  return all;
}

TEST(GoldenCoverage, FindsTheGoldenFiles) {
  const std::vector<std::string> files = GoldenFiles();
  EXPECT_GE(std::count_if(files.begin(), files.end(),
                          [](const std::string& f) { return StartsWith(f, "ok_"); }),
            5);
  EXPECT_TRUE(std::find(files.begin(), files.end(), "rich_e0204.sled") != files.end());
}

TEST(GoldenCoverage, EveryCodeIsReportedByAGoldenFile) {
  const std::string expected = AllExpectedDiagnostics();
  const std::vector<std::string> files = GoldenFiles();
  for (const lang::DiagnosticInfo& info : lang::AllDiagnostics()) {
    if (ExemptFromGolden(info.code)) continue;
    const std::string tag = "[" + std::string(info.code) + "]";
    EXPECT_NE(expected.find(tag), std::string::npos)
        << info.code << " (" << info.name << ") appears in no tests/golden/*.stderr file";
    const std::string prefix =
        (info.severity == lang::Severity::kNote ? "note_" : "fail_") + std::string(info.code) + "_";
    const bool named = std::any_of(files.begin(), files.end(), [&](const std::string& file) {
      return StartsWith(Upper(file), Upper(prefix));
    });
    EXPECT_TRUE(named) << "no tests/golden/" << prefix << "<what>.sled";
  }
}

TEST(GoldenCoverage, EveryExpectedFileHasItsInput) {
  std::error_code error;
  for (const auto& entry : fs::directory_iterator(kRoot / kGoldenFolder, error)) {
    const std::string extension = entry.path().extension().string();
    if (extension != ".stderr" && extension != ".checked" && extension != ".rendered") continue;
    fs::path input = entry.path();
    input.replace_extension(".sled");
    EXPECT_TRUE(fs::exists(input)) << entry.path().filename() << " has no " << input.filename();
  }
}

TEST(GoldenCoverage, EveryCodeHasADocumentationPage) {
  const fs::path docs = kRoot / "docs/diagnostics";
  const std::string index = ReadText(docs / "README.md").value_or("");
  for (const lang::DiagnosticInfo& info : lang::AllDiagnostics()) {
    const std::string code(info.code);
    const std::optional<std::string> page = ReadText(docs / (code + ".md"));
    if (!page) {
      ADD_FAILURE() << "no docs/diagnostics/" << code << ".md for " << info.name;
      continue;
    }
    EXPECT_TRUE(StartsWith(*page, "# " + code + ": "))
        << code << ".md must start with `# " << code << ": <title>`";
    // The pages are embedded in raw string literals delimited by `)sledpage"`.
    EXPECT_EQ(page->find(")sledpage\""), std::string::npos) << code << ".md";
    EXPECT_NE(page->find("```sled"), std::string::npos) << code << ".md has no example";
    const std::string link = std::string("[").append(code).append("](").append(code).append(".md)");
    EXPECT_NE(index.find(link), std::string::npos)
        << "docs/diagnostics/README.md does not link " << code;
  }
}

TEST(GoldenCoverage, EveryDocumentationPageIsARegisteredCode) {
  std::error_code error;
  int pages = 0;
  for (const auto& entry : fs::directory_iterator(kRoot / "docs/diagnostics", error)) {
    if (entry.path().extension() != ".md" || entry.path().filename() == "README.md") continue;
    ++pages;
    const std::string code = entry.path().stem().string();
    EXPECT_TRUE(lang::FindDiagnosticByCode(code).has_value())
        << "docs/diagnostics/" << code << ".md documents no registered code";
  }
  EXPECT_GT(pages, 0);
}

// --- The registry ------------------------------------------------------------------------------

TEST(GoldenRegistry, FindDiagnosticByCodeFindsEveryCode) {
  std::set<std::string_view> codes;
  for (const lang::DiagnosticInfo& info : lang::AllDiagnostics()) {
    EXPECT_TRUE(codes.insert(info.code).second) << info.code << " is registered twice";
    const auto kind = lang::FindDiagnosticByCode(info.code);
    ASSERT_TRUE(kind.has_value()) << info.code;
    EXPECT_EQ(*kind, info.kind) << info.code;
    EXPECT_EQ(lang::InfoOf(*kind).code, info.code);
    EXPECT_EQ(lang::InfoOf(*kind).name, info.name);
  }
}

TEST(GoldenRegistry, FindDiagnosticByCodeRejectsOtherText) {
  for (std::string_view text : {"", "E", "E9999", "W0000", "E02044", "0204", " E0204", "E0204 "}) {
    EXPECT_FALSE(lang::FindDiagnosticByCode(text).has_value()) << "`" << text << "`";
  }
}

TEST(GoldenRegistry, CodesFollowTheNumberingScheme) {
  for (const lang::DiagnosticInfo& info : lang::AllDiagnostics()) {
    const std::string_view code = info.code;
    ASSERT_EQ(code.size(), 5u) << code;
    EXPECT_TRUE(std::all_of(code.begin() + 1, code.end(), [](char c) {
      return std::isdigit(static_cast<unsigned char>(c));
    })) << code;
    if (code[0] == 'E') {
      EXPECT_EQ(info.severity, lang::Severity::kError) << code;
      EXPECT_TRUE(code[1] == '0' && code[2] >= '1' && code[2] <= '6') << code;
    } else if (code[0] == 'N') {
      // Notes come from the lowering only (E04xx's stage).
      EXPECT_EQ(info.severity, lang::Severity::kNote) << code;
      EXPECT_TRUE(code[1] == '0' && code[2] == '4') << code;
    } else {
      EXPECT_EQ(code[0], 'W') << code;
      EXPECT_EQ(info.severity, lang::Severity::kWarning) << code;
    }
    EXPECT_FALSE(info.summary.empty()) << code;
  }
}

}  // namespace
}  // namespace sled::compiler
