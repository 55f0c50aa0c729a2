// The range and tick marks of a plot axis: round steps (1, 2 or 5 times a power of ten) so the
// labels read easily, and a range that starts and ends on a tick and holds every value.
#pragma once

#include <span>
#include <string>
#include <vector>

namespace sled::report {

struct AxisTicks {
  double low = 0.0;   // the axis starts here (a tick)
  double high = 1.0;  // and ends here (a tick)
  double step = 0.2;
  std::vector<double> values;  // low, low + step, ..., high
  int decimals = 1;            // digits after the point the labels need
};

// The smallest of 1, 2, 5 and 10 times a power of ten that is at least `rough` (> 0).
double NiceStep(double rough);

// Ticks for data from `low` to `high` with about `target` intervals (at least 2). Equal ends
// (a constant channel) get a range around the value; non-finite ends give 0 to 1.
AxisTicks ChooseTicks(double low, double high, int target = 5);

// The finite extremes of some values (nullopt-like: low > high when none is finite).
struct ValueRange {
  double low = 0.0;
  double high = -1.0;
  bool empty() const { return low > high; }
  void Include(double value);
  void Include(std::span<const double> values);
};

// A tick's label: fixed point with the axis's decimals, and "0" for a zero that rounding made
// negative.
std::string TickLabel(double value, int decimals);

}  // namespace sled::report
