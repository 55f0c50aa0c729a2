// The SVG plot generator: where data lands in the plot area, the ticks and labels it draws, a
// path thinned to the pixel columns that still holds every peak, and breaks at missing values.
#include "output/report/svg_plot.h"

#include <cmath>
#include <limits>
#include <regex>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "output/report/polyline_thinning.h"

namespace sled::report {
namespace {

struct Point {
  double x;
  double y;
};

// The points of a path's "M x,y L x,y ..." data, and how many pieces (M commands) it has.
std::vector<Point> PathPoints(const std::string& path, int* pieces = nullptr) {
  std::vector<Point> points;
  if (pieces) *pieces = 0;
  const std::regex command("([ML])(-?[0-9.]+),(-?[0-9.]+)");
  for (auto it = std::sregex_iterator(path.begin(), path.end(), command);
       it != std::sregex_iterator(); ++it) {
    if (pieces && (*it)[1] == "M") ++*pieces;
    points.push_back({std::stod((*it)[2]), std::stod((*it)[3])});
  }
  return points;
}

int Count(const std::string& text, const std::string& what) {
  int count = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) {
    ++count;
  }
  return count;
}

PlotSpec LineSpec() {
  // y = 2 x for x from 0 to 10 in 11 samples.
  PlotSpec spec;
  spec.title = "line";
  spec.x_label = "time [ms]";
  spec.y_label = "force [kN]";
  PlotSeries series;
  for (int i = 0; i <= 10; ++i) {
    series.x.push_back(i);
    series.y.push_back(2.0 * i);
  }
  spec.series.push_back(series);
  return spec;
}

TEST(SvgPlot, FrameHoldsTheDataOnRoundTicks) {
  const PlotSpec spec = LineSpec();
  const PlotFrame frame = FramePlot(spec);
  EXPECT_DOUBLE_EQ(frame.x.low, 0.0);
  EXPECT_DOUBLE_EQ(frame.x.high, 10.0);
  EXPECT_DOUBLE_EQ(frame.y.low, 0.0);
  EXPECT_DOUBLE_EQ(frame.y.high, 20.0);
  // The plot area lies inside the SVG with room for labels on every side.
  EXPECT_GT(frame.left, 0.0);
  EXPECT_GT(frame.top, 0.0);
  EXPECT_LT(frame.left + frame.width, spec.width);
  EXPECT_LT(frame.top + frame.height, spec.height);
  // The corners of the data range map onto the corners of the plot area (y grows downward).
  EXPECT_DOUBLE_EQ(frame.X(0.0), frame.left);
  EXPECT_DOUBLE_EQ(frame.X(10.0), frame.left + frame.width);
  EXPECT_DOUBLE_EQ(frame.Y(0.0), frame.top + frame.height);
  EXPECT_DOUBLE_EQ(frame.Y(20.0), frame.top);
}

TEST(SvgPlot, PathPassesThroughEverySampleOfAShortSeries) {
  const PlotSpec spec = LineSpec();
  const PlotFrame frame = FramePlot(spec);
  int pieces = 0;
  const std::vector<Point> points =
      PathPoints(SeriesPath(frame, spec.series[0].x, spec.series[0].y), &pieces);
  ASSERT_EQ(points.size(), 11u);
  EXPECT_EQ(pieces, 1);
  for (int i = 0; i <= 10; ++i) {
    // x = i ms maps to left + i/10 of the width; y = 2 i to bottom - 2i/20 of the height.
    EXPECT_NEAR(points[i].x, frame.left + frame.width * i / 10.0, 0.051) << i;
    EXPECT_NEAR(points[i].y, frame.top + frame.height * (1.0 - i / 10.0), 0.051) << i;
  }
}

TEST(SvgPlot, ThinnedPathKeepsThePeakOfALongSeries) {
  // 20001 samples of zero with one spike of 7 in the middle and a dip of -3 near the end: far
  // more samples than pixel columns.
  PlotSpec spec;
  PlotSeries series;
  for (int i = 0; i <= 20000; ++i) {
    series.x.push_back(i * 1e-2);
    series.y.push_back(i == 10000 ? 7.0 : i == 19000 ? -3.0 : 0.0);
  }
  spec.series.push_back(series);
  const PlotFrame frame = FramePlot(spec);
  const std::vector<Point> points = PathPoints(SeriesPath(frame, series.x, series.y));
  EXPECT_LE(points.size(), static_cast<std::size_t>(4.0 * std::ceil(frame.width)));
  double top = frame.top + frame.height;
  double bottom = frame.top;
  for (const Point& p : points) {
    top = std::min(top, p.y);
    bottom = std::max(bottom, p.y);
  }
  EXPECT_NEAR(top, frame.Y(7.0), 0.051);
  EXPECT_NEAR(bottom, frame.Y(-3.0), 0.051);
  // The path still starts and ends at the first and last sample.
  EXPECT_NEAR(points.front().x, frame.X(0.0), 0.051);
  EXPECT_NEAR(points.back().x, frame.X(200.0), 0.051);
}

TEST(SvgPlot, MissingValuesBreakThePath) {
  std::vector<double> x = {0, 1, 2, 3, 4, 5};
  std::vector<double> y = {0, 1, std::numeric_limits<double>::quiet_NaN(), 3, 4, 5};
  PlotSpec spec;
  spec.series.push_back({x, y, {}});
  int pieces = 0;
  const std::vector<Point> points = PathPoints(SeriesPath(FramePlot(spec), x, y), &pieces);
  EXPECT_EQ(pieces, 2);
  EXPECT_EQ(points.size(), 5u);
}

TEST(PolylineThinning, KeepsEverySampleWhenThereAreFewerThanColumns) {
  const std::vector<double> x = {0, 1, 2, 3};
  const std::vector<double> y = {5, -5, 5, -5};
  const std::vector<std::size_t> kept = ThinForColumns(x, y, 0.0, 3.0, 100);
  EXPECT_EQ(kept, (std::vector<std::size_t>{0, 1, 2, 3}));
}

TEST(PolylineThinning, OneColumnKeepsFirstExtremesAndLastInOrder) {
  const std::vector<double> x = {0.0, 0.1, 0.2, 0.3, 0.4, 0.5};
  const std::vector<double> y = {1.0, 9.0, 2.0, -4.0, 3.0, 2.5};
  // All six samples fall into one of two columns over [0, 10].
  const std::vector<std::size_t> kept = ThinForColumns(x, y, 0.0, 10.0, 2);
  EXPECT_EQ(kept, (std::vector<std::size_t>{0, 1, 3, 5}));
}

TEST(SvgPlot, DrawsTicksLabelsLegendAndEscapesText) {
  PlotSpec spec = LineSpec();
  spec.title = "a<b & c";
  spec.legend.push_back({"x", {"#ff0000", 1.5, 1.0}});
  spec.legend.push_back({"raw", {"#555", 1.0, 0.4}});
  const std::string svg = RenderSvgPlot(spec);
  EXPECT_EQ(svg.rfind("<svg", 0), 0u);
  EXPECT_NE(svg.find("</svg>"), std::string::npos);
  EXPECT_NE(svg.find("a&lt;b &amp; c"), std::string::npos);
  EXPECT_EQ(svg.find("a<b"), std::string::npos);
  EXPECT_NE(svg.find(">time [ms]</text>"), std::string::npos);
  EXPECT_NE(svg.find(">force [kN]</text>"), std::string::npos);
  // x ticks 0, 2, ..., 10 (8 intervals asked, a step of 2) and y ticks 0, 5, ..., 20.
  for (const char* label : {">0<", ">2<", ">4<", ">6<", ">8<", ">10<", ">5<", ">15<", ">20<"}) {
    EXPECT_NE(svg.find(label), std::string::npos) << label;
  }
  EXPECT_EQ(Count(svg, "<path "), 1);
  EXPECT_NE(svg.find(">raw</text>"), std::string::npos);
  EXPECT_NE(svg.find("stroke-opacity=\"0.4\""), std::string::npos);
}

}  // namespace
}  // namespace sled::report
