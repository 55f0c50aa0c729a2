// runtime::Run: integrates a Model from its start to its end time, sampling the output channels
// every output step. A numerical failure stops the run and keeps every row up to it.
#pragma once

#include <string>
#include <vector>

#include "runtime/data.h"
#include "runtime/integrate/ode.h"

namespace sled::runtime {

// Rows of `columns` values: time, then the channels of ChannelNames(model).
struct TimeSeries {
  std::vector<std::string> names;  // without the time column
  std::size_t columns = 0;         // 1 + names.size()
  std::vector<double> values;      // row-major
  std::size_t rows() const { return columns == 0 ? 0 : values.size() / columns; }
};

struct RunSummary {
  std::string integrator;
  IntegratorStats stats;
  double wall_seconds = 0.0;
  bool failed = false;
  Failure failure;
  double end_time = 0.0;  // where the run stopped
};

// Sees the state of the run where it stops: at each output row, and at the extra stop times.
// Both are called after Forward, so accelerations, forces and joint wrenches are current.
class RunObserver {
 public:
  virtual ~RunObserver() = default;
  virtual void OnRow(const Model& model, const Data& data) = 0;
  virtual void OnStop(const Model& model, const Data& data) = 0;
};

struct RunOptions {
  // Called after each output row, e.g. to show progress; may be empty.
  void (*progress)(double fraction, void* context) = nullptr;
  void* progress_context = nullptr;
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
