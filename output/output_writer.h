// Writing a run's results: timeseries.csv (a `time [s]` column, then one per channel) and
// summary.json (integrator statistics, wall time, error estimate, status, injury criteria,
// warnings).
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "output/post/channel_peaks.h"
#include "output/post/criterion_value.h"
#include "runtime/forces/table_range.h"
#include "runtime/run/run.h"

namespace sled::runtime {

// The writers return false with `error` set when a file cannot be written.
// timeseries.csv (or the filtered rows): `two_threads` formats half the rows on a second thread.
bool WriteTimeSeriesCsv(const std::string& path, const TimeSeries& series, std::string* error,
                        bool two_threads = false);
// The same file in parts: its header line, and the lines of rows (`columns` values each)
// appended to `out`; WriteCsvText writes a header and rows made so.
std::string TimeSeriesCsvHeader(const TimeSeries& series);
void AppendCsvRows(std::span<const double> values, std::size_t columns, std::string& out);
bool WriteCsvText(const std::string& path, const std::string& header, const std::string& rows,
                  std::string* error);
// What summary.json says besides the Model, the rows and the RunSummary.
struct SummaryExtras {
  std::vector<std::string> warnings;
  std::vector<post::CriterionValue> criteria;
  std::string interrupted_by;            // the signal that interrupted the run: "SIGINT", ...
  std::vector<post::ChannelPeak> peaks;  // each channel's extreme of largest magnitude
  std::vector<TableExtrapolation> extrapolations;  // elements that left their tables' rows
};

// The run's status word: "ok", "failed" (numerical failure), "interrupted" or "write_failed"
// (an output written during the run, a checkpoint, could not be).
std::string_view RunStatus(const RunSummary& summary);

// summary.json is always valid JSON: a number that is not finite is written as null, with a
// warning that names it, and text that is not valid UTF-8 has U+FFFD in place of its bad bytes.
bool WriteSummaryJson(const std::string& path, const Model& model, const TimeSeries& series,
                      const RunSummary& summary, const SummaryExtras& extras, std::string* error);

// A JSON string literal with the characters JSON requires escaped (and invalid UTF-8 replaced).
std::string JsonString(const std::string& text);

}  // namespace sled::runtime
