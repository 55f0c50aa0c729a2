// docs/architecture.md against the tree, so the map stays true:
//   - every path it names in backticks exists, and every `file:Name` names something in the file;
//   - the include rules of its library table hold for every source file of the libraries.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace sled {
namespace {

namespace fs = std::filesystem;

const fs::path kRoot = SLED_SOURCE_ROOT;
// The folders whose files the include rules govern, and the top folders an include can name.
const std::vector<std::string> kTopFolders = {"lang/", "compiler/", "runtime/", "output/", "sled/"};

std::string ReadText(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

bool StartsWith(const std::string& text, const std::string& prefix) {
  return text.compare(0, prefix.size(), prefix) == 0;
}

// The backticked words of a text.
std::vector<std::string> Backticked(const std::string& text) {
  std::vector<std::string> words;
  static const std::regex kWord("`([^`\n]+)`");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), kWord);
       it != std::sregex_iterator(); ++it) {
    words.push_back((*it)[1].str());
  }
  return words;
}

// A backticked word that names a path of the repository: it starts with a top folder of the
// tree and has no spaces.
bool IsRepositoryPath(const std::string& word) {
  static const std::vector<std::string> kFolders = {"lang/",   "compiler/", "runtime/", "output/",
                                                    "sled/",   "tests/",    "docs/",    "examples/",
                                                    "stdlib/", "scripts/"};
  return word.find(' ') == std::string::npos &&
         std::any_of(kFolders.begin(), kFolders.end(),
                     [&](const std::string& folder) { return StartsWith(word, folder); });
}

const std::string kDoc = ReadText(kRoot / "docs/architecture.md");

TEST(Architecture, TheDocumentExists) { ASSERT_GT(kDoc.size(), 1000u); }

TEST(Architecture, EveryNamedFileAndNameExists) {
  int checked = 0;
  for (const std::string& word : Backticked(kDoc)) {
    if (!IsRepositoryPath(word)) continue;
    std::string path = word;
    std::string name;
    if (const std::size_t colon = word.find(':'); colon != std::string::npos) {
      path = word.substr(0, colon);
      name = word.substr(colon + 1);
    }
    if (path.find('<') != std::string::npos) continue;  // a pattern: docs/diagnostics/<code>.md
    ++checked;
    const fs::path full = kRoot / path;
    if (!fs::exists(full)) {
      ADD_FAILURE() << "docs/architecture.md names `" << word << "`, and " << path
                    << " does not exist";
      continue;
    }
    if (!name.empty()) {
      // The last part of a qualified name (Lowering::AddNote -> AddNote), as a whole word.
      const std::string last =
          name.substr(name.rfind(':') == std::string::npos ? 0 : name.rfind(':') + 1);
      const std::regex whole("\\b" + last + "\\b");
      EXPECT_TRUE(std::regex_search(ReadText(full), whole))
          << "docs/architecture.md names `" << word << "`, and " << path << " has no " << last;
    }
  }
  EXPECT_GT(checked, 40) << "the document names fewer files than expected: is it the map?";
}

// One row of the library table: a folder, the folders its files may include, and those they
// may not although an allowed folder contains them.
struct IncludeRule {
  std::string folder;
  std::vector<std::string> allowed;
  std::vector<std::string> forbidden;
};

std::vector<std::string> SplitCells(const std::string& line) {
  std::vector<std::string> cells;
  std::string cell;
  for (std::size_t i = 1; i < line.size(); ++i) {
    if (line[i] == '|') {
      cells.push_back(cell);
      cell.clear();
    } else {
      cell += line[i];
    }
  }
  return cells;
}

std::vector<IncludeRule> IncludeRules() {
  std::vector<IncludeRule> rules;
  std::istringstream lines(kDoc.substr(kDoc.find("## 2. ")));
  std::string line;
  while (std::getline(lines, line)) {
    if (StartsWith(line, "## 3.")) break;
    if (!StartsWith(line, "| `")) continue;
    const std::vector<std::string> cells = SplitCells(line);
    if (cells.size() < 4) continue;
    const std::vector<std::string> folder = Backticked(cells[0]);
    if (folder.size() != 1) continue;
    rules.push_back({folder[0], Backticked(cells[2]), Backticked(cells[3])});
  }
  return rules;
}

TEST(Architecture, TheLibraryTableHasARowPerLibraryFolder) {
  std::vector<std::string> folders;
  for (const IncludeRule& rule : IncludeRules()) folders.push_back(rule.folder);
  for (const char* folder : {"lang/", "lang/legacy/", "runtime/", "output/", "output/report/",
                             "compiler/", "compiler/driver/", "sled/"}) {
    EXPECT_NE(std::find(folders.begin(), folders.end(), folder), folders.end())
        << "no row for " << folder << " in docs/architecture.md's library table";
  }
}

TEST(Architecture, EverySourceFileKeepsItsLibrarysIncludeRule) {
  const std::vector<IncludeRule> rules = IncludeRules();
  ASSERT_FALSE(rules.empty());
  static const std::regex kInclude("^#include \"([^\"]+)\"");
  int files = 0;
  for (const std::string& top : kTopFolders) {
    for (const auto& entry : fs::recursive_directory_iterator(kRoot / top)) {
      const std::string extension = entry.path().extension().string();
      if (!entry.is_regular_file() || (extension != ".h" && extension != ".cpp")) continue;
      const std::string relative = fs::relative(entry.path(), kRoot).generic_string();
      // The longest folder of the table that holds the file decides.
      const IncludeRule* rule = nullptr;
      for (const IncludeRule& candidate : rules) {
        if (StartsWith(relative, candidate.folder) &&
            (rule == nullptr || candidate.folder.size() > rule->folder.size())) {
          rule = &candidate;
        }
      }
      ASSERT_NE(rule, nullptr) << relative << " is in no folder of the library table";
      ++files;
      std::istringstream lines(ReadText(entry.path()));
      std::string line;
      for (int number = 1; std::getline(lines, line); ++number) {
        std::smatch match;
        if (!std::regex_search(line, match, kInclude)) continue;
        const std::string included = match[1].str();
        const bool project =
            std::any_of(kTopFolders.begin(), kTopFolders.end(),
                        [&](const std::string& f) { return StartsWith(included, f); });
        if (!project) continue;
        auto under = [&](const std::vector<std::string>& folders) {
          return std::any_of(folders.begin(), folders.end(),
                             [&](const std::string& f) { return StartsWith(included, f); });
        };
        EXPECT_TRUE(under(rule->allowed) && !under(rule->forbidden))
            << relative << ":" << number << " includes \"" << included << "\", which "
            << rule->folder << " may not include (docs/architecture.md, section 2)";
      }
    }
  }
  EXPECT_GT(files, 200);
}

}  // namespace
}  // namespace sled
