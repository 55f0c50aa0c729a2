#include "sled/simulate.h"

#include <cmath>
#include <future>
#include <utility>

#include <fmt/format.h>

#include "output/checkpoint_file.h"
#include "output/post/channel_filters.h"
#include "output/post/global_error.h"
#include "output/post/injury_criteria.h"
#include "runtime/contact/contact_reach.h"

namespace sled {
namespace {

// Hands the runtime's observer calls to every sink in turn.
class SinkFanOut : public runtime::RunObserver {
 public:
  explicit SinkFanOut(const std::vector<RunSink*>& sinks) : sinks_(sinks) {}
  void OnRow(const runtime::Model& model, const runtime::Data& data) override {
    for (RunSink* sink : sinks_) sink->OnRow(model, data);
  }
  void OnRowValues(std::span<const double> row) override {
    for (RunSink* sink : sinks_) sink->OnRowValues(row);
  }
  void OnStop(const runtime::Model& model, const runtime::Data& data) override {
    for (RunSink* sink : sinks_) sink->OnStop(model, data);
  }

 private:
  const std::vector<RunSink*>& sinks_;
};

void ReportProgress(double fraction, void* context) {
  (*static_cast<std::function<void(double)>*>(context))(fraction);
}

}  // namespace

void RunSink::OnRow(const runtime::Model& model, const runtime::Data& data) {
  (void)model;
  (void)data;
}

void RunSink::OnStop(const runtime::Model& model, const runtime::Data& data) {
  (void)model;
  (void)data;
}

void RunSink::OnRowValues(std::span<const double> row) { (void)row; }

void RunSink::OnRows(const runtime::Model& model, const runtime::TimeSeries& series) {
  (void)model;
  (void)series;
}

bool RunSink::OnEnd(const runtime::Model& model, const RunResult& result, std::string* error) {
  (void)model;
  (void)result;
  (void)error;
  return true;
}

RunResult Simulate(const runtime::Model& model, const SimulateOptions& options,
                   const std::vector<RunSink*>& sinks) {
  RunResult result;
  runtime::Data data = runtime::MakeData(model);
  SinkFanOut fan_out(sinks);
  runtime::RunOptions run_options;
  std::function<void(double)> progress = options.progress;
  if (progress) {
    run_options.progress = ReportProgress;
    run_options.progress_context = &progress;
  }
  run_options.observer = sinks.empty() ? nullptr : &fan_out;
  run_options.stop_times = options.stop_times;
  output::CheckpointFolder checkpoint_folder(options.checkpoint_directory);
  run_options.checkpoint_every = options.checkpoint_every;
  run_options.checkpoints = &checkpoint_folder;
  run_options.resume = options.resume;
  run_options.stop = options.stop;
  run_options.row_thread = options.threaded;
  result.summary = runtime::Run(model, data, result.series, run_options);
  if (result.summary.failed) LocateFailure(model, result.summary.failure);
  for (RunSink* sink : sinks) sink->OnRows(model, result.series);

  // Filtered channels and injury criteria, from the rows there are (up to a failure).
  // The criteria read the unfiltered rows: with a second thread, beside the filters.
  std::future<std::vector<runtime::post::CriterionValue>> criteria;
  if (options.threaded) {
    criteria = std::async(std::launch::async, runtime::post::EvaluateCriteria, std::cref(model),
                          std::cref(result.series));
  }
  runtime::post::FilteredChannels filtered =
      runtime::post::FilterOutputChannels(model, result.series);
  result.filtered = std::move(filtered.series);
  result.criteria =
      criteria.valid() ? criteria.get() : runtime::post::EvaluateCriteria(model, result.series);
  const double first_row = result.series.rows() > 0 ? result.series.values[0] : model.start_time;
  if (!result.summary.complete() || first_row > model.start_time) {
    runtime::post::MarkIncomplete(result.criteria, first_row, result.summary.end_time);
  }
  result.warnings = result.summary.notes;
  result.extrapolations = runtime::TableExtrapolations(model, data);
  for (const runtime::TableExtrapolation& e : result.extrapolations) {
    result.warnings.push_back("warning: " + e.Describe());
  }
  for (std::string& warning : runtime::ContactReachWarnings(model, data)) {
    result.warnings.push_back(std::move(warning));
  }
  for (std::string& warning : filtered.warnings) result.warnings.push_back(std::move(warning));
  if (options.error_estimate && result.summary.complete()) {
    const runtime::post::GlobalErrorEstimate estimate =
        runtime::post::EstimateGlobalError(model, result.series, result.criteria);
    if (estimate.computed) {
      result.summary.error_estimate = estimate.overall;
    } else {
      result.warnings.push_back("no global error estimate: " + estimate.reason);
    }
  }

  for (RunSink* sink : sinks) {
    std::string error;
    if (!sink->OnEnd(model, result, &error)) result.sink_errors.push_back(std::move(error));
  }
  return result;
}

std::string CheckpointStepError(const runtime::Model& model, double every) {
  const double rows = every / model.output_every;
  if (every > 0 && model.output_every > 0 && std::llround(rows) >= 1 &&
      std::abs(rows - static_cast<double>(std::llround(rows))) <= 1e-9 * rows) {
    return {};
  }
  return fmt::format(
      "{} s is not a multiple of the output step {} s; checkpoints are taken at output rows", every,
      model.output_every);
}

void LocateFailure(const runtime::Model& model, runtime::Failure& failure) {
  if (failure.where.empty()) return;
  for (std::size_t s = 0; s < model.nsegment() && failure.source.file.empty(); ++s) {
    if (model.segment_name[s] == failure.where) {
      failure.source = model.segment_source[s];
    } else if (model.joint_name[s] == failure.where) {
      failure.source = model.joint_source[s];
    }
  }
  for (std::size_t c = 0; c < model.constraint_source.size() && failure.source.file.empty(); ++c) {
    if (model.constraint_name[c] == failure.where) failure.source = model.constraint_source[c];
  }
}

std::string DescribeFailure(const runtime::Model& model, runtime::Failure failure) {
  LocateFailure(model, failure);
  return fmt::format(
      "at t = {:.6g} s{}: {}{}", failure.time,
      failure.where.empty() ? "" : fmt::format(" in `{}`", failure.where), failure.cause,
      failure.source.file.empty() ? ""
                                  : fmt::format(" ({}:{}:{})", failure.source.file,
                                                failure.source.line, failure.source.column));
}

}  // namespace sled
