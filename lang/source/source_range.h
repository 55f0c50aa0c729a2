// A span of bytes in one source buffer. Ranges are what every AST node, diagnostic and model
// side-table entry carries; line and column are computed on demand from the buffer's line table.
#pragma once

#include <cstdint>

namespace sled::lang {

// Identifies a buffer inside a SourceManager. Id 0 is "no file" (synthetic nodes).
struct FileId {
  std::uint32_t value = 0;
  friend bool operator==(FileId, FileId) = default;
};

struct SourceRange {
  FileId file;
  std::uint32_t begin = 0;  // byte offset of the first byte
  std::uint32_t end = 0;    // byte offset one past the last byte

  bool valid() const { return file.value != 0; }
  std::uint32_t size() const { return end - begin; }
  friend bool operator==(const SourceRange&, const SourceRange&) = default;
};

// The smallest range that covers both (they must be in the same file, or one invalid).
inline SourceRange Join(SourceRange a, SourceRange b) {
  if (!a.valid()) return b;
  if (!b.valid()) return a;
  return {a.file, a.begin < b.begin ? a.begin : b.begin, a.end > b.end ? a.end : b.end};
}

// True when a comes before b in reading order (file, then offset).
inline bool Precedes(const SourceRange& a, const SourceRange& b) {
  if (a.file.value != b.file.value) return a.file.value < b.file.value;
  if (a.begin != b.begin) return a.begin < b.begin;
  return a.end < b.end;
}

}  // namespace sled::lang
