// Reading the CSV files `sled run` writes (a header of names, then rows of numbers), for tests
// that compare other outputs with them.
#pragma once

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace sled::testing {

struct CsvTable {
  std::vector<std::string> names;         // including `time [s]`
  std::vector<std::vector<double>> rows;  // one value per name
  std::size_t Column(const std::string& name) const {
    for (std::size_t c = 0; c < names.size(); ++c) {
      if (names[c] == name) return c;
    }
    return names.size();
  }
};

inline std::vector<std::string> SplitCommas(const std::string& line) {
  std::vector<std::string> fields;
  std::stringstream stream(line);
  std::string field;
  while (std::getline(stream, field, ',')) fields.push_back(field);
  return fields;
}

inline CsvTable ReadCsv(const std::filesystem::path& path) {
  CsvTable table;
  std::ifstream in(path);
  std::string line;
  if (!std::getline(in, line)) return table;
  table.names = SplitCommas(line);
  while (std::getline(in, line)) {
    std::vector<double> row;
    for (const std::string& field : SplitCommas(line))
      row.push_back(std::strtod(field.c_str(), nullptr));
    table.rows.push_back(std::move(row));
  }
  return table;
}

}  // namespace sled::testing
