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
  std::vector<std::string> warnings = options_.notes;
  warnings.insert(warnings.end(), result.warnings.begin(), result.warnings.end());
  const std::filesystem::path out(options_.directory);
  return runtime::WriteTimeSeriesCsv((out / "timeseries.csv").string(), result.series, error) &&
         (result.filtered.names.empty() ||
          runtime::WriteTimeSeriesCsv((out / "timeseries_filtered.csv").string(), result.filtered,
                                      error)) &&
         runtime::WriteSummaryJson((out / "summary.json").string(), model, result.series,
                                   result.summary, warnings, error, result.criteria,
                                   runtime::post::ChannelPeaks(result.series, result.filtered)) &&
         runtime::WriteAnimationGlb((out / "animation.glb").string(), model, animation_, error) &&
         (!options_.iso_mme ||
          runtime::WriteIsoMme((out / "iso-mme").string(), options_.test_name, model, result.series,
                               result.filtered, result.criteria, error));
}

}  // namespace sled
