// An open document as the editor holds it: its text, version, and the mapping between byte
// offsets (what sled's source ranges count) and LSP positions (a 0-based line and a column in
// UTF-16 code units, the protocol's default encoding).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace sled::lsp {

struct Position {
  std::uint32_t line = 0;
  std::uint32_t character = 0;  // UTF-16 code units
};

struct Range {
  Position start;
  Position end;
};

// Line starts of a text, for offset <-> position conversion.
class LineIndex {
 public:
  explicit LineIndex(std::string_view text);

  // The position of a byte offset (clamped to the text); an offset inside a UTF-8 sequence
  // counts as the start of that character.
  Position PositionOf(std::string_view text, std::uint32_t offset) const;
  // The byte offset of a position; a line past the end gives the text's end, a column past the
  // line's end gives the line's end (before its line break), as the protocol asks.
  std::uint32_t OffsetOf(std::string_view text, Position position) const;

 private:
  std::vector<std::uint32_t> line_starts_;
};

class TextDocument {
 public:
  TextDocument(std::string uri, std::string text, std::int64_t version);

  const std::string& uri() const { return uri_; }
  const std::string& text() const { return text_; }
  std::int64_t version() const { return version_; }
  const LineIndex& lines() const { return lines_; }

  // Replaces `range` with `new_text` (an incremental change of textDocument/didChange).
  void Edit(Range range, std::string_view new_text);
  // Replaces the whole text (a change without a range).
  void Replace(std::string text);
  void set_version(std::int64_t version) { version_ = version; }

  Position PositionOf(std::uint32_t offset) const { return lines_.PositionOf(text_, offset); }
  std::uint32_t OffsetOf(Position position) const { return lines_.OffsetOf(text_, position); }

 private:
  std::string uri_;
  std::string text_;
  std::int64_t version_ = 0;
  LineIndex lines_;
};

// file:///a/b%20c.sled <-> /a/b c.sled. Other schemes (untitled:) give a path under the current
// folder named after the URI's last part, so imports resolve from there.
std::string PathOfUri(std::string_view uri);
std::string UriOfPath(std::string_view path);

}  // namespace sled::lsp
