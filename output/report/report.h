// `sled report DIR`: reads what `sled run` wrote into DIR (summary.json, timeseries.csv,
// timeseries_filtered.csv, animation.glb) and writes the report page.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace sled::report {

struct ReportResult {
  bool written = false;
  std::string error;               // why nothing was written
  std::vector<std::string> notes;  // files that were missing or unreadable (the page says so too)
};

// Writes the page for the run in `directory` to `output`. summary.json must be readable; a
// missing or unreadable channel file or animation leaves its section out with a note.
ReportResult WriteReport(const std::filesystem::path& directory,
                         const std::filesystem::path& output);

}  // namespace sled::report
