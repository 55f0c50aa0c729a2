#include "output/report/sweep_page.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <fmt/format.h>

#include "output/report/html_text.h"
#include "output/report/number_text.h"
#include "output/report/report_assets.h"
#include "output/report/report_page.h"
#include "output/report/svg_plot.h"

namespace sled::report {
namespace {

// A CSV field: quoted when it holds a comma, a quote or a line break.
std::string CsvField(const std::string& text) {
  if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
  std::string quoted = "\"";
  for (const char c : text) {
    if (c == '"') quoted += '"';
    quoted += c;
  }
  return quoted + "\"";
}

// Viridis at five stops, linearly between them: t in [0, 1].
std::string ColorAt(double t) {
  static constexpr std::array<std::array<double, 3>, 5> kStops = {
      {{68, 1, 84}, {59, 82, 139}, {33, 145, 140}, {94, 201, 98}, {253, 231, 37}}};
  t = std::clamp(std::isfinite(t) ? t : 0.0, 0.0, 1.0) * 4.0;
  const auto i = std::min<std::size_t>(3, static_cast<std::size_t>(t));
  const double f = t - static_cast<double>(i);
  std::array<int, 3> rgb{};
  for (std::size_t k = 0; k < 3; ++k) {
    rgb[k] = static_cast<int>(std::lround(kStops[i][k] + f * (kStops[i + 1][k] - kStops[i][k])));
  }
  return fmt::format("#{:02x}{:02x}{:02x}", rgb[0], rgb[1], rgb[2]);
}

// Solves A c = b (n x n, row-major) by Gaussian elimination with partial pivoting; false when
// a pivot is negligible against the matrix's scale.
bool Solve(std::vector<double> a, std::vector<double> b, std::size_t n, std::vector<double>& c) {
  double scale = 0.0;
  for (const double value : a) scale = std::max(scale, std::abs(value));
  for (std::size_t k = 0; k < n; ++k) {
    std::size_t pivot = k;
    for (std::size_t r = k + 1; r < n; ++r) {
      if (std::abs(a[r * n + k]) > std::abs(a[pivot * n + k])) pivot = r;
    }
    if (!(std::abs(a[pivot * n + k]) > 1e-10 * scale)) return false;
    for (std::size_t j = 0; j < n; ++j) std::swap(a[k * n + j], a[pivot * n + j]);
    std::swap(b[k], b[pivot]);
    for (std::size_t r = k + 1; r < n; ++r) {
      const double factor = a[r * n + k] / a[k * n + k];
      for (std::size_t j = k; j < n; ++j) a[r * n + j] -= factor * a[k * n + j];
      b[r] -= factor * b[k];
    }
  }
  c.assign(n, 0.0);
  for (std::size_t k = n; k-- > 0;) {
    double sum = b[k];
    for (std::size_t j = k + 1; j < n; ++j) sum -= a[k * n + j] * c[j];
    c[k] = sum / a[k * n + k];
  }
  return true;
}

// The surface of one output over two inputs, or an empty string when it cannot be drawn.
std::string SurfacePlot(const SweepTable& table, std::size_t output, std::size_t ix,
                        std::size_t iy) {
  std::vector<double> x;
  std::vector<double> y;
  std::vector<double> z;
  for (const SweepRow& row : table.rows) {
    const auto& value = row.outputs[output];
    if (!value || !std::isfinite(*value)) continue;
    x.push_back(row.inputs[ix]);
    y.push_back(row.inputs[iy]);
    z.push_back(*value);
  }
  if (z.size() < 2) return "";
  const auto fit = FitQuadratic(x, y, z);
  double low = *std::min_element(z.begin(), z.end());
  double high = *std::max_element(z.begin(), z.end());
  PlotSpec spec;
  spec.title =
      fmt::format("{} over {} and {}", table.outputs[output], table.inputs[ix], table.inputs[iy]);
  spec.x_label = table.inputs[ix];
  spec.y_label = table.inputs[iy];
  spec.width = 460;
  spec.height = 340;
  const PlotFrame frame = FramePlot([&] {
    PlotSpec bounds = spec;
    bounds.series.push_back({x, y, {}});
    return bounds;
  }());
  constexpr int kCells = 36;
  std::vector<double> cells;
  if (fit) {
    for (int j = 0; j < kCells; ++j) {
      for (int i = 0; i < kCells; ++i) {
        const double cx = frame.x.low + (i + 0.5) / kCells * (frame.x.high - frame.x.low);
        const double cy = frame.y.low + (j + 0.5) / kCells * (frame.y.high - frame.y.low);
        cells.push_back((*fit)(cx, cy));
      }
    }
  }
  const double span = high > low ? high - low : 1.0;
  for (std::size_t k = 0; k < z.size(); ++k) {
    PlotSeries point;
    point.x = {x[k]};
    point.y = {y[k]};
    point.style.markers = true;
    point.style.width = 3.0;
    point.style.color = ColorAt((z[k] - low) / span);
    spec.series.push_back(std::move(point));
  }
  auto underlay = [&](const PlotFrame& f) {
    std::string svg = "<g class=\"surface\" opacity=\"0.75\">";
    const double w = f.width / kCells;
    const double h = f.height / kCells;
    for (int j = 0; j < kCells && !cells.empty(); ++j) {
      for (int i = 0; i < kCells; ++i) {
        svg += fmt::format(
            "<rect x=\"{:.1f}\" y=\"{:.1f}\" width=\"{:.2f}\" height=\"{:.2f}\" fill=\"{}\"/>",
            f.left + i * w, f.top + f.height - (j + 1) * h, w + 0.3, h + 0.3,
            ColorAt((cells[static_cast<std::size_t>(j * kCells + i)] - low) / span));
      }
    }
    return svg + "</g>";
  };
  std::string html = "<figure class=\"surface\">" + RenderSvgPlot(spec, underlay);
  html += fmt::format(
      "<figcaption>dots: the runs; colour from <span class=\"swatch\" style=\"background:{}\">"
      "</span> {} to <span class=\"swatch\" style=\"background:{}\"></span> {}. {}</figcaption>",
      ColorAt(0), EscapeHtml(Significant(low)), ColorAt(1), EscapeHtml(Significant(high)),
      fit ? fmt::format("Cells: a quadratic in the two inputs fitted by least squares, R² = {}{}.",
                        EscapeHtml(Significant(fit->r_squared, 3)),
                        table.inputs.size() > 2 ? ", over every value of the other inputs" : "")
          : "Too few distinct runs to fit a surface.");
  return html + "</figure>";
}

std::string ScatterPlot(const SweepTable& table, std::size_t output, std::size_t input) {
  PlotSpec spec;
  spec.title = table.outputs[output];
  spec.x_label = table.inputs[input];
  spec.y_label = table.outputs[output];
  spec.width = 380;
  spec.height = 260;
  PlotSeries points;
  points.style.markers = true;
  points.style.width = 2.0;
  for (const SweepRow& row : table.rows) {
    const auto& value = row.outputs[output];
    if (!value) continue;
    points.x.push_back(row.inputs[input]);
    points.y.push_back(*value);
  }
  if (points.x.empty()) return "";
  spec.series.push_back(std::move(points));
  return RenderSvgPlot(spec);
}

// Every plot of one output: against each input, then (for criteria) the surfaces of pairs of
// inputs (of the first four inputs).
std::string OutputFigures(const SweepTable& table, std::size_t output, bool surfaces_too) {
  std::string html = "<div class=\"plots\">";
  for (std::size_t i = 0; i < table.inputs.size(); ++i) html += ScatterPlot(table, output, i);
  html += "</div>";
  const std::size_t surfaced = surfaces_too ? std::min<std::size_t>(table.inputs.size(), 4) : 0;
  std::string surfaces;
  for (std::size_t i = 0; i < surfaced; ++i) {
    for (std::size_t j = i + 1; j < surfaced; ++j) surfaces += SurfacePlot(table, output, i, j);
  }
  if (!surfaces.empty()) html += "<div class=\"plots\">" + surfaces + "</div>";
  return html;
}

std::string RunsTable(const SweepTable& table) {
  std::string html =
      "<section id=\"runs\"><h2>Runs</h2><div class=\"scroll\"><table><thead><tr>"
      "<th>run</th>";
  for (const std::string& input : table.inputs) html += "<th>" + EscapeHtml(input) + "</th>";
  html += "<th>status</th><th>wall [s]</th>";
  for (std::size_t o = 0; o < table.criteria; ++o) {
    html += "<th>" + EscapeHtml(table.outputs[o]) + "</th>";
  }
  html += "</tr></thead><tbody>";
  for (const SweepRow& row : table.rows) {
    html += "<tr><td><code>" + EscapeHtml(row.folder) + "</code></td>";
    for (const double input : row.inputs) html += "<td>" + Significant(input, 6) + "</td>";
    html += fmt::format("<td class=\"{}\" title=\"{}\">{}</td><td>{}</td>",
                        row.status == "done" ? "ok" : "failed", EscapeHtml(row.message),
                        EscapeHtml(row.status), Significant(row.wall_seconds, 3));
    for (std::size_t o = 0; o < table.criteria; ++o) {
      html += "<td>" + EscapeHtml(row.outputs[o] ? Significant(*row.outputs[o], 4) : "") + "</td>";
    }
    html += "</tr>";
  }
  return html + "</tbody></table></div></section>";
}

constexpr const char* kPeakPicker = R"(<script>
(function () {
  var picker = document.getElementById('peak-picker');
  if (picker) {
    var show = function () {
      var shown = document.querySelectorAll('.peak');
      for (var i = 0; i < shown.length; ++i) shown[i].hidden = shown[i].id !== picker.value;
    };
    picker.addEventListener('change', show);
    show();
  }
  document.documentElement.setAttribute('data-sweep', 'ready');
  document.documentElement.setAttribute('data-plots', String(document.querySelectorAll('svg.plot').length));
})();
</script>)";

}  // namespace

