#include "compiler/lsp/text_document.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

namespace sled::lsp {
namespace {

// The length in bytes of the UTF-8 sequence that starts with `lead` (1 for a stray byte).
std::uint32_t SequenceLength(unsigned char lead) {
  if (lead >= 0xF0 && lead <= 0xF7) return 4;
  if (lead >= 0xE0) return lead <= 0xEF ? 3 : 1;
  if (lead >= 0xC0) return 2;
  return 1;
}

}  // namespace

LineIndex::LineIndex(std::string_view text) {
  line_starts_.push_back(0);
  for (std::uint32_t i = 0; i < text.size(); ++i) {
    if (text[i] == '\n') line_starts_.push_back(i + 1);
  }
}

Position LineIndex::PositionOf(std::string_view text, std::uint32_t offset) const {
  offset = std::min<std::uint32_t>(offset, static_cast<std::uint32_t>(text.size()));
  const auto after = std::upper_bound(line_starts_.begin(), line_starts_.end(), offset);
  const auto line = static_cast<std::uint32_t>(after - line_starts_.begin() - 1);
  std::uint32_t character = 0;
  for (std::uint32_t i = line_starts_[line]; i < offset;) {
    const std::uint32_t length = SequenceLength(static_cast<unsigned char>(text[i]));
    if (i + length > offset) break;
    character += length == 4 ? 2 : 1;  // a character beyond the BMP is a surrogate pair
    i += length;
  }
  return {line, character};
}

std::uint32_t LineIndex::OffsetOf(std::string_view text, Position position) const {
  if (position.line >= line_starts_.size()) return static_cast<std::uint32_t>(text.size());
  std::uint32_t end = position.line + 1 < line_starts_.size()
                          ? line_starts_[position.line + 1] - 1
                          : static_cast<std::uint32_t>(text.size());
  if (end > line_starts_[position.line] && text[end - 1] == '\r') --end;
  std::uint32_t offset = line_starts_[position.line];
  std::uint32_t units = 0;
  while (offset < end && units < position.character) {
    const std::uint32_t length = SequenceLength(static_cast<unsigned char>(text[offset]));
    units += length == 4 ? 2 : 1;
    offset = std::min(offset + length, end);
  }
  return offset;
}

TextDocument::TextDocument(std::string uri, std::string text, std::int64_t version)
    : uri_(std::move(uri)), text_(std::move(text)), version_(version), lines_(text_) {}

void TextDocument::Edit(Range range, std::string_view new_text) {
  std::uint32_t begin = OffsetOf(range.start);
  std::uint32_t end = OffsetOf(range.end);
  if (end < begin) std::swap(begin, end);
  text_.replace(begin, end - begin, new_text);
  lines_ = LineIndex(text_);
}

void TextDocument::Replace(std::string text) {
  text_ = std::move(text);
  lines_ = LineIndex(text_);
}

namespace {

int HexValue(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

std::string PercentDecode(std::string_view text) {
  std::string decoded;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '%' && i + 2 < text.size() && HexValue(text[i + 1]) >= 0 &&
        HexValue(text[i + 2]) >= 0) {
      decoded.push_back(static_cast<char>(HexValue(text[i + 1]) * 16 + HexValue(text[i + 2])));
      i += 2;
    } else {
      decoded.push_back(text[i]);
    }
  }
  return decoded;
}

}  // namespace

std::string PathOfUri(std::string_view uri) {
  constexpr std::string_view kFile = "file://";
  if (uri.substr(0, kFile.size()) == kFile) {
    std::string path = PercentDecode(uri.substr(kFile.size()));
    // file://host/path: drop a host name (localhost or empty in practice).
    if (!path.empty() && path.front() != '/') {
      const std::size_t slash = path.find('/');
      path = slash == std::string::npos ? "/" : path.substr(slash);
    }
    return path;
  }
  // untitled:Untitled-1 and other schemes: a name in the current folder.
  std::string name = PercentDecode(uri.substr(uri.find_last_of(":/") + 1));
  if (name.empty()) name = "untitled.sled";
  return (std::filesystem::current_path() / name).string();
}

std::string UriOfPath(std::string_view path) {
  const std::string absolute =
      std::filesystem::absolute(std::filesystem::path(path)).lexically_normal().string();
  std::string uri = "file://";
  constexpr std::string_view kHex = "0123456789ABCDEF";
  for (const char c : absolute) {
    const auto byte = static_cast<unsigned char>(c);
    if (std::isalnum(byte) || c == '/' || c == '-' || c == '_' || c == '.' || c == '~') {
      uri.push_back(c);
    } else {
      uri.push_back('%');
      uri.push_back(kHex[byte >> 4]);
      uri.push_back(kHex[byte & 15]);
    }
  }
  return uri;
}

}  // namespace sled::lsp
