// The report page: one self-contained HTML file (style, script and animation inside) built
// from what a run's folder holds.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "output/report/channel_table.h"
#include "output/report/run_summary.h"

namespace sled::report {

struct ReportInputs {
  std::string folder;  // the run folder, as named in the page
  RunSummaryFile summary;
  std::optional<ChannelTable> raw;       // timeseries.csv
  std::optional<ChannelTable> filtered;  // timeseries_filtered.csv
  std::string glb;                       // animation.glb's bytes; empty when there is none
  std::vector<std::string> notes;        // what was missing or unreadable, shown on the page
};

std::string BuildReportPage(const ReportInputs& inputs);

// A <script> that runs before anything else: an uncaught error anywhere in the page is written
// into the DOM (`data-script-error` on the root element and a visible line), so a headless
// browser's DOM dump shows it. The report and the sweep page start with it.
std::string_view ErrorTrapScript();

}  // namespace sled::report
