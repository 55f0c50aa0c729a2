#include "output/post/peak_load.h"

namespace sled::runtime::post {

PeakResult PositivePeak(std::span<const double> signal, double sample_period, double start_time) {
  PeakResult peak{0.0, start_time};
  for (std::size_t k = 0; k < signal.size(); ++k) {
    if (signal[k] > peak.value) {
      peak = {signal[k], start_time + static_cast<double>(k) * sample_period};
    }
  }
  return peak;
}

}  // namespace sled::runtime::post
