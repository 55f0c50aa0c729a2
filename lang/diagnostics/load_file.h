// Reading a user's file with a diagnostic when it cannot be read (E0107), for every front end
// that takes a path: sled::Compile, `sled check`, `sled fmt`, `sled convert`.
#pragma once

#include <optional>
#include <string>

#include "lang/diagnostics/diagnostic.h"
#include "lang/source/source_manager.h"

namespace sled::lang {

// Loads `path` into `sources`, or reports E0107 (saying when the path is a folder or too large)
// and returns nullopt.
std::optional<FileId> LoadFileOrReport(SourceManager& sources, const std::string& path,
                                       DiagnosticConsumer& diagnostics);

}  // namespace sled::lang
