// `sled run FILE [-o DIR] [--set NAME=VALUE]... [--format iso-mme] [--dump-at T[,T...]]`: compile
// and simulate; write timeseries.csv, timeseries_filtered.csv, summary.json and animation.glb
// into DIR, with --format iso-mme also the ISO-MME data set in DIR/iso-mme, with --dump-at the
// complete state at each time T in DIR/dump_<T>.txt, with --checkpoint-every T a checkpoint
// every T into DIR; --resume FILE continues from a checkpoint. Exit 0 done, 1 input errors (or a
// checkpoint that does not fit the scene), 2 a dump time outside the run or a checkpoint step
// that is not a multiple of the output step, 3 numerical failure (outputs kept).
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "sled/compile.h"

namespace sled::driver {

struct RunCommandOptions {
  std::string file;
  std::string output_directory;  // empty: `<file stem>-out` in the current folder
  std::string stdlib;
  std::vector<std::pair<std::string, std::string>> overrides;
  bool compact_diagnostics = false;
  bool color = false;
  bool progress = false;           // show progress (on a terminal)
  bool iso_mme = false;            // also write the ISO-MME data set
  std::vector<double> dump_times;  // [s], increasing, no repeats
  double checkpoint_every = 0.0;   // [s]; 0: no checkpoints
  std::string resume;              // a checkpoint file to continue from
  bool report = false;             // also write DIR/report.html (sled report)
  // Also run a companion at a tenth of the tolerances for a global error estimate
  // (output/post/global_error.h) in summary.json.
  bool error_estimate = false;
  // A second thread for the output rows and the files (SimulateOptions::threaded); a sweep's
  // runs, one per core, say --single-thread.
  bool threaded = true;
};

// The items of a comma-separated option value, empty ones included ("a,,b" has three).
std::vector<std::string> SplitAtCommas(const std::string& text);

// One time in seconds or with a unit `s` or `ms` (0.05, 50ms). False for anything else or a
// negative time.
bool ParseTime(const std::string& text, double* seconds);

// The value of `--format`: a comma-separated list of csv (always written) and iso-mme. False
// with `error` set for an unknown format.
bool ParseFormats(const std::string& text, bool* iso_mme, std::string* error);

// The value of `--dump-at`: times separated by commas, in seconds or with a unit `s` or `ms`
// (0.05, 50ms); sorted, repeats dropped. False with `error` set for a text that is no time or a
// negative time.
bool ParseDumpTimes(const std::string& text, std::vector<double>* times, std::string* error);

// The scene of `options.file` through sled::Compile, its diagnostics (the lowering's notes
// among them) printed to standard error; nullopt when it cannot be read or has errors.
std::optional<Compilation> CompileScene(const RunCommandOptions& options);

int RunCommand(const RunCommandOptions& options);

}  // namespace sled::driver
