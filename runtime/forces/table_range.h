// Table functions beyond their rows. A table is linear between its rows and continues the slope
// of its first or last segment beyond them (EvaluateFunction): a force element driven past the
// rows runs on a line nobody measured (a foam crushed 3 mm past its last row kept stiffening and
// gave a HIC of 19,035). The run records, for every element with a table function, when its
// argument first left the rows, where, and how far it went; `sled run` reports each element once
// (standard error and summary.json), docs/runtime.md says what happens.
//
// Contacts and belts are watched at every accepted integration step (where their loading
// histories are committed); joints, springs and airbag inflators at every output row.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "runtime/model/model.h"
#include "runtime/run/archive.h"

namespace sled::runtime {

struct Data;

// One element's record: whether its argument left its table's rows, and when and how far.
struct TableOverrun {
  bool seen = false;
  double first_time = 0.0;
  double first_argument = 0.0;
  double farthest_argument = 0.0;  // the argument farthest outside the rows

  void Serialize(Archive& a) {
    a.Field(seen);
    a.Field(first_time);
    a.Field(first_argument);
    a.Field(farthest_argument);
  }
};

// The records of a run, one per element that can use a table (sized by MakeData).
struct TableWatch {
  std::vector<TableOverrun> contact;  // per contact pair
  std::vector<TableOverrun> belt;     // per belt
  std::vector<TableOverrun> joint;    // per segment's joint, three function slots each
  std::vector<TableOverrun> spring;
  std::vector<TableOverrun> airbag;  // the inflator's flow against time

  void Serialize(Archive& a) {
    for (auto* records : {&contact, &belt, &joint, &spring, &airbag}) {
      for (TableOverrun& record : *records) record.Serialize(a);
    }
  }
};

void SizeTableWatch(const Model& model, TableWatch& watch);

// Records `x`, the argument of table function `id` at time t, when it lies outside the rows.
// Other kinds of function (and -1) are never recorded. No allocation.
void RecordTableArgument(const FunctionTable& functions, std::int32_t id, double t, double x,
                         TableOverrun& record);

// At an output row (after Forward): the joints', springs' and inflators' arguments.
void WatchTablesAtRow(const Model& model, Data& data);

// One element that left its table, for the run's report.
struct TableExtrapolation {
  std::string element;  // "contact `occupant.head` with `panel`", "joint `occupant.knee_l` flexure"
  std::string argument;  // "deflection", "strain", "angle", "elongation", "time"
  double first_time = 0.0;
  double first_argument = 0.0;
  double farthest_argument = 0.0;
  double low = 0.0;  // the table's rows span [low, high] in its argument
  double high = 0.0;
  std::string Describe() const;  // one line: what, when, how far, beyond which row
};
std::vector<TableExtrapolation> TableExtrapolations(const Model& model, const Data& data);

}  // namespace sled::runtime
