#include "compiler/check/library_paths.h"

#include <cstdlib>
#include <filesystem>
#include <system_error>

// Set by compiler/CMakeLists.txt; the fallbacks keep the file compilable on its own.
#ifndef SLED_SOURCE_ROOT
#define SLED_SOURCE_ROOT "."
#endif
#ifndef SLED_STDLIB_FROM_BINDIR
#define SLED_STDLIB_FROM_BINDIR "../share/sled/stdlib"
#endif
#ifndef SLED_INSTALL_STDLIB
#define SLED_INSTALL_STDLIB "/usr/local/share/sled/stdlib"
#endif

namespace sled::compiler {
namespace {

namespace fs = std::filesystem;

bool IsFolder(const fs::path& path) {
  std::error_code error;
  return fs::is_directory(path, error);
}

// The folder of the running program; empty when the system does not say.
fs::path ProgramFolder() {
  std::error_code error;
  const fs::path self = fs::read_symlink("/proc/self/exe", error);
  return error ? fs::path() : self.parent_path();
}

}  // namespace

std::string DefaultStdlibRoot() {
  if (const char* from_environment = std::getenv("SLED_STDLIB")) return from_environment;
  const fs::path program = ProgramFolder();
  if (!program.empty()) {
    const fs::path beside = (program / SLED_STDLIB_FROM_BINDIR).lexically_normal();
    if (IsFolder(beside)) return beside.string();
  }
  const fs::path source_tree = fs::path(SLED_SOURCE_ROOT) / "stdlib";
  if (IsFolder(source_tree)) return source_tree.string();
  return SLED_INSTALL_STDLIB;
}

std::vector<std::string> ModulePathFromEnvironment() {
  std::vector<std::string> folders;
  const char* value = std::getenv("SLED_PATH");
  if (value == nullptr) return folders;
  const std::string text = value;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t colon = std::min(text.find(':', start), text.size());
    if (colon > start) folders.push_back(text.substr(start, colon - start));
    start = colon + 1;
  }
  return folders;
}

}  // namespace sled::compiler
