// One computed injury criterion, as summary.json reports it.
#pragma once

#include <string>

namespace sled::runtime::post {

struct CriterionValue {
  std::string name;     // as the language spells it: hic15, chest_3ms, nij, ...
  std::string variant;  // "cumulative" / "continuous" (3 ms), "NTE" ... (Nij quadrants), or ""
  std::string target;   // the segment or joint: occupant.head
  bool computed = false;
  std::string reason;  // why not, when not computed
  double value = 0.0;
  std::string unit;           // "" for indices, "g", "N", "m/s"
  double window_start = 0.0;  // the time window behind the value [s] (start = end for a peak)
  double window_end = 0.0;
  int filter_class = 0;  // CFC of the channels it was computed from
  bool has_limit = false;
  double limit = 0.0;
  std::string limit_source;  // the regulation that gives the limit
  bool pass = true;          // value <= limit (true without a limit)
};

}  // namespace sled::runtime::post
