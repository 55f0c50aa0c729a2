// The binary search that finds a table's row: the right row for every argument (against a
// linear scan), and a number of comparisons that grows with log2 of the rows, not with the rows.
#include <cmath>
#include <cstddef>
#include <vector>

#include <gtest/gtest.h>

#include "runtime/forces/row_search.h"

namespace sled::runtime {
namespace {

TEST(RowSearch, FindsTheRowThatAScanFinds) {
  const std::vector<double> times = {-1.0, 0.0, 0.5, 0.75, 2.0, 9.0};
  for (double x = -2.0; x <= 10.0; x += 0.125) {
    std::size_t scanned = 0;
    while (scanned < times.size() && times[scanned] <= x) ++scanned;
    EXPECT_EQ(RowsUpTo(
                  times.size(), [&](std::size_t k) { return times[k]; }, x),
              scanned)
        << x;
  }
  EXPECT_EQ(RowsUpTo(
                0, [](std::size_t) { return 0.0; }, 1.0),
            0u);
}

TEST(RowSearch, ComparisonsGrowWithTheLogarithmOfTheRows) {
  for (const std::size_t count :
       {std::size_t{301}, std::size_t{3003}, std::size_t{6003}, std::size_t{600003}}) {
    std::vector<double> times(count);
    for (std::size_t k = 0; k < count; ++k) times[k] = 1e-4 * static_cast<double>(k);
    const auto bound =
        static_cast<std::size_t>(std::ceil(std::log2(static_cast<double>(count) + 1.0)));
    std::size_t worst = 0;
    for (std::size_t k = 0; k < 200; ++k) {
      const double x = times.back() * static_cast<double>(k) / 199.0 + 0.3e-4;
      std::size_t comparisons = 0;
      RowsUpTo(
          count,
          [&](std::size_t i) {
            ++comparisons;
            return times[i];
          },
          x);
      worst = std::max(worst, comparisons);
    }
    EXPECT_LE(worst, bound) << count << " rows";
  }
}

}  // namespace
}  // namespace sled::runtime
