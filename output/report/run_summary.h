// What summary.json says about a run (docs/runtime.md#outputs), read back for the report. A
// member the file lacks keeps its default, so a summary from an older sled still reads.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace sled::report {

struct IntegratorSummary {
  std::string method;
  double relative_tolerance = 0.0;
  double absolute_tolerance = 0.0;
  long long steps = 0;
  long long rejected_steps = 0;
  long long evaluations = 0;
  long long jacobians = 0;
  long long factorizations = 0;
  long long events = 0;
  long long decaying_steps = 0;  // exponential method only
  double max_local_error = 0.0;
  // The global error estimate of the channels' ranges (`sled run --error-estimate`); none when
  // the run did not compute one. (Older summaries held a sum of local error estimates here.)
  std::optional<double> error_estimate;
};

struct EnergySummary {
  double kinetic = 0.0;
  double potential = 0.0;
  double absorbed = 0.0;
  double prescribed_work = 0.0;
  double applied_work = 0.0;
  double impulses = 0.0;
  double residual = 0.0;
  double largest_residual = 0.0;
  double scale = 0.0;
  double relative_residual = 0.0;
};

struct FailureSummary {
  double time = 0.0;
  std::string where;
  std::string cause;
  std::string source;  // file:line:column, or empty
};

struct CriterionSummary {
  std::string name;
  std::string variant;
  std::string target;
  std::optional<double> value;  // nullopt: not computed (see `reason`)
  std::string unit;
  std::optional<double> window_start;
  std::optional<double> window_end;
  int filter_class = 0;
  std::optional<double> limit;
  std::string limit_source;
  std::optional<bool> pass;  // nullopt: not computed, or not judged (incomplete)
  // "pass", "fail", "no limit", "not computed" or "incomplete" (the run stopped early: the value
  // is over the rows up to `seen_until`); empty in summaries written before verdicts.
  std::string verdict;
  std::optional<double> seen_from;
  std::optional<double> seen_until;
  std::string reason;

  bool incomplete() const { return verdict == "incomplete"; }
};

// A channel's peak: its value of largest magnitude and when (summary.json's `peaks`).
struct PeakSummary {
  std::string channel;
  double value = 0.0;
  double time = 0.0;
  bool filtered = false;
};

struct RunSummaryFile {
  std::string scenario;
  std::string status;  // "ok", "failed", "interrupted" or "write_failed"
  double start_time = 0.0;
  double end_time = 0.0;
  double stopped_at = 0.0;
  double output_every = 0.0;
  long long rows = 0;
  long long channels = 0;
  IntegratorSummary integrator;
  double wall_time_seconds = 0.0;
  std::optional<EnergySummary> energy_balance;
  std::optional<FailureSummary> failure;
  std::vector<CriterionSummary> criteria;
  std::vector<PeakSummary> peaks;
  std::vector<std::string> warnings;
};

// Reads summary.json text; nullopt with `error` set when it is no JSON object or a member has the
// wrong type.
std::optional<RunSummaryFile> ParseRunSummary(const std::string& text, std::string* error);

}  // namespace sled::report
