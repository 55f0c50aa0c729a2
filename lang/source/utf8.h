// Source text is UTF-8, and every column sled shows (diagnostics, the formatter's line widths)
// counts characters, not bytes. A byte starts a character unless it is a continuation byte
// (10xxxxxx); these helpers are the one place that says so.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>

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

}  // namespace sled::lang