std::string SweepCsv(const SweepTable& table) {
  std::string csv = "run,folder";
  for (const std::string& input : table.inputs) csv += "," + CsvField(input);
  csv += ",status,exit_code,wall_seconds,message";
  for (const std::string& output : table.outputs) csv += "," + CsvField(output);
  csv += "\n";
  for (std::size_t r = 0; r < table.rows.size(); ++r) {
    const SweepRow& row = table.rows[r];
    csv += fmt::format("{},{}", r, CsvField(row.folder));
    for (const double input : row.inputs) csv += fmt::format(",{}", input);
    csv +=
        fmt::format(",{},{},{},{}", row.status,
                    row.exit_code < 0 ? std::string() : std::to_string(row.exit_code),
                    row.status == "not run" ? std::string() : fmt::format("{}", row.wall_seconds),
                    CsvField(row.message));
    for (const auto& output : row.outputs) {
      csv += output ? fmt::format(",{}", *output) : std::string(",");
    }
    csv += "\n";
  }
  return csv;
}

std::optional<QuadraticFit> FitQuadratic(const std::vector<double>& x, const std::vector<double>& y,
                                         const std::vector<double>& z) {
  const std::size_t n = z.size();
  if (n < 3 || x.size() != n || y.size() != n) return std::nullopt;
  // Inputs scaled to [0, 1] for a well-conditioned system; the terms used: the full quadratic,
  // else the bilinear surface (two levels per input), else a plane.
  const auto [x_low, x_high] = std::minmax_element(x.begin(), x.end());
  const auto [y_low, y_high] = std::minmax_element(y.begin(), y.end());
  const double x0 = *x_low;
  const double y0 = *y_low;
  const double sx = *x_high > x0 ? *x_high - x0 : 1.0;
  const double sy = *y_high > y0 ? *y_high - y0 : 1.0;
  // A squared term only for an input with three values or more (with two, x^2 is a line too).
  auto distinct = [](std::vector<double> values) {
    std::sort(values.begin(), values.end());
    return std::unique(values.begin(), values.end()) - values.begin();
  };
  const bool x_curved = distinct(x) >= 3;
  const bool y_curved = distinct(y) >= 3;
  const std::array<std::array<bool, 6>, 3> kTerms = {{{true, true, true, x_curved, true, y_curved},
                                                      {true, true, true, false, true, false},
                                                      {true, true, true, false, false, false}}};
  for (const auto& terms : kTerms) {
    std::vector<std::size_t> used;
    for (std::size_t t = 0; t < 6; ++t) {
      if (terms[t]) used.push_back(t);
    }
    const std::size_t m = used.size();
    if (n < m) continue;
    std::vector<double> ata(m * m, 0.0);
    std::vector<double> atb(m, 0.0);
    auto basis = [&](std::size_t k) {
      const double u = (x[k] - x0) / sx;
      const double v = (y[k] - y0) / sy;
      const std::array<double, 6> all = {1.0, u, v, u * u, u * v, v * v};
      std::vector<double> row;
      for (const std::size_t t : used) row.push_back(all[t]);
      return row;
    };
    for (std::size_t k = 0; k < n; ++k) {
      const auto row = basis(k);
      for (std::size_t a = 0; a < m; ++a) {
        atb[a] += row[a] * z[k];
        for (std::size_t b = 0; b < m; ++b) ata[a * m + b] += row[a] * row[b];
      }
    }
    std::vector<double> c;
    if (!Solve(ata, atb, m, c)) continue;
    // Back to the inputs' own scale: u = (x - x0) / sx, v = (y - y0) / sy.
    std::array<double, 6> s{};
    for (std::size_t a = 0; a < m; ++a) s[used[a]] = c[a];
    QuadraticFit fit;
    fit.c[3] = s[3] / (sx * sx);
    fit.c[4] = s[4] / (sx * sy);
    fit.c[5] = s[5] / (sy * sy);
    fit.c[1] = s[1] / sx - 2 * fit.c[3] * x0 - fit.c[4] * y0;
    fit.c[2] = s[2] / sy - 2 * fit.c[5] * y0 - fit.c[4] * x0;
    fit.c[0] = s[0] - s[1] * x0 / sx - s[2] * y0 / sy + fit.c[3] * x0 * x0 + fit.c[4] * x0 * y0 +
               fit.c[5] * y0 * y0;
    double mean = 0.0;
    for (const double value : z) mean += value / static_cast<double>(n);
    double total = 0.0;
    double residual = 0.0;
    for (std::size_t k = 0; k < n; ++k) {
      total += (z[k] - mean) * (z[k] - mean);
      residual += (z[k] - fit(x[k], y[k])) * (z[k] - fit(x[k], y[k]));
    }
    fit.r_squared = total > 0 ? 1.0 - residual / total : 1.0;
    return fit;
  }
  return std::nullopt;
}

