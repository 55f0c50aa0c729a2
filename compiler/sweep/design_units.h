// Units of a design's values against the parameter they vary: shared by `--vary` texts and CSV
// design files.
#pragma once

#include <optional>
#include <string>

#include "compiler/check/checked_scenario.h"
#include "compiler/sweep/design.h"
#include "compiler/sweep/design_text.h"
#include "lang/diagnostics/diagnostic.h"
#include "lang/source/source_manager.h"

namespace sled::compiler {

// The scene's `param` of this name, or null after reporting E0602 at `range` (with a "did you
// mean" among the scene's parameters).
const ScenarioParameter* FindDesignParameter(const CheckedScenario& scene, const std::string& name,
                                             lang::SourceRange range,
                                             lang::DiagnosticConsumer& diagnostics);

// Starts the variable of `parameter`, its values in the unit `unit` (or dimensionless when
// none): reports E0301 for an unknown unit symbol and E0603 when the unit does not fit the
// parameter; `where` names the values for the message. Nullopt after an error.
std::optional<DesignVariable> VariableInUnit(const lang::SourceManager& sources,
                                             const ScenarioParameter& parameter,
                                             const std::optional<lang::ast::Unit>& unit,
                                             lang::SourceRange where,
                                             lang::DiagnosticConsumer& diagnostics);

// A written value in the variable's unit: its own unit (which must fit, else E0603) converted,
// or the variable's when it has none. Nullopt after an error.
std::optional<double> ValueInUnit(const lang::SourceManager& sources, const WrittenQuantity& value,
                                  const DesignVariable& variable,
                                  const ScenarioParameter& parameter,
                                  lang::DiagnosticConsumer& diagnostics);

// True for a parameter with one component; for a vector, reports E0605 at `range`.
bool IsScalarParameter(const ScenarioParameter& parameter, lang::SourceRange range,
                       lang::DiagnosticConsumer& diagnostics);

}  // namespace sled::compiler
