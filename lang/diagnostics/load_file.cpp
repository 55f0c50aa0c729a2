#include "lang/diagnostics/load_file.h"

#include <filesystem>
#include <system_error>
#include <utility>

#include <fmt/format.h>

namespace sled::lang {

std::optional<FileId> LoadFileOrReport(SourceManager& sources, const std::string& path,
                                       DiagnosticConsumer& diagnostics) {
  std::string why;
  if (auto id = sources.Load(path, &why)) return id;
  std::error_code error;
  const bool folder = std::filesystem::is_directory(path, error);
  auto diagnostic =
      MakeDiagnostic(DiagnosticKind::kFileUnreadable, {},
                     fmt::format("cannot read `{}`{}{}", path, why.empty() ? "" : ": ", why));
  diagnostic.labels.clear();
  diagnostic.help = why.empty() ? "check the path and the file's permissions"
                    : folder    ? "name a scenario file, not a folder"
                             : fmt::format("sled reads files of up to {} MiB", kMaxFileBytes >> 20);
  diagnostics.Consume(std::move(diagnostic));
  return std::nullopt;
}

}  // namespace sled::lang
