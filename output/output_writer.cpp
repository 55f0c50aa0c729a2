#include "output/output_writer.h"

#include <cmath>
#include <cstdio>
#include <future>

#include <fmt/format.h>

#include "output/atomic_file.h"
#include "output/number_text.h"

namespace sled::runtime {
namespace {

// The length of the valid UTF-8 sequence at text[i], or 0 when the bytes there are none
// (overlong forms, surrogates and code points above U+10FFFF included).
std::size_t Utf8SequenceLength(const std::string& text, std::size_t i) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char lead = byte(i);
  if (lead < 0x80) return 1;
  std::size_t length = 0;
  unsigned char low = 0x80, high = 0xbf;  // the range of the second byte
  if (lead >= 0xc2 && lead <= 0xdf) {
    length = 2;
  } else if (lead >= 0xe0 && lead <= 0xef) {
    length = 3;
    if (lead == 0xe0) low = 0xa0;
    if (lead == 0xed) high = 0x9f;
  } else if (lead >= 0xf0 && lead <= 0xf4) {
    length = 4;
    if (lead == 0xf0) low = 0x90;
    if (lead == 0xf4) high = 0x8f;
  } else {
    return 0;
  }
  if (i + length > text.size()) return 0;
  if (byte(i + 1) < low || byte(i + 1) > high) return 0;
  for (std::size_t k = 2; k < length; ++k) {
    if (byte(i + k) < 0x80 || byte(i + k) > 0xbf) return 0;
  }
  return length;
}

// Numbers for summary.json: a value that is not finite becomes null, and a warning names it.
class JsonNumbers {
 public:
  std::string operator()(std::string_view name, double value) {
    if (std::isfinite(value)) return fmt::format("{}", value);
    notes_.push_back(fmt::format("`{}` was not finite ({}) and is written as null", name, value));
    return "null";
  }
  const std::vector<std::string>& notes() const { return notes_; }

 private:
  std::vector<std::string> notes_;
};

// "pass", "fail", "no limit", "not computed" or, when the run stopped early, "incomplete".
std::string Verdict(const post::CriterionValue& c) {
  if (!c.computed) return "not computed";
  if (c.incomplete) return "incomplete";
  if (!c.has_limit) return "no limit";
  return c.pass ? "pass" : "fail";
}

// The "criteria" array; a value that was not computed is null, with the reason; a criterion of
// a run that stopped early is "incomplete", with the time it saw up to, and never passes.
void WriteCriteria(AtomicFile& out, const std::vector<post::CriterionValue>& criteria,
                   JsonNumbers& number) {
  out << "  \"criteria\": [";
  for (std::size_t i = 0; i < criteria.size(); ++i) {
    const post::CriterionValue& c = criteria[i];
    const std::string name = fmt::format("criteria {}({})", c.name, c.target);
    auto known = [&](bool is_known, std::string_view field, double value) {
      return is_known ? number(fmt::format("{} {}", name, field), value) : std::string("null");
    };
    out << (i == 0 ? "\n    {" : ",\n    {");
    out << fmt::format("\"name\": {}, \"variant\": {}, \"target\": {}, ", JsonString(c.name),
                       JsonString(c.variant), JsonString(c.target));
    out << fmt::format("\"value\": {}, \"unit\": {}, ", known(c.computed, "value", c.value),
                       JsonString(c.unit));
    out << fmt::format("\"window_start\": {}, \"window_end\": {}, \"filter_class\": {}, ",
                       known(c.computed, "window_start", c.window_start),
                       known(c.computed, "window_end", c.window_end), c.filter_class);
    out << fmt::format("\"limit\": {}, \"limit_source\": {}, \"pass\": {}, \"verdict\": {}",
                       known(c.has_limit, "limit", c.limit), JsonString(c.limit_source),
                       c.computed && !c.incomplete ? (c.pass ? "true" : "false") : "null",
                       JsonString(Verdict(c)));
    if (c.incomplete) {
      out << fmt::format(", \"seen_from\": {}, \"seen_until\": {}",
                         known(true, "seen_from", c.seen_from),
                         known(true, "seen_until", c.seen_until));
    }
    if (!c.computed) out << fmt::format(", \"reason\": {}", JsonString(c.reason));
    out << "}";
  }
  out << (criteria.empty() ? "],\n" : "\n  ],\n");
}

// The "peaks" array: each channel's extreme of largest magnitude and its time.
void WritePeaks(AtomicFile& out, const std::vector<post::ChannelPeak>& peaks, JsonNumbers& number) {
  out << "  \"peaks\": [";
  for (std::size_t i = 0; i < peaks.size(); ++i) {
    const post::ChannelPeak& p = peaks[i];
    out << (i == 0 ? "\n    " : ",\n    ");
    out << fmt::format("{{\"channel\": {}, \"value\": {}, \"time\": {}, \"filtered\": {}}}",
                       JsonString(p.channel), number("peaks " + p.channel + " value", p.value),
                       number("peaks " + p.channel + " time", p.time),
                       p.filtered ? "true" : "false");
  }
  out << (peaks.empty() ? "],\n" : "\n  ],\n");
}

}  // namespace

