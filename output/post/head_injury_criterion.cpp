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
  // The windows are ranked by duration * m^2 sqrt(m), m the mean: the same order as with
  // m^2.5 (both are monotone in the same quantity, to a rounding), at a fraction of pow's cost;
  // the value is the best window's, by pow, at the end.
  double best_rank = 0.0;
  std::size_t best_i = 0, best_j = 0;
  for (std::size_t i = 0; i + 1 < n; ++i) {
    const std::size_t last = std::min(n - 1, i + widest);
    for (std::size_t j = i + 1; j <= last; ++j) {
      const double integral = area[j] - area[i];
      if (integral <= 0.0) continue;
      const double duration = static_cast<double>(j - i) * sample_period;
      const double mean = integral / duration;
      const double rank = duration * (mean * mean * std::sqrt(mean));
      if (rank > best_rank) {
        best_rank = rank;
        best_i = i;
        best_j = j;
      }
    }
  }
  if (best_j > best_i) {
    const double duration = static_cast<double>(best_j - best_i) * sample_period;
    best = {duration * std::pow((area[best_j] - area[best_i]) / duration, 2.5),
            start_time + static_cast<double>(best_i) * sample_period,
            start_time + static_cast<double>(best_j) * sample_period};
  }
  return best;
}

}  // namespace sled::runtime::post
