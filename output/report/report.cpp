#include "output/report/report.h"

#include <optional>

#include <fmt/format.h>

#include "lang/source/source_manager.h"
#include "output/atomic_file.h"
#include "output/report/report_page.h"

namespace sled::report {
namespace {

// A channel file, or nullopt with a note saying what went wrong.
std::optional<ChannelTable> ReadChannels(const std::filesystem::path& path,
                                         std::vector<std::string>& notes) {
  const std::optional<std::string> text = lang::ReadFile(path.string());
  if (!text) {
    notes.push_back(fmt::format("{} is missing: its plots are left out", path.filename().string()));
    return std::nullopt;
  }
  std::string error;
  std::optional<ChannelTable> table = ParseChannelTable(*text, &error);
  if (!table) {
    notes.push_back(fmt::format("{} is unreadable ({}): its plots are left out",
                                path.filename().string(), error));
  }
  return table;
}

}  // namespace

ReportResult WriteReport(const std::filesystem::path& directory,
                         const std::filesystem::path& output) {
  ReportResult result;
  const std::filesystem::path summary_path = directory / "summary.json";
  const std::optional<std::string> summary_text = lang::ReadFile(summary_path.string());
  if (!summary_text) {
    result.error = fmt::format("cannot read `{}`: is `{}` the output folder of `sled run`?",
                               summary_path.string(), directory.string());
    return result;
  }
  ReportInputs inputs;
  std::string error;
  std::optional<RunSummaryFile> summary = ParseRunSummary(*summary_text, &error);
  if (!summary) {
    result.error = fmt::format("`{}`: {}", summary_path.string(), error);
    return result;
  }
  inputs.summary = std::move(*summary);
  inputs.folder = directory.string();
  inputs.raw = ReadChannels(directory / "timeseries.csv", inputs.notes);
  if (inputs.raw) {
    inputs.filtered = ReadChannels(directory / "timeseries_filtered.csv", inputs.notes);
  }
  if (std::optional<std::string> glb = lang::ReadFile((directory / "animation.glb").string())) {
    inputs.glb = std::move(*glb);
  } else {
    inputs.notes.emplace_back("animation.glb is missing: the page has no animation");
  }
  const std::string page = BuildReportPage(inputs);
  if (!runtime::ReplaceFile(output.string(), page, &result.error)) return result;
  result.written = true;
  result.notes = std::move(inputs.notes);
  return result;
}

}  // namespace sled::report
