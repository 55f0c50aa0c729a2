// `sled sweep --slurm`: the design as a Slurm job array (docs/sweeps.md#on-a-cluster). Task K
// of T runs `sled sweep resume DIR --slice K/T`, the runs i with i % T == K; a last job,
// submitted to start after every task (afterany), collects the table. The sweep folder, the
// scene and the sled program must be where every node sees them (a shared file system).
#pragma once

#include <string>
#include <vector>

#include "compiler/driver/sweep_folder.h"

namespace sled::driver {

struct SlurmOptions {
  std::string partition;
  std::string account;
  std::string time_limit;                     // per task, as sbatch takes it: 10:00, 1-00:00:00
  int tasks = 0;                              // array tasks; 0: one per run, at most kMaxArrayTasks
  int cpus_per_task = 1;                      // runs in parallel inside a task
  std::vector<std::string> sbatch_arguments;  // passed to sbatch as they are
  bool wait = false;  // wait for the array and the collecting job, then report
};

inline constexpr int kMaxArrayTasks = 1000;  // Slurm's default MaxArraySize is 1001

// Writes DIR/slurm/array.sh and DIR/slurm/collect.sh and submits both with sbatch; with `wait`,
// waits until both have left the queue. Returns the exit code for `sled sweep`.
int SubmitSweep(const std::string& directory, const SweepManifest& manifest,
                const SlurmOptions& options);

}  // namespace sled::driver
