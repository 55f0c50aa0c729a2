#include "lang/legacy/convert.h"

#include <cctype>
#include <memory>
#include <string>

#include "lang/legacy/card_reader.h"
#include "lang/legacy/deck_reader.h"
#include "lang/legacy/list_reader.h"

namespace sled::lang::legacy {

std::optional<DeckFormat> DeckFormatOfPath(std::string_view path) {
  const std::size_t dot = path.find_last_of('.');
  if (dot == std::string_view::npos || path.find_first_of("/\\", dot) != std::string_view::npos) {
    return std::nullopt;
  }
  std::string extension(path.substr(dot + 1));
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (extension == "ain") return DeckFormat::kFixed;
  if (extension == "lin") return DeckFormat::kList;
  return std::nullopt;
}

ast::File ConvertDeck(const SourceManager& sources, FileId deck, const ConvertOptions& options) {
  ErrorTrackingConsumer tracking(*options.diagnostics);
  std::unique_ptr<DeckSource> source;
  if (options.format == DeckFormat::kList) {
    source = std::make_unique<ListReader>(sources, deck, tracking);
  } else {
    source = std::make_unique<CardReader>(sources, deck, options.blanks, tracking);
  }
  const Deck read = ReadDeck(*source);
  if (tracking.seen_error()) return ast::File{deck, {}};
  ast::File file = DeckToAst(read, tracking);
  file.file = deck;
  return file;
}

}  // namespace sled::lang::legacy
