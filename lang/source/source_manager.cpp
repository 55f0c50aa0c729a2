#include "lang/source/source_manager.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "lang/source/utf8.h"

namespace sled::lang {

SourceBuffer::SourceBuffer(std::string path, std::string text)
    : path_(std::move(path)), text_(std::move(text)) {
  line_starts_.push_back(0);
  std::uint32_t characters = 0;
  for (std::uint32_t i = 0; i < text_.size(); ++i) {
    if (i % kBlockBytes == 0) characters_before_block_.push_back(characters);
    if (text_[i] == '\n') line_starts_.push_back(i + 1);
    if (StartsCharacter(text_[i])) ++characters;
  }
  // The end of a text whose size is a whole number of blocks starts a block of its own.
  if (text_.size() % kBlockBytes == 0) characters_before_block_.push_back(characters);
}

std::uint32_t SourceBuffer::CharactersBefore(std::uint32_t offset) const {
  offset = std::min<std::uint32_t>(offset, static_cast<std::uint32_t>(text_.size()));
  const std::uint32_t block = offset / kBlockBytes;
  return characters_before_block_[block] +
         CountCharacters(std::string_view(text_).substr(std::size_t{block} * kBlockBytes,
                                                        offset - block * kBlockBytes));
}

LineColumn SourceBuffer::Locate(std::uint32_t offset) const {
  offset = std::min<std::uint32_t>(offset, static_cast<std::uint32_t>(text_.size()));
  auto it = std::upper_bound(line_starts_.begin(), line_starts_.end(), offset);
  const auto line_index = static_cast<std::uint32_t>(it - line_starts_.begin()) - 1;
  const std::uint32_t start = line_starts_[line_index];
  return {line_index + 1, CharactersBefore(offset) - CharactersBefore(start) + 1};
}

std::string_view SourceBuffer::Line(std::uint32_t line) const {
  if (line == 0 || line > line_starts_.size()) return {};
  const std::uint32_t start = line_starts_[line - 1];
  std::uint32_t end = line < line_starts_.size() ? line_starts_[line] - 1
                                                 : static_cast<std::uint32_t>(text_.size());
  if (end > start && text_[end - 1] == '\r') --end;
  return std::string_view(text_).substr(start, end - start);
}

std::uint32_t SourceBuffer::OffsetOf(std::uint32_t line, std::uint32_t column) const {
  if (line == 0) return 0;
  if (line > line_starts_.size()) return static_cast<std::uint32_t>(text_.size());
  const std::uint32_t start = line_starts_[line - 1];
  const std::string_view rest = Line(line);
  std::uint32_t offset = 0;
  std::uint32_t characters = 1;
  while (offset < rest.size() && characters < column) {
    offset = static_cast<std::uint32_t>(NextCharacterStart(rest, offset));
    ++characters;
  }
  return start + offset;
}

SourceManager::SourceManager() = default;

FileId SourceManager::Add(std::string path, std::string text) {
  buffers_.push_back(std::make_unique<SourceBuffer>(std::move(path), std::move(text)));
  return FileId{static_cast<std::uint32_t>(buffers_.size())};
}

std::optional<FileId> SourceManager::Load(const std::string& path, std::string* why) {
  auto text = ReadFile(path, why);
  if (!text) return std::nullopt;
  return Add(path, std::move(*text));
}

std::optional<FileId> SourceManager::Find(std::string_view path) const {
  for (std::size_t i = 0; i < buffers_.size(); ++i) {
    if (buffers_[i]->path() == path) return FileId{static_cast<std::uint32_t>(i + 1)};
  }
  return std::nullopt;
}

const SourceBuffer& SourceManager::buffer(FileId id) const {
  if (id.value == 0 || id.value > buffers_.size()) {
    throw std::logic_error("lang::SourceManager: no buffer with id " + std::to_string(id.value));
  }
  return *buffers_[id.value - 1];
}

std::string_view SourceManager::Text(const SourceRange& range) const {
  if (!range.valid()) return {};
  const std::string_view text = buffer(range.file).text();
  if (range.begin > text.size()) return {};
  return text.substr(range.begin, range.end - range.begin);
}

std::optional<std::string> ReadFile(const std::string& path, std::string* why) {
  const auto fail = [why](std::string reason) -> std::optional<std::string> {
    if (why) *why = std::move(reason);
    return std::nullopt;
  };
  if (why) why->clear();
  // A directory opens as a stream on Linux and reads as empty text, which would pass for an
  // empty file.
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) return fail("it is a folder");
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  // In blocks, up to the limit: the size on disk is unknown for a pipe or a device.
  std::string contents;
  char block[1 << 16];
  while (in.read(block, sizeof block) || in.gcount() > 0) {
    if (contents.size() + static_cast<std::size_t>(in.gcount()) > kMaxFileBytes) {
      return fail("it is larger than " + std::to_string(kMaxFileBytes >> 20) + " MiB");
    }
    contents.append(block, static_cast<std::size_t>(in.gcount()));
  }
  if (in.bad()) return std::nullopt;
  return contents;
}

}  // namespace sled::lang
