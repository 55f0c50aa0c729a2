#include "lang/legacy/convert.h"

#include "lang/legacy/ain_reader.h"
#include "lang/legacy/card_reader.h"

namespace sled::lang::legacy {

ast::File ConvertAinDeck(const SourceManager& sources, FileId deck, const ConvertOptions& options) {
  ErrorTrackingConsumer tracking(*options.diagnostics);
  CardReader reader(sources, deck, options.blanks, tracking);
  const Deck read = ReadAinDeck(reader);
  if (tracking.seen_error()) return ast::File{deck, {}};
  ast::File file = DeckToAst(read, tracking);
  file.file = deck;
  return file;
}

}  // namespace sled::lang::legacy
