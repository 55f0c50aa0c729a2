// How the `sled` program reports problems with a user's files: E0107 for a file it cannot read,
// and a collector's diagnostics rendered to standard error, rich or compact.
#pragma once

#include <optional>
#include <string>

#include "lang/diagnostics/diagnostic.h"
#include "lang/source/source_manager.h"

namespace sled::driver {

// Loads `path` into `sources`, or reports E0107 (saying when the path is a folder) and returns
// nullopt.
std::optional<lang::FileId> LoadUserFile(lang::SourceManager& sources, const std::string& path,
                                         lang::DiagnosticCollector& collector);

// Prints every diagnostic, sorted by position; in the rich form, ends with the error and warning
// counts when there are any.
void PrintDiagnostics(const lang::SourceManager& sources, lang::DiagnosticCollector& collector,
                      bool compact, bool color);

}  // namespace sled::driver
