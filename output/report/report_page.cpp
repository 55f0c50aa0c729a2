#include "output/report/report_page.h"

#include <fmt/format.h>

#include "output/report/animation_section.h"
#include "output/report/channel_plots.h"
#include "output/report/criteria_table.h"
#include "output/report/html_text.h"
#include "output/report/number_text.h"
#include "output/report/report_assets.h"
#include "output/report/summary_tables.h"

namespace sled::report {
namespace {

constexpr const char* kErrorTrap = R"(<script>
window.addEventListener('error', function (event) {
  var message = (event && event.message) || 'script error';
  document.documentElement.setAttribute('data-script-error', message);
  var line = document.createElement('p');
  line.className = 'script-error';
  line.textContent = 'Script error: ' + message;
  (document.body || document.documentElement).appendChild(line);
});
</script>)";

}  // namespace

std::string_view ErrorTrapScript() { return kErrorTrap; }

namespace {

std::string Header(const ReportInputs& inputs) {
  const RunSummaryFile& s = inputs.summary;
  const std::string title = s.scenario.empty() ? inputs.folder : s.scenario;
  std::string html = fmt::format("<header><h1>{}</h1><p class=\"subtitle\">", EscapeHtml(title));
  html += fmt::format("<span class=\"badge {}\">{}</span> ", s.status == "ok" ? "ok" : "failed",
                      s.status == "ok" ? std::string("completed") : EscapeHtml(s.status));
  int failed = 0;
  bool incomplete = s.status != "ok";
  for (const CriterionSummary& c : s.criteria) {
    if (c.value && c.limit && !c.incomplete() && !c.pass.value_or(false)) ++failed;
    incomplete = incomplete || c.incomplete();
  }
  if (!s.criteria.empty() && incomplete) {
    // A run that stopped early shows nothing green: its criteria saw only part of it.
    html +=
        "<span class=\"badge failed\">criteria incomplete: the rows do not cover the whole "
        "run</span> ";
  } else if (!s.criteria.empty()) {
    html += fmt::format("<span class=\"badge {}\">{}</span> ", failed == 0 ? "ok" : "failed",
                        failed == 0   ? std::string("criteria within limits")
                        : failed == 1 ? std::string("1 criterion over its limit")
                                      : fmt::format("{} criteria over their limits", failed));
  }
  html += fmt::format("run folder <code>{}</code></p>", EscapeHtml(inputs.folder));
  html +=
      "<nav><a href=\"#run\">run</a><a href=\"#criteria\">criteria</a>"
      "<a href=\"#animation\">animation</a><a href=\"#channels\">channels</a>"
      "<a href=\"#integrator\">integrator</a><a href=\"#energy\">energy</a></nav></header>";
  return html;
}

}  // namespace

std::string BuildReportPage(const ReportInputs& inputs) {
  const RunSummaryFile& s = inputs.summary;
  std::string html = "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">";
  html += "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">";
  html += fmt::format("<title>{} – sled report</title>",
                      EscapeHtml(s.scenario.empty() ? inputs.folder : s.scenario));
  html += kErrorTrap;
  html += "<style>";
  html += PageStyle();
  html += "</style></head><body>";
  html += Header(inputs);
  html += "<main>";
  if (!inputs.notes.empty()) {
    html += "<section id=\"notes\"><ul class=\"notes\">";
    for (const std::string& note : inputs.notes) html += "<li>" + EscapeHtml(note) + "</li>";
    html += "</ul></section>";
  }
  html += "<div class=\"columns\">" + RunSection(s) + CriteriaSection(s.criteria) + "</div>";
  html += WarningsSection(s);
  html += AnimationSection(inputs.glb);
  if (inputs.raw) {
    html += ChannelPlotsSection(*inputs.raw, inputs.filtered ? &*inputs.filtered : nullptr);
  }
  html += "<div class=\"columns\">" + IntegratorSection(s.integrator) + EnergySection(s) + "</div>";
  html += "</main><footer>Written by <code>sled report</code>.</footer>";
  html += "<script>";
  html += ViewerScript();
  html += "</script></body></html>\n";
  return html;
}

}  // namespace sled::report
