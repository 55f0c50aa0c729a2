#include "output/post/thoracic_trauma_index.h"

#include <cmath>
#include <vector>

#include "output/post/peak_load.h"

namespace sled::runtime::post {
namespace {

PeakResult PeakMagnitude(std::span<const double> signal, double sample_period, double start_time) {
  std::vector<double> magnitude(signal.begin(), signal.end());
  for (double& value : magnitude) value = std::abs(value);
  return PositivePeak(magnitude, sample_period, start_time);
}

}  // namespace

TtiResult ThoracicTraumaIndex(std::span<const double> rib_lateral,
                              std::span<const double> spine_lateral, double sample_period,
                              double start_time) {
  const PeakResult rib = PeakMagnitude(rib_lateral, sample_period, start_time);
  const PeakResult spine = PeakMagnitude(spine_lateral, sample_period, start_time);
  return {0.5 * (rib.value + spine.value), rib.value, spine.value, rib.time, spine.time};
}

}  // namespace sled::runtime::post
