// One computed injury criterion, as summary.json reports it.
#pragma once

#include <string>
#include <vector>

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
  // The rows do not cover the whole run: it stopped before its end (a numerical failure, an
  // interruption), or a resumed run's rows start at its checkpoint. The value is over the rows
  // from `seen_from` to `seen_until` only and says nothing of the rest, so it neither passes
  // nor fails.
  bool incomplete = false;
  double seen_from = 0.0;
  double seen_until = 0.0;
};

// Marks every criterion of rows that cover only [seen_from, seen_until] of the run incomplete.
inline void MarkIncomplete(std::vector<CriterionValue>& criteria, double seen_from,
                           double seen_until) {
  for (CriterionValue& c : criteria) {
    c.incomplete = true;
    c.seen_from = seen_from;
    c.seen_until = seen_until;
  }
}

}  // namespace sled::runtime::post
