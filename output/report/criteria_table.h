// The injury criteria against their limits: one row per criterion of summary.json with its
// value, time window, filter class, limit and source, and whether it passes.
#pragma once

#include <string>
#include <vector>

#include "output/report/run_summary.h"

namespace sled::report {

// The section; a note when the scene requested no criteria.
std::string CriteriaSection(const std::vector<CriterionSummary>& criteria);

}  // namespace sled::report
