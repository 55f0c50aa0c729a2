#include "output/report/channel_plots.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <fmt/format.h>

#include "output/report/channel_groups.h"
#include "output/report/display_unit.h"
#include "output/report/html_text.h"
#include "output/report/number_text.h"

namespace sled::report {
namespace {

// The most plots one page holds (each is a few kilobytes of SVG).
constexpr std::size_t kMaxPlots = 500;

// Distinct hues for the components of one plot (x, y, z, normal, ...).
constexpr std::array<const char*, 8> kPalette = {"#1f5fbf", "#d62728", "#2a9d3a", "#8e44ad",
                                                 "#e67e22", "#6d4c41", "#d63384", "#0f9fb0"};
constexpr double kFilteredWidth = 1.7;
constexpr double kRawWidth = 1.0;
constexpr double kRawOpacity = 0.4;

std::vector<double> Scaled(const std::vector<double>& values, double scale) {
  std::vector<double> out(values.size());
  for (std::size_t i = 0; i < values.size(); ++i) out[i] = values[i] * scale;
  return out;
}

// "x: peak −45.2 g at 62.1 ms" for the larger in magnitude of a channel's extremes.
std::string PeakText(const std::string& component, const std::vector<double>& time,
                     const std::vector<double>& values, const DisplayUnit& unit) {
  std::size_t peak = values.size();
  for (std::size_t i = 0; i < values.size() && i < time.size(); ++i) {
    if (!std::isfinite(values[i])) continue;
    if (peak == values.size() || std::abs(values[i]) > std::abs(values[peak])) peak = i;
  }
  if (peak == values.size()) return "";
  return fmt::format("<span>{}{}{} {} at {} ms</span>",
                     component.empty() ? "" : "<b>" + EscapeHtml(component) + "</b> ",
                     component.empty() ? "peak " : "", Significant(values[peak] * unit.scale, 4),
                     EscapeHtml(unit.unit), Milliseconds(time[peak]));
}

}  // namespace

PlotSpec GroupPlot(const std::string& title, const std::vector<std::string>& names,
                   const std::vector<std::string>& components, const std::string& si_unit,
                   const ChannelTable& raw, const ChannelTable* filtered,
                   const std::string& quantity) {
  const DisplayUnit unit = DisplayUnitFor(si_unit);
  const DisplayUnit time_unit = DisplayUnitFor("s");
  PlotSpec spec;
  spec.title = title;
  spec.x_label = fmt::format("time [{}]", time_unit.unit);
  spec.y_label = unit.unit.empty() ? quantity : fmt::format("{} [{}]", quantity, unit.unit);
  bool any_raw = false;
  bool any_filtered = false;
  for (std::size_t i = 0; i < names.size(); ++i) {
    const std::string color = kPalette[i % kPalette.size()];
    const std::vector<double>* raw_values = raw.Find(names[i]);
    const std::vector<double>* filtered_values = filtered ? filtered->Find(names[i]) : nullptr;
    // The raw one first, so the filtered one is drawn over it.
    if (raw_values) {
      spec.series.push_back({Scaled(raw.time, time_unit.scale),
                             Scaled(*raw_values, unit.scale),
                             {color, filtered_values ? kRawWidth : kFilteredWidth,
                              filtered_values ? kRawOpacity : 1.0}});
      any_raw = true;
    }
    if (filtered_values) {
      spec.series.push_back({Scaled(filtered->time, time_unit.scale),
                             Scaled(*filtered_values, unit.scale),
                             {color, kFilteredWidth, 1.0}});
      any_filtered = true;
    }
    if (names.size() > 1 || !components[i].empty()) {
      spec.legend.push_back({components[i], {color, kFilteredWidth, 1.0}});
    }
  }
  // Which line is which, when a plot shows both.
  if (any_raw && any_filtered) {
    spec.legend.push_back({"filtered", {"#555", kFilteredWidth, 1.0}});
    spec.legend.push_back({"raw", {"#555", kRawWidth, kRawOpacity}});
  }
  return spec;
}

std::string ChannelPlotsSection(const ChannelTable& raw, const ChannelTable* filtered) {
  std::string html = "<section id=\"channels\"><h2>Channels</h2>";
  const std::vector<ChannelGroup> groups = GroupChannels(raw.names);
  if (groups.empty()) return html + "<p class=\"note\">The run wrote no channels.</p></section>";
  html += fmt::format(
      "<p class=\"note\">{} channels in {} plots, in the units engineers read them (the files "
      "hold SI units). {}</p>",
      raw.names.size(), groups.size(),
      filtered ? "Each filtered channel (bold) is drawn over its raw one (light)."
               : "No filtered channels were found (timeseries_filtered.csv).");
  // A page of many thousand plots opens in no browser: the first ones, and a note.
  const std::size_t plotted = std::min(groups.size(), kMaxPlots);
  if (plotted < groups.size()) {
    html += fmt::format(
        "<p class=\"note\">The first {} of the {} plots are shown; every channel is in "
        "timeseries.csv.</p>",
        plotted, groups.size());
  }
  html += "<div class=\"plots\">";
  for (std::size_t g = 0; g < plotted; ++g) {
    const ChannelGroup& group = groups[g];
    // "occupant.head: acceleration", or the base alone when it names no known quantity.
    const std::string title =
        group.quantity.empty() ? group.base : group.request + ": " + group.quantity;
    const PlotSpec spec = GroupPlot(title, group.names, group.components, group.unit, raw, filtered,
                                    group.quantity.empty() ? group.base : group.quantity);
    html += "<figure class=\"plot\">" + RenderSvgPlot(spec) + "<figcaption>";
    const DisplayUnit unit = DisplayUnitFor(group.unit);
    for (std::size_t i = 0; i < group.names.size(); ++i) {
      // The peak of what the plot shows bold: the filtered channel where there is one.
      const bool has_filtered = filtered != nullptr && filtered->Find(group.names[i]) != nullptr;
      const ChannelTable& table = has_filtered ? *filtered : raw;
      html += PeakText(group.components[i], table.time, *table.Find(group.names[i]), unit);
    }
    html += "</figcaption></figure>";
  }
  html += "</div>";
  return html + "</section>";
}

}  // namespace sled::report
