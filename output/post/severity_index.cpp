#include "output/post/severity_index.h"

#include <algorithm>
#include <cmath>

namespace sled::runtime::post {

double GaddSeverityIndex(std::span<const double> resultant_g, double sample_period) {
  double index = 0.0;
  for (std::size_t k = 1; k < resultant_g.size(); ++k) {
    const double a = std::pow(std::max(resultant_g[k - 1], 0.0), 2.5);
    const double b = std::pow(std::max(resultant_g[k], 0.0), 2.5);
    index += 0.5 * sample_period * (a + b);
  }
  return index;
}

}  // namespace sled::runtime::post
