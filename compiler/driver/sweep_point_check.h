// Checks a sweep's scene at every point of its design, as each run will check it, before any run
// starts: a design with a point the scene refuses runs nothing. The points are shared out over
// forked workers (process_pool.h), so on N cores the check takes about 1/N of the time.
#pragma once

#include <cstddef>
#include <string>

#include "compiler/check/check.h"
#include "compiler/sweep/design.h"

namespace sled::driver {

struct PointCheckResult {
  std::size_t failing = 0;   // points whose check found errors
  std::size_t first = 0;     // the first of them, with failing > 0
  std::string diagnostics;   // its diagnostics, rendered
  bool interrupted = false;  // SIGINT, SIGTERM or SIGHUP stopped the check
  bool incomplete = false;   // a worker ended without its answer (a crash)
};

// Checks `scene` with `base` (its stdlib root, the fixed overrides; no lints) and each point's
// overrides, over `workers` processes (1: in this process).
PointCheckResult CheckDesignPoints(const std::string& scene, const compiler::CheckOptions& base,
                                   const compiler::Design& design, int workers, bool compact,
                                   bool color);

}  // namespace sled::driver
