// compiler::Lower: a checked scenario to the runtime's flat Model (DESIGN.md §2, §4). Segments are
// put in tree order (a parent before its children), joints become generalized coordinates, values
// stay in SI, and only what the scene uses is copied: functions no lowered element refers to are
// dropped. Features the runtime does not simulate yet are left out, each with a note.
#pragma once

#include <string>
#include <vector>

#include "compiler/check/checked_scenario.h"
#include "lang/diagnostics/diagnostic.h"
#include "lang/source/source_manager.h"
#include "runtime/model.h"

namespace sled::compiler {

struct LowerOptions {
  lang::DiagnosticConsumer* diagnostics = nullptr;  // optional; lowering reports no errors yet
};

struct Lowered {
  runtime::Model model;
  // What the Model leaves out and why, one line each, in source order:
  // `PATH:LINE:COL: note: belt `lap` is not simulated yet; left out`. Notes about the
  // scenario as a whole (symmetry, settling) have no position: `note: ...`.
  std::vector<std::string> notes;
};

// Lowers a checked scenario. The scenario must have checked without errors: a broken tree or an
// index out of range is a programming error (std::logic_error naming the stage and the object).
// Features the runtime does not simulate yet (the viscous criterion, settling) and contact pairs
// that can never touch are left out of the Model; `notes` lists each with its source position so
// `sled run` can say so.
Lowered Lower(const CheckedScenario& scenario, const lang::SourceManager& sources,
              const LowerOptions& options);

}  // namespace sled::compiler
