// textDocument/completion. What is offered depends on where the cursor is, read from the text
// itself (a statement being typed rarely parses): at the start of a statement, the keywords the
// enclosing block allows (attributes from the schema, declarations, output requests); after a
// number or a vector, unit symbols; after `=` of a word attribute, its choices; elsewhere in a
// value, the names the checker declared (segments, surfaces, functions, parameters) and, in
// `criteria`, the injury criteria.
#pragma once

#include <cstdint>
#include <string_view>

#include "compiler/lsp/analysis.h"
#include "compiler/lsp/protocol.h"

namespace sled::lsp {

// The enclosing blocks at `offset` of `text`, outermost first, as the keyword of each block's
// header (`segment`, `time`, a table attribute's name), skipping comments and strings; and the
// block kind of the innermost one (nullopt when the schema does not know it).
struct BlockChain {
  std::vector<std::string> keywords;
  std::vector<bool> has_value;  // the header had `=` (an attribute with a table block)
  std::optional<compiler::BlockKind> kind;
};
BlockChain BlockChainAt(std::string_view text, std::uint32_t offset);

// The completion list (a JSON array of CompletionItem).
Json Completions(const Analysis& analysis, std::string_view text, std::uint32_t offset);

}  // namespace sled::lsp
