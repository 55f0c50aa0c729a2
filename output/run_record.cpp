#include "output/run_record.h"

#include <type_traits>

#include "runtime/run/archive.h"

namespace sled::runtime {
namespace {

// Every field, once, for both directions (runtime/run/archive.h). A field added to RunSummary,
// Failure or TimeSeries must be added here: the size checks below fail until it is.
static_assert(std::is_trivially_copyable_v<IntegratorStats>);
static_assert(std::is_trivially_copyable_v<EnergySummary>);
static_assert(sizeof(SettleSummary) == 144 || sizeof(std::string) != 32,
              "SettleSummary changed: list the new field in Serialize");
static_assert(sizeof(std::string) != 32 ||
                  (sizeof(RunSummary) == 608 && sizeof(Failure) == 112 && sizeof(TimeSeries) == 56),
              "RunSummary, Failure or TimeSeries changed: list the new field in Serialize");

void Strings(Archive& archive, std::vector<std::string>& texts) {
  std::int64_t count = static_cast<std::int64_t>(texts.size());
  archive.Field(count);
  if (archive.reading()) {
    if (count < 0 || count > (std::int64_t{1} << 32)) {
      archive.Fail();
      return;
    }
    texts.assign(static_cast<std::size_t>(count), std::string());
  }
  for (std::string& text : texts) archive.Resizable(text);
}

void Serialize(Archive& archive, RunSummary& summary, TimeSeries& series) {
  archive.Resizable(summary.integrator);
  archive.Field(summary.stats);
  archive.Field(summary.output_evaluations);
  archive.Field(summary.error_estimate);
  archive.Field(summary.wall_seconds);
  archive.Field(summary.failed);
  archive.Field(summary.failure.time);
  archive.Resizable(summary.failure.where);
  archive.Resizable(summary.failure.cause);
  archive.Resizable(summary.failure.source.file);
  archive.Field(summary.failure.source.line);
  archive.Field(summary.failure.source.column);
  archive.Field(summary.interrupted);
  archive.Resizable(summary.output_error);
  archive.Field(summary.end_time);
  archive.Field(summary.energy);
  SettleSummary& settle = summary.settle;
  archive.Field(settle.settled);
  archive.Field(settle.converged);
  archive.Field(settle.time);
  archive.Field(settle.steps);
  archive.Field(settle.evaluations);
  archive.Field(settle.largest_velocity);
  archive.Resizable(settle.fastest_segment);
  archive.Field(settle.largest_angular_velocity);
  archive.Field(settle.largest_acceleration);
  archive.Field(settle.largest_angular_acceleration);
  archive.Field(settle.largest_force_change);
  archive.Field(settle.largest_force);
  archive.Resizable(settle.failure);
  Strings(archive, summary.checkpoints);
  Strings(archive, summary.notes);
  Strings(archive, series.names);
  std::int64_t columns = static_cast<std::int64_t>(series.columns);
  archive.Field(columns);
  series.columns = static_cast<std::size_t>(columns);
  archive.Resizable(series.values);
}

}  // namespace

std::string SaveRunRecord(const RunSummary& summary, const TimeSeries& series) {
  Archive archive = Archive::ForWriting();
  RunSummary summary_copy = summary;  // Serialize takes references; writing changes nothing
  TimeSeries series_copy = series;
  Serialize(archive, summary_copy, series_copy);
  return archive.bytes();
}

bool LoadRunRecord(std::string bytes, RunSummary* summary, TimeSeries* series) {
  Archive archive = Archive::ForReading(std::move(bytes));
  RunSummary read_summary;
  TimeSeries read_series;
  Serialize(archive, read_summary, read_series);
  if (!archive.ok() || !archive.at_end()) return false;
  *summary = std::move(read_summary);
  *series = std::move(read_series);
  return true;
}

}  // namespace sled::runtime
