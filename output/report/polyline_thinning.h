// Which samples of a long series a plot needs: no more than a few per pixel column, yet every
// peak. A 200 ms run at 0.1 ms has 2001 samples per channel, a plot some 560 columns; keeping
// the first, the lowest, the highest and the last sample of each column draws the same picture
// as all of them, and keeps the page small.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

namespace sled::report {

// The indices to keep, increasing, of samples (x[i], y[i]) whose x runs from `x_low` to
// `x_high` over `columns` pixel columns. Non-finite samples are kept (the path breaks there).
std::vector<std::size_t> ThinForColumns(std::span<const double> x, std::span<const double> y,
                                        double x_low, double x_high, int columns);

}  // namespace sled::report
