#include "output/post/exceedance.h"

#include <algorithm>

namespace sled::runtime::post {
namespace {

struct TimeAbove {
  double total = 0.0;    // summed over the record
  double longest = 0.0;  // the longest single interval
  double longest_start = 0.0, longest_end = 0.0;
  double first = -1.0, last = -1.0;  // first and last moment above; -1: never
};

// The parts of the piecewise-linear signal at or above `level`, in time from the record start.
TimeAbove MeasureAbove(std::span<const double> x, double dt, double level) {
  TimeAbove out;
  double run_start = -1.0;  // start of the current interval above, -1 when below
  auto close_run = [&](double end) {
    if (run_start < 0.0) return;
    if (end - run_start > out.longest) {
      out.longest = end - run_start;
      out.longest_start = run_start;
      out.longest_end = end;
    }
    out.last = end;
    run_start = -1.0;
  };
  if (x[0] >= level) {
    run_start = 0.0;
    out.first = 0.0;
  }
  for (std::size_t k = 0; k + 1 < x.size(); ++k) {
    const double t0 = static_cast<double>(k) * dt;
    const double a = x[k], b = x[k + 1];
    const bool a_above = a >= level, b_above = b >= level;
    if (a_above && b_above) {
      out.total += dt;
    } else if (a_above != b_above) {
      const double crossing = t0 + dt * (level - a) / (b - a);
      if (a_above) {
        out.total += crossing - t0;
        close_run(crossing);
      } else {
        out.total += t0 + dt - crossing;
        run_start = crossing;
        if (out.first < 0.0) out.first = crossing;
      }
    }
  }
  close_run(static_cast<double>(x.size() - 1) * dt);
  return out;
}

}  // namespace

ExceedanceResult LevelExceededFor(std::span<const double> signal, double sample_period,
                                  double start_time, double duration, ExceedanceKind kind) {
  ExceedanceResult result;
  if (signal.size() < 2 || !(sample_period > 0.0)) return result;
  const double record = static_cast<double>(signal.size() - 1) * sample_period;
  if (record < duration) return result;
  auto enough = [&](const TimeAbove& above) {
    return (kind == ExceedanceKind::kCumulative ? above.total : above.longest) >=
           duration * (1.0 - 1e-12);
  };
  // The time above a level falls as the level rises: bisect for the highest level still held
  // for the duration. The lowest sample is held for the whole record.
  double low = *std::min_element(signal.begin(), signal.end());
  double high = *std::max_element(signal.begin(), signal.end());
  if (enough(MeasureAbove(signal, sample_period, high))) low = high;
  for (int iteration = 0; iteration < 200 && high - low > 1e-12 * std::max(1.0, high);
       ++iteration) {
    const double middle = 0.5 * (low + high);
    (enough(MeasureAbove(signal, sample_period, middle)) ? low : high) = middle;
  }
  const TimeAbove above = MeasureAbove(signal, sample_period, low);
  result.defined = true;
  result.level = low;
  if (kind == ExceedanceKind::kContinuous) {
    result.t_start = start_time + above.longest_start;
    result.t_end = start_time + above.longest_end;
  } else {
    result.t_start = start_time + above.first;
    result.t_end = start_time + above.last;
  }
  return result;
}

}  // namespace sled::runtime::post
