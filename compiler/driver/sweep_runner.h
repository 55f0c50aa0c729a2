// Runs the runs of a sweep folder that have not finished, each as `sled run` in a child
// process, at most `jobs` at a time; records how each ended in its status.json.
#pragma once

#include <functional>
#include <string>

#include "compiler/driver/sweep_folder.h"

namespace sled::driver {

struct RunnerOptions {
  int jobs = 1;
  int slice = 0;  // with slices > 0: run only the runs i with i % slices == slice
  int slices = 0;
  bool retry_failed = false;  // run again those that ended other than done
  bool quiet = false;         // no line per run
  // Called as each run ends, once its status.json is written (while other runs go on).
  std::function<void(std::size_t run)> on_run_done;
};

struct RunnerResult {
  bool interrupted = false;
  int started = 0;
  int skipped = 0;  // finished before
};

// The argument list of run `index`: sled run SCENE -o DIR/runs/NNNN ... --set NAME=VALUE...
std::vector<std::string> RunArguments(const std::string& sled, const std::string& directory,
                                      const SweepManifest& manifest, std::size_t index);

RunnerResult RunPending(const std::string& directory, const SweepManifest& manifest,
                        const RunnerOptions& options);

}  // namespace sled::driver