std::string BuildSweepPage(const SweepTable& table) {
  std::size_t done = 0;
  for (const SweepRow& row : table.rows) done += row.status == "done" ? 1 : 0;
  std::string html = "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">";
  html += "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">";
  html += fmt::format("<title>{} – sled sweep</title>", EscapeHtml(table.scene));
  html += ErrorTrapScript();
  html += "<style>";
  html += PageStyle();
  html +=
      ".plots{display:flex;flex-wrap:wrap;gap:8px}.swatch{display:inline-block;width:10px;"
      "height:10px}.scroll{overflow-x:auto}figure.surface{margin:0}</style></head><body>";
  html += fmt::format(
      "<header><h1>Sweep of {}</h1><p class=\"subtitle\"><span class=\"badge {}\">{} of {} runs "
      "done</span> inputs: {}</p><nav><a href=\"#criteria\">criteria</a><a href=\"#peaks\">"
      "peaks</a><a href=\"#runs\">runs</a></nav></header><main>",
      EscapeHtml(table.scene), done == table.rows.size() ? "ok" : "failed", done, table.rows.size(),
      EscapeHtml(fmt::format("{}", fmt::join(table.inputs, ", "))));
  html += "<section id=\"criteria\"><h2>Injury criteria</h2>";
  if (table.criteria == 0) html += "<p>The scene requests no injury criteria.</p>";
  for (std::size_t o = 0; o < table.criteria; ++o) {
    html += "<h3>" + EscapeHtml(table.outputs[o]) + "</h3>" + OutputFigures(table, o, true);
  }
  html += "</section><section id=\"peaks\"><h2>Channel peaks</h2>";
  if (table.outputs.size() == table.criteria) {
    html += "<p>The runs recorded no channel peaks.</p>";
  } else {
    html +=
        "<p>The value of largest magnitude of each channel (filtered where the run filters "
        "it). <select id=\"peak-picker\">";
    for (std::size_t o = table.criteria; o < table.outputs.size(); ++o) {
      html += fmt::format("<option value=\"peak-{}\">{}</option>", o, EscapeHtml(table.outputs[o]));
    }
    html += "</select></p>";
    for (std::size_t o = table.criteria; o < table.outputs.size(); ++o) {
      html += fmt::format("<div class=\"peak\" id=\"peak-{}\">", o) +
              OutputFigures(table, o, false) + "</div>";
    }
  }
  html += "</section>" + RunsTable(table);
  html +=
      "</main><footer>Written by <code>sled sweep</code>; the numbers are in "
      "<code>sweep.csv</code>.</footer>";
  html += kPeakPicker;
  html += "</body></html>\n";
  return html;
}

}  // namespace sled::report
