// Runs jobs in child processes, at most N at a time: the sweep's runs (each `sled run` exec'd
// with its own output folder and log) and the study's ladder (each sample computed in a forked
// child). A child's crash or kill is its own outcome and never the parent's; an interrupted
// parent (SIGINT, SIGTERM, SIGHUP) stops starting jobs, passes the signal on to the running
// children, waits for them and says so.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace sled::driver {

struct ProcessJob {
  // Either a program to exec (argv[0] a path) ...
  std::vector<std::string> argv;
  // ... or a function run in the forked child; its return value is the exit code.
  std::function<int()> body;
  std::string log_path;  // stdout and stderr go here (empty: inherited); stdin is /dev/null
};

struct ProcessOutcome {
  int exit_code = -1;  // -1 when it ended by a signal
  int signal = 0;      // the signal that ended it, or 0
  double wall_seconds = 0.0;
  // Ended by a signal that stops work rather than reports a fault (SIGINT, SIGTERM, SIGHUP,
  // SIGKILL), or exited 128 + SIGINT, SIGTERM or SIGHUP after catching one: the job did not
  // finish and should run again.
  bool interrupted() const;
};

// The number of cores this process may run on (sched_getaffinity), at least 1.
int AvailableCores();

// Runs `jobs` over at most `workers` children; `on_start(i)` is called in the parent just before
// job i starts and `on_done(i, outcome)` as it ends, in completion order. Returns false when the
// parent was interrupted (the jobs not yet done got no on_done call, except those that ended).
bool RunProcesses(const std::vector<ProcessJob>& jobs, int workers,
                  const std::function<void(std::size_t)>& on_start,
                  const std::function<void(std::size_t, const ProcessOutcome&)>& on_done);

// Computes work(i) for every i < count in forked children, at most `workers` at a time, and
// gives back what each returned: (*results)[i], or nullopt for a child that did not finish (a
// crash, a kill). `on_done(i)` is called in the parent as each ends. A forked child computes
// exactly what the parent would: the same code on a copy of the same memory. False when the
// parent was interrupted.
bool RunInWorkers(std::size_t count, int workers,
                  const std::function<std::string(std::size_t)>& work,
                  std::vector<std::optional<std::string>>* results,
                  const std::function<void(std::size_t)>& on_done = {});

// The path of the running program (/proc/self/exe), to run `sled` itself in a child.
std::string SelfExecutable();

}  // namespace sled::driver
