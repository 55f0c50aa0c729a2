#include "output/report/summary_tables.h"

#include <fmt/format.h>

#include "output/report/html_text.h"
#include "output/report/number_text.h"

namespace sled::report {
namespace {

// A two-column table of labels and values (the values already HTML).
std::string KeyValueTable(const std::vector<std::pair<std::string, std::string>>& rows) {
  std::string html = "<table class=\"facts\">";
  for (const auto& [label, value] : rows) {
    html += fmt::format("<tr><th>{}</th><td>{}</td></tr>", EscapeHtml(label), value);
  }
  return html + "</table>";
}

}  // namespace

std::string RunSection(const RunSummaryFile& summary) {
  const bool ok = summary.status == "ok";
  std::string html = "<section id=\"run\"><h2>Run</h2>";
  html += fmt::format(
      "<p class=\"status {}\">{}</p>", ok ? "ok" : "failed",
      ok                                ? std::string("completed")
      : summary.status == "interrupted" ? "interrupted at " + Milliseconds(summary.stopped_at) +
                                              " ms (the rows up to then are kept)"
      : summary.status == "write_failed"
          ? "stopped at " + Milliseconds(summary.stopped_at) + " ms: an output could not be written"
          : EscapeHtml("failed" +
                       (summary.status == "failed" ? std::string() : " (" + summary.status + ")")));
  if (summary.failure) {
    const FailureSummary& f = *summary.failure;
    std::string where = EscapeHtml(f.where);
    if (!f.source.empty()) where += fmt::format(" (<code>{}</code>)", EscapeHtml(f.source));
    html += KeyValueTable({{"failed at", Milliseconds(f.time) + " ms"},
                           {"where", where},
                           {"cause", EscapeHtml(f.cause)}});
  }
  html += KeyValueTable({
      {"simulated", fmt::format("{} ms to {} ms", Milliseconds(summary.start_time),
                                Milliseconds(summary.end_time))},
      {"stopped at", Milliseconds(summary.stopped_at) + " ms"},
      {"output every", Milliseconds(summary.output_every) + " ms"},
      {"rows × channels", fmt::format("{} × {}", summary.rows, summary.channels)},
      {"wall time", Significant(summary.wall_time_seconds, 3) + " s"},
  });
  return html + "</section>";
}

std::string IntegratorSection(const IntegratorSummary& s) {
  std::string html = "<section id=\"integrator\"><h2>Integrator</h2>";
  std::vector<std::pair<std::string, std::string>> rows = {
      {"method", EscapeHtml(s.method)},
      {"tolerance (relative, absolute)", fmt::format("{}, {}", Significant(s.relative_tolerance, 3),
                                                     Significant(s.absolute_tolerance, 3))},
      {"steps (rejected)", fmt::format("{} ({})", s.steps, s.rejected_steps)},
      {"right-hand side evaluations", fmt::format("{}", s.evaluations)},
      {"Jacobians, factorizations", fmt::format("{}, {}", s.jacobians, s.factorizations)},
      {"events", fmt::format("{}", s.events)},
      {"largest local error", Significant(s.max_local_error, 3)},
  };
  if (s.error_estimate) {
    rows.push_back({"global error estimate (of channel range)", Significant(*s.error_estimate, 3)});
  }
  if (s.method == "cvs") {
    // How much of the run the exponential part carried; the rest were third-order RK steps.
    rows.push_back({"steps with a decay rate", fmt::format("{} of {}", s.decaying_steps, s.steps)});
  }
  html += KeyValueTable(rows);
  return html + "</section>";
}

std::string EnergySection(const RunSummaryFile& summary) {
  if (!summary.energy_balance) return "";
  const EnergySummary& e = *summary.energy_balance;
  std::string html = "<section id=\"energy\"><h2>Energy balance</h2>";
  html += fmt::format(
      "<p>kinetic + potential + absorbed − prescribed work − impulses stays at its initial value "
      "to {} % (largest residual {} J of {} J).</p>",
      Significant(100.0 * e.relative_residual, 3), Significant(e.largest_residual, 3),
      Significant(e.scale, 4));
  html += KeyValueTable({
      {"kinetic", Significant(e.kinetic) + " J"},
      {"potential", Significant(e.potential) + " J"},
      {"absorbed by the force elements", Significant(e.absorbed) + " J"},
      {"work of the prescribed motion", Significant(e.prescribed_work) + " J"},
      {"work of the applied loads", Significant(e.applied_work) + " J"},
      {"changed by impulses", Significant(e.impulses) + " J"},
      {"residual at the end", Significant(e.residual, 3) + " J"},
  });
  return html + "</section>";
}

std::string WarningsSection(const RunSummaryFile& summary) {
  if (summary.warnings.empty()) return "";
  std::string html =
      fmt::format("<section id=\"warnings\"><h2>Warnings ({})</h2><ul>", summary.warnings.size());
  for (const std::string& warning : summary.warnings) {
    html += "<li>" + EscapeHtml(warning) + "</li>";
  }
  return html + "</ul></section>";
}

}  // namespace sled::report
