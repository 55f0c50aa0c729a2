#include "sled/output_folder.h"

#include <filesystem>
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
  write("timeseries.csv",
        runtime::WriteTimeSeriesCsv((out / "timeseries.csv").string(), result.series, &why), why);
  if (!result.filtered.names.empty()) {
    write("timeseries_filtered.csv",
          runtime::WriteTimeSeriesCsv((out / "timeseries_filtered.csv").string(), result.filtered,
                                      &why),
          why);
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
  write("animation.glb",
        runtime::WriteAnimationGlb((out / "animation.glb").string(), model, animation_, &why), why);
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
