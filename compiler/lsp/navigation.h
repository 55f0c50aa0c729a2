// Go to definition, find references and the document outline, from the names the checker
// resolved (compiler::NameReference) and the document's tree.
#pragma once

#include <cstdint>

#include "compiler/lsp/analysis.h"
#include "compiler/lsp/protocol.h"

namespace sled::lsp {

// textDocument/definition: the declaration of the name under the cursor (in the document, an
// imported module or the standard library); null when there is no name there.
Json Definition(const Analysis& analysis, RangeConverter& ranges, std::uint32_t offset);

// textDocument/references: every use of the name under the cursor in the files this check read
// (and its declaration when `include_declaration`).
Json References(const Analysis& analysis, RangeConverter& ranges, std::uint32_t offset,
                bool include_declaration);

// textDocument/documentSymbol: the outline (scenario, bodies, segments, joints, contacts, ...),
// nested as the blocks are.
Json DocumentSymbols(const Analysis& analysis, RangeConverter& ranges);

}  // namespace sled::lsp
