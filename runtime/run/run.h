// runtime::Run: integrates a Model from its start to its end time, sampling the output channels
// every output step. A numerical failure stops the run and keeps every row up to it.
#pragma once

#include <atomic>
#include <span>
#include <string>
#include <vector>

#include "runtime/integrate/ode.h"
#include "runtime/model/data.h"
#include "runtime/run/settle.h"
#include "runtime/run/time_series.h"

namespace sled::runtime {

// The energy balance of a run (runtime/run/energy.h) at its last row, and the largest residual of
// any row against the largest term of the balance at any row.
struct EnergySummary {
  double kinetic = 0.0;
  double potential = 0.0;
  double absorbed = 0.0;         // by the force elements: stored + dissipated
  double prescribed_work = 0.0;  // done by the prescribed vehicle motion
  double applied_work = 0.0;     // done by the applied loads
  double impulses = 0.0;         // kinetic energy changed by impulsive events
  double residual = 0.0;         // KE + PE + absorbed - prescribed - impulses - initial
  double largest_residual = 0.0;
  double scale = 0.0;  // the largest |term| of the balance (KE, PE change, absorbed, ...)
  double relative() const { return scale > 0 ? largest_residual / scale : 0.0; }
};

struct RunSummary {
  std::string integrator;
  IntegratorStats stats;
  // Evaluations of the dynamics for the output rows after the first and for the stop times, on
  // the rows' own Data (runtime/run/output_rows.h); not in stats.evaluations.
  long output_evaluations = 0;
  // The global error estimate of the run, of the channels' ranges (output/post/
  // global_error.h), when the caller computed one; -1 otherwise.
  double error_estimate = -1.0;
  double wall_seconds = 0.0;
  bool failed = false;  // a numerical failure: `failure` says when, where and why
  Failure failure;
  bool interrupted = false;  // stopped early on request (RunOptions::stop)
  std::string output_error;  // a checkpoint that could not be written stopped the run: why
  double end_time = 0.0;     // where the run stopped
  // Ran to the end time: no failure, no interruption, no output error.
  bool complete() const { return !failed && !interrupted && output_error.empty(); }
  EnergySummary energy;
  SettleSummary settle;                  // how the scene settled before the run, if it did
  std::vector<std::string> checkpoints;  // where the checkpoint sink kept them (files)
  std::vector<std::string> notes;        // what the user should know (a resume's changes)
};

// Sees the state of the run at each output row and at the extra stop times, both read from the
// integrator's dense output. Both are called after Forward, so accelerations, forces and joint
// wrenches are current.
class RunObserver {
 public:
  virtual ~RunObserver() = default;
  virtual void OnRow(const Model& model, const Data& data) = 0;
  // The row just appended to the TimeSeries (time, then the channels), before OnRow.
  virtual void OnRowValues(std::span<const double> row) { (void)row; }
  virtual void OnStop(const Model& model, const Data& data) = 0;
};

struct Checkpoint;     // runtime/run/checkpoint.h
class CheckpointSink;  // runtime/run/checkpoint.h

struct RunOptions {
  // Called after each output row, e.g. to show progress; may be empty.
  void (*progress)(double fraction, void* context) = nullptr;
  void* progress_context = nullptr;
  // A checkpoint every this many seconds of simulated time (a multiple of the output step; the
  // caller checks), handed to `checkpoints`, named by that multiple (CheckpointFileName) and
  // taken at the end of the first step that reaches it (so taking them changes no step); 0 (or
  // no sink): none.
  double checkpoint_every = 0.0;
  CheckpointSink* checkpoints = nullptr;
  // Continue from this checkpoint (its fingerprint already checked against the Model).
  const Checkpoint* resume = nullptr;
  // Sees each output row and stop time (the animation, the state dumps); may be null. A resumed
  // run shows it the rows from the checkpoint on.
  RunObserver* observer = nullptr;
  // Increasing times inside [start, end] where the observer's OnStop sees the state, read from
  // the dense output as the rows are (they add no output row); times outside the run are never
  // reached.
  std::vector<double> stop_times;
  // When set and true, the run stops after the output row it is at (a signal handler sets it);
  // the rows so far are kept and RunSummary::interrupted is set.
  const std::atomic<bool>* stop = nullptr;
  // Evaluate the output rows and stop times on a second thread while the integration goes on
  // (runtime/run/output_rows.h): the same rows bit for bit, with the observer and `progress`
  // called from that thread. Off for callers that already use every core (sweeps, studies).
  bool row_thread = false;
};

// The integrator options a Model's run settings give (the run's and its settling's).
IntegratorOptions IntegratorOptionsOf(const Model& model);

// The rows a complete run writes: the start, then one per output step up to the end.
std::size_t OutputRowCount(const Model& model);

RunSummary Run(const Model& model, Data& data, TimeSeries& series, const RunOptions& options = {});

}  // namespace sled::runtime
