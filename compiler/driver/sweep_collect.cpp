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

int CollectSweep(const std::string& directory) {
  std::string error;
  const auto manifest = ReadManifest(directory, &error);
  if (!manifest) {
    std::cerr << "sled: " << error << '\n';
    return 1;
  }
  report::SweepTable table;
  table.scene = manifest->scene;
  for (const SweepVariable& variable : manifest->variables) {
    table.inputs.push_back(variable.unit.empty() ? variable.name
                                                 : variable.name + " [" + variable.unit + "]");
  }
  Columns criteria;
  Columns peaks;
  std::vector<std::map<std::size_t, double>> criterion_values(manifest->runs.size());
  std::vector<std::map<std::size_t, double>> peak_values(manifest->runs.size());
  std::size_t done = 0;
  for (std::size_t r = 0; r < manifest->runs.size(); ++r) {
    const SweepRun& run = manifest->runs[r];
    const fs::path folder = fs::path(directory) / run.folder;
    report::SweepRow row;
    row.folder = run.folder;
    row.inputs = run.numbers;
    const auto status = ReadRunStatus(folder.string());
    row.status = status ? status->status : "not run";
    if (status) {
      row.exit_code = status->exit_code;
      row.wall_seconds = status->wall_seconds;
      row.message = status->message;
    }
    done += row.status == "done" ? 1 : 0;
    // A failed run has its summary up to the failure: its criteria and peaks are kept.
    if (const auto text = lang::ReadFile((folder / "summary.json").string()); text && status) {
      std::string why;
      if (const auto summary = report::ParseRunSummary(*text, &why)) {
        for (const report::CriterionSummary& c : summary->criteria) {
          const std::size_t column = criteria.Of(CriterionColumn(c));
          if (c.value) criterion_values[r][column] = *c.value;
        }
        for (const report::PeakSummary& p : summary->peaks) {
          peak_values[r][peaks.Of("peak " + p.channel)] = p.value;
        }
      } else if (row.message.empty()) {
        row.message = why;
      }
    }
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
  const fs::path csv = fs::path(directory) / "sweep.csv";
  const fs::path html = fs::path(directory) / "sweep.html";
  if (!runtime::ReplaceFile(csv.string(), report::SweepCsv(table), &error) ||
      !runtime::ReplaceFile(html.string(), report::BuildSweepPage(table), &error)) {
    std::cerr << "sled: " << error << '\n';
    return 1;
  }
  std::cerr << fmt::format("sled: {} of {} runs done; the table is `{}`, the plots `{}`\n", done,
                           table.rows.size(), csv.string(), html.string());
  return done == table.rows.size() ? 0 : 3;
}

}  // namespace sled::driver
