#include "output/post/whiplash_criterion.h"

#include <algorithm>
#include <limits>

namespace sled::runtime::post {

NicResult NeckInjuryCriterionOfRearImpact(std::span<const double> t1, std::span<const double> head,
                                          double sample_period, double start_time) {
  const std::size_t n = std::min(t1.size(), head.size());
  NicResult best{-std::numeric_limits<double>::infinity(), start_time};
  double relative_velocity = 0.0;
  double previous = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    const double relative = t1[k] - head[k];
    if (k > 0) relative_velocity += 0.5 * (previous + relative) * sample_period;
    previous = relative;
    const double nic = 0.2 * relative + relative_velocity * relative_velocity;
    if (nic > best.value) best = {nic, start_time + static_cast<double>(k) * sample_period};
  }
  if (n == 0) best.value = 0.0;
  return best;
}

}  // namespace sled::runtime::post
