// A run's record read back from bytes is the run, field by field, and damaged bytes are refused.
#include <gtest/gtest.h>

#include "output/run_record.h"

namespace sled::runtime {
namespace {

RunSummary EveryFieldSet() {
  RunSummary s;
  s.integrator = "exponential";
  s.stats = {
      4399, 113, 13539, 2, 3, 4, 3323, 0.9957541920744579, {3000, 0.12, 0.05}, {1399, 0.08, 0.2},
      7};
  s.output_evaluations = 1999;
  s.error_estimate = 2.5e-6;
  s.wall_seconds = 0.252734325;
  s.failed = true;
  s.failure = {
      0.0638, "ball.sphere", "the error test failed at the minimum step", {"s.sled", 6, 13}};
  s.end_time = 0.0639;
  s.energy = {9056.7, 166.5, 2037.3, 11112.2, 0.5, -4.0e-5, 4.5e-4, 15686.9};
  s.checkpoints = {"out/checkpoint_0.05s.bin"};
  s.notes = {"resumed", "with other outputs"};
  return s;
}

TEST(RunRecord, ReadsBackEveryField) {
  const RunSummary s = EveryFieldSet();
  TimeSeries series;
  series.names = {"ball.sphere.position.z [m]", "b [N]"};
  series.columns = 3;
  series.values = {0.0, 0.07, 1.0 / 3.0, 0.001, 0.0699999, -2.5e-300};
  RunSummary r;
  TimeSeries t;
  ASSERT_TRUE(LoadRunRecord(SaveRunRecord(s, series), &r, &t));
  EXPECT_EQ(r.integrator, s.integrator);
  EXPECT_EQ(r.stats.steps, s.stats.steps);
  EXPECT_EQ(r.stats.rejected, s.stats.rejected);
  EXPECT_EQ(r.stats.evaluations, s.stats.evaluations);
  EXPECT_EQ(r.stats.jacobians, s.stats.jacobians);
  EXPECT_EQ(r.stats.factorizations, s.stats.factorizations);
  EXPECT_EQ(r.stats.events, s.stats.events);
  EXPECT_EQ(r.stats.decaying_steps, s.stats.decaying_steps);
  EXPECT_EQ(r.stats.max_local_error, s.stats.max_local_error);
  EXPECT_EQ(r.output_evaluations, s.output_evaluations);
  EXPECT_EQ(r.error_estimate, s.error_estimate);
  EXPECT_EQ(r.stats.explicit_share.steps, s.stats.explicit_share.steps);
  EXPECT_EQ(r.stats.explicit_share.simulated, s.stats.explicit_share.simulated);
  EXPECT_EQ(r.stats.exponential_share.wall_seconds, s.stats.exponential_share.wall_seconds);
  EXPECT_EQ(r.stats.switches, s.stats.switches);
  EXPECT_EQ(r.wall_seconds, s.wall_seconds);
  EXPECT_EQ(r.failed, s.failed);
  EXPECT_EQ(r.failure.time, s.failure.time);
  EXPECT_EQ(r.failure.where, s.failure.where);
  EXPECT_EQ(r.failure.cause, s.failure.cause);
  EXPECT_EQ(r.failure.source.file, s.failure.source.file);
  EXPECT_EQ(r.failure.source.line, s.failure.source.line);
  EXPECT_EQ(r.failure.source.column, s.failure.source.column);
  EXPECT_EQ(r.end_time, s.end_time);
  EXPECT_EQ(r.energy.kinetic, s.energy.kinetic);
  EXPECT_EQ(r.energy.scale, s.energy.scale);
  EXPECT_EQ(r.energy.residual, s.energy.residual);
  EXPECT_EQ(r.checkpoints, s.checkpoints);
  EXPECT_EQ(r.notes, s.notes);
  EXPECT_EQ(t.names, series.names);
  EXPECT_EQ(t.columns, series.columns);
  EXPECT_EQ(t.values, series.values);  // bit for bit
}

TEST(RunRecord, RefusesATruncatedOrLongerRecord) {
  const std::string bytes = SaveRunRecord(EveryFieldSet(), TimeSeries{});
  RunSummary r;
  TimeSeries t;
  EXPECT_FALSE(LoadRunRecord(bytes.substr(0, bytes.size() - 1), &r, &t));
  EXPECT_FALSE(LoadRunRecord(bytes + "x", &r, &t));
  EXPECT_FALSE(LoadRunRecord("", &r, &t));
}

}  // namespace
}  // namespace sled::runtime
