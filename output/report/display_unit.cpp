#include "output/report/display_unit.h"

#include <array>
#include <numbers>
#include <string_view>

namespace sled::report {
namespace {

constexpr double kStandardGravity = 9.80665;  // [m/s^2], the g of SAE J211 and ISO 6487
constexpr double kDegreesPerRadian = 180.0 / std::numbers::pi;

struct Conversion {
  std::string_view si;
  std::string_view shown;
  double scale;
};

constexpr std::array kConversions = {
    Conversion{"s", "ms", 1e3},
    Conversion{"m/s^2", "g", 1.0 / kStandardGravity},
    Conversion{"N", "kN", 1e-3},
    Conversion{"N*m", "N·m", 1.0},
    Conversion{"m", "mm", 1e3},
    Conversion{"rad", "deg", kDegreesPerRadian},
    Conversion{"rad/s", "deg/s", kDegreesPerRadian},
    Conversion{"rad/s^2", "rad/s²", 1.0},
};

}  // namespace

DisplayUnit DisplayUnitFor(const std::string& si_unit) {
  for (const Conversion& c : kConversions) {
    if (c.si == si_unit) return {std::string(c.shown), c.scale};
  }
  return {si_unit, 1.0};
}

}  // namespace sled::report
