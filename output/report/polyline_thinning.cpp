#include "output/report/polyline_thinning.h"

#include <algorithm>
#include <cmath>

namespace sled::report {

std::vector<std::size_t> ThinForColumns(std::span<const double> x, std::span<const double> y,
                                        double x_low, double x_high, int columns) {
  const std::size_t n = std::min(x.size(), y.size());
  std::vector<std::size_t> kept;
  if (n == 0) return kept;
  const double width = x_high - x_low;
  auto column_of = [&](double value) {
    if (!(width > 0.0) || !std::isfinite(value)) return -1L;
    return static_cast<long>(std::floor((value - x_low) / width * columns));
  };
  // One run of samples in the same column at a time: its first, lowest, highest and last.
  std::size_t start = 0;
  while (start < n) {
    const long column = column_of(x[start]);
    std::size_t end = start + 1;
    if (std::isfinite(y[start]) && column >= 0) {
      while (end < n && std::isfinite(y[end]) && column_of(x[end]) == column) ++end;
    }
    std::size_t lowest = start;
    std::size_t highest = start;
    for (std::size_t i = start; i < end; ++i) {
      if (y[i] < y[lowest]) lowest = i;
      if (y[i] > y[highest]) highest = i;
    }
    for (const std::size_t i :
         {start, std::min(lowest, highest), std::max(lowest, highest), end - 1}) {
      if (kept.empty() || kept.back() < i) kept.push_back(i);
    }
    start = end;
  }
  return kept;
}

}  // namespace sled::report
