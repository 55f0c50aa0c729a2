#include "output/post/neck_injury_criterion.h"

#include <algorithm>
#include <cmath>

namespace sled::runtime::post {

const char* QuadrantName(NeckQuadrant quadrant) {
  switch (quadrant) {
    case NeckQuadrant::kTensionExtension:
      return "NTE";
    case NeckQuadrant::kTensionFlexion:
      return "NTF";
    case NeckQuadrant::kCompressionExtension:
      return "NCE";
    case NeckQuadrant::kCompressionFlexion:
      return "NCF";
  }
  return "";
}

const char* NkmQuadrantName(NeckQuadrant quadrant) {
  switch (quadrant) {
    case NeckQuadrant::kTensionExtension:
      return "NEA";
    case NeckQuadrant::kTensionFlexion:
      return "NFA";
    case NeckQuadrant::kCompressionExtension:
      return "NEP";
    case NeckQuadrant::kCompressionFlexion:
      return "NFP";
  }
  return "";
}

NijResult NeckInjuryCriterion(std::span<const double> fz, std::span<const double> fx,
                              std::span<const double> my, double condyle_offset,
                              const NeckIntercepts& intercepts, double sample_period,
                              double start_time) {
  NijResult result;
  const std::size_t n = std::min({fz.size(), fx.size(), my.size()});
  for (std::size_t k = 0; k < n; ++k) {
    const double moment = my[k] - condyle_offset * fx[k];
    const bool tension = fz[k] >= 0.0;
    const bool flexion = moment >= 0.0;
    const double value = std::abs(fz[k]) / (tension ? intercepts.tension : intercepts.compression) +
                         std::abs(moment) / (flexion ? intercepts.flexion : intercepts.extension);
    const NeckQuadrant quadrant =
        tension
            ? (flexion ? NeckQuadrant::kTensionFlexion : NeckQuadrant::kTensionExtension)
            : (flexion ? NeckQuadrant::kCompressionFlexion : NeckQuadrant::kCompressionExtension);
    QuadrantPeak& peak = result.quadrants[static_cast<std::size_t>(quadrant)];
    const double time = start_time + static_cast<double>(k) * sample_period;
    if (!peak.reached || value > peak.value) peak = {value, time, true};
    if (value > result.value || k == 0) {
      result.value = value;
      result.time = time;
      result.quadrant = quadrant;
    }
  }
  return result;
}

}  // namespace sled::runtime::post
