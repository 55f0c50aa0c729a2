#include "runtime/run/output_rows.h"

#include <algorithm>
#include <cmath>

#include "runtime/dynamics/dynamics.h"
#include "runtime/forces/table_range.h"
#include "runtime/run/energy.h"
#include "runtime/run/outputs.h"

namespace sled::runtime {
namespace {

// Slots in the ring: enough for the worker to fall a few steps behind without holding the
// integration up.
constexpr std::size_t kThreadedSlots = 8;

}  // namespace

void RunHistories::Take(const Data& from) {
  locked = from.locked;
  joint_histories = from.joint_histories;
  contacts = from.contacts;
  belts = from.belts;
  airbags = from.airbags;
  energy = from.energy;
  settling_damping = from.settling_damping;
  if (from.constraints) TakeConstraintHistory(*from.constraints, constraints);
}

void RunHistories::Give(Data& to) const {
  to.locked = locked;
  to.joint_histories = joint_histories;
  to.contacts = contacts;
  to.belts = belts;
  to.airbags = airbags;
  to.energy = energy;
  to.settling_damping = settling_damping;
  if (to.constraints) GiveConstraintHistory(constraints, *to.constraints);
}

void UpdateEnergy(const Model& model, const Data& data, double initial_potential,
                  EnergySummary& energy) {
  const EnergyBalance& balance = data.energy;
  energy.kinetic = KineticEnergy(model, data);
  energy.potential = PotentialEnergy(model, data);
  energy.absorbed = balance.Absorbed();
  energy.prescribed_work = balance.PrescribedWork();
  energy.applied_work = balance.applied_work;
  energy.impulses = balance.impulses;
  energy.residual = balance.Residual(energy.kinetic, energy.potential);
  energy.largest_residual = std::max(energy.largest_residual, std::abs(energy.residual));
  for (double term : {energy.kinetic, energy.potential - initial_potential, energy.absorbed,
                      energy.prescribed_work, energy.applied_work, energy.impulses}) {
    energy.scale = std::max(energy.scale, std::abs(term));
  }
}

void AppendRow(const Model& model, const Data& data, TimeSeries& series) {
  const std::size_t start = series.values.size();
  series.values.resize(start + series.columns);  // reserved in advance: no reallocation
  series.values[start] = data.time;
  EvaluateChannels(model, data,
                   std::span<double>(series.values).subspan(start + 1, series.columns - 1));
}

void MergeTableWatch(const Model& model, const TableWatch& from, TableWatch& to) {
  const FunctionTable& functions = model.functions;
  // Recording the earliest argument, then the farthest, leaves the earliest of both first and
  // the farthest of both farthest.
  auto merge = [&](const TableOverrun& record, std::int32_t function, TableOverrun& into) {
    if (!record.seen) return;
    RecordTableArgument(functions, function, record.first_time, record.first_argument, into);
    RecordTableArgument(functions, function, record.first_time, record.farthest_argument, into);
  };
  for (std::size_t k = 0; k < model.contacts.npair(); ++k) {
    merge(from.contact[k], model.contacts.pair_function[k], to.contact[k]);
  }
  for (std::size_t b = 0; b < model.belts.size(); ++b) {
    merge(from.belt[b], model.belts.function[b], to.belt[b]);
  }
  for (std::size_t s = 0; s < model.nsegment(); ++s) {
    for (std::size_t k = 0; k < 3; ++k) {
      merge(from.joint[3 * s + k], model.joint_function[s][k], to.joint[3 * s + k]);
    }
  }
  for (std::size_t k = 0; k < model.nspring(); ++k) {
    merge(from.spring[k], model.spring_function[k], to.spring[k]);
  }
  for (std::size_t b = 0; b < model.airbags.size(); ++b) {
    merge(from.airbag[b], model.airbags.inflow[b], to.airbag[b]);
  }
}

std::span<double> OutputRows::Job::Add(const Entry& entry, std::size_t state_size) {
  const std::size_t start = entries.size() * state_size;
  entries.push_back(entry);
  if (states.size() < start + state_size) states.resize(start + state_size);
  return std::span<double>(states).subspan(start, state_size);
}

OutputRows::OutputRows(const Model& model, TimeSeries& series, const RunOptions& options,
                       std::size_t next_row, std::size_t outputs, double initial_potential,
                       const EnergySummary& energy, bool threaded)
    : model_(model),
      series_(series),
      options_(options),
      next_row_(next_row),
      outputs_(outputs),
      initial_potential_(initial_potential),
      energy_(energy),
      data_(MakeData(model)),
      slots_(threaded ? kThreadedSlots : 1),
      threaded_(threaded) {
  if (threaded_) worker_ = std::thread([this] { Work(); });
}

OutputRows::~OutputRows() {
  if (!worker_.joinable()) return;
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  changed_.notify_all();
  worker_.join();
}

OutputRows::Job& OutputRows::NextJob() {
  std::unique_lock<std::mutex> lock(mutex_);
  changed_.wait(lock, [this] { return count_ < slots_.size(); });
  Job& job = slots_[head_];
  job.entries.clear();
  return job;
}

void OutputRows::Submit() {
  if (!threaded_) {
    Evaluate(slots_[head_]);
    return;
  }
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    head_ = (head_ + 1) % slots_.size();
    ++count_;
  }
  changed_.notify_all();
}

