#include "output/report/svg_plot.h"

#include <cmath>

#include <fmt/format.h>

#include "output/report/html_text.h"
#include "output/report/polyline_thinning.h"

namespace sled::report {
namespace {

// Margins around the plot area: room for the y tick labels and the rotated y label on the
// left, the x tick labels and the x label below, the title and legend above.
constexpr double kLeft = 70.0;
constexpr double kRight = 16.0;
constexpr double kTop = 34.0;
constexpr double kBottom = 46.0;
constexpr int kXTicks = 8;
constexpr int kYTicks = 5;

std::string StrokeAttributes(const LineStyle& style) {
  std::string out =
      fmt::format("stroke=\"{}\" stroke-width=\"{}\"", EscapeHtml(style.color), style.width);
  if (style.opacity < 1.0) out += fmt::format(" stroke-opacity=\"{}\"", style.opacity);
  return out;
}

void AppendGridAndTicks(const PlotFrame& f, std::string& svg) {
  const double right = f.left + f.width;
  const double bottom = f.top + f.height;
  svg += "<g class=\"grid\">";
  for (const double value : f.x.values) {
    const double px = f.X(value);
    svg += fmt::format("<line x1=\"{0:.1f}\" y1=\"{1:.1f}\" x2=\"{0:.1f}\" y2=\"{2:.1f}\"/>", px,
                       f.top, bottom);
  }
  for (const double value : f.y.values) {
    const double py = f.Y(value);
    svg += fmt::format("<line x1=\"{0:.1f}\" y1=\"{1:.1f}\" x2=\"{2:.1f}\" y2=\"{1:.1f}\"/>",
                       f.left, py, right);
  }
  svg += "</g>";
  // The zero line, when zero is inside the range and not its edge.
  if (f.y.low < 0.0 && f.y.high > 0.0) {
    svg += fmt::format(
        "<line class=\"zero\" x1=\"{0:.1f}\" y1=\"{1:.1f}\" x2=\"{2:.1f}\" y2=\"{1:.1f}\"/>",
        f.left, f.Y(0.0), right);
  }
  svg += fmt::format(
      "<rect class=\"frame\" x=\"{:.1f}\" y=\"{:.1f}\" width=\"{:.1f}\" height=\"{:.1f}\"/>",
      f.left, f.top, f.width, f.height);
  svg += "<g class=\"ticks x\">";
  for (const double value : f.x.values) {
    svg += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\">{}</text>", f.X(value), bottom + 16.0,
                       TickLabel(value, f.x.decimals));
  }
  svg += "</g><g class=\"ticks y\">";
  for (const double value : f.y.values) {
    svg += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\">{}</text>", f.left - 6.0, f.Y(value) + 4.0,
                       TickLabel(value, f.y.decimals));
  }
  svg += "</g>";
}

void AppendLegend(const PlotSpec& spec, std::string& svg) {
  // Right-aligned in the top margin: entries from the right edge leftwards, in reverse, so the
  // first reads first.
  double x = spec.width - kRight;
  std::string entries;
  for (auto entry = spec.legend.rbegin(); entry != spec.legend.rend(); ++entry) {
    const double text_width = 7.0 * static_cast<double>(entry->label.size());
    x -= text_width;
    entries =
        fmt::format("<text x=\"{:.1f}\" y=\"20\">{}</text>", x, EscapeHtml(entry->label)) + entries;
    x -= 22.0;
    entries = fmt::format("<line x1=\"{:.1f}\" y1=\"16\" x2=\"{:.1f}\" y2=\"16\" {}/>", x, x + 18.0,
                          StrokeAttributes(entry->style)) +
              entries;
    x -= 12.0;
  }
  svg += "<g class=\"legend\">" + entries + "</g>";
}

}  // namespace

PlotFrame FramePlot(const PlotSpec& spec) {
  PlotFrame frame;
  frame.left = kLeft;
  frame.top = kTop;
  frame.width = spec.width - kLeft - kRight;
  frame.height = spec.height - kTop - kBottom;
  ValueRange xs;
  ValueRange ys;
  for (const PlotSeries& series : spec.series) {
    xs.Include(series.x);
    ys.Include(series.y);
  }
  frame.x = xs.empty() ? ChooseTicks(0.0, 1.0, kXTicks) : ChooseTicks(xs.low, xs.high, kXTicks);
  frame.y = ys.empty() ? ChooseTicks(0.0, 1.0, kYTicks) : ChooseTicks(ys.low, ys.high, kYTicks);
  return frame;
}

std::string SeriesPath(const PlotFrame& frame, std::span<const double> x,
                       std::span<const double> y) {
  const std::vector<std::size_t> kept =
      ThinForColumns(x, y, frame.x.low, frame.x.high, static_cast<int>(std::ceil(frame.width)));
  std::string path;
  bool pen_down = false;
  for (const std::size_t i : kept) {
    if (!std::isfinite(x[i]) || !std::isfinite(y[i])) {
      pen_down = false;
      continue;
    }
    path += fmt::format("{}{:.1f},{:.1f}", pen_down ? 'L' : 'M', frame.X(x[i]), frame.Y(y[i]));
    pen_down = true;
  }
  return path;
}

std::string RenderSvgPlot(const PlotSpec& spec,
                          const std::function<std::string(const PlotFrame&)>& underlay) {
  const PlotFrame frame = FramePlot(spec);
  std::string svg = fmt::format(
      "<svg class=\"plot\" xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 {0} {1}\" "
      "width=\"{0}\" height=\"{1}\" role=\"img\" aria-label=\"{2}\">",
      spec.width, spec.height, EscapeHtml(spec.title));
  svg += fmt::format("<text class=\"title\" x=\"{:.1f}\" y=\"20\">{}</text>", frame.left,
                     EscapeHtml(spec.title));
  AppendLegend(spec, svg);
  AppendGridAndTicks(frame, svg);
  svg += fmt::format("<text class=\"label x\" x=\"{:.1f}\" y=\"{:.1f}\">{}</text>",
                     frame.left + 0.5 * frame.width, spec.height - 8.0, EscapeHtml(spec.x_label));
  svg += fmt::format(
      "<text class=\"label y\" transform=\"translate(16 {:.1f}) rotate(-90)\">{}</text>",
      frame.top + 0.5 * frame.height, EscapeHtml(spec.y_label));
  if (underlay) svg += underlay(frame);
  svg += "<g class=\"series\" fill=\"none\">";
  for (const PlotSeries& series : spec.series) {
    if (series.style.markers) {
      for (std::size_t i = 0; i < series.x.size() && i < series.y.size(); ++i) {
        if (!std::isfinite(series.x[i]) || !std::isfinite(series.y[i])) continue;
        svg += fmt::format(
            "<circle cx=\"{:.1f}\" cy=\"{:.1f}\" r=\"{}\" fill=\"{}\" stroke=\"#fff\" "
            "stroke-width=\"0.8\"/>",
            frame.X(series.x[i]), frame.Y(series.y[i]), 1.5 + series.style.width,
            EscapeHtml(series.style.color));
      }
      continue;
    }
    const std::string path = SeriesPath(frame, series.x, series.y);
    if (path.empty()) continue;
    svg += fmt::format("<path d=\"{}\" {}/>", path, StrokeAttributes(series.style));
  }
  svg += "</g></svg>";
  return svg;
}

}  // namespace sled::report
