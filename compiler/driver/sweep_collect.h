// `sled sweep collect DIR`: gathers what every run of a sweep folder wrote into DIR/sweep.csv
// and DIR/sweep.html. The sweep itself collects as its runs end (a SweepCollector reads each
// run's results while the others still run, so only the table and the page are left for the
// end); a Slurm job array's last job collects too.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "compiler/driver/sweep_folder.h"

namespace sled::driver {

class SweepCollector {
 public:
  SweepCollector(std::string directory, const SweepManifest& manifest);

  // Reads run `run`'s status and summary (again, if it was read before).
  void Add(std::size_t run);
  // Reads the runs not added yet and writes sweep.csv and sweep.html, the columns in the order
  // the runs first name them (whatever order the runs ended in). Exit 0 when every run is done,
  // 3 when some failed or did not run, 1 when the files cannot be written.
  int Write();

 private:
  struct Gathered {
    std::optional<RunStatus> status;
    std::vector<std::pair<std::string, std::optional<double>>> criteria;  // column, value
    std::vector<std::pair<std::string, double>> peaks;
    std::string problem;  // why its summary could not be read
  };
  std::string directory_;
  const SweepManifest& manifest_;
  std::vector<std::optional<Gathered>> runs_;
};

// Exit 0 when every run is done, 3 when some failed or did not run, 1 when the folder is no
// sweep or the files cannot be written.
int CollectSweep(const std::string& directory);

}  // namespace sled::driver
