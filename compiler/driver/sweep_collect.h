// `sled sweep collect DIR`: gathers what every run of a sweep folder wrote into DIR/sweep.csv
// and DIR/sweep.html. The sweep itself collects when its runs end; a Slurm job array's last job
// does too.
#pragma once

#include <string>

namespace sled::driver {

// Exit 0 when every run is done, 3 when some failed or did not run, 1 when the folder is no
// sweep or the files cannot be written.
int CollectSweep(const std::string& directory);

}  // namespace sled::driver
