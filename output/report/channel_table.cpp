#include "output/report/channel_table.h"

#include <charconv>
#include <cmath>
#include <limits>
#include <string_view>

#include <fmt/format.h>

namespace sled::report {
namespace {

std::vector<std::string_view> SplitFields(std::string_view line) {
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  std::vector<std::string_view> fields;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    fields.push_back(
        line.substr(start, comma == std::string_view::npos ? line.npos : comma - start));
    if (comma == std::string_view::npos) return fields;
    start = comma + 1;
  }
}

double ToNumber(std::string_view field) {
  double value = std::numeric_limits<double>::quiet_NaN();
  const char* end = field.data() + field.size();
  const auto [at, status] = std::from_chars(field.data(), end, value);
  // fmt writes "inf" and "nan" for non-finite values, which from_chars reads too.
  if (status != std::errc() || at != end) return std::numeric_limits<double>::quiet_NaN();
  return value;
}

}  // namespace

const std::vector<double>* ChannelTable::Find(const std::string& name) const {
  if (!index.empty()) {
    const auto at = index.find(name);
    return at == index.end() ? nullptr : &columns[at->second];
  }
  for (std::size_t c = 0; c < names.size(); ++c) {
    if (names[c] == name) return &columns[c];
  }
  return nullptr;
}

std::optional<ChannelTable> ParseChannelTable(const std::string& text, std::string* error) {
  auto fail = [&](const std::string& message) -> std::optional<ChannelTable> {
    if (error) *error = message;
    return std::nullopt;
  };
  ChannelTable table;
  std::string_view rest = text;
  std::size_t line_number = 0;
  bool header = true;
  while (!rest.empty()) {
    const std::size_t newline = rest.find('\n');
    const std::string_view line = rest.substr(0, newline);
    rest = newline == std::string_view::npos ? std::string_view() : rest.substr(newline + 1);
    ++line_number;
    if (line.empty() || line == "\r") continue;
    const std::vector<std::string_view> fields = SplitFields(line);
    if (header) {
      if (fields.front().substr(0, 4) != "time") {
        return fail("the first column is not the time");
      }
      for (std::size_t f = 1; f < fields.size(); ++f) {
        table.index.emplace(fields[f], table.names.size());
        table.names.emplace_back(fields[f]);
      }
      table.columns.resize(table.names.size());
      header = false;
      continue;
    }
    if (fields.size() != table.names.size() + 1) {
      return fail(fmt::format("line {} has {} fields, the header {}", line_number, fields.size(),
                              table.names.size() + 1));
    }
    table.time.push_back(ToNumber(fields[0]));
    for (std::size_t c = 0; c < table.names.size(); ++c) {
      table.columns[c].push_back(ToNumber(fields[c + 1]));
    }
  }
  if (header) return fail("the file is empty");
  return table;
}

}  // namespace sled::report
