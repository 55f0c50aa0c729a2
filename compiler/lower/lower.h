// compiler::Lower: a checked scenario to the runtime's flat Model (docs/architecture.md). Segments
// are put in tree order (a parent before its children), joints become generalized coordinates,
// values stay in SI, and only what the scene uses is copied: functions no lowered element refers to
// are dropped. Features the runtime does not simulate yet are left out, each with a note. Programs
// call this through sled::Compile (sled/compile.h), which runs every stage.
#pragma once

#include "compiler/check/checked_scenario.h"
#include "lang/diagnostics/diagnostic.h"
#include "lang/source/source_manager.h"
#include "runtime/model/model.h"

namespace sled::compiler {

struct LowerOptions {
  // Required: receives the notes (N04xx) on what the Model leaves out or simulates otherwise
  // than the scene writes it. Lowering reports no errors: the scenario checked clean.
  lang::DiagnosticConsumer* diagnostics = nullptr;
};

// Lowers a checked scenario. The scenario must have checked without errors: a broken tree or an
// index out of range is a programming error (std::logic_error naming the stage and the object),
// and so is a missing LowerOptions::diagnostics, and so is a lowered Model that FinalizeModel
// refuses (its message names the field). Features the runtime does not simulate yet (rolling
// constraints; a function's unloading slope and a joint's energy loss, which only change how it
// unloads) and contact pairs that can never touch are left out, each with a note (N0401-N0404)
// at its source position.
runtime::Model Lower(const CheckedScenario& scenario, const lang::SourceManager& sources,
                     const LowerOptions& options);

}  // namespace sled::compiler
