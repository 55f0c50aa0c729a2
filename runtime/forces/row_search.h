// Finding the row of a table that starts the piece holding a time (or an argument): a binary
// search, ceil(log2(count + 1)) comparisons at most, for tables whose rows are read through an
// accessor (a column of rows, the corners of a trapezoid). Tests count the comparisons through
// the accessor.
#pragma once

#include <cstddef>

namespace sled::runtime {

// How many of the `count` rows, in increasing `key_of(k)`, have a key at most `x`: the row that
// starts the piece holding x is one less (none when it is 0, the last row when it is count).
template <typename Key>
std::size_t RowsUpTo(std::size_t count, Key key_of, double x) {
  std::size_t low = 0, high = count;
  while (low < high) {
    const std::size_t middle = low + (high - low) / 2;
    if (key_of(middle) <= x) {
      low = middle + 1;
    } else {
      high = middle;
    }
  }
  return low;
}

}  // namespace sled::runtime
