#include "compiler/driver/owned_folder.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

#include <fmt/format.h>

#include "output/atomic_file.h"

namespace sled::driver {
namespace fs = std::filesystem;

namespace {

bool StartsEnds(const std::string& name, std::string_view start, std::string_view end) {
  return name.size() >= start.size() + end.size() && name.starts_with(start) && name.ends_with(end);
}

}  // namespace

bool OwnedFolder::IsSledOutput(const std::string& name) {
  // What `sled run` (and `sled report`, `sled study`) write into a folder.
  static const char* const kNames[] = {"timeseries.csv", "timeseries_filtered.csv",
                                       "summary.json",   "animation.glb",
                                       "report.html",    "iso-mme",
                                       "study.csv",      "study.svg",
                                       "reference.csv"};
  if (std::find(std::begin(kNames), std::end(kNames), name) != std::end(kNames)) return true;
  return StartsEnds(name, "dump_", ".txt") || StartsEnds(name, "checkpoint_", "s.bin") ||
         runtime::AtomicFile::IsTemporaryName(name) || name.starts_with(".sled-probe-");
}

std::unique_ptr<OwnedFolder> OwnedFolder::Open(const std::string& text, std::string* error) {
  if (text.empty()) {
    *error = "the output folder is an empty name";
    return nullptr;
  }
  const fs::path path(text);
  std::error_code code;
  const fs::file_status status = fs::status(path, code);
  if (fs::exists(status) && !fs::is_directory(status)) {
    *error = fmt::format("cannot write into `{}`: it is a file, not a folder", text);
    return nullptr;
  }
  if (!fs::exists(status)) {
    fs::create_directories(path, code);
    if (code) {
      *error = fmt::format("cannot create the output folder `{}`: {}", text, code.message());
      return nullptr;
    }
  }
  const int fd = open(text.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) {
    *error = fmt::format("cannot open the output folder `{}`: {}", text, std::strerror(errno));
    return nullptr;
  }
  if (flock(fd, LOCK_EX | LOCK_NB) != 0) {
    const int cause = errno;
    close(fd);
    *error =
        cause == EWOULDBLOCK
            ? fmt::format(
                  "`{}` is in use by another sled run; wait for it to finish, or "
                  "give this run another folder with -o",
                  text)
            : fmt::format("cannot lock the output folder `{}`: {}", text, std::strerror(cause));
    return nullptr;
  }
  // Can a file be made there? (A read-only file system, a folder without write permission.)
  const fs::path probe = path / fmt::format(".sled-probe-{}", getpid());
  const int probe_fd = open(probe.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0600);
  if (probe_fd < 0) {
    const int cause = errno;
    close(fd);
    *error =
        fmt::format("cannot write into the output folder `{}`: {}", text, std::strerror(cause));
    return nullptr;
  }
  close(probe_fd);
  unlink(probe.c_str());
  return std::unique_ptr<OwnedFolder>(new OwnedFolder(path, fd));
}

OwnedFolder::~OwnedFolder() {
  if (fd_ >= 0) close(fd_);  // closing releases the lock
}

OwnedFolder::Cleared OwnedFolder::RemoveEarlierOutputs(const std::vector<fs::path>& keep) const {
  Cleared cleared;
  std::error_code code;
  std::vector<fs::directory_entry> entries;
  for (const fs::directory_entry& entry : fs::directory_iterator(path_, code)) {
    entries.push_back(entry);
  }
  std::sort(entries.begin(), entries.end());
  for (const fs::directory_entry& entry : entries) {
    const std::string name = entry.path().filename().string();
    if (!IsSledOutput(name)) {
      cleared.foreign.push_back(name);
      continue;
    }
    const bool kept = std::any_of(keep.begin(), keep.end(), [&](const fs::path& file) {
      std::error_code same;
      return fs::equivalent(entry.path(), file, same);
    });
    if (kept) continue;
    const bool folder = entry.is_directory(code);
    fs::remove_all(entry.path(), code);
    if (code) {
      if (cleared.error.empty()) {
        cleared.error =
            fmt::format("cannot remove `{}`: {}", entry.path().string(), code.message());
      }
      continue;
    }
    // Temporary files of a killed run are not worth naming.
    if (!runtime::AtomicFile::IsTemporaryName(name)) {
      cleared.removed.push_back(folder ? name + "/" : name);
    }
  }
  return cleared;
}

}  // namespace sled::driver
