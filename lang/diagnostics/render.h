// Turns diagnostics into text: the rich form (source line, carets, help) and the compact
// one-line form `PATH:LINE:COL: error[E0204]: message`.
#pragma once

#include <string>
#include <vector>

#include "lang/diagnostics/diagnostic.h"
#include "lang/source/source_manager.h"

namespace sled::lang {

struct RenderOptions {
  bool color = false;
};

std::string RenderRich(const SourceManager& sources, const Diagnostic& diagnostic,
                       const RenderOptions& options = {});
std::string RenderCompact(const SourceManager& sources, const Diagnostic& diagnostic);

enum class DiagnosticStyle { kRich, kCompact };

// Every diagnostic in the given order, each followed by a newline; the rich form ends with a
// line of the error and warning counts when there are any.
std::string RenderAll(const SourceManager& sources, const std::vector<Diagnostic>& diagnostics,
                      DiagnosticStyle style, const RenderOptions& options = {});

}  // namespace sled::lang
