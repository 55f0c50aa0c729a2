// sled::Simulate: a compiled Model from its start to its end time, with the post-processing every
// run gets (SAE J211 filtered channels, injury criteria), handing the run to sinks as it goes.
// The one run loop of `sled run`, `sled study`, the tests and programs that embed sled.
//
//   sled::OutputFolder folder(model, {.directory = "out"});   // sled/output_folder.h
//   sled::RunResult run = sled::Simulate(model, {}, {&folder});
//   if (run.failed()) std::cerr << sled::DescribeFailure(model, run.summary.failure) << '\n';
#pragma once

#include <atomic>
#include <functional>
#include <string>
#include <vector>

#include "output/post/criterion_value.h"
#include "runtime/forces/table_range.h"
#include "runtime/model/data.h"
#include "runtime/model/model.h"
#include "runtime/run/checkpoint.h"
#include "runtime/run/run.h"

namespace sled {

// Everything a run produced. A run that failed numerically keeps its rows up to the failure,
// and its filtered channels and criteria are computed from those rows.
struct RunResult {
  // Integrator and its statistics, wall time, energy balance, checkpoints written, and the
  // failure (time, element, cause and its scene line) when `summary.failed`.
  runtime::RunSummary summary;
  runtime::TimeSeries series;    // time, then every channel of runtime::ChannelNames(model)
  runtime::TimeSeries filtered;  // the channels of groups with an SAE J211 class, filtered
  // The criteria from the rows there are; when the rows do not cover the whole run (a failure,
  // an interruption, a resumed run whose rows start at its checkpoint) they are incomplete and
  // never pass (CriterionValue::incomplete).
  std::vector<runtime::post::CriterionValue> criteria;
  // The elements whose argument left their table function's rows, once each, when and how far
  // (runtime/forces/table_range.h); each is also among the warnings.
  std::vector<runtime::TableExtrapolation> extrapolations;
  // What the user should know, one line each: the run's notes (a resume's changes) and the
  // groups the filters left unfiltered.
  std::vector<std::string> warnings;
  // Sinks that could not keep the result (RunSink::OnEnd returned false), one line each.
  std::vector<std::string> sink_errors;

  bool failed() const { return summary.failed; }
};

// Receives a run as it goes and its result at the end: the output folder, state dumps, a
// study's or sweep's collector. Every method has a do-nothing default.
class RunSink {
 public:
  virtual ~RunSink() = default;
  // At each output row, after the state there is evaluated (forces, accelerations, joint
  // wrenches current). A resumed run shows the rows from its checkpoint on.
  virtual void OnRow(const runtime::Model& model, const runtime::Data& data);
  // Just before OnRow: the row's values as the TimeSeries holds them (time, then the channels).
  virtual void OnRowValues(std::span<const double> row);
  // At each of SimulateOptions::stop_times the run reaches, evaluated the same way.
  virtual void OnStop(const runtime::Model& model, const runtime::Data& data);
  // Once, when the run has stopped and its rows are final, before the post-processing: a sink
  // may start writing them on a thread of its own (the rows stay unchanged until OnEnd).
  virtual void OnRows(const runtime::Model& model, const runtime::TimeSeries& series);
  // Once, after the run, numerical failure included. False with `error` set when the sink could
  // not keep the result (a file it could not write); Simulate lists it in sink_errors.
  virtual bool OnEnd(const runtime::Model& model, const RunResult& result, std::string* error);
};

struct SimulateOptions {
  // Called after each output row with the fraction of the run done; may be empty.
  std::function<void(double fraction)> progress;
  // Increasing times where the sinks' OnStop see the state, read from the dense output as the
  // rows are (they add no output row and no step); times outside the run are never reached.
  std::vector<double> stop_times;
  // A checkpoint every this many seconds of simulated time, a multiple of the output step
  // (CheckpointStepError says whether it is), into checkpoint_directory, each a file named by
  // output::CheckpointFileName; 0: none.
  double checkpoint_every = 0.0;
  std::string checkpoint_directory = ".";
  // Continue from this checkpoint, read and checked against the Model by the caller
  // (output::ReadCheckpoint, runtime::CheckpointMismatch); null: start at the start time.
  const runtime::Checkpoint* resume = nullptr;
  // Also run a companion at a tenth of the tolerances for the global error estimate
  // (output/post/global_error.h) in summary.error_estimate; a warning says why when it cannot.
  bool error_estimate = false;
  // When set and true, the run stops after its current output row (a signal handler sets it):
  // its rows so far are post-processed and handed to the sinks, summary.interrupted is set.
  const std::atomic<bool>* stop = nullptr;
  // Use a second thread: the output rows are evaluated on it while the integration goes on
  // (runtime::RunOptions::row_thread; the rows are the same bit for bit, the sinks' OnRow and
  // OnStop and `progress` are called from it). `sled run` sets it; leave it off where every
  // core already has a run (sweeps, studies).
  bool threaded = false;
};

// Runs the Model with a fresh Data, post-processes the rows, then calls every sink's OnEnd in
// order. Never throws for a numerical failure: it is in result.summary.
RunResult Simulate(const runtime::Model& model, const SimulateOptions& options = {},
                   const std::vector<RunSink*>& sinks = {});

// Why `every` seconds cannot be the checkpoint step of the Model (not a positive multiple of its
// output step); empty when it can.
std::string CheckpointStepError(const runtime::Model& model, double every);

// Sets a failure's scene line from the segment, joint or constraint it names, when the runtime
// gave none.
void LocateFailure(const runtime::Model& model, runtime::Failure& failure);
// A numerical failure in one line: `at t = 0.0638 s in `ball.sphere`: why (scene.sled:6:13)`.
std::string DescribeFailure(const runtime::Model& model, runtime::Failure failure);

}  // namespace sled
