// `sled sweep`: one scene over a design of parameter values (docs/sweeps.md).
//
//   sled sweep FILE (--vary SPEC... | --design FILE.csv) [--sample lhs=N|sobol=N] [--seed S]
//                   [-o DIR] [--jobs N] [--check] [--restart] [--retry-failed] [--slurm ...]
//   sled sweep resume DIR [--jobs N] [--slice K/T] [--retry-failed]
//   sled sweep collect DIR
//
// Each run is `sled run` in a child process with its own folder DIR/runs/NNNN; DIR/sweep.csv
// and DIR/sweep.html gather the inputs, status, criteria and peaks of every run. Exit 0 when
// every run is done, 1 input errors (scene or design), 2 usage errors, 3 when a run failed or
// did not run (the table says which), 130 when interrupted (run again to resume).
#pragma once

#include <string>
#include <vector>

namespace sled::driver {

// `args` are the words after `sled sweep`.
int SweepCommand(const std::vector<std::string>& args, bool color);

}  // namespace sled::driver
