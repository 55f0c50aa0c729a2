// The report page from known inputs: it holds the run's summary and failure, the criteria
// table with its verdicts, one plot per channel group with filtered and raw series, the
// warnings, and the animation's bytes as base64 with the viewer script; and WriteReport reads
// a run folder, noting what is missing, refusing a folder without summary.json.
#include "output/report/report_page.h"

#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "output/report/base64.h"
#include "output/report/report.h"
#include "tests/compiler/sled_process.h"

namespace sled::report {
namespace {

int Count(const std::string& text, const std::string& what) {
  int count = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) {
    ++count;
  }
  return count;
}

ChannelTable Table(const std::vector<std::string>& names, double scale) {
  ChannelTable table;
  table.names = names;
  table.columns.resize(names.size());
  for (int row = 0; row <= 100; ++row) {
    table.time.push_back(row * 1e-4);
    for (std::size_t c = 0; c < names.size(); ++c) {
      table.columns[c].push_back(scale * static_cast<double>(c + 1) * std::sin(row * 0.1));
    }
  }
  return table;
}

ReportInputs Inputs() {
  ReportInputs inputs;
  inputs.folder = "runs/frontal";
  RunSummaryFile& s = inputs.summary;
  s.scenario = "frontal <sled>";
  s.status = "failed";
  s.failure = FailureSummary{0.0421, "joint occupant.neck", "singular system", "a.sled:3:1"};
  s.integrator.method = "exponential";
  s.integrator.steps = 789;
  s.integrator.error_estimate = 0.00292;
  s.energy_balance = EnergySummary{};
  s.energy_balance->relative_residual = 1.1e-6;
  CriterionSummary hic;
  hic.name = "hic15";
  hic.target = "occupant.head";
  hic.value = 812.5;
  hic.limit = 700;
  hic.limit_source = "FMVSS 208";
  hic.pass = false;
  hic.window_start = 0.06;
  hic.window_end = 0.075;
  CriterionSummary chest = hic;
  chest.name = "chest_3ms";
  chest.variant = "cumulative";
  chest.target = "occupant.thorax";
  chest.value = 41.0;
  chest.unit = "g";
  chest.limit = 60;
  chest.pass = true;
  CriterionSummary nij;
  nij.name = "nij";
  nij.variant = "NCF";
  nij.limit = 1;
  nij.reason = "never in this quadrant";
  s.criteria = {hic, chest, nij};
  s.warnings = {"contact pad: <check> the stiffness"};
  const std::vector<std::string> names = {
      "occupant.head.acceleration.x [m/s^2]", "occupant.head.acceleration.y [m/s^2]",
      "occupant.head.acceleration.z [m/s^2]", "belt.lap.belt_force.span1 [N]"};
  inputs.raw = Table(names, 100.0);
  inputs.filtered = Table({names[0], names[1], names[2]}, 90.0);
  static constexpr char kGlb[] = "glTF\x02\x00\x00\x00 binary bytes";
  inputs.glb = std::string(kGlb, sizeof(kGlb) - 1);  // the NULs are part of the bytes
  return inputs;
}

TEST(ReportPage, HoldsTheSummaryAndTheFailure) {
  const std::string page = BuildReportPage(Inputs());
  EXPECT_EQ(page.rfind("<!DOCTYPE html>", 0), 0u);
  EXPECT_NE(page.find("<h1>frontal &lt;sled&gt;</h1>"), std::string::npos);
  EXPECT_NE(page.find("joint occupant.neck"), std::string::npos);
  EXPECT_NE(page.find("singular system"), std::string::npos);
  EXPECT_NE(page.find("42.1 ms"), std::string::npos);
  EXPECT_NE(page.find("exponential"), std::string::npos);
  EXPECT_NE(page.find("<td>789 (0)</td>"), std::string::npos);
  EXPECT_NE(page.find("global error estimate (of channel range)</th><td>0.00292"),
            std::string::npos);
  EXPECT_NE(page.find("id=\"energy\""), std::string::npos);
  EXPECT_NE(page.find("contact pad: &lt;check&gt; the stiffness"), std::string::npos);
}

TEST(ReportPage, CriteriaTableGivesValuesLimitsAndVerdicts) {
  ReportInputs inputs = Inputs();
  inputs.summary.status = "ok";
  inputs.summary.failure.reset();
  const std::string page = BuildReportPage(inputs);
  const std::size_t table = page.find("<table class=\"criteria\">");
  ASSERT_NE(table, std::string::npos);
  const std::string criteria = page.substr(table, page.find("</table>", table) - table);
  EXPECT_EQ(Count(criteria, "<tr>"), 4);  // the header and three criteria
  EXPECT_NE(criteria.find("812.5"), std::string::npos);
  EXPECT_NE(criteria.find("FMVSS 208"), std::string::npos);
  EXPECT_NE(criteria.find("60 – 75"), std::string::npos);  // the window in ms
  EXPECT_NE(criteria.find("41 g"), std::string::npos);
  EXPECT_EQ(Count(criteria, "class=\"verdict fail\""), 1);
  EXPECT_EQ(Count(criteria, "class=\"verdict pass\""), 1);
  EXPECT_NE(criteria.find("not computed: never in this quadrant"), std::string::npos);
  EXPECT_NE(page.find("1 criterion over its limit"), std::string::npos);
}

TEST(ReportPage, AFailedRunsCriteriaAreIncompleteNeverWithinLimits) {
  // A run that failed at 42.1 ms: its criteria, as summary.json gives them, are incomplete.
  ReportInputs inputs = Inputs();
  for (CriterionSummary& c : inputs.summary.criteria) {
    if (!c.value) continue;
    c.pass.reset();
    c.verdict = "incomplete";
    c.seen_from = 0.0;
    c.seen_until = 0.0421;
  }
  inputs.summary.criteria[0].value = 12.0;  // below its limit, as far as the rows go
  const std::string page = BuildReportPage(inputs);
  EXPECT_EQ(page.find("criteria within limits"), std::string::npos);
  EXPECT_EQ(page.find("class=\"verdict pass\""), std::string::npos);
  EXPECT_NE(page.find("criteria incomplete"), std::string::npos);
  EXPECT_EQ(Count(page, "incomplete: over 0 ms to 42.1 ms of the run only"), 2);
  // Even a summary of an older sled, whose failed run says `pass`, shows no green badge.
  const std::string old_page = BuildReportPage(Inputs());
  EXPECT_EQ(old_page.find("criteria within limits"), std::string::npos);
}

TEST(ReportPage, PlotsEachChannelGroupWithFilteredOverRaw) {
  const std::string page = BuildReportPage(Inputs());
  // Two groups: the head's acceleration (x, y, z raw and filtered) and the belt's span.
  EXPECT_EQ(Count(page, "<svg class=\"plot\""), 2);
  EXPECT_EQ(Count(page, "<path d=\"M"), 3 * 2 + 1);
  EXPECT_NE(page.find("occupant.head: acceleration"), std::string::npos);
  EXPECT_NE(page.find(">acceleration [g]</text>"), std::string::npos);
  EXPECT_NE(page.find(">belt_force [kN]</text>"), std::string::npos);
  EXPECT_NE(page.find(">time [ms]</text>"), std::string::npos);
  EXPECT_NE(page.find(">filtered</text>"), std::string::npos);
}

TEST(ReportPage, EmbedsTheAnimationAndTheViewer) {
  const ReportInputs inputs = Inputs();
  const std::string page = BuildReportPage(inputs);
  EXPECT_NE(page.find("<canvas id=\"viewer-canvas\""), std::string::npos);
  const std::string glb = "<script type=\"application/octet-stream\" id=\"animation-glb\">" +
                          Base64(inputs.glb) + "</script>";
  EXPECT_NE(page.find(glb), std::string::npos);
  EXPECT_NE(page.find("function parseGlb"), std::string::npos);
  // Self-contained: nothing is fetched from anywhere.
  EXPECT_EQ(page.find("src=\"http"), std::string::npos);
  EXPECT_EQ(page.find("href=\"http"), std::string::npos);
}

TEST(ReportPage, WithoutAnimationSaysSo) {
  ReportInputs inputs = Inputs();
  inputs.glb.clear();
  const std::string page = BuildReportPage(inputs);
  EXPECT_EQ(page.find("id=\"animation-glb\""), std::string::npos);
  EXPECT_NE(page.find("data-state=\"absent\""), std::string::npos);
}

TEST(WriteReport, ReadsARunFolderAndNotesWhatIsMissing) {
  testing::TempFolder temp;
  const auto& dir = temp.path();
  testing::WriteText(dir / "summary.json",
                     R"({"scenario": "tiny", "status": "ok", "criteria": [], "warnings": []})");
  testing::WriteText(dir / "timeseries.csv", "time [s],a.position.x [m]\n0,0\n0.001,0.002\n");
  const ReportResult result = WriteReport(dir, dir / "report.html");
  ASSERT_TRUE(result.written) << result.error;
  ASSERT_EQ(result.notes.size(), 2u);
  EXPECT_NE(result.notes[0].find("timeseries_filtered.csv is missing"), std::string::npos);
  EXPECT_NE(result.notes[1].find("animation.glb is missing"), std::string::npos);
  const std::string page = testing::ReadText(dir / "report.html");
  EXPECT_NE(page.find("<h1>tiny</h1>"), std::string::npos);
  EXPECT_EQ(Count(page, "<svg class=\"plot\""), 1);
  EXPECT_NE(page.find(">position [mm]</text>"), std::string::npos);
}

TEST(WriteReport, RefusesAFolderWithoutOrWithABrokenSummary) {
  testing::TempFolder temp;
  ReportResult result = WriteReport(temp.path(), temp.path() / "report.html");
  EXPECT_FALSE(result.written);
  EXPECT_NE(result.error.find("summary.json"), std::string::npos);
  testing::WriteText(temp.path() / "summary.json", "{\"rows\": \"x\"}");
  result = WriteReport(temp.path(), temp.path() / "report.html");
  EXPECT_FALSE(result.written);
  EXPECT_NE(result.error.find("`rows` should be a number"), std::string::npos) << result.error;
  EXPECT_FALSE(std::filesystem::exists(temp.path() / "report.html"));
}

}  // namespace
}  // namespace sled::report
