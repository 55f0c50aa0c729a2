// A run's output rows: what runtime::Run fills and the output library (filters, criteria,
// writers, export) reads, without the rest of the run's interface.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace sled::runtime {

// Rows of `columns` values: time, then the channels of ChannelNames(model).
struct TimeSeries {
  std::vector<std::string> names;  // without the time column
  std::size_t columns = 0;         // 1 + names.size()
  std::vector<double> values;      // row-major
  std::size_t rows() const { return columns == 0 ? 0 : values.size() / columns; }
};

}  // namespace sled::runtime
