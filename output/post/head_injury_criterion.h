// The Head Injury Criterion: HIC = max over windows t1 < t2 with t2 - t1 <= W of
// (t2 - t1) * [ (1 / (t2 - t1)) * integral of a(t) from t1 to t2 ]^2.5, with the head's resultant
// acceleration a in g and t in s (W = 15 ms for HIC15, 36 ms for HIC36). Every pair of samples
// is tried: the largest window is not always the worst, since the expression is not monotone in
// the window's length.
#pragma once

#include <span>

namespace sled::runtime::post {

struct HicResult {
  double value = 0.0;
  double t1 = 0.0;  // the window that gives the value [s]
  double t2 = 0.0;
};

// `resultant_g`: samples every `sample_period` seconds from `start_time`. The integral is the
// trapezoid rule over the samples, so windows start and end on samples. A record without any
// window of positive integral gives 0 over an empty window at `start_time`.
HicResult HeadInjuryCriterion(std::span<const double> resultant_g, double sample_period,
                              double start_time, double max_window);

}  // namespace sled::runtime::post
