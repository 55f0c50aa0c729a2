#include "output/report/axis_ticks.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

namespace sled::report {

double NiceStep(double rough) {
  const double power = std::pow(10.0, std::floor(std::log10(rough)));
  const double fraction = rough / power;  // in [1, 10)
  // A small allowance so that a rough step of exactly 2e-3, which the division may leave a hair
  // above 2, stays 2e-3.
  constexpr double kSlack = 1e-9;
  for (const double nice : {1.0, 2.0, 5.0}) {
    if (fraction <= nice * (1.0 + kSlack)) return nice * power;
  }
  return 10.0 * power;
}

AxisTicks ChooseTicks(double low, double high, int target) {
  target = std::max(target, 2);
  if (!std::isfinite(low) || !std::isfinite(high)) {
    low = 0.0;
    high = 1.0;
  }
  if (low > high) std::swap(low, high);
  if (high - low <= 1e-12 * std::max(std::abs(low), std::abs(high))) {
    // A constant: show it in the middle of a range of its own size (or of 1 around zero).
    const double half = low == 0.0 ? 1.0 : 0.5 * std::abs(low);
    low -= half;
    high += half;
  }
  AxisTicks ticks;
  ticks.step = NiceStep((high - low) / target);
  // Tick k is k * mantissa * 10^exponent, computed as an integer over an exact power of ten so
  // that it is the double nearest the decimal (0.3, not 3 * 0.1 = 0.30000000000000004).
  const int exponent = static_cast<int>(std::floor(std::log10(ticks.step) + 1e-9));
  const double power = std::pow(10.0, std::abs(exponent));
  const double mantissa = std::round(exponent < 0 ? ticks.step * power : ticks.step / power);
  auto tick = [&](double k) { return exponent < 0 ? k * mantissa / power : k * mantissa * power; };
  const double first = std::floor(low / ticks.step);
  const double last = std::ceil(high / ticks.step);
  for (double k = first; k <= last; k += 1.0) ticks.values.push_back(tick(k));
  ticks.low = ticks.values.front();
  ticks.high = ticks.values.back();
  ticks.step = tick(1.0);
  ticks.decimals = std::max(0, -exponent);
  return ticks;
}

void ValueRange::Include(double value) {
  if (!std::isfinite(value)) return;
  if (empty()) {
    low = high = value;
    return;
  }
  low = std::min(low, value);
  high = std::max(high, value);
}

void ValueRange::Include(std::span<const double> values) {
  for (const double value : values) Include(value);
}

std::string TickLabel(double value, int decimals) {
  std::string label = fmt::format("{:.{}f}", value, decimals);
  if (label.find_first_not_of("-0.") == std::string::npos) return "0";
  return label;
}

}  // namespace sled::report
