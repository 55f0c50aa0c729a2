// A sweep's design: which `param`s of a scene vary, and the value each takes in each run. Built
// from `--vary` texts (grids, lists, ranges to sample), a sampling method (Latin hypercube, Sobol)
// or a CSV file, and checked against the scene's parameters before anything runs
// (docs/sweeps.md). Every problem is a diagnostic located in the `--vary` text or the CSV file.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "compiler/check/checked_scenario.h"
#include "compiler/units/dimension.h"
#include "lang/diagnostics/diagnostic.h"
#include "lang/source/source_manager.h"

namespace sled::compiler {

// One varied parameter: its values are numbers in `unit` (as the user wrote it, "km/h").
struct DesignVariable {
  std::string name;
  std::string unit;  // empty: dimensionless
  double scale_to_si = 1.0;
  Dimension dimension;
};

struct Design {
  std::string method;  // "grid", "lhs", "sobol" or "csv" (the last may be combined with a grid)
  std::uint64_t seed = 0;
  std::vector<DesignVariable> variables;
  std::vector<std::vector<double>> points;  // points[run][variable], in the variable's unit

  // The value of one variable in one run as `--set` text: the shortest spelling that reads back
  // to the same double, and the unit ("47.5 km/h").
  std::string ValueText(std::size_t run, std::size_t variable) const;
  // Every value of one run as `--set` overrides.
  std::vector<std::pair<std::string, std::string>> Overrides(std::size_t run) const;
};

// How to sample the ranges given without `step` or `count`.
enum class Sampling { kNone, kLatinHypercube, kSobol };

struct DesignRequest {
  std::vector<lang::FileId> vary;   // each a `--vary` text added to the source manager
  std::optional<lang::FileId> csv;  // a design file added to the source manager
  Sampling sampling = Sampling::kNone;
  int samples = 0;  // with a sampling method: how many points to draw
  std::uint64_t seed = 1;
  // Parameters `--set` fixes for every run: they cannot vary as well.
  std::vector<std::string> fixed;
};

// The largest design `sled sweep` accepts: a grid of more points is almost always a mistake.
inline constexpr std::size_t kMaxDesignPoints = 100000;

// Builds the design: parses each `--vary` text and the CSV file, checks every name against the
// scene's `param`s and every unit against the parameter's dimension, builds the grid of the
// listed values and the sampled points of the ranges (their product when there are both).
// Reports E06xx diagnostics and returns nullopt on any error.
std::optional<Design> BuildDesign(const lang::SourceManager& sources, const DesignRequest& request,
                                  const CheckedScenario& scene,
                                  lang::DiagnosticConsumer& diagnostics);

}  // namespace sled::compiler
