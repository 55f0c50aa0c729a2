// A run's results as bytes and back, for a run computed in another process (`sled study` runs
// its ladder in worker processes and reads each run's summary and rows back): every field of
// RunSummary and TimeSeries, so that nothing reads back as a silent default.
#pragma once

#include <string>

#include "runtime/run/run.h"

namespace sled::runtime {

std::string SaveRunRecord(const RunSummary& summary, const TimeSeries& series);
// False when the bytes are not a whole record.
bool LoadRunRecord(std::string bytes, RunSummary* summary, TimeSeries* series);

}  // namespace sled::runtime
