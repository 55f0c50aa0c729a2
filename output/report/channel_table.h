// A time-series file `sled run` writes (timeseries.csv, timeseries_filtered.csv): a header of
// channel names, the first `time [s]`, then one row of numbers per output time.
#pragma once

#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

namespace sled::report {

struct ChannelTable {
  std::vector<double> time;                  // [s], one per row
  std::vector<std::string> names;            // the channels, without the time column
  std::vector<std::vector<double>> columns;  // columns[c][row]
  // The column of each name, for Find (ParseChannelTable fills it; empty: a linear search).
  std::unordered_map<std::string, std::size_t> index;

  // The column of `name`, or nullptr.
  const std::vector<double>* Find(const std::string& name) const;
};

// Reads CSV text; nullopt with `error` set when the header does not start with a time column
// or a row has the wrong number of fields. A field that is no number reads as NaN.
std::optional<ChannelTable> ParseChannelTable(const std::string& text, std::string* error);

}  // namespace sled::report
