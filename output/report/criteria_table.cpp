#include "output/report/criteria_table.h"

#include <fmt/format.h>

#include "output/report/html_text.h"
#include "output/report/number_text.h"

namespace sled::report {
namespace {

// The verdict cell: pass or fail against the limit, "no limit" when no regulation gives one,
// the reason when the value was not computed.
std::string Verdict(const CriterionSummary& c) {
  if (!c.value) {
    return fmt::format("<td class=\"verdict none\">not computed{}</td>",
                       c.reason.empty() ? "" : ": " + EscapeHtml(c.reason));
  }
  if (c.incomplete()) {
    return fmt::format(
        "<td class=\"verdict incomplete\">incomplete: over {} ms to {} ms of the run only</td>",
        c.seen_from ? Milliseconds(*c.seen_from) : "?",
        c.seen_until ? Milliseconds(*c.seen_until) : "?");
  }
  if (!c.limit) return "<td class=\"verdict none\">no limit</td>";
  const bool pass = c.pass.value_or(false);
  return fmt::format("<td class=\"verdict {0}\">{0}</td>", pass ? "pass" : "fail");
}

}  // namespace

std::string CriteriaSection(const std::vector<CriterionSummary>& criteria) {
  std::string html = "<section id=\"criteria\"><h2>Injury criteria</h2>";
  if (criteria.empty()) {
    return html + "<p class=\"note\">The scene requested no injury criteria.</p></section>";
  }
  int passed = 0;
  int failed = 0;
  int incomplete = 0;
  for (const CriterionSummary& c : criteria) {
    if (c.value && c.incomplete()) {
      ++incomplete;
    } else if (c.value && c.limit) {
      (c.pass.value_or(false) ? passed : failed) += 1;
    }
  }
  if (incomplete > 0) {
    html += fmt::format(
        "<p class=\"note incomplete\">The rows do not cover the whole run: {} of the criteria "
        "are incomplete, their values over the part of the run there is, and are not "
        "judged.</p>",
        incomplete);
  } else {
    html += fmt::format("<p class=\"note\">{} of {} criteria with a limit pass{}.</p>", passed,
                        passed + failed, failed > 0 ? fmt::format("; {} fail", failed) : "");
  }
  html +=
      "<table class=\"criteria\"><thead><tr><th>criterion</th><th>of</th><th>value</th>"
      "<th>limit</th><th>window [ms]</th><th>CFC</th><th>limit from</th><th>result</th></tr>"
      "</thead><tbody>";
  for (const CriterionSummary& c : criteria) {
    const std::string unit = c.unit.empty() ? "" : " " + EscapeHtml(c.unit);
    const std::string name =
        EscapeHtml(c.name) +
        (c.variant.empty() ? "" : " <small>" + EscapeHtml(c.variant) + "</small>");
    const std::string window =
        c.window_start && c.window_end
            ? fmt::format("{} – {}", Milliseconds(*c.window_start), Milliseconds(*c.window_end))
            : "–";
    html += fmt::format(
        "<tr><td>{}</td><td>{}</td><td class=\"number\">{}</td><td class=\"number\">{}</td>"
        "<td>{}</td><td>{}</td><td>{}</td>{}</tr>",
        name, EscapeHtml(c.target), c.value ? Significant(*c.value) + unit : "–",
        c.limit ? Significant(*c.limit) + unit : "–", window,
        c.filter_class > 0 ? fmt::format("{}", c.filter_class) : "–", EscapeHtml(c.limit_source),
        Verdict(c));
  }
  return html + "</tbody></table></section>";
}

}  // namespace sled::report
