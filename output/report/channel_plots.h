// The plots of a run's channels: one per channel group (the components of one quantity of one
// request), under a heading per request; the filtered channel drawn bold over its raw one,
// in display units (g, kN, mm, deg against ms), with each component's peak below the plot.
#pragma once

#include <optional>
#include <string>

#include "output/report/channel_table.h"
#include "output/report/svg_plot.h"

namespace sled::report {

// The plot spec of one group: the raw and the filtered series of each named column (either
// table may lack a column, `filtered` may be absent), the y axis labelled with `quantity` and
// the display unit of `si_unit`, the legend naming the components.
PlotSpec GroupPlot(const std::string& title, const std::vector<std::string>& names,
                   const std::vector<std::string>& components, const std::string& si_unit,
                   const ChannelTable& raw, const ChannelTable* filtered,
                   const std::string& quantity);

// The section with every plot; a note instead when there are no channels.
std::string ChannelPlotsSection(const ChannelTable& raw, const ChannelTable* filtered);

}  // namespace sled::report
