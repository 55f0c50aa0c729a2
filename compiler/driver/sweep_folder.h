// The folder of a sweep (docs/sweeps.md): `sweep.json` records the scene (with a digest of each
// file it reads), the arguments every run gets and the design, run by run; `runs/NNNN/` holds
// what `sled run` wrote for run NNNN, its log `run.log` and, once it has ended, `status.json`.
// A run with a status is finished; resuming runs only the others.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace sled::driver {

struct SweepFile {
  std::string path;    // absolute
  std::string digest;  // FNV-1a of the bytes, 16 hex digits
};

struct SweepVariable {
  std::string name;
  std::string unit;
};

struct SweepRun {
  std::string folder;               // relative to the sweep folder: runs/0007
  std::vector<double> numbers;      // each variable's value in its unit
  std::vector<std::string> values;  // the same as `--set` text: "48 km/h"
};

struct SweepManifest {
  std::string scene;                       // absolute path
  std::vector<SweepFile> files;            // the scene and every file it imports
  std::vector<std::string> run_arguments;  // given to every `sled run` (--stdlib, --set, ...)
  std::string method;                      // grid, lhs, sobol, csv, grid+lhs, ...
  unsigned long long seed = 0;
  std::vector<std::string> vary;  // the --vary texts
  std::string design_file;        // the CSV design, absolute, or empty
  std::vector<SweepVariable> variables;
  std::vector<SweepRun> runs;

  // The parts that decide the results: equal for a sweep that may be resumed.
  bool SameSweep(const SweepManifest& other) const;
};

// How a run ended, as its status.json records it.
struct RunStatus {
  std::string status;  // done, failed (numerical failure), error (input or write), crashed
  int exit_code = -1;
  int signal = 0;
  double wall_seconds = 0.0;
  std::string message;  // the first error line of the log, for a run that did not finish well
};

inline constexpr const char* kManifestName = "sweep.json";

bool WriteManifest(const std::string& directory, const SweepManifest& manifest, std::string* error);
std::optional<SweepManifest> ReadManifest(const std::string& directory, std::string* error);

// The digest of a file's bytes, or empty when it cannot be read.
std::string FileDigest(const std::string& path);
// The files whose digest changed since the manifest was written ("" when none).
std::string ChangedFiles(const SweepManifest& manifest);

std::string RunFolderName(std::size_t run, std::size_t runs);

bool WriteRunStatus(const std::string& run_directory, const RunStatus& status, std::string* error);
std::optional<RunStatus> ReadRunStatus(const std::string& run_directory);

// An exclusive lock on the sweep folder for this process's lifetime (flock on `.lock`): two
// sweeps never run the same runs at once. False with `error` when another process holds it.
bool LockSweepFolder(const std::string& directory, std::string* error);

}  // namespace sled::driver
