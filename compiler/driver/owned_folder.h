// The folder a run writes into, made ready before the simulation starts: created when missing,
// checked to be a writable folder (a failure names its cause, before any time is spent
// simulating), locked against a second sled run into it, and cleared of what an earlier run
// wrote there, so that no stale report.html, iso-mme/, dump or filtered CSV sits beside the new
// data. Files that no sled command writes are left alone.
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace sled::driver {

class OwnedFolder {
 public:
  // Nullptr with `error` set: the path is empty or not a folder, the folder cannot be created or
  // written (with the cause: `Permission denied`, `Read-only file system`), or another sled run
  // holds it.
  static std::unique_ptr<OwnedFolder> Open(const std::string& path, std::string* error);
  ~OwnedFolder();  // releases the lock
  OwnedFolder(const OwnedFolder&) = delete;
  OwnedFolder& operator=(const OwnedFolder&) = delete;

  const std::filesystem::path& path() const { return path_; }

  struct Cleared {
    std::vector<std::string> removed;  // earlier outputs, as `name` or `name/`
    std::vector<std::string> foreign;  // left alone: no sled command writes them
    std::string error;                 // the first removal that failed, with its cause
  };
  // Removes the outputs of earlier runs (the names sled writes), except the files in `keep` (a
  // checkpoint being resumed from).
  Cleared RemoveEarlierOutputs(const std::vector<std::filesystem::path>& keep) const;

  // Whether `name` (a file or folder name in an output folder) is one sled writes.
  static bool IsSledOutput(const std::string& name);

 private:
  OwnedFolder(std::filesystem::path path, int fd) : path_(std::move(path)), fd_(fd) {}
  std::filesystem::path path_;
  int fd_ = -1;  // the folder, open and locked (flock) while the run writes
};

}  // namespace sled::driver
