// The output rows and stop times of a run, evaluated on a Data of their own. Each accepted step
// hands over the states at its row and stop times (read from its dense output) with the
// histories the step ended with (RunHistories), and the rows are evaluated from those alone. So
// the rows never disturb the integration (its warm starts and its evaluation cache), and they can
// be evaluated on a second thread while the integration goes on (RunOptions::row_thread): the
// same evaluations, in the same order, of the same inputs, so the rows are bit for bit those of
// one thread.
#pragma once

#include <condition_variable>
#include <cstdint>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

#include "runtime/dynamics/constraints.h"
#include "runtime/integrate/ode.h"
#include "runtime/model/data.h"
#include "runtime/run/run.h"

namespace sled::runtime {

// What an evaluation reads besides the state: what a checkpoint carries of a Data (SerializeData)
// except the state itself and the report of table overruns.
struct RunHistories {
  std::vector<std::uint8_t> locked;
  JointHistories joint_histories;
  ContactState contacts;
  BeltState belts;
  AirbagState airbags;
  EnergyBalance energy;
  double settling_damping = 0.0;
  ConstraintHistory constraints;

  // Copies; no allocation once sized by a first Take.
  void Take(const Data& from);
  void Give(Data& to) const;
};

// The balance at data's state (after Forward) into `energy`: its terms, the residual and the
// largest of each.
void UpdateEnergy(const Model& model, const Data& data, double initial_potential,
                  EnergySummary& energy);
// Appends the row of data's state (after Forward) to `series` (reserved: no reallocation).
void AppendRow(const Model& model, const Data& data, TimeSeries& series);
// Folds the table overruns `from` recorded into `to`: the earliest first and the farthest of
// both. Merging the same records again changes nothing.
void MergeTableWatch(const Model& model, const TableWatch& from, TableWatch& to);

class OutputRows {
 public:
  // One evaluation on a step: an output row, or a stop time (the observer's OnStop), which at a
  // row's time sees the row's evaluation (`evaluate` false).
  struct Entry {
    bool row = true;
    bool evaluate = true;
    double time = 0.0;
  };
  // What one accepted step hands over.
  struct Job {
    RunHistories histories;
    IntegratorStats stats;  // the integrator's after the step, for a run the rows stop
    std::vector<Entry> entries;
    std::vector<double> states;  // entries.size() x the state size, row-major

    // Appends an entry and returns where its state goes (allocates only past earlier sizes).
    std::span<double> Add(const Entry& entry, std::size_t state_size);
  };

  // `series` holds the rows before `next_row` (the first, or a checkpoint's); `energy` the
  // balance up to them. `threaded`: a worker thread evaluates the jobs.
  OutputRows(const Model& model, TimeSeries& series, const RunOptions& options,
             std::size_t next_row, std::size_t outputs, double initial_potential,
             const EnergySummary& energy, bool threaded);
  ~OutputRows();
  OutputRows(const OutputRows&) = delete;
  OutputRows& operator=(const OutputRows&) = delete;

  // The job to fill for the next step (waits while every slot is taken), emptied; then Submit.
  Job& NextJob();
  // Hands the filled job over: evaluated now, or by the worker.
  void Submit();
  // Waits until every job submitted is evaluated (a checkpoint's rows).
  void Drain();
  // Drain, then stops the worker; rethrows what it threw.
  void Finish();

  // The rows stopped: a row could not be evaluated (failure()), or the stop request came
  // (interrupted()). May be read without Drain; the rest only after Drain or Finish.
  bool halted() const;
  bool interrupted() const { return interrupted_; }
  bool failed() const { return failed_; }
  const Failure& failure() const { return failure_; }
  double halt_time() const { return halt_time_; }
  const IntegratorStats& halt_stats() const { return halt_stats_; }
  const EnergySummary& energy() const { return energy_; }
  long evaluations() const { return evaluations_; }
  std::size_t next_row() const { return next_row_; }
  const Data& data() const { return data_; }

 private:
  void Evaluate(const Job& job);
  void Work();
  void Halt(const Job& job, double time);

  const Model& model_;
  TimeSeries& series_;
  const RunOptions& options_;
  std::size_t next_row_;
  std::size_t outputs_;
  double initial_potential_;
  EnergySummary energy_;
  Data data_;
  long evaluations_ = 0;
  bool interrupted_ = false;
  bool failed_ = false;
  Failure failure_;
  double halt_time_ = 0.0;
  IntegratorStats halt_stats_;

  // A ring of jobs: the main thread fills slot `head_`, the worker evaluates `count_` filled
  // ones from (head_ - count_). Slots are read by one side at a time, handed over under mutex_.
  std::vector<Job> slots_;
  std::size_t head_ = 0;
  std::size_t count_ = 0;  // filled and not yet evaluated
  bool threaded_ = false;
  bool stopping_ = false;
  std::atomic<bool> halted_{false};
  std::exception_ptr worker_error_;
  std::mutex mutex_;
  std::condition_variable changed_;
  std::thread worker_;
};

}  // namespace sled::runtime
