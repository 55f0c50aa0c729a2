// Peak loads (neck tension and compression, femur compression): the largest positive sample and
// when it occurs.
#pragma once

#include <span>

namespace sled::runtime::post {

struct PeakResult {
  double value = 0.0;  // 0 when no sample is positive
  double time = 0.0;
};

PeakResult PositivePeak(std::span<const double> signal, double sample_period, double start_time);

}  // namespace sled::runtime::post
