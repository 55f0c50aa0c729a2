// How the `sled` program shows diagnostics: a collector's diagnostics rendered to standard error,
// rich or compact.
#pragma once

#include "lang/diagnostics/diagnostic.h"
#include "lang/source/source_manager.h"

namespace sled::driver {

// Prints every diagnostic, sorted by position; in the rich form, ends with the error and warning
// counts when there are any.
void PrintDiagnostics(const lang::SourceManager& sources, lang::DiagnosticCollector& collector,
                      bool compact, bool color);

}  // namespace sled::driver
