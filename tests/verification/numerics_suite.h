// The numerics suite's list of cases (examples/numerics/suite.txt), which the verification test
// and scripts/numerics.sh both read, so they always run the same scenes.
#pragma once

#include <filesystem>
#include <fstream>
#include <ostream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace sled::verification {

struct SuiteCase {
  std::string kind;  // smooth, stiff or extreme
  std::string name;
  std::filesystem::path file;
  std::vector<std::pair<std::string, std::string>> overrides;  // as `--set NAME=VALUE`
};

// How gtest shows a case.
inline void PrintTo(const SuiteCase& suite_case, std::ostream* out) { *out << suite_case.name; }

inline std::string Trimmed(const std::string& text) {
  const auto first = text.find_first_not_of(" \t");
  if (first == std::string::npos) return "";
  return text.substr(first, text.find_last_not_of(" \t") - first + 1);
}

// Empty when the list cannot be read.
inline std::vector<SuiteCase> LoadSuite() {
  const std::filesystem::path examples = std::filesystem::path(SLED_SOURCE_ROOT) / "examples";
  std::ifstream in(examples / "numerics" / "suite.txt");
  std::vector<SuiteCase> suite;
  std::string line;
  while (std::getline(in, line)) {
    if (Trimmed(line).empty() || Trimmed(line)[0] == '#') continue;
    std::istringstream fields(line);
    SuiteCase c;
    std::string file;
    fields >> c.kind >> c.name >> file;
    c.file = examples / file;
    std::string rest;
    std::getline(fields, rest);
    std::istringstream items(rest);
    std::string item;
    while (std::getline(items, item, ';')) {
      item = Trimmed(item);
      const auto equals = item.find('=');
      if (equals == std::string::npos) continue;
      c.overrides.emplace_back(Trimmed(item.substr(0, equals)), Trimmed(item.substr(equals + 1)));
    }
    suite.push_back(std::move(c));
  }
  return suite;
}

}  // namespace sled::verification
