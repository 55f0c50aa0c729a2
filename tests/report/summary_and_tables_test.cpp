// Reading what `sled run` writes: summary.json (every member, nulls for values not computed,
// escapes, a member of the wrong type), the time-series CSV, and base64 for the animation.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "output/report/base64.h"
#include "output/report/channel_table.h"
#include "output/report/run_summary.h"

namespace sled::report {
namespace {

constexpr const char* kSummary = R"({
  "scenario": "sled \"A\" caf\u00e9",
  "status": "failed",
  "start_time": 0, "end_time": 0.2, "stopped_at": 0.0421, "output_every": 0.0001,
  "rows": 422, "channels": 3,
  "integrator": {"method": "rosenbrock", "relative_tolerance": 1e-05, "absolute_tolerance": 1e-09,
                 "steps": 1234, "rejected_steps": 12, "evaluations": 5000, "jacobians": 40,
                 "factorizations": 41, "events": 2, "max_local_error": 0.93,
                 "error_estimate": 0.0029},
  "wall_time_seconds": 1.5,
  "energy_balance": {"kinetic": 1, "potential": 2, "absorbed": 3, "prescribed_work": 4,
                     "impulses": 0, "residual": 1e-4, "largest_residual": 2e-4, "scale": 4,
                     "relative_residual": 5e-5},
  "failure": {"time": 0.0421, "where": "joint occupant.neck", "cause": "singular system",
              "source": "scene.sled:12:3"},
  "criteria": [
    {"name": "hic15", "variant": "", "target": "occupant.head", "value": 812.5, "unit": "",
     "window_start": 0.06, "window_end": 0.075, "filter_class": 1000, "limit": 700,
     "limit_source": "FMVSS 208", "pass": false},
    {"name": "nij", "variant": "NCF", "target": "occupant.neck", "value": null, "unit": "",
     "window_start": null, "window_end": null, "filter_class": 600, "limit": 1,
     "limit_source": "FMVSS 208", "pass": null, "reason": "never in this quadrant"}
  ],
  "warnings": ["first\nsecond", "tab\there"]
})";

TEST(RunSummary, ReadsEveryMember) {
  std::string error;
  const std::optional<RunSummaryFile> summary = ParseRunSummary(kSummary, &error);
  ASSERT_TRUE(summary) << error;
  EXPECT_EQ(summary->scenario, "sled \"A\" caf\xc3\xa9");
  EXPECT_EQ(summary->status, "failed");
  EXPECT_DOUBLE_EQ(summary->stopped_at, 0.0421);
  EXPECT_EQ(summary->rows, 422);
  EXPECT_EQ(summary->integrator.method, "rosenbrock");
  EXPECT_EQ(summary->integrator.steps, 1234);
  EXPECT_EQ(summary->integrator.factorizations, 41);
  ASSERT_TRUE(summary->integrator.error_estimate);
  EXPECT_DOUBLE_EQ(*summary->integrator.error_estimate, 0.0029);
  ASSERT_TRUE(summary->energy_balance);
  EXPECT_DOUBLE_EQ(summary->energy_balance->relative_residual, 5e-5);
  ASSERT_TRUE(summary->failure);
  EXPECT_EQ(summary->failure->where, "joint occupant.neck");
  EXPECT_EQ(summary->failure->source, "scene.sled:12:3");
  ASSERT_EQ(summary->criteria.size(), 2u);
  EXPECT_EQ(summary->criteria[0].value, 812.5);
  EXPECT_EQ(summary->criteria[0].pass, false);
  EXPECT_EQ(summary->criteria[0].filter_class, 1000);
  EXPECT_FALSE(summary->criteria[1].value);
  EXPECT_FALSE(summary->criteria[1].pass);
  EXPECT_FALSE(summary->criteria[1].window_start);
  EXPECT_EQ(summary->criteria[1].limit, 1.0);
  EXPECT_EQ(summary->criteria[1].reason, "never in this quadrant");
  ASSERT_EQ(summary->warnings.size(), 2u);
  EXPECT_EQ(summary->warnings[0], "first\nsecond");
}

TEST(RunSummary, AnOkRunHasNoFailure) {
  std::string error;
  const auto summary =
      ParseRunSummary(R"({"scenario": "s", "status": "ok", "criteria": []})", &error);
  ASSERT_TRUE(summary) << error;
  EXPECT_FALSE(summary->failure);
  EXPECT_FALSE(summary->energy_balance);
}

TEST(RunSummary, RejectsMalformedTextAndWrongTypes) {
  std::string error;
  EXPECT_FALSE(ParseRunSummary("{\"scenario\": ", &error));
  EXPECT_NE(error.find("no JSON object"), std::string::npos) << error;
  EXPECT_FALSE(ParseRunSummary("[1, 2]", &error));
  error.clear();
  EXPECT_FALSE(ParseRunSummary(R"({"integrator": {"steps": "many"}})", &error));
  EXPECT_NE(error.find("`integrator.steps` should be a number"), std::string::npos) << error;
  error.clear();
  EXPECT_FALSE(ParseRunSummary(R"({"criteria": [{"value": true}]})", &error));
  EXPECT_NE(error.find("`criteria[0].value`"), std::string::npos) << error;
}

TEST(ChannelTable, ReadsTimeAndColumns) {
  std::string error;
  const auto table =
      ParseChannelTable("time [s],a.x [N],a.y [N]\n0,1,2\n0.0001,-1.5e3,nan\n", &error);
  ASSERT_TRUE(table) << error;
  EXPECT_EQ(table->names, (std::vector<std::string>{"a.x [N]", "a.y [N]"}));
  EXPECT_EQ(table->time, (std::vector<double>{0.0, 0.0001}));
  ASSERT_NE(table->Find("a.x [N]"), nullptr);
  EXPECT_EQ((*table->Find("a.x [N]"))[1], -1500.0);
  EXPECT_TRUE(std::isnan((*table->Find("a.y [N]"))[1]));
  EXPECT_EQ(table->Find("a.z [N]"), nullptr);
}

TEST(ChannelTable, RejectsRowsOfTheWrongWidthAndFilesWithoutTime) {
  std::string error;
  EXPECT_FALSE(ParseChannelTable("time [s],a\n0,1\n0.1\n", &error));
  EXPECT_NE(error.find("line 3 has 1 fields"), std::string::npos) << error;
  EXPECT_FALSE(ParseChannelTable("a,b\n0,1\n", &error));
  EXPECT_FALSE(ParseChannelTable("", &error));
}

TEST(Base64, MatchesTheRfc4648Vectors) {
  EXPECT_EQ(Base64(""), "");
  EXPECT_EQ(Base64("f"), "Zg==");
  EXPECT_EQ(Base64("fo"), "Zm8=");
  EXPECT_EQ(Base64("foo"), "Zm9v");
  EXPECT_EQ(Base64("foob"), "Zm9vYg==");
  EXPECT_EQ(Base64("fooba"), "Zm9vYmE=");
  EXPECT_EQ(Base64("foobar"), "Zm9vYmFy");
  EXPECT_EQ(Base64(std::string("\xff\x00\x80", 3)), "/wCA");
}

}  // namespace
}  // namespace sled::report
