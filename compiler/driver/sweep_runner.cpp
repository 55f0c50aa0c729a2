#include "compiler/driver/sweep_runner.h"

#include <csignal>
#include <filesystem>
#include <iostream>

#include <fmt/format.h>

#include "compiler/driver/process_pool.h"
#include "lang/source/source_manager.h"

namespace sled::driver {
namespace {

namespace fs = std::filesystem;

// The first line of the log that says what went wrong, for the table.
std::string FirstErrorLine(const std::string& log_path) {
  const auto text = lang::ReadFile(log_path);
  if (!text) return "";
  std::size_t start = 0;
  std::string fallback;
  while (start < text->size()) {
    std::size_t end = text->find('\n', start);
    if (end == std::string::npos) end = text->size();
    std::string line = text->substr(start, end - start);
    if (line.find("error") != std::string::npos || line.find("failed") != std::string::npos) {
      return line;
    }
    if (fallback.empty() && !line.empty()) fallback = line;
    start = end + 1;
  }
  return fallback;
}

RunStatus StatusOf(const ProcessOutcome& outcome, const std::string& log_path) {
  RunStatus status;
  status.exit_code = outcome.exit_code;
  status.signal = outcome.signal;
  status.wall_seconds = outcome.wall_seconds;
  if (outcome.signal != 0) {
    status.status = "crashed";
    status.message =
        fmt::format("ended by signal {} ({})", outcome.signal, strsignal(outcome.signal));
    return status;
  }
  status.status = outcome.exit_code == 0 ? "done" : outcome.exit_code == 3 ? "failed" : "error";
  if (outcome.exit_code != 0) status.message = FirstErrorLine(log_path);
  return status;
}

}  // namespace

std::vector<std::string> RunArguments(const std::string& sled, const std::string& directory,
                                      const SweepManifest& manifest, std::size_t index) {
  const SweepRun& run = manifest.runs.at(index);
  std::vector<std::string> argv = {sled,
                                   "run",
                                   manifest.scene,
                                   "-o",
                                   (fs::path(directory) / run.folder).string(),
                                   "--diagnostics=compact",
                                   "--single-thread"};  // every core has a run
  argv.insert(argv.end(), manifest.run_arguments.begin(), manifest.run_arguments.end());
  for (std::size_t v = 0; v < manifest.variables.size(); ++v) {
    argv.push_back("--set");
    argv.push_back(manifest.variables[v].name + "=" + run.values[v]);
  }
  return argv;
}

RunnerResult RunPending(const std::string& directory, const SweepManifest& manifest,
                        const RunnerOptions& options) {
  RunnerResult result;
  const std::string sled = SelfExecutable();
  std::vector<std::size_t> pending;
  for (std::size_t i = 0; i < manifest.runs.size(); ++i) {
    if (options.slices > 0 &&
        static_cast<int>(i % static_cast<std::size_t>(options.slices)) != options.slice) {
      continue;
    }
    const std::string folder = (fs::path(directory) / manifest.runs[i].folder).string();
    const auto status = ReadRunStatus(folder);
    if (status && (status->status == "done" || !options.retry_failed)) {
      ++result.skipped;
      continue;
    }
    pending.push_back(i);
  }
  std::vector<ProcessJob> jobs;
  for (const std::size_t i : pending) {
    const std::string folder = (fs::path(directory) / manifest.runs[i].folder).string();
    ProcessJob job;
    job.argv = RunArguments(sled, directory, manifest, i);
    job.log_path = (fs::path(folder) / "run.log").string();
    jobs.push_back(std::move(job));
  }
  // Out of the runs this call answers for: all of them, or one slice's.
  const std::size_t total = pending.size() + static_cast<std::size_t>(result.skipped);
  int finished = result.skipped;
  auto describe = [&](std::size_t i) {
    std::string text;
    for (std::size_t v = 0; v < manifest.variables.size(); ++v) {
      text += fmt::format("{}{} = {}", v == 0 ? "" : ", ", manifest.variables[v].name,
                          manifest.runs[i].values[v]);
    }
    return text;
  };
  auto on_start = [&](std::size_t job) {
    // A fresh folder: whatever an interrupted attempt left is gone.
    const std::string folder = (fs::path(directory) / manifest.runs[pending[job]].folder).string();
    std::error_code error;
    fs::remove_all(folder, error);
    fs::create_directories(folder, error);
    ++result.started;
  };
  auto on_done = [&](std::size_t job, const ProcessOutcome& outcome) {
    const std::size_t i = pending[job];
    if (outcome.interrupted()) return;  // not finished: a resume runs it again
    const std::string folder = (fs::path(directory) / manifest.runs[i].folder).string();
    const RunStatus status = StatusOf(outcome, jobs[job].log_path);
    std::string error;
    if (!WriteRunStatus(folder, status, &error)) std::cerr << "sled: " << error << '\n';
    if (options.on_run_done) options.on_run_done(i);
    ++finished;
    if (!options.quiet) {
      std::cerr << fmt::format("sled: [{}/{}] {} {} ({}) in {:.2f} s{}\n", finished, total,
                               manifest.runs[i].folder, status.status, describe(i),
                               status.wall_seconds,
                               status.message.empty() ? "" : ": " + status.message);
    }
  };
  result.interrupted = !RunProcesses(jobs, options.jobs, on_start, on_done);
  return result;
}

}  // namespace sled::driver
