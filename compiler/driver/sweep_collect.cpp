#include "compiler/driver/sweep_collect.h"

#include <filesystem>
#include <iostream>
#include <map>

#include <fmt/format.h>

#include "compiler/driver/sweep_folder.h"
#include "lang/source/source_manager.h"
#include "output/atomic_file.h"
#include "output/report/run_summary.h"
#include "output/report/sweep_page.h"

namespace sled::driver {
namespace {

namespace fs = std::filesystem;

// A criterion's column: `hic15(occupant.head)`, `head_3ms(occupant.head) cumulative [g]`.
std::string CriterionColumn(const report::CriterionSummary& c) {
  return fmt::format("{}({}){}{}", c.name, c.target, c.variant.empty() ? "" : " " + c.variant,
                     c.unit.empty() ? "" : " [" + c.unit + "]");
}

// The column order: first seen first, criteria before peaks.
class Columns {
 public:
  std::size_t Of(const std::string& name) {
    const auto [it, added] = index_.emplace(name, names_.size());
    if (added) names_.push_back(name);
    return it->second;
  }
  const std::vector<std::string>& names() const { return names_; }

 private:
  std::map<std::string, std::size_t> index_;
  std::vector<std::string> names_;
};

}  // namespace

SweepCollector::SweepCollector(std::string directory, const SweepManifest& manifest)
    : directory_(std::move(directory)), manifest_(manifest), runs_(manifest.runs.size()) {}

void SweepCollector::Add(std::size_t run) {
  const fs::path folder = fs::path(directory_) / manifest_.runs.at(run).folder;
  Gathered gathered;
  gathered.status = ReadRunStatus(folder.string());
  // A failed run has its summary up to the failure: its criteria and peaks are kept.
  if (const auto text = lang::ReadFile((folder / "summary.json").string());
      text && gathered.status) {
    if (const auto summary = report::ParseRunSummary(*text, &gathered.problem)) {
      for (const report::CriterionSummary& c : summary->criteria) {
        gathered.criteria.emplace_back(CriterionColumn(c), c.value);
      }
      for (const report::PeakSummary& p : summary->peaks) {
        gathered.peaks.emplace_back("peak " + p.channel, p.value);
      }
    }
  }
  runs_[run] = std::move(gathered);
}

int SweepCollector::Write() {
  report::SweepTable table;
  table.scene = manifest_.scene;
  for (const SweepVariable& variable : manifest_.variables) {
    table.inputs.push_back(variable.unit.empty() ? variable.name
                                                 : variable.name + " [" + variable.unit + "]");
  }
  Columns criteria;
  Columns peaks;
  std::vector<std::map<std::size_t, double>> criterion_values(manifest_.runs.size());
  std::vector<std::map<std::size_t, double>> peak_values(manifest_.runs.size());
  std::size_t done = 0;
  for (std::size_t r = 0; r < manifest_.runs.size(); ++r) {
    if (!runs_[r]) Add(r);
    const Gathered& gathered = *runs_[r];
    report::SweepRow row;
    row.folder = manifest_.runs[r].folder;
    row.inputs = manifest_.runs[r].numbers;
    row.status = gathered.status ? gathered.status->status : "not run";
    if (gathered.status) {
      row.exit_code = gathered.status->exit_code;
      row.wall_seconds = gathered.status->wall_seconds;
      row.message = gathered.status->message;
    }
    if (row.message.empty()) row.message = gathered.problem;
    done += row.status == "done" ? 1 : 0;
    for (const auto& [name, value] : gathered.criteria) {
      const std::size_t column = criteria.Of(name);
      if (value) criterion_values[r][column] = *value;
    }
    for (const auto& [name, value] : gathered.peaks) peak_values[r][peaks.Of(name)] = value;
    table.rows.push_back(std::move(row));
  }
  table.outputs = criteria.names();
  table.criteria = table.outputs.size();
  table.outputs.insert(table.outputs.end(), peaks.names().begin(), peaks.names().end());
  for (std::size_t r = 0; r < table.rows.size(); ++r) {
    auto& outputs = table.rows[r].outputs;
    outputs.assign(table.outputs.size(), std::nullopt);
    for (const auto& [column, value] : criterion_values[r]) outputs[column] = value;
    for (const auto& [column, value] : peak_values[r]) outputs[table.criteria + column] = value;
  }
  const fs::path csv = fs::path(directory_) / "sweep.csv";
  const fs::path html = fs::path(directory_) / "sweep.html";
  std::string error;
  if (!runtime::ReplaceFile(csv.string(), report::SweepCsv(table), &error) ||
      !runtime::ReplaceFile(html.string(), report::BuildSweepPage(table), &error)) {
    std::cerr << "sled: " << error << '\n';
    return 1;
  }
  std::cerr << fmt::format("sled: {} of {} runs done; the table is `{}`, the plots `{}`\n", done,
                           table.rows.size(), csv.string(), html.string());
  return done == table.rows.size() ? 0 : 3;
}

int CollectSweep(const std::string& directory) {
  std::string error;
  const auto manifest = ReadManifest(directory, &error);
  if (!manifest) {
    std::cerr << "sled: " << error << '\n';
    return 1;
  }
  return SweepCollector(directory, *manifest).Write();
}

}  // namespace sled::driver
