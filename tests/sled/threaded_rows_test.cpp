// SimulateOptions::threaded: the output rows evaluated on a second thread while the integration
// goes on (runtime/run/output_rows.h) give the run of one thread bit for bit: the rows, the
// filtered rows, the criteria, the statistics, the energy balance, the stop times' states and
// the checkpoints, for scenes with contacts, belts, airbags and loop constraints.
#include <bit>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "runtime/run/checkpoint.h"
#include "sled/sled.h"

namespace sled {
namespace {

namespace fs = std::filesystem;
const fs::path kRoot = SLED_SOURCE_ROOT;

// Bitwise equality (NaN included), with the first difference named.
void ExpectSameBits(const std::vector<double>& a, const std::vector<double>& b,
                    const std::string& what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (std::bit_cast<std::uint64_t>(a[i]) != std::bit_cast<std::uint64_t>(b[i])) {
      FAIL() << what << " differ at value " << i << ": " << a[i] << " and " << b[i];
    }
  }
}

// Keeps each stop time's evaluated state (q, v and the accelerations).
class StopRecorder : public RunSink {
 public:
  void OnStop(const runtime::Model& model, const runtime::Data& data) override {
    (void)model;
    states.push_back({data.time});
    std::vector<double>& state = states.back();
    state.insert(state.end(), data.q.begin(), data.q.end());
    state.insert(state.end(), data.v.begin(), data.v.end());
    state.insert(state.end(), data.vdot.begin(), data.vdot.end());
  }
  std::vector<std::vector<double>> states;
};

// Keeps the checkpoints in memory.
class CheckpointMemory : public runtime::CheckpointSink {
 public:
  bool Keep(const runtime::Checkpoint& checkpoint, std::string* where,
            std::string* error) override {
    (void)error;
    kept.push_back(checkpoint);
    *where = "memory";
    return true;
  }
  std::vector<runtime::Checkpoint> kept;
};

void ExpectSameRuns(const std::string& example) {
  CompileOptions compile_options;
  compile_options.stdlib = (kRoot / "stdlib").string();
  const Compilation compiled =
      Compile(Source::File((kRoot / "examples" / example).string()), compile_options);
  ASSERT_TRUE(compiled.ok()) << compiled.Render();
  const runtime::Model& model = compiled.model();
  SimulateOptions options;
  const double span = model.end_time - model.start_time;
  options.stop_times = {model.start_time + 0.3 * span, model.start_time + 0.7 * span};
  StopRecorder stops_one, stops_two;
  const RunResult one = Simulate(model, options, {&stops_one});
  options.threaded = true;
  const RunResult two = Simulate(model, options, {&stops_two});

  EXPECT_EQ(one.failed(), two.failed()) << example;
  ExpectSameBits(one.series.values, two.series.values, example + " rows");
  ExpectSameBits(one.filtered.values, two.filtered.values, example + " filtered rows");
  ASSERT_EQ(one.criteria.size(), two.criteria.size());
  for (std::size_t c = 0; c < one.criteria.size(); ++c) {
    EXPECT_EQ(one.criteria[c].value, two.criteria[c].value)
        << example << " " << one.criteria[c].name;
  }
  EXPECT_EQ(one.summary.stats.steps, two.summary.stats.steps) << example;
  EXPECT_EQ(one.summary.stats.evaluations, two.summary.stats.evaluations) << example;
  EXPECT_EQ(one.summary.output_evaluations, two.summary.output_evaluations) << example;
  EXPECT_EQ(one.summary.end_time, two.summary.end_time) << example;
  EXPECT_EQ(one.summary.energy.largest_residual, two.summary.energy.largest_residual) << example;
  EXPECT_EQ(one.summary.energy.kinetic, two.summary.energy.kinetic) << example;
  EXPECT_EQ(one.warnings, two.warnings) << example;
  ASSERT_EQ(stops_one.states.size(), 2u) << example;
  ASSERT_EQ(stops_one.states.size(), stops_two.states.size()) << example;
  for (std::size_t k = 0; k < stops_one.states.size(); ++k) {
    ExpectSameBits(stops_one.states[k], stops_two.states[k], example + " stop state");
  }
}

TEST(ThreadedRows, FlagshipSameBitForBit) { ExpectSameRuns("frontal_sled.sled"); }
TEST(ThreadedRows, AirbagSameBitForBit) { ExpectSameRuns("frontal_sled_airbag.sled"); }
TEST(ThreadedRows, LoopConstraintsSameBitForBit) { ExpectSameRuns("four_bar.sled"); }
TEST(ThreadedRows, PedestrianSameBitForBit) { ExpectSameRuns("pedestrian.sled"); }

// Checkpoints taken with the rows on their own thread are those of one thread, and a run
// resumed from one (threaded) ends with the uninterrupted run's rows.
TEST(ThreadedRows, CheckpointsAndResumeSameBitForBit) {
  CompileOptions compile_options;
  compile_options.stdlib = (kRoot / "stdlib").string();
  const Compilation compiled =
      Compile(Source::File((kRoot / "examples/frontal_sled.sled").string()), compile_options);
  ASSERT_TRUE(compiled.ok()) << compiled.Render();
  const runtime::Model& model = compiled.model();
  std::vector<std::vector<runtime::Checkpoint>> kept;
  std::vector<runtime::TimeSeries> series;
  for (const bool threaded : {false, true}) {
    runtime::Data data = runtime::MakeData(model);
    CheckpointMemory memory;
    runtime::RunOptions options;
    options.checkpoint_every = 50 * model.output_every;
    options.checkpoints = &memory;
    options.row_thread = threaded;
    runtime::TimeSeries rows;
    const runtime::RunSummary summary = runtime::Run(model, data, rows, options);
    ASSERT_TRUE(summary.complete());
    kept.push_back(memory.kept);
    series.push_back(rows);
  }
  ASSERT_EQ(kept[0].size(), kept[1].size());
  ASSERT_GE(kept[0].size(), 2u);
  for (std::size_t k = 0; k < kept[0].size(); ++k) {
    EXPECT_EQ(kept[0][k].next_row, kept[1][k].next_row);
    ExpectSameBits(kept[0][k].series.values, kept[1][k].series.values, "checkpoint rows");
  }
  ExpectSameBits(series[0].values, series[1].values, "rows");

  // Resumed from the second checkpoint, on two threads: the same rows to the end.
  runtime::Data data = runtime::MakeData(model);
  runtime::RunOptions options;
  options.resume = &kept[1][1];
  options.row_thread = true;
  runtime::TimeSeries resumed;
  ASSERT_TRUE(runtime::Run(model, data, resumed, options).complete());
  ExpectSameBits(series[0].values, resumed.values, "resumed rows");
}

}  // namespace
}  // namespace sled
