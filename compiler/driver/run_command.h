// `sled run FILE [-o DIR] [--set NAME=VALUE]...`: compile and simulate, write timeseries.csv and
// summary.json into DIR. Exit 0 done, 1 input errors, 3 numerical failure (outputs kept).
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace sled::driver {

struct RunCommandOptions {
  std::string file;
  std::string output_directory;  // empty: `<file stem>-out` in the current folder
  std::string stdlib;
  std::vector<std::pair<std::string, std::string>> overrides;
  bool compact_diagnostics = false;
  bool color = false;
  bool progress = false;  // show progress (on a terminal)
};

int RunCommand(const RunCommandOptions& options);

}  // namespace sled::driver
