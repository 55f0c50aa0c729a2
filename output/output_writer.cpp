#include "output/output_writer.h"

#include <cmath>
#include <cstdio>

#include <fmt/format.h>

#include "output/atomic_file.h"

namespace sled::runtime {

std::string JsonString(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    switch (c) {
      case '"':
        out += "\\\"";
        break;
      case '\\':
        out += "\\\\";
        break;
      case '\n':
        out += "\\n";
        break;
      case '\t':
        out += "\\t";
        break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          out += fmt::format("\\u{:04x}", static_cast<unsigned>(static_cast<unsigned char>(c)));
        } else {
          out += c;
        }
    }
  }
  return out + "\"";
}

namespace {

// The "criteria" array; a value that was not computed is null, with the reason.
void WriteCriteria(AtomicFile& out, const std::vector<post::CriterionValue>& criteria) {
  auto number = [](bool known, double value) {
    return known && std::isfinite(value) ? fmt::format("{}", value) : std::string("null");
  };
  out << "  \"criteria\": [";
  for (std::size_t i = 0; i < criteria.size(); ++i) {
    const post::CriterionValue& c = criteria[i];
    out << (i == 0 ? "\n    {" : ",\n    {");
    out << fmt::format("\"name\": {}, \"variant\": {}, \"target\": {}, ", JsonString(c.name),
                       JsonString(c.variant), JsonString(c.target));
    out << fmt::format("\"value\": {}, \"unit\": {}, ", number(c.computed, c.value),
                       JsonString(c.unit));
    out << fmt::format("\"window_start\": {}, \"window_end\": {}, \"filter_class\": {}, ",
                       number(c.computed, c.window_start), number(c.computed, c.window_end),
                       c.filter_class);
    out << fmt::format("\"limit\": {}, \"limit_source\": {}, \"pass\": {}",
                       number(c.has_limit, c.limit), JsonString(c.limit_source),
                       c.computed ? (c.pass ? "true" : "false") : "null");
    if (!c.computed) out << fmt::format(", \"reason\": {}", JsonString(c.reason));
    out << "}";
  }
  out << (criteria.empty() ? "],\n" : "\n  ],\n");
}

// The "peaks" array: each channel's extreme of largest magnitude and its time.
void WritePeaks(AtomicFile& out, const std::vector<post::ChannelPeak>& peaks) {
  out << "  \"peaks\": [";
  for (std::size_t i = 0; i < peaks.size(); ++i) {
    const post::ChannelPeak& p = peaks[i];
    out << (i == 0 ? "\n    " : ",\n    ");
    out << fmt::format("{{\"channel\": {}, \"value\": {}, \"time\": {}, \"filtered\": {}}}",
                       JsonString(p.channel), p.value, p.time, p.filtered ? "true" : "false");
  }
  out << (peaks.empty() ? "],\n" : "\n  ],\n");
}

}  // namespace

bool WriteTimeSeriesCsv(const std::string& path, const TimeSeries& series, std::string* error) {
  AtomicFile out(path);
  // Names hold no commas or quotes (dotted names and units), so they need no CSV quoting.
  std::string header = "time [s]";
  for (const std::string& name : series.names) header += ',' + name;
  out << header << "\n";
  std::string line;
  for (std::size_t row = 0; row < series.rows(); ++row) {
    line.clear();
    for (std::size_t column = 0; column < series.columns; ++column) {
      if (column > 0) line += ',';
      // Shortest text that reads back to the same double.
      line += fmt::format("{}", series.values[row * series.columns + column]);
    }
    line += '\n';
    out << line;
  }
  return out.Commit(error);
}

bool WriteSummaryJson(const std::string& path, const Model& model, const TimeSeries& series,
                      const RunSummary& summary, const std::vector<std::string>& warnings,
                      std::string* error, const std::vector<post::CriterionValue>& criteria,
                      const std::vector<post::ChannelPeak>& peaks) {
  AtomicFile out(path);
  const IntegratorStats& s = summary.stats;
  out << "{\n";
  out << fmt::format("  \"scenario\": {},\n", JsonString(model.title));
  out << fmt::format("  \"status\": {},\n", JsonString(summary.failed ? "failed" : "ok"));
  out << fmt::format("  \"start_time\": {},\n  \"end_time\": {},\n  \"stopped_at\": {},\n",
                     model.start_time, model.end_time, summary.end_time);
  out << fmt::format("  \"output_every\": {},\n  \"rows\": {},\n  \"channels\": {},\n",
                     model.output_every, series.rows(), series.names.size());
  out << "  \"integrator\": {\n";
  out << fmt::format("    \"method\": {},\n", JsonString(summary.integrator));
  out << fmt::format("    \"relative_tolerance\": {},\n    \"absolute_tolerance\": {},\n",
                     model.relative_tolerance, model.absolute_tolerance);
  out << fmt::format("    \"steps\": {},\n    \"rejected_steps\": {},\n", s.steps, s.rejected);
  out << fmt::format("    \"evaluations\": {},\n    \"output_evaluations\": {},\n", s.evaluations,
                     summary.output_evaluations);
  out << fmt::format("    \"jacobians\": {},\n", s.jacobians);
  out << fmt::format("    \"factorizations\": {},\n    \"events\": {},\n", s.factorizations,
                     s.events);
  out << fmt::format("    \"decaying_steps\": {},\n", s.decaying_steps);
  out << fmt::format("    \"max_local_error\": {},\n", s.max_local_error);
  // The global error estimate when the run asked for one (output/post/global_error.h).
  out << fmt::format("    \"error_estimate\": {}\n", summary.error_estimate >= 0
                                                         ? fmt::format("{}", summary.error_estimate)
                                                         : std::string("null"));
  out << "  },\n";
  out << fmt::format("  \"wall_time_seconds\": {},\n", summary.wall_seconds);
  const EnergySummary& e = summary.energy;
  out << "  \"energy_balance\": {\n";
  out << fmt::format(
      "    \"kinetic\": {},\n    \"potential\": {},\n    \"absorbed\": {},\n"
      "    \"prescribed_work\": {},\n    \"impulses\": {},\n    \"residual\": {},\n"
      "    \"largest_residual\": {},\n    \"scale\": {},\n    \"relative_residual\": {}\n",
      e.kinetic, e.potential, e.absorbed, e.prescribed_work, e.impulses, e.residual,
      e.largest_residual, e.scale, e.relative());
  out << "  },\n";
  if (summary.failed) {
    const Failure& f = summary.failure;
    out << "  \"failure\": {\n";
    out << fmt::format("    \"time\": {},\n    \"where\": {},\n    \"cause\": {}", f.time,
                       JsonString(f.where), JsonString(f.cause));
    if (!f.source.file.empty()) {
      out << fmt::format(
          ",\n    \"source\": {}",
          JsonString(fmt::format("{}:{}:{}", f.source.file, f.source.line, f.source.column)));
    }
    out << "\n  },\n";
  }
  WriteCriteria(out, criteria);
  WritePeaks(out, peaks);
  out << "  \"warnings\": [";
  for (std::size_t i = 0; i < warnings.size(); ++i) {
    out << (i == 0 ? "\n    " : ",\n    ") << JsonString(warnings[i]);
  }
  out << (warnings.empty() ? "]\n" : "\n  ]\n");
  out << "}\n";
  return out.Commit(error);
}

}  // namespace sled::runtime
