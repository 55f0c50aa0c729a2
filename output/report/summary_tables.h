// The report's first sections: what ran and how it ended, the integrator's statistics with the
// error estimate, and the energy balance, as HTML tables.
#pragma once

#include <string>

#include "output/report/run_summary.h"

namespace sled::report {

// The run: status (and the failure: time, where, cause, scene line), times, rows, wall time.
std::string RunSection(const RunSummaryFile& summary);
// The integrator: method, tolerances, steps, rejections, evaluations, ..., error estimate.
std::string IntegratorSection(const IntegratorSummary& integrator);
// The energy balance terms and how well it closes; empty text when the summary has none.
std::string EnergySection(const RunSummaryFile& summary);
// The warnings as a list; empty text when there are none.
std::string WarningsSection(const RunSummaryFile& summary);

}  // namespace sled::report
