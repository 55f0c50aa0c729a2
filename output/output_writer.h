// Writing a run's results: timeseries.csv (a `time [s]` column, then one per channel) and
// summary.json (integrator statistics, wall time, error estimate, status, injury criteria,
// warnings).
#pragma once

#include <string>
#include <vector>

#include "output/post/channel_peaks.h"
#include "output/post/criterion_value.h"
#include "runtime/run.h"

namespace sled::runtime {

// Both return false with `error` set when a file cannot be written.
bool WriteTimeSeriesCsv(const std::string& path, const TimeSeries& series, std::string* error);
bool WriteSummaryJson(const std::string& path, const Model& model, const TimeSeries& series,
                      const RunSummary& summary, const std::vector<std::string>& warnings,
                      std::string* error, const std::vector<post::CriterionValue>& criteria = {},
                      const std::vector<post::ChannelPeak>& peaks = {});

// A JSON string literal with the characters JSON requires escaped.
std::string JsonString(const std::string& text);

}  // namespace sled::runtime
