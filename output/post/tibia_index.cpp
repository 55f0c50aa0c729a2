#include "output/post/tibia_index.h"

#include <algorithm>
#include <cmath>

namespace sled::runtime::post {

TibiaResult TibiaIndex(std::span<const double> moment_x, std::span<const double> moment_y,
                       std::span<const double> axial_force, double sample_period, double start_time,
                       const TibiaConstants& constants) {
  const std::size_t n = std::min({moment_x.size(), moment_y.size(), axial_force.size()});
  TibiaResult best{0.0, start_time};
  for (std::size_t k = 0; k < n; ++k) {
    const double index = std::hypot(moment_x[k], moment_y[k]) / constants.critical_moment +
                         std::abs(axial_force[k]) / constants.critical_force;
    if (index > best.value) best = {index, start_time + static_cast<double>(k) * sample_period};
  }
  return best;
}

}  // namespace sled::runtime::post
