#include "runtime/airbag/gas.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace sled::runtime {

double OrificeMassFlow(double discharge_area, double pressure, double temperature,
                       double ambient_pressure, double gamma, double gas_constant) {
  if (discharge_area <= 0 || pressure <= ambient_pressure || temperature <= 0) return 0.0;
  const double ratio = ambient_pressure / pressure;
  const double critical = std::pow(2.0 / (gamma + 1.0), gamma / (gamma - 1.0));
  const double density_speed = pressure / std::sqrt(gas_constant * temperature);  // p / sqrt(RT)
  if (ratio <= critical) {
    // Sonic at the throat: the flow no longer depends on the outside pressure.
    return discharge_area * density_speed * std::sqrt(gamma) *
           std::pow(2.0 / (gamma + 1.0), (gamma + 1.0) / (2.0 * (gamma - 1.0)));
  }
  const double expansion = std::pow(ratio, 2.0 / gamma) - std::pow(ratio, (gamma + 1.0) / gamma);
  return discharge_area * density_speed *
         std::sqrt(2.0 * gamma / (gamma - 1.0) * std::max(expansion, 0.0));
}

double PolytropicPressure(double ambient_pressure, double ambient_volume, double volume,
                          double gamma) {
  return ambient_pressure * std::pow(ambient_volume / volume, gamma);
}

double SquareRootVentFlow(double discharge_area, double density, double gauge,
                          double opening_pressure) {
  if (discharge_area <= 0 || gauge <= 0 || gauge <= opening_pressure) return 0.0;
  return discharge_area * std::sqrt(2.0 * density * gauge);
}

EllipsoidCap CutEllipsoidCap(const Vec3& semi_axes, const Mat3& rotation, const Vec3& normal,
                             double height) {
  // Cross-sections perpendicular to n have area A0 (1 - s^2 / H^2) at distance s from the
  // centre, H being the support extent along n and A0 = pi a b c / H.
  const Vec3 local = rotation.transpose() * normal;
  const double extent = std::sqrt(local.cwiseProduct(semi_axes).squaredNorm());
  const double h = std::clamp(height, 0.0, 2.0 * extent);
  const double k = std::numbers::pi * semi_axes.prod() / (extent * extent * extent);
  return {k * (extent * h * h - h * h * h / 3.0), k * h * (2.0 * extent - h)};
}

}  // namespace sled::runtime
