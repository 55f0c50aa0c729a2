// The "3 ms" criteria: the highest level a signal exceeds for a given duration (head 3 ms,
// chest 3 ms clip). The signal is the straight line between samples. Cumulative: the time above
// the level summed over the record is at least the duration (FMVSS 208's "intervals whose
// cumulative duration is not more than 3 ms"). Continuous: one single interval above the level
// lasts at least the duration (the single-peak clip).
#pragma once

#include <span>

namespace sled::runtime::post {

enum class ExceedanceKind { kCumulative, kContinuous };

struct ExceedanceResult {
  bool defined = false;  // false when the record is shorter than the duration
  double level = 0.0;    // in the signal's unit
  // Continuous: the interval above the level. Cumulative: from the first to the last moment
  // above it.
  double t_start = 0.0;
  double t_end = 0.0;
};

ExceedanceResult LevelExceededFor(std::span<const double> signal, double sample_period,
                                  double start_time, double duration, ExceedanceKind kind);

}  // namespace sled::runtime::post
