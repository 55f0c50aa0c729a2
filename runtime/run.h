// runtime::Run: integrates a Model from its start to its end time, sampling the output channels
// every output step. A numerical failure stops the run and keeps every row up to it.
#pragma once

#include <string>
#include <vector>

#include "runtime/data.h"
#include "runtime/integrate/ode.h"
#include "runtime/time_series.h"

namespace sled::runtime {

// The energy balance of a run (runtime/energy.h) at its last row, and the largest residual of
// any row against the largest term of the balance at any row.
struct EnergySummary {
  double kinetic = 0.0;
  double potential = 0.0;
  double absorbed = 0.0;         // by the force elements: stored + dissipated
  double prescribed_work = 0.0;  // done by the prescribed vehicle motion
  double impulses = 0.0;         // kinetic energy changed by impulsive events
  double residual = 0.0;         // KE + PE + absorbed - prescribed - impulses - initial
  double largest_residual = 0.0;
  double scale = 0.0;  // the largest |term| of the balance (KE, PE change, absorbed, ...)
  double relative() const { return scale > 0 ? largest_residual / scale : 0.0; }
};

struct RunSummary {
  std::string integrator;
  IntegratorStats stats;
  double wall_seconds = 0.0;
  bool failed = false;
  Failure failure;
  double end_time = 0.0;  // where the run stopped
  EnergySummary energy;
  std::vector<std::string> checkpoints;  // where the checkpoint sink kept them (files)
  std::vector<std::string> notes;        // what the user should know (a resume's changes)
};

// Sees the state of the run where it stops: at each output row, and at the extra stop times.
// Both are called after Forward, so accelerations, forces and joint wrenches are current.
class RunObserver {
 public:
  virtual ~RunObserver() = default;
  virtual void OnRow(const Model& model, const Data& data) = 0;
  virtual void OnStop(const Model& model, const Data& data) = 0;
};

struct Checkpoint;     // runtime/checkpoint.h
class CheckpointSink;  // runtime/checkpoint.h

struct RunOptions {
  // Called after each output row, e.g. to show progress; may be empty.
  void (*progress)(double fraction, void* context) = nullptr;
  void* progress_context = nullptr;
  // A checkpoint every this many seconds of simulated time (a multiple of the output step; the
  // caller checks), handed to `checkpoints`; 0 (or no sink): none.
  double checkpoint_every = 0.0;
  CheckpointSink* checkpoints = nullptr;
  // Continue from this checkpoint (its fingerprint already checked against the Model).
  const Checkpoint* resume = nullptr;
  // Sees each output row and stop time (the animation, the state dumps); may be null. A resumed
  // run shows it the rows from the checkpoint on.
  RunObserver* observer = nullptr;
  // Increasing times inside [start, end] where the integrator lands exactly, as on output times,
  // and the observer's OnStop sees the state (they add no output row); times outside the run are
  // never reached.
  std::vector<double> stop_times;
};

// The rows a complete run writes: the start, then one per output step up to the end.
std::size_t OutputRowCount(const Model& model);

RunSummary Run(const Model& model, Data& data, TimeSeries& series, const RunOptions& options = {});

}  // namespace sled::runtime
