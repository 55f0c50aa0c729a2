// `sled study FILE [-o DIR] [--tolerances T,T,...] [--set NAME=VALUE]...`: how accurate a run is
// and what more accuracy costs. Runs the scene with each integrator over a ladder of
// tolerances, builds a reference (Dormand–Prince at a hundredth of the tightest tolerance,
// cross-checked by the exponential method there; both a decade tighter, at most twice, while
// they differ by more than the tightest tolerance), and reports each run's error against the
// reference (every channel over its range, positions, acceleration peaks, injury criteria)
// beside its run time: a table on standard output, DIR/study.csv and a work-precision plot
// DIR/study.svg. It also states the error of the scene's own settings. Exit 0 done, 1 input
// errors or a reference that failed.
#pragma once

#include <string>
#include <vector>

#include "compiler/driver/run_command.h"

namespace sled::driver {

struct StudyOptions {
  RunCommandOptions scene;         // file, stdlib, overrides, diagnostics, output folder
  std::vector<double> tolerances;  // relative; empty: 1e-3 to 1e-7
  int jobs = 0;                    // worker processes; 0: every core
};

// The value of `--tolerances`: positive numbers separated by commas. False with `error` set.
bool ParseTolerances(const std::string& text, std::vector<double>* tolerances, std::string* error);

int StudyCommand(const StudyOptions& options);

}  // namespace sled::driver
