#include "output/post/channel_peaks.h"

#include <cmath>
#include <unordered_map>

namespace sled::runtime::post {

std::vector<ChannelPeak> ChannelPeaks(const TimeSeries& raw, const TimeSeries& filtered) {
  std::unordered_map<std::string, std::size_t> filtered_column;
  for (std::size_t c = 0; c < filtered.names.size(); ++c) filtered_column[filtered.names[c]] = c;
  std::vector<ChannelPeak> peaks;
  for (std::size_t c = 0; c < raw.names.size(); ++c) {
    const auto found = filtered_column.find(raw.names[c]);
    const bool use_filtered = found != filtered_column.end();
    const TimeSeries& series = use_filtered ? filtered : raw;
    const std::size_t column = 1 + (use_filtered ? found->second : c);
    ChannelPeak peak{raw.names[c], 0.0, 0.0, use_filtered};
    bool any = false;
    for (std::size_t row = 0; row < series.rows(); ++row) {
      const double value = series.values[row * series.columns + column];
      if (!std::isfinite(value)) continue;
      if (!any || std::abs(value) > std::abs(peak.value)) {
        peak.value = value;
        peak.time = series.values[row * series.columns];
        any = true;
      }
    }
    if (any) peaks.push_back(std::move(peak));
  }
  return peaks;
}

}  // namespace sled::runtime::post
