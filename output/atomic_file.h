// Files that are never seen half-written. An AtomicFile writes into a temporary file beside its
// target (`.NAME.sled-tmp-PID`) and renames it over the target only once every byte is on disk,
// so a full disk, a missing permission or a killed process leaves the target as it was (or
// absent), never truncated; the failure is reported with its cause (`No space left on device`).
#pragma once

#include <string>
#include <string_view>

namespace sled::runtime {

class AtomicFile {
 public:
  // Opens the temporary file; a failure is kept and reported by Commit.
  explicit AtomicFile(std::string path);
  // Removes the temporary file unless Commit succeeded.
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  // Buffered; after the first failure, further writes do nothing.
  void Write(std::string_view bytes);
  AtomicFile& operator<<(std::string_view bytes) {
    Write(bytes);
    return *this;
  }
  bool failed() const { return !error_.empty(); }

  // Flushes, syncs and renames the temporary file over the target (through a symbolic link,
  // keeping the permissions of a file that is there). False with `error` set to what failed
  // and why: "cannot write `out/timeseries.csv`: No space left on device".
  bool Commit(std::string* error);

  // Whether `name` is the temporary file of some AtomicFile (left behind by a killed process).
  static bool IsTemporaryName(std::string_view name);

 private:
  void Fail(std::string_view what, int error_number);
  bool Flush();

  std::string path_;       // the target, a symbolic link resolved
  std::string temporary_;  // beside it
  int fd_ = -1;
  std::string buffer_;
  std::string error_;
  bool committed_ = false;
};

// The whole text at once, as an AtomicFile.
bool ReplaceFile(const std::string& path, std::string_view text, std::string* error);

}  // namespace sled::runtime
