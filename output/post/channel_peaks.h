// The peak of every output channel of a run: the value of largest magnitude and its time, from
// the filtered channel where the run filters one (as the criteria and the report use it), else
// from the raw channel. summary.json lists them; `sled sweep` tabulates them across runs.
#pragma once

#include <string>
#include <vector>

#include "runtime/run/time_series.h"

namespace sled::runtime::post {

struct ChannelPeak {
  std::string channel;  // the column name, `occupant.head.acceleration.x [m/s^2]`
  double value = 0.0;   // signed: the extreme of larger magnitude
  double time = 0.0;    // [s]
  bool filtered = false;
};

// One peak per channel of `raw`, in its order; a channel with no finite value has none.
std::vector<ChannelPeak> ChannelPeaks(const TimeSeries& raw, const TimeSeries& filtered);

}  // namespace sled::runtime::post
