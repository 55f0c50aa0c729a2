// LSP JSON shapes built from sled's types: positions, ranges and locations from source ranges
// (byte offsets in any buffer of a compilation), and back.
#pragma once

#include <map>
#include <optional>

#include <nlohmann/json.hpp>

#include "compiler/lsp/text_document.h"
#include "lang/source/source_manager.h"

namespace sled::lsp {

using Json = nlohmann::json;

Json PositionJson(Position position);
Json RangeJson(Range range);
// A position from a request's `position`; nullopt when it is missing or malformed.
std::optional<Position> PositionFrom(const Json& json);
std::optional<Range> RangeFrom(const Json& json);

// Converts source ranges of one compilation to LSP ranges and locations, indexing each buffer's
// lines once.
class RangeConverter {
 public:
  explicit RangeConverter(const lang::SourceManager& sources) : sources_(sources) {}

  Range RangeOf(const lang::SourceRange& range);
  // {uri, range}; the buffer's path made absolute.
  Json LocationOf(const lang::SourceRange& range);
  std::string UriOf(lang::FileId file);
  // The URI the client named a buffer by (the open document), used instead of its path's.
  void SetUri(lang::FileId file, std::string uri) { uris_[file.value] = std::move(uri); }

 private:
  const lang::SourceManager& sources_;
  std::map<std::uint32_t, LineIndex> lines_;
  std::map<std::uint32_t, std::string> uris_;
};

}  // namespace sled::lsp
