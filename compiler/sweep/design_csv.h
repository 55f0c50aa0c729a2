// A design read from a CSV file: a header naming the varied `param`s, each optionally with its
// unit in brackets, then one row per run:
//
//   speed [km/h], belt_slack [mm]
//   40, 5
//   48, 10 mm
//
// A cell is a number with an optional unit of its own (converted to the column's); a column
// whose header has no unit takes the unit of its first cell that has one. Lines starting with
// `#` and blank lines are skipped; a field may be enclosed in double quotes.
#pragma once

#include <optional>
#include <vector>

#include "compiler/check/checked_scenario.h"
#include "compiler/sweep/design.h"

namespace sled::compiler {

struct CsvDesign {
  std::vector<DesignVariable> variables;
  std::vector<lang::SourceRange> headers;  // each variable's header field
  std::vector<std::vector<double>> points;
};

// Reads the design file; reports E0601 (a malformed header or row), E0602, E0603, E0605 and
// returns nullopt on any error.
std::optional<CsvDesign> ReadCsvDesign(const lang::SourceManager& sources, lang::FileId file,
                                       const CheckedScenario& scene,
                                       lang::DiagnosticConsumer& diagnostics);

}  // namespace sled::compiler