std::string JsonString(const std::string& text) {
  std::string out = "\"";
  for (std::size_t i = 0; i < text.size();) {
    const std::size_t length = Utf8SequenceLength(text, i);
    if (length == 0) {
      out += "\\ufffd";  // a byte that is no UTF-8: the replacement character
      ++i;
      continue;
    }
    if (length > 1) {
      out.append(text, i, length);
      i += length;
      continue;
    }
    const char c = text[i++];
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

std::string_view RunStatus(const RunSummary& summary) {
  if (summary.failed) return "failed";
  if (summary.interrupted) return "interrupted";
  if (!summary.output_error.empty()) return "write_failed";
  return "ok";
}

std::string TimeSeriesCsvHeader(const TimeSeries& series) {
  // Names hold no commas or quotes (dotted names and units), so they need no CSV quoting.
  std::string header = "time [s]";
  for (const std::string& name : series.names) header += ',' + name;
  return header + '\n';
}

void AppendCsvRows(std::span<const double> values, std::size_t columns, std::string& out) {
  if (columns == 0) return;
  // Each row written into one buffer with room for every value, a comma and the newline.
  std::string line(columns * (kShortestMaxChars + 1), '\0');
  for (std::size_t start = 0; start + columns <= values.size(); start += columns) {
    char* end = line.data();
    for (std::size_t column = 0; column < columns; ++column) {
      if (column > 0) *end++ = ',';
      end = WriteShortest(end, values[start + column]);
    }
    *end++ = '\n';
    out.append(line.data(), static_cast<std::size_t>(end - line.data()));
  }
}

bool WriteTimeSeriesCsv(const std::string& path, const TimeSeries& series, std::string* error,
                        bool two_threads) {
  // With two threads, the second half of the rows is formatted on the other meanwhile.
  const std::size_t split = two_threads ? series.rows() / 2 * series.columns : series.values.size();
  const std::span<const double> values(series.values);
  std::future<std::string> second;
  if (split < values.size()) {
    second = std::async(std::launch::async, [&] {
      std::string text;
      AppendCsvRows(values.subspan(split), series.columns, text);
      return text;
    });
  }
  std::string text = TimeSeriesCsvHeader(series);
  AppendCsvRows(values.first(split), series.columns, text);
  AtomicFile out(path);
  out << text;
  if (second.valid()) out << second.get();
  return out.Commit(error);
}

bool WriteCsvText(const std::string& path, const std::string& header, const std::string& rows,
                  std::string* error) {
  AtomicFile out(path);
  out << header << rows;
  return out.Commit(error);
}

bool WriteSummaryJson(const std::string& path, const Model& model, const TimeSeries& series,
                      const RunSummary& summary, const SummaryExtras& extras, std::string* error) {
  AtomicFile out(path);
  JsonNumbers number;
  const IntegratorStats& s = summary.stats;
  out << "{\n";
  out << fmt::format("  \"scenario\": {},\n", JsonString(model.title));
  out << fmt::format("  \"status\": {},\n", JsonString(std::string(RunStatus(summary))));
  out << fmt::format("  \"start_time\": {},\n  \"end_time\": {},\n  \"stopped_at\": {},\n",
                     number("start_time", model.start_time), number("end_time", model.end_time),
                     number("stopped_at", summary.end_time));
  out << fmt::format("  \"output_every\": {},\n  \"rows\": {},\n  \"channels\": {},\n",
                     number("output_every", model.output_every), series.rows(),
                     series.names.size());
  out << "  \"integrator\": {\n";
  out << fmt::format("    \"method\": {},\n", JsonString(summary.integrator));
  out << fmt::format("    \"relative_tolerance\": {},\n    \"absolute_tolerance\": {},\n",
                     number("integrator.relative_tolerance", model.relative_tolerance),
                     number("integrator.absolute_tolerance", model.absolute_tolerance));
  out << fmt::format("    \"steps\": {},\n    \"rejected_steps\": {},\n", s.steps, s.rejected);
  out << fmt::format("    \"evaluations\": {},\n    \"output_evaluations\": {},\n", s.evaluations,
                     summary.output_evaluations);
  out << fmt::format("    \"jacobians\": {},\n", s.jacobians);
  out << fmt::format("    \"factorizations\": {},\n    \"events\": {},\n", s.factorizations,
                     s.events);
  out << fmt::format("    \"decaying_steps\": {},\n", s.decaying_steps);
  if (summary.integrator == "auto") {
    // What each of auto's methods had: steps, simulated seconds, wall seconds of the
    // integrator's own work; and how often it switched.
    auto share = [](const IntegratorStats::Share& x) {
      return fmt::format("{{\"steps\": {}, \"simulated_seconds\": {}, \"wall_seconds\": {}}}",
                         x.steps, x.simulated, x.wall_seconds);
    };
    out << fmt::format("    \"auto\": {{\"switches\": {}, \"dopri5\": {}, \"exponential\": {}}},\n",
                       s.switches, share(s.explicit_share), share(s.exponential_share));
  }
  out << fmt::format("    \"max_local_error\": {},\n",
                     number("integrator.max_local_error", s.max_local_error));
  // The global error estimate when the run asked for one (output/post/global_error.h).
  out << fmt::format("    \"error_estimate\": {}\n",
                     summary.error_estimate >= 0
                         ? number("integrator.error_estimate", summary.error_estimate)
                         : std::string("null"));
  out << "  },\n";
  out << fmt::format("  \"wall_time_seconds\": {},\n",
                     number("wall_time_seconds", summary.wall_seconds));
  const EnergySummary& e = summary.energy;
  out << "  \"energy_balance\": {\n";
  out << fmt::format(
      "    \"kinetic\": {},\n    \"potential\": {},\n    \"absorbed\": {},\n"
      "    \"prescribed_work\": {},\n    \"applied_work\": {},\n    \"impulses\": {},\n"
      "    \"residual\": {},\n"
      "    \"largest_residual\": {},\n    \"scale\": {},\n    \"relative_residual\": {}\n",
      number("energy_balance.kinetic", e.kinetic), number("energy_balance.potential", e.potential),
      number("energy_balance.absorbed", e.absorbed),
      number("energy_balance.prescribed_work", e.prescribed_work),
      number("energy_balance.applied_work", e.applied_work),
      number("energy_balance.impulses", e.impulses), number("energy_balance.residual", e.residual),
      number("energy_balance.largest_residual", e.largest_residual),
      number("energy_balance.scale", e.scale),
      number("energy_balance.relative_residual", e.relative()));
  out << "  },\n";
  if (summary.settle.settled) {
    // How the scene settled before the run (runtime/run/settle.h): the convergence test's measures
    // at its last check, against its tolerances.
    const SettleSummary& settle = summary.settle;
    const Model::Settle& want = model.settle;
    out << "  \"settle\": {\n";
    out << fmt::format("    \"converged\": {},\n    \"time\": {},\n    \"duration\": {},\n",
                       settle.converged ? "true" : "false", settle.time, want.duration);
    out << fmt::format("    \"steps\": {},\n    \"evaluations\": {},\n", settle.steps,
                       settle.evaluations);
    out << fmt::format("    \"largest_velocity\": {},\n    \"velocity_tolerance\": {},\n",
                       settle.largest_velocity, want.velocity);
    out << fmt::format(
        "    \"largest_angular_velocity\": {},\n    \"angular_velocity_tolerance\": {},\n",
        settle.largest_angular_velocity, want.angular_velocity);
    out << fmt::format("    \"largest_acceleration\": {},\n    \"acceleration_tolerance\": {},\n",
                       settle.largest_acceleration, want.velocity / want.check_every);
    out << fmt::format(
        "    \"largest_angular_acceleration\": {},\n    \"angular_acceleration_tolerance\": "
        "{},\n",
        settle.largest_angular_acceleration, want.angular_velocity / want.check_every);
    out << fmt::format("    \"largest_force\": {},\n", settle.largest_force);
    out << fmt::format("    \"largest_force_change\": {},\n    \"force_change_tolerance\": {}\n",
                       settle.largest_force_change, want.force_change);
    out << "  },\n";
  }
  if (summary.failed) {
    const Failure& f = summary.failure;
    out << "  \"failure\": {\n";
    out << fmt::format("    \"time\": {},\n    \"where\": {},\n    \"cause\": {}",
                       number("failure.time", f.time), JsonString(f.where), JsonString(f.cause));
    if (!f.source.file.empty()) {
      out << fmt::format(
          ",\n    \"source\": {}",
          JsonString(fmt::format("{}:{}:{}", f.source.file, f.source.line, f.source.column)));
    }
    out << "\n  },\n";
  }
  if (summary.interrupted) {
    out << fmt::format(
        "  \"interrupted\": {{\"signal\": {}, \"time\": {}}},\n",
        JsonString(extras.interrupted_by.empty() ? "request" : extras.interrupted_by),
        number("interrupted.time", summary.end_time));
  }
  if (!summary.output_error.empty()) {
    out << fmt::format("  \"write_error\": {},\n", JsonString(summary.output_error));
  }
  WriteCriteria(out, extras.criteria, number);
  WritePeaks(out, extras.peaks, number);
  out << "  \"table_extrapolations\": [";
  for (std::size_t i = 0; i < extras.extrapolations.size(); ++i) {
    const TableExtrapolation& x = extras.extrapolations[i];
    out << (i == 0 ? "\n    {" : ",\n    {");
    out << fmt::format(
        "\"element\": {}, \"argument\": {}, \"first_time\": {}, \"first_argument\": {}, "
        "\"farthest_argument\": {}, \"rows_from\": {}, \"rows_to\": {}}}",
        JsonString(x.element), JsonString(x.argument), number("first_time", x.first_time),
        number("first_argument", x.first_argument),
        number("farthest_argument", x.farthest_argument), number("rows_from", x.low),
        number("rows_to", x.high));
  }
  out << (extras.extrapolations.empty() ? "],\n" : "\n  ],\n");
  std::vector<std::string> warnings = extras.warnings;
  warnings.insert(warnings.end(), number.notes().begin(), number.notes().end());
  out << "  \"warnings\": [";
  for (std::size_t i = 0; i < warnings.size(); ++i) {
    out << (i == 0 ? "\n    " : ",\n    ") << JsonString(warnings[i]);
  }
  out << (warnings.empty() ? "]\n" : "\n  ]\n");
  out << "}\n";
  return out.Commit(error);
}

}  // namespace sled::runtime
