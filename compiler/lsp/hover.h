// textDocument/hover: what the thing under the cursor is and means. A number with a unit shows
// its value in SI; a name shows what it resolved to (a segment's mass and inertia, a joint's
// segments, a parameter's current value) and where it was declared, with that line of source
// (an imported definition's file); a keyword shows its schema entry (dimension, what it does).
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "compiler/lsp/analysis.h"

namespace sled::lsp {

struct HoverResult {
  std::string markdown;
  lang::SourceRange range;  // in the document
};

std::optional<HoverResult> Hover(const Analysis& analysis, std::uint32_t offset);

}  // namespace sled::lsp
