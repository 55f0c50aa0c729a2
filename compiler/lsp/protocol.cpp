#include "compiler/lsp/protocol.h"

namespace sled::lsp {

Json PositionJson(Position position) {
  return {{"line", position.line}, {"character", position.character}};
}

Json RangeJson(Range range) {
  return {{"start", PositionJson(range.start)}, {"end", PositionJson(range.end)}};
}

std::optional<Position> PositionFrom(const Json& json) {
  if (!json.is_object()) return std::nullopt;
  const auto line = json.find("line");
  const auto character = json.find("character");
  if (line == json.end() || character == json.end() || !line->is_number_unsigned() ||
      !character->is_number_unsigned()) {
    return std::nullopt;
  }
  // Clamp rather than wrap: a huge number means "past the end".
  constexpr std::uint64_t kMax = 0xFFFFFFFFu;
  return Position{static_cast<std::uint32_t>(std::min(line->get<std::uint64_t>(), kMax)),
                  static_cast<std::uint32_t>(std::min(character->get<std::uint64_t>(), kMax))};
}

std::optional<Range> RangeFrom(const Json& json) {
  if (!json.is_object() || !json.contains("start") || !json.contains("end")) return std::nullopt;
  const auto start = PositionFrom(json["start"]);
  const auto end = PositionFrom(json["end"]);
  if (!start || !end) return std::nullopt;
  return Range{*start, *end};
}

Range RangeConverter::RangeOf(const lang::SourceRange& range) {
  if (!range.valid() || range.file.value > sources_.size()) return {};
  const std::string_view text = sources_.buffer(range.file).text();
  auto it = lines_.find(range.file.value);
  if (it == lines_.end()) it = lines_.emplace(range.file.value, LineIndex(text)).first;
  return {it->second.PositionOf(text, range.begin), it->second.PositionOf(text, range.end)};
}

std::string RangeConverter::UriOf(lang::FileId file) {
  if (file.value == 0 || file.value > sources_.size()) return {};
  if (const auto it = uris_.find(file.value); it != uris_.end()) return it->second;
  return UriOfPath(sources_.buffer(file).path());
}

Json RangeConverter::LocationOf(const lang::SourceRange& range) {
  return {{"uri", UriOf(range.file)}, {"range", RangeJson(RangeOf(range))}};
}

}  // namespace sled::lsp
