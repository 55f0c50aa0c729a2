#include "output/checkpoint_file.h"

#include <sys/stat.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "output/atomic_file.h"
#include "runtime/run/archive.h"
#include "runtime/run/fnv1a.h"

namespace sled::output {
namespace {

using runtime::Archive;
using runtime::Checkpoint;

// Format 3 (2 with the table-range records in the Data's state) ends with a 16-hex-digit FNV-1a
// checksum of everything between the magic line and it, so that a damaged file (a flipped byte, a
// torn write) is refused rather than resumed from.
constexpr char kMagic[] = "sled checkpoint 3\n";
constexpr char kMagicPrefix[] = "sled checkpoint ";
constexpr std::size_t kChecksumDigits = 16;

// The checksum that ends a format-2 file: FNV-1a of the payload in kChecksumDigits hex digits.
std::string ChecksumText(const std::string& payload) {
  return fmt::format("{:0{}x}", runtime::Fnv1a(payload), kChecksumDigits);
}

void SerializeFingerprint(Archive& archive, runtime::ModelFingerprint& model) {
  archive.Field(model.physics);
  archive.Resizable(model.settings);
  archive.Resizable(model.outputs);
}

}  // namespace

std::string CheckpointFileName(double time) { return fmt::format("checkpoint_{:.6f}s.bin", time); }

bool WriteCheckpoint(const std::string& path, const Checkpoint& checkpoint, std::string* error) {
  Archive archive = Archive::ForWriting();
  Checkpoint copy = checkpoint;  // Serialize takes references; the writer does not change them
  SerializeFingerprint(archive, copy.model);
  archive.Field(copy.time);
  archive.Field(copy.next_row);
  std::string names;
  for (const std::string& name : copy.series.names) names += name + "\n";
  archive.Resizable(names);
  std::int64_t columns = static_cast<std::int64_t>(copy.series.columns);
  archive.Field(columns);
  archive.Resizable(copy.series.values);
  archive.Resizable(copy.state);
  // Through a temporary file: a full disk leaves no truncated checkpoint under its name.
  runtime::AtomicFile out(path);
  out << kMagic << archive.bytes() << ChecksumText(archive.bytes());
  return out.Commit(error);
}

bool ReadCheckpoint(const std::string& path, Checkpoint* checkpoint, std::string* error) {
  // A device or a pipe (`--resume /dev/zero`) would be read until memory runs out.
  struct stat status {};
  if (stat(path.c_str(), &status) != 0) {
    *error = fmt::format("cannot read the checkpoint `{}`: {}", path, std::strerror(errno));
    return false;
  }
  if (!S_ISREG(status.st_mode)) {
    *error = fmt::format("`{}` is not a checkpoint: it is {}", path,
                         S_ISDIR(status.st_mode) ? "a folder" : "not a regular file");
    return false;
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    *error = fmt::format("cannot read the checkpoint `{}`: {}", path, std::strerror(errno));
    return false;
  }
  std::stringstream content;
  content << in.rdbuf();
  std::string bytes = content.str();
  const std::string magic = kMagic;
  if (!bytes.starts_with(magic)) {
    const std::string version = bytes.substr(0, bytes.find('\n'));
    *error = version.starts_with(kMagicPrefix) && version.size() < 40
                 ? fmt::format(
                       "`{}` is a checkpoint of another format (`{}`); this sled reads "
                       "`{}`: run the scene again to write it",
                       path, version, magic.substr(0, magic.size() - 1))
                 : fmt::format("`{}` is not a sled checkpoint (it does not start with `{}`)", path,
                               magic.substr(0, magic.size() - 1));
    return false;
  }
  const std::string_view rest = std::string_view(bytes).substr(magic.size());
  const std::string payload(rest.substr(0, rest.size() - std::min(rest.size(), kChecksumDigits)));
  if (rest.size() < kChecksumDigits || rest.substr(payload.size()) != ChecksumText(payload)) {
    *error = fmt::format(
        "the checkpoint `{}` is truncated or damaged: its checksum does not match its contents",
        path);
    return false;
  }
  Archive archive = Archive::ForReading(payload);
  SerializeFingerprint(archive, checkpoint->model);
  archive.Field(checkpoint->time);
  archive.Field(checkpoint->next_row);
  std::string names;
  archive.Resizable(names);
  std::int64_t columns = 0;
  archive.Field(columns);
  archive.Resizable(checkpoint->series.values);
  archive.Resizable(checkpoint->state);
  if (!archive.ok() || !archive.at_end() || columns < 1 ||
      checkpoint->series.values.size() % static_cast<std::size_t>(columns) != 0) {
    *error = fmt::format("the checkpoint `{}` is truncated or damaged", path);
    return false;
  }
  checkpoint->series.columns = static_cast<std::size_t>(columns);
  checkpoint->series.names.clear();
  std::istringstream lines(names);
  for (std::string name; std::getline(lines, name);) checkpoint->series.names.push_back(name);
  return true;
}

bool CheckpointFolder::Keep(const Checkpoint& checkpoint, std::string* where, std::string* error) {
  *where = directory_ + "/" + CheckpointFileName(checkpoint.time);
  return WriteCheckpoint(*where, checkpoint, error);
}

}  // namespace sled::output
