#include "output/report/number_text.h"

#include <cmath>

#include <fmt/format.h>

namespace sled::report {

namespace {
constexpr const char* kMissing = "–";
}

std::string Significant(double value, int digits) {
  if (!std::isfinite(value)) return kMissing;
  return fmt::format("{:.{}g}", value, digits);
}

std::string Milliseconds(double seconds) {
  if (!std::isfinite(seconds)) return kMissing;
  std::string text = fmt::format("{:.2f}", seconds * 1e3);
  // 62.10 -> 62.1, 30.00 -> 30
  while (text.back() == '0') text.pop_back();
  if (text.back() == '.') text.pop_back();
  if (text == "-0") text = "0";
  return text;
}

std::string Significant(const std::optional<double>& value, int digits) {
  return value ? Significant(*value, digits) : kMissing;
}

}  // namespace sled::report
