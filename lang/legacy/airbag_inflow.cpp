#include "lang/legacy/airbag_inflow.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>

#include <fmt/format.h>

namespace sled::lang::legacy {
namespace {

constexpr int kIntervals = 50;
constexpr double kDeliveredShare = 0.999;

// `value` to 6 significant digits, as the scenario prints it.
double Rounded(double value) { return std::strtod(fmt::format("{:.6g}", value).c_str(), nullptr); }

// The largest 1, 2 or 5 times a power of ten at most `value` (> 0), exactly as its decimal reads.
double RoundStep(double value) {
  const int exponent = static_cast<int>(std::floor(std::log10(value)));
  for (const int mantissa : {5, 2, 1}) {
    const double step = std::strtod(fmt::format("{}e{}", mantissa, exponent).c_str(), nullptr);
    if (step <= value) return step;
  }
  return std::strtod(fmt::format("5e{}", exponent - 1).c_str(), nullptr);
}

}  // namespace

InflowTable TabulateCylinder(const Cylinder& c) {
  const double k1 = c.gamma - 1;
  const double sound = std::sqrt(c.gamma * c.gas_constant * c.temperature * c.g);
  const double length = c.volume / c.throat_area;
  const double choke = std::pow((c.gamma + 1) / 2, -(c.gamma + 1) / (2 * k1));
  const double rate = k1 / 2 * sound * c.discharge / length * choke;  // ATB's CYC
  const double weight = c.volume * (c.supply_pressure + c.ambient_pressure) /
                        (c.gas_constant * c.temperature);  // V0 rho0
  // The mass flow dW/dt / G against the time since CYTD.
  auto flow = [&](double t) {
    return weight / c.g * (2 * rate / k1) * std::pow(1 + rate * t, -(c.gamma + 1) / k1);
  };
  InflowTable table;
  table.end = (std::pow(1 - kDeliveredShare, -k1 / 2) - 1) / rate;
  // Extreme deck values (a vanishing throat, G = 0, overflow) give no time to tabulate over.
  if (!std::isfinite(table.end) || !(table.end > 0) || !std::isnormal(table.end / kIntervals)) {
    return table;
  }
  table.step = RoundStep(table.end / kIntervals);
  const int rows = static_cast<int>(std::ceil(table.end / table.step - 1e-9)) + 1;
  double mass = 0;
  for (int k = 0; k < rows; ++k) {
    const double t = Rounded(k * table.step);
    table.rows.emplace_back(t, Rounded(flow(t)));
    if (k > 0) {
      const auto& [t0, f0] = table.rows[static_cast<std::size_t>(k - 1)];
      mass += (t - t0) * (f0 + table.rows.back().second) / 2;
    }
  }
  table.delivered = mass / (weight / c.g);
  table.valid = std::isfinite(table.delivered);
  for (const auto& [t, f] : table.rows) table.valid = table.valid && std::isfinite(f);
  return table;
}

BagFill FillFreeBag(const Cylinder& c, double bag_volume) {
  const double k1 = c.gamma - 1;
  const double pressure = c.supply_pressure + c.ambient_pressure;                // CYP0
  const double weight = c.volume * pressure / (c.gas_constant * c.temperature);  // V0 rho0
  const double largest = c.volume / c.gamma * pressure / c.ambient_pressure;     // CYVMAX
  // The weight delivered and the volume it takes at the ambient pressure, against Q.
  auto delivered = [&](double q) { return weight * (1 - std::pow(q, -2 / k1)); };
  auto ambient_volume = [&](double q) { return largest * (1 - std::pow(q, -2 * c.gamma / k1)); };
  BagFill fill;
  fill.fills = largest > bag_volume;
  if (!fill.fills) {
    fill.reference_temperature = c.temperature / c.gamma;
    return fill;
  }
  const double q_full = std::pow(1 - bag_volume / largest, -k1 / (2 * c.gamma));
  const double per_weight = bag_volume / delivered(q_full);  // SWITCH
  fill.reference_temperature = per_weight * c.ambient_pressure / c.gas_constant;
  constexpr int kSamples = 2000;
  for (int k = 1; k <= kSamples; ++k) {
    const double q = 1 + (q_full - 1) * k / kSamples;
    const double difference = std::abs(ambient_volume(q) - per_weight * delivered(q));
    fill.largest_unfolding_difference =
        std::max(fill.largest_unfolding_difference, difference / bag_volume);
  }
  return fill;
}

}  // namespace sled::lang::legacy
