#include "compiler/driver/driver_diagnostics.h"

#include <filesystem>
#include <iostream>
#include <system_error>

#include <fmt/format.h>

#include "lang/diagnostics/render.h"

namespace sled::driver {

std::optional<lang::FileId> LoadUserFile(lang::SourceManager& sources, const std::string& path,
                                         lang::DiagnosticCollector& collector) {
  std::string why;
  if (auto id = sources.Load(path, &why)) return id;
  std::error_code error;
  const bool folder = std::filesystem::is_directory(path, error);
  auto diagnostic =
      lang::MakeDiagnostic(lang::DiagnosticKind::kFileUnreadable, {},
                           fmt::format("cannot read `{}`{}{}", path, why.empty() ? "" : ": ", why));
  diagnostic.labels.clear();
  diagnostic.help =
      why.empty() ? "check the path and the file's permissions"
      : folder    ? "name a scenario file, not a folder"
                  : fmt::format("sled reads files of up to {} MiB", lang::kMaxFileBytes >> 20);
  collector.Consume(std::move(diagnostic));
  return std::nullopt;
}

void PrintDiagnostics(const lang::SourceManager& sources, lang::DiagnosticCollector& collector,
                      bool compact, bool color) {
  collector.SortByPosition();
  const lang::RenderOptions render{color};
  for (const auto& diagnostic : collector.diagnostics()) {
    std::cerr << (compact ? lang::RenderCompact(sources, diagnostic)
                          : lang::RenderRich(sources, diagnostic, render))
              << '\n';
  }
  if (!compact && (collector.error_count() > 0 || collector.warning_count() > 0)) {
    std::cerr << fmt::format("{} error{}, {} warning{}\n", collector.error_count(),
                             collector.error_count() == 1 ? "" : "s", collector.warning_count(),
                             collector.warning_count() == 1 ? "" : "s");
  }
}

}  // namespace sled::driver
