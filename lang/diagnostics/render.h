// Turns diagnostics into text: the rich form (source line, carets, help) and the compact
// one-line form `PATH:LINE:COL: error[E0204]: message`.
#pragma once

#include <string>

#include "lang/diagnostics/diagnostic.h"
#include "lang/source/source_manager.h"

namespace sled::lang {

struct RenderOptions {
  bool color = false;
};

std::string RenderRich(const SourceManager& sources, const Diagnostic& diagnostic,
                       const RenderOptions& options = {});
std::string RenderCompact(const SourceManager& sources, const Diagnostic& diagnostic);

}  // namespace sled::lang
