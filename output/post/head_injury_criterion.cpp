#include "output/post/head_injury_criterion.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace sled::runtime::post {

HicResult HeadInjuryCriterion(std::span<const double> resultant_g, double sample_period,
                              double start_time, double max_window) {
  HicResult best{0.0, start_time, start_time};
  const std::size_t n = resultant_g.size();
  if (n < 2 || !(sample_period > 0.0) || !(max_window > 0.0)) return best;
  // Cumulative trapezoid integral: the integral over samples i..j is area[j] - area[i].
  std::vector<double> area(n, 0.0);
  for (std::size_t k = 1; k < n; ++k) {
    area[k] = area[k - 1] + 0.5 * sample_period * (resultant_g[k - 1] + resultant_g[k]);
  }
  const auto widest =
      static_cast<std::size_t>(std::floor(max_window / sample_period * (1.0 + 1e-12)));
  for (std::size_t i = 0; i + 1 < n; ++i) {
    const std::size_t last = std::min(n - 1, i + widest);
    for (std::size_t j = i + 1; j <= last; ++j) {
      const double integral = area[j] - area[i];
      if (integral <= 0.0) continue;
      const double duration = static_cast<double>(j - i) * sample_period;
      const double value = duration * std::pow(integral / duration, 2.5);
      if (value > best.value) {
        best = {value, start_time + static_cast<double>(i) * sample_period,
                start_time + static_cast<double>(j) * sample_period};
      }
    }
  }
  return best;
}

}  // namespace sled::runtime::post
