#include "compiler/driver/driver_diagnostics.h"

#include <iostream>

#include "lang/diagnostics/render.h"

namespace sled::driver {

void PrintDiagnostics(const lang::SourceManager& sources, lang::DiagnosticCollector& collector,
                      bool compact, bool color) {
  collector.SortByPosition();
  std::cerr << lang::RenderAll(
      sources, collector.diagnostics(),
      compact ? lang::DiagnosticStyle::kCompact : lang::DiagnosticStyle::kRich, {color});
}

}  // namespace sled::driver
