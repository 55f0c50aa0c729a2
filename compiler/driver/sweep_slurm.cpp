#include "compiler/driver/sweep_slurm.h"

#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <iostream>
#include <thread>

#include <fmt/format.h>

#include "compiler/driver/process_pool.h"
#include "compiler/driver/sweep_collect.h"
#include "lang/source/source_manager.h"
#include "output/atomic_file.h"

namespace sled::driver {
namespace {

namespace fs = std::filesystem;

// A word for a shell script, in single quotes.
std::string ShellQuote(const std::string& text) {
  std::string quoted = "'";
  for (const char c : text) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

struct Captured {
  int exit_code = -1;
  std::string out;  // standard output; standard error passes through
};

// Runs a program found on PATH and captures its standard output.
Captured RunCapturing(const std::vector<std::string>& argv) {
  Captured result;
  int pipe_fds[2];
  if (pipe(pipe_fds) != 0) return result;
  std::fflush(stdout);
  std::fflush(stderr);
  const pid_t pid = fork();
  if (pid == 0) {
    dup2(pipe_fds[1], STDOUT_FILENO);
    close(pipe_fds[0]);
    close(pipe_fds[1]);
    std::vector<char*> args;
    for (const std::string& arg : argv) args.push_back(const_cast<char*>(arg.c_str()));
    args.push_back(nullptr);
    execvp(args[0], args.data());
    _exit(127);
  }
  close(pipe_fds[1]);
  if (pid < 0) {
    close(pipe_fds[0]);
    return result;
  }
  char buffer[4096];
  ssize_t got = 0;
  while ((got = read(pipe_fds[0], buffer, sizeof(buffer))) > 0) {
    result.out.append(buffer, static_cast<std::size_t>(got));
  }
  close(pipe_fds[0]);
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

std::string Trim(std::string text) {
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ' || text.back() == '\r')) {
    text.pop_back();
  }
  return text;
}

// The #SBATCH lines every job of the sweep gets.
std::string CommonDirectives(const SlurmOptions& options) {
  std::string lines;
  if (!options.partition.empty()) lines += "#SBATCH --partition=" + options.partition + "\n";
  if (!options.account.empty()) lines += "#SBATCH --account=" + options.account + "\n";
  return lines;
}

}  // namespace

int SubmitSweep(const std::string& directory, const SweepManifest& manifest,
                const SlurmOptions& options) {
  const std::string folder = fs::absolute(directory).lexically_normal().string();
  const fs::path slurm = fs::path(folder) / "slurm";
  std::error_code code;
  fs::create_directories(slurm, code);
  const int runs = static_cast<int>(manifest.runs.size());
  const int tasks = std::min({options.tasks > 0 ? options.tasks : runs, runs, kMaxArrayTasks});
  const std::string sled = SelfExecutable();

  std::string array =
      "#!/bin/bash\n# Written by `sled sweep --slurm`: task K runs the runs i with i % " +
      std::to_string(tasks) + " == K.\n";
  array += "#SBATCH --job-name=sled-sweep\n";
  array += fmt::format("#SBATCH --array=0-{}\n", tasks - 1);
  array += fmt::format("#SBATCH --output={}/task-%a.log\n", slurm.string());
  array += fmt::format("#SBATCH --cpus-per-task={}\n", options.cpus_per_task);
  if (!options.time_limit.empty()) array += "#SBATCH --time=" + options.time_limit + "\n";
  array += CommonDirectives(options);
  array +=
      fmt::format("exec {} sweep resume {} --slice \"${{SLURM_ARRAY_TASK_ID}}/{}\" --jobs {}\n",
                  ShellQuote(sled), ShellQuote(folder), tasks, options.cpus_per_task);
  std::string collect =
      "#!/bin/bash\n# Written by `sled sweep --slurm`: gathers the table once every task has "
      "ended.\n";
  collect += "#SBATCH --job-name=sled-sweep-collect\n";
  collect += fmt::format("#SBATCH --output={}/collect.log\n", slurm.string());
  collect += CommonDirectives(options);
  collect += fmt::format("exec {} sweep collect {}\n", ShellQuote(sled), ShellQuote(folder));
  std::string error;
  const std::string array_path = (slurm / "array.sh").string();
  const std::string collect_path = (slurm / "collect.sh").string();
  if (!runtime::ReplaceFile(array_path, array, &error) ||
      !runtime::ReplaceFile(collect_path, collect, &error)) {
    std::cerr << "sled: " << error << '\n';
    return 1;
  }

  std::vector<std::string> submit = {"sbatch", "--parsable"};
  submit.insert(submit.end(), options.sbatch_arguments.begin(), options.sbatch_arguments.end());
  submit.push_back(array_path);
  const Captured array_job = RunCapturing(submit);
  const std::string array_id = Trim(array_job.out.substr(0, array_job.out.find(';')));
  if (array_job.exit_code != 0 || array_id.empty()) {
    std::cerr << fmt::format("sled: sbatch did not accept the job array{} (the script is `{}`)\n",
                             array_job.exit_code == 127
                                 ? ": there is no `sbatch` on PATH; submit from a Slurm "
                                   "login node"
                                 : "",
                             array_path);
    return 1;
  }
  const Captured collect_job =
      RunCapturing({"sbatch", "--parsable", "--dependency=afterany:" + array_id, collect_path});
  const std::string collect_id = Trim(collect_job.out.substr(0, collect_job.out.find(';')));
  if (collect_job.exit_code != 0 || collect_id.empty()) {
    std::cerr << fmt::format(
        "sled: sbatch did not accept the collecting job `{}`; once the "
        "array {} ends, run `sled sweep collect {}`\n",
        collect_path, array_id, directory);
  }
  runtime::ReplaceFile((slurm / "jobs.txt").string(),
                       fmt::format("array {}\ncollect {}\n", array_id, collect_id), &error);
  std::cerr << fmt::format(
      "sled: submitted {} runs as Slurm job array {} ({} task{}) and the collecting job {}; "
      "the logs go to `{}`\n",
      runs, array_id, tasks, tasks == 1 ? "" : "s", collect_id, slurm.string());
  if (!options.wait) {
    std::cerr << fmt::format(
        "sled: the table will be in `{}/sweep.csv`; `squeue -j {}` shows the tasks, `sled sweep "
        "collect {}` gathers what has finished\n",
        directory, array_id, directory);
    return 0;
  }
  // Until both jobs have left the queue: squeue lists nothing (or no longer knows them).
  const std::string jobs = collect_id.empty() ? array_id : array_id + "," + collect_id;
  while (true) {
    const Captured queue = RunCapturing({"squeue", "--noheader", "--jobs=" + jobs, "--format=%i"});
    if (queue.exit_code != 0 || Trim(queue.out).empty()) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
  }
  return CollectSweep(directory);
}

}  // namespace sled::driver
