#include "output/atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

#include <fmt/format.h>

namespace sled::runtime {
namespace {

constexpr std::size_t kBufferBytes = 1 << 16;
constexpr std::string_view kTemporaryMarker = ".sled-tmp-";

}  // namespace

AtomicFile::AtomicFile(std::string path) : path_(std::move(path)) {
  namespace fs = std::filesystem;
  std::error_code code;
  fs::path target(path_);
  // Replace the file a link points to, not the link.
  if (fs::is_symlink(fs::symlink_status(target, code))) {
    const fs::path resolved = fs::canonical(target, code);
    if (code) {
      error_ = fmt::format("cannot write `{}`: {}", path_, code.message());
      return;
    }
    target = resolved;
  }
  path_ = target.string();
  temporary_ = (target.parent_path() /
                fmt::format(".{}{}{}", target.filename().string(), kTemporaryMarker, getpid()))
                   .string();
  fd_ = open(temporary_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (fd_ < 0) Fail("cannot write", errno);
  buffer_.reserve(kBufferBytes);
}

AtomicFile::~AtomicFile() {
  if (fd_ >= 0) close(fd_);
  if (!committed_ && !temporary_.empty()) unlink(temporary_.c_str());
}

void AtomicFile::Fail(std::string_view what, int error_number) {
  if (error_.empty()) {
    error_ = fmt::format("{} `{}`: {}", what, path_, std::strerror(error_number));
  }
}

bool AtomicFile::Flush() {
  std::size_t done = 0;
  while (done < buffer_.size() && error_.empty()) {
    const ssize_t written = write(fd_, buffer_.data() + done, buffer_.size() - done);
    if (written < 0) {
      if (errno == EINTR) continue;
      Fail("cannot write", errno);
    } else {
      done += static_cast<std::size_t>(written);
    }
  }
  buffer_.clear();
  return error_.empty();
}

void AtomicFile::Write(std::string_view bytes) {
  if (!error_.empty()) return;
  if (buffer_.size() + bytes.size() > kBufferBytes && !Flush()) return;
  if (bytes.size() >= kBufferBytes) {
    buffer_.assign(bytes);
    Flush();
    return;
  }
  buffer_.append(bytes);
}

bool AtomicFile::Commit(std::string* error) {
  if (error_.empty() && Flush() && fsync(fd_) != 0) Fail("cannot write", errno);
  if (fd_ >= 0 && close(fd_) != 0) Fail("cannot write", errno);
  fd_ = -1;
  if (error_.empty()) {
    // Keep the permissions of the file being replaced (a user's scenario under `sled fmt`).
    struct stat existing {};
    if (stat(path_.c_str(), &existing) == 0) chmod(temporary_.c_str(), existing.st_mode & 07777);
    if (rename(temporary_.c_str(), path_.c_str()) != 0) {
      Fail("cannot replace", errno);
    } else {
      committed_ = true;
    }
  }
  if (!committed_ && error) *error = error_;
  return committed_;
}

bool AtomicFile::IsTemporaryName(std::string_view name) {
  return name.starts_with('.') && name.find(kTemporaryMarker) != std::string_view::npos;
}

bool ReplaceFile(const std::string& path, std::string_view text, std::string* error) {
  AtomicFile file(path);
  file.Write(text);
  return file.Commit(error);
}

}  // namespace sled::runtime
