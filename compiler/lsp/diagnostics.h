// The checker's diagnostics as LSP diagnostics, published per file (the document's own, and
// those an import of it has), and the code actions of the diagnostics that carry a fix.
#pragma once

#include <map>
#include <string>

#include "compiler/lsp/analysis.h"
#include "compiler/lsp/protocol.h"

namespace sled::lsp {

// Where a diagnostic code's long explanation (what `sled explain CODE` prints) can be opened:
// the docs/diagnostics page of the source tree beside the standard library when there is one,
// else the embedded page written once into a folder under the system's temporary folder.
class ExplainLinks {
 public:
  // A file:// URI, or empty when the code has no page.
  std::string LinkOf(std::string_view code);

 private:
  std::map<std::string, std::string, std::less<>> links_;
};

// Every diagnostic of the check, grouped by the URI of its file (the document's diagnostics
// under its own URI, always present, possibly empty).
std::map<std::string, Json> DiagnosticsByUri(const Analysis& analysis, RangeConverter& ranges,
                                             ExplainLinks& links);

// textDocument/codeAction: a quick fix for each diagnostic in `range` whose help suggests
// names ("did you mean `pelvis`?", "one of: `ball`, `pin`"), replacing the misspelled word.
Json CodeActions(const Analysis& analysis, RangeConverter& ranges, const std::string& uri,
                 std::uint32_t begin, std::uint32_t end, ExplainLinks& links);

}  // namespace sled::lsp
