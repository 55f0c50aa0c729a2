// Source text is UTF-8, and every column sled shows (diagnostics, the formatter's line widths)
// counts characters, not bytes. A byte starts a character unless it is a continuation byte
// (10xxxxxx); these helpers are the one place that says so.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>
#include <vector>

namespace sled::lang {

constexpr bool StartsCharacter(char byte) {
  return (static_cast<unsigned char>(byte) & 0xC0u) != 0x80u;
}

// Characters in a span of bytes; a tab counts as one.
constexpr std::uint32_t CountCharacters(std::string_view text) {
  std::uint32_t count = 0;
  for (const char byte : text) count += StartsCharacter(byte) ? 1 : 0;
  return count;
}

// The first offset after `offset` that starts a character (or the end of the text): the end
// of the character at `offset`.
constexpr std::size_t NextCharacterStart(std::string_view text, std::size_t offset) {
  ++offset;
  while (offset < text.size() && !StartsCharacter(text[offset])) ++offset;
  return offset;
}

// The length of the well-formed UTF-8 sequence at `offset` (1 to 4), or 0 when the bytes there
// are none: a stray continuation byte, an overlong form, a surrogate, a code point above
// U+10FFFF or a sequence cut short.
constexpr std::size_t Utf8SequenceLength(std::string_view text, std::size_t offset) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char lead = byte(offset);
  if (lead < 0x80) return 1;
  std::size_t length = 0;
  unsigned char low = 0x80, high = 0xBF;  // the range of the second byte
  if (lead >= 0xC2 && lead <= 0xDF) {
    length = 2;
  } else if (lead >= 0xE0 && lead <= 0xEF) {
    length = 3;
    if (lead == 0xE0) low = 0xA0;
    if (lead == 0xED) high = 0x9F;
  } else if (lead >= 0xF0 && lead <= 0xF4) {
    length = 4;
    if (lead == 0xF0) low = 0x90;
    if (lead == 0xF4) high = 0x8F;
  } else {
    return 0;
  }
  if (offset + length > text.size()) return 0;
  if (byte(offset + 1) < low || byte(offset + 1) > high) return 0;
  for (std::size_t k = 2; k < length; ++k) {
    if (byte(offset + k) < 0x80 || byte(offset + k) > 0xBF) return 0;
  }
  return length;
}

// The offset of the first byte that is not UTF-8 on each line that has one (in comments and
// strings too: a file is UTF-8 throughout).
inline std::vector<std::size_t> InvalidUtf8PerLine(std::string_view text) {
  std::vector<std::size_t> found;
  for (std::size_t at = 0; at < text.size();) {
    const std::size_t length = Utf8SequenceLength(text, at);
    if (length > 0) {
      at += length;
      continue;
    }
    found.push_back(at);
    const std::size_t line_end = text.find('\n', at);
    at = line_end == std::string_view::npos ? text.size() : line_end;
  }
  return found;
}

}  // namespace sled::lang