void OutputRows::Drain() {
  if (!threaded_) return;
  std::unique_lock<std::mutex> lock(mutex_);
  changed_.wait(lock, [this] { return count_ == 0; });
  if (worker_error_) std::rethrow_exception(worker_error_);
}

void OutputRows::Finish() {
  Drain();
  if (!worker_.joinable()) return;
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  changed_.notify_all();
  worker_.join();
}

bool OutputRows::halted() const { return halted_.load(std::memory_order_acquire); }

void OutputRows::Work() {
  for (;;) {
    std::size_t slot = 0;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      changed_.wait(lock, [this] { return count_ > 0 || stopping_; });
      if (count_ == 0) return;  // stopping, with nothing left
      slot = (head_ + slots_.size() - count_) % slots_.size();
    }
    // The slot is the worker's until count_ drops: the main thread fills only free ones.
    try {
      if (!worker_error_) Evaluate(slots_[slot]);
    } catch (...) {
      worker_error_ = std::current_exception();
      halted_.store(true, std::memory_order_release);
    }
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      --count_;
    }
    changed_.notify_all();
  }
}

void OutputRows::Halt(const Job& job, double time) {
  halt_time_ = time;
  halt_stats_ = job.stats;
  halted_.store(true, std::memory_order_release);
}

void OutputRows::Evaluate(const Job& job) {
  if (halted() || job.entries.empty()) return;
  job.histories.Give(data_);
  const std::size_t n = StateSize(model_);
  auto same_time = [](double a, double b) {
    return std::abs(a - b) <= 1e-12 * std::max(1.0, std::abs(b));
  };
  for (std::size_t i = 0; i < job.entries.size(); ++i) {
    const Entry& entry = job.entries[i];
    if (entry.evaluate) {
      LoadState(data_, entry.time, std::span<const double>(job.states).subspan(i * n, n));
      ++evaluations_;
      Failure failure;
      if (!Forward(model_, data_, &failure)) {
        failed_ = true;
        failure_ = failure;
        failure_.time = entry.time;
        Halt(job, entry.time);
        return;
      }
    }
    if (!entry.row) {
      if (options_.observer) options_.observer->OnStop(model_, data_);
      continue;
    }
    UpdateEnergy(model_, data_, initial_potential_, energy_);
    WatchTablesAtRow(model_, data_);
    AppendRow(model_, data_, series_);
    if (options_.observer) {
      options_.observer->OnRowValues(std::span<const double>(series_.values).last(series_.columns));
      options_.observer->OnRow(model_, data_);
    }
    ++next_row_;
    if (options_.progress) {
      options_.progress(static_cast<double>(next_row_ - 1) / static_cast<double>(outputs_ - 1),
                        options_.progress_context);
    }
    // A stop request (a signal) ends the run after this row and the stops at its time.
    if (options_.stop != nullptr && options_.stop->load() && next_row_ < outputs_) {
      while (i + 1 < job.entries.size() && !job.entries[i + 1].row &&
             same_time(job.entries[i + 1].time, entry.time)) {
        if (options_.observer) options_.observer->OnStop(model_, data_);
        ++i;
      }
      interrupted_ = true;
      Halt(job, entry.time);
      return;
    }
  }
}

}  // namespace sled::runtime
