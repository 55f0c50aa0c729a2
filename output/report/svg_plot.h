// A line plot as an SVG element: axes with round ticks and grid lines, labels with units, a
// legend, and one path per series. The report draws every channel group with it.
#pragma once

#include <functional>
#include <span>
#include <string>
#include <vector>

#include "output/report/axis_ticks.h"

namespace sled::report {

struct LineStyle {
  std::string color = "#1f77b4";
  double width = 1.5;
  double opacity = 1.0;
  bool markers = false;  // a dot at each point instead of a line through them
};

struct PlotSeries {
  std::vector<double> x;
  std::vector<double> y;
  LineStyle style;
};

struct LegendEntry {
  std::string label;
  LineStyle style;
};

struct PlotSpec {
  std::string title;
  std::string x_label;  // with the unit, like "time [ms]"
  std::string y_label;
  std::vector<PlotSeries> series;
  std::vector<LegendEntry> legend;
  int width = 640;
  int height = 300;
};

// Where the plot area lies in the SVG and how data maps onto it.
struct PlotFrame {
  double left = 0.0;
  double top = 0.0;
  double width = 0.0;
  double height = 0.0;
  AxisTicks x;
  AxisTicks y;
  double X(double value) const { return left + (value - x.low) / (x.high - x.low) * width; }
  double Y(double value) const { return top + (y.high - value) / (y.high - y.low) * height; }
};

// The frame for a spec: the margins, and ticks that hold every finite value of every series.
PlotFrame FramePlot(const PlotSpec& spec);

// The path data ("M x,y L x,y ...", one decimal) of a series in a frame: thinned to the plot's
// pixel columns, broken where a value is not finite.
std::string SeriesPath(const PlotFrame& frame, std::span<const double> x,
                       std::span<const double> y);

// The whole <svg> element; `underlay`, when given, adds SVG drawn over the grid and under the
// series (a response surface's colored cells).
std::string RenderSvgPlot(const PlotSpec& spec,
                          const std::function<std::string(const PlotFrame&)>& underlay = {});

}  // namespace sled::report
