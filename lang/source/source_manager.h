// Owns the text of every file a run reads (scenarios, imports, decks, C++ builder sources) and
// turns byte ranges into line and column numbers for diagnostics.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "lang/source/source_range.h"

namespace sled::lang {

// One line-and-column position, both 1-based; columns count characters (UTF-8 aware, tabs as one).
struct LineColumn {
  std::uint32_t line = 0;
  std::uint32_t column = 0;
};

class SourceBuffer {
 public:
  SourceBuffer(std::string path, std::string text);

  const std::string& path() const { return path_; }
  std::string_view text() const { return text_; }
  std::uint32_t line_count() const { return static_cast<std::uint32_t>(line_starts_.size()); }

  LineColumn Locate(std::uint32_t offset) const;
  // The text of a 1-based line without its line terminator.
  std::string_view Line(std::uint32_t line) const;
  // The byte offset of a 1-based line and column (columns in characters), clamped to the buffer.
  std::uint32_t OffsetOf(std::uint32_t line, std::uint32_t column) const;

 private:
  std::string path_;
  // Characters before `offset`, in time bounded by kBlockBytes whatever the line length.
  std::uint32_t CharactersBefore(std::uint32_t offset) const;

  static constexpr std::uint32_t kBlockBytes = 4096;
  std::string text_;
  std::vector<std::uint32_t> line_starts_;
  // Characters before each kBlockBytes-aligned offset: a column in a line of megabytes (a
  // generated file) is found without counting the whole line, once per diagnostic.
  std::vector<std::uint32_t> characters_before_block_;
};

class SourceManager {
 public:
  SourceManager();
  SourceManager(const SourceManager&) = delete;
  SourceManager& operator=(const SourceManager&) = delete;

  // Adds a buffer and returns its id. Paths need not be unique (stdin, generated text).
  FileId Add(std::string path, std::string text);
  // Reads a file from disk; nullopt when it cannot be read (ReadFile says why).
  std::optional<FileId> Load(const std::string& path, std::string* why = nullptr);
  // The id of a buffer already added under this path, if any.
  std::optional<FileId> Find(std::string_view path) const;

  const SourceBuffer& buffer(FileId id) const;
  // How many buffers there are: their ids are 1 to size().
  std::size_t size() const { return buffers_.size(); }
  std::string_view Text(const SourceRange& range) const;

 private:
  std::vector<std::unique_ptr<SourceBuffer>> buffers_;  // index = FileId::value - 1
};

// The largest file sled reads: source offsets are 32-bit, and no scenario or deck comes near it
// (an endless file such as /dev/zero would otherwise be read until memory runs out).
inline constexpr std::size_t kMaxFileBytes = std::size_t{256} << 20;

// Reads a whole file; nullopt when it cannot be opened, is a folder or is larger than
// kMaxFileBytes, with `why` (when given) set to "it is a folder", "it is larger than 256 MiB"
// or, when the file cannot be opened, left empty.
std::optional<std::string> ReadFile(const std::string& path, std::string* why = nullptr);

}  // namespace sled::lang
