#include "sled/output_folder.h"

#include <filesystem>
#include <optional>
#include <utility>

#include "output/export/animation_glb.h"
#include "output/export/iso_mme_writer.h"
#include "output/export/state_dump.h"
#include "output/output_writer.h"
#include "output/post/channel_peaks.h"

namespace sled {

OutputFolder::OutputFolder(const runtime::Model& model, OutputFolderOptions options)
    : options_(std::move(options)), animation_(model, runtime::OutputRowCount(model)) {}

void OutputFolder::OnRow(const runtime::Model& model, const runtime::Data& data) {
  (void)model;
  animation_.Record(data);
}

void OutputFolder::OnStop(const runtime::Model& model, const runtime::Data& data) {
  const std::filesystem::path path =
      std::filesystem::path(options_.directory) / runtime::StateDumpFileName(data.time);
  std::string error;
  if (runtime::WriteStateDump(path.string(), model, data, &error)) {
    dumps_written_.push_back(path.string());
  } else {
    dump_errors_.push_back(error);
  }
}

namespace {

std::pair<bool, std::string> WriteSeries(const std::string& path, const runtime::TimeSeries& series,
                                         bool two_threads) {
  std::string why;
  const bool written = runtime::WriteTimeSeriesCsv(path, series, &why, two_threads);
  return {written, why};
}

}  // namespace

void OutputFolder::OnRowValues(std::span<const double> row) {
  if (!options_.parallel_writes) return;
  runtime::AppendCsvRows(row, row.size(), row_lines_);
  ++rows_seen_;
}

void OutputFolder::OnRows(const runtime::Model& model, const runtime::TimeSeries& series) {
  (void)model;
  if (!options_.parallel_writes) return;
  const std::string path = (std::filesystem::path(options_.directory) / "timeseries.csv").string();
  // The lines made as the rows came, unless the series has rows this sink did not see (those
  // a resumed run kept from its checkpoint).
  if (rows_seen_ == series.rows()) {
    series_written_ = std::async(std::launch::async, [this, path, &series] {
      std::string why;
      const bool written =
          runtime::WriteCsvText(path, runtime::TimeSeriesCsvHeader(series), row_lines_, &why);
      return std::pair<bool, std::string>(written, why);
    });
    return;
  }
  series_written_ = std::async(std::launch::async, WriteSeries, path, std::cref(series), true);
}

bool OutputFolder::OnEnd(const runtime::Model& model, const RunResult& result, std::string* error) {
  // Every file is tried: a full disk for the time series still leaves a summary that says so.
  std::vector<std::string> errors;
  auto write = [&](const std::string& name, bool written, const std::string& why) {
    if (written) {
      written_.insert(name);
    } else {
      errors.push_back(why);
    }
  };
  const std::filesystem::path out(options_.directory);
  std::string why;
  // With the rows on a thread of their own (OnRows), the filtered rows and the animation
  // meanwhile; the files are listed (and their errors said) in the same order either way.
  const bool filtered = !result.filtered.names.empty();
  const bool rows_on_thread = series_written_.valid();
  const std::string glb_path = (out / "animation.glb").string();
  std::optional<std::pair<bool, std::string>> filtered_written, glb_written;
  auto write_filtered = [&] {
    return WriteSeries((out / "timeseries_filtered.csv").string(), result.filtered,
                       options_.parallel_writes);
  };
  auto write_glb = [&] {
    std::string glb_why;
    const bool written = runtime::WriteAnimationGlb(glb_path, model, animation_, &glb_why);
    return std::pair<bool, std::string>(written, glb_why);
  };
  if (rows_on_thread) {
    std::future<std::pair<bool, std::string>> glb = std::async(std::launch::async, write_glb);
    if (filtered) filtered_written = write_filtered();
    glb_written = glb.get();
  }
  const std::pair<bool, std::string> series_written =
      rows_on_thread ? series_written_.get()
                     : WriteSeries((out / "timeseries.csv").string(), result.series, false);
  write("timeseries.csv", series_written.first, series_written.second);
  if (filtered) {
    if (!filtered_written) filtered_written = write_filtered();
    write("timeseries_filtered.csv", filtered_written->first, filtered_written->second);
  }
  runtime::SummaryExtras extras;
  extras.warnings = options_.notes;
  extras.warnings.insert(extras.warnings.end(), result.warnings.begin(), result.warnings.end());
  extras.warnings.insert(extras.warnings.end(), errors.begin(), errors.end());
  if (!result.summary.output_error.empty()) extras.warnings.push_back(result.summary.output_error);
  extras.criteria = result.criteria;
  extras.peaks = runtime::post::ChannelPeaks(result.series, result.filtered);
  extras.extrapolations = result.extrapolations;
  if (result.summary.interrupted && options_.interrupted_by) {
    extras.interrupted_by = options_.interrupted_by();
  }
  write("summary.json",
        runtime::WriteSummaryJson((out / "summary.json").string(), model, result.series,
                                  result.summary, extras, &why),
        why);
  if (!glb_written) glb_written = write_glb();
  write("animation.glb", glb_written->first, glb_written->second);
  if (options_.iso_mme) {
    write("iso-mme/",
          runtime::WriteIsoMme((out / "iso-mme").string(), options_.test_name, model, result.series,
                               result.filtered, result.criteria, &why),
          why);
  }
  if (errors.empty()) return true;
  std::string joined;
  for (const std::string& e : errors) joined += (joined.empty() ? "" : "\n") + e;
  if (error) *error = joined;
  return false;
}

}  // namespace sled
