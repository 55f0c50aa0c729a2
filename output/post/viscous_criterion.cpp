#include "output/post/viscous_criterion.h"

namespace sled::runtime::post {

ViscousResult ViscousCriterion(std::span<const double> deflection, double sample_period,
                               double start_time, const ViscousConstants& constants) {
  ViscousResult result;
  const std::span<const double> d = deflection;
  bool first = true;
  for (std::size_t i = 2; i + 2 < d.size(); ++i) {
    const double velocity =
        (8.0 * (d[i + 1] - d[i - 1]) - (d[i + 2] - d[i - 2])) / (12.0 * sample_period);
    const double vc = constants.scale * velocity * d[i] / constants.critical_deflection;
    if (first || vc > result.value) {
      result = {vc, start_time + static_cast<double>(i) * sample_period};
      first = false;
    }
  }
  return result;
}

}  // namespace sled::runtime::post
