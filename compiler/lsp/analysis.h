// One check of an open document: the document's text through sled::Compile (parse, check and
// lints; no lowering, which an editor does not need), and the lookups every request shares:
// the statement under the cursor, the block kind it sits in, the name reference there.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "compiler/check/schema.h"
#include "sled/compile.h"

namespace sled::lsp {

struct AnalysisOptions {
  std::string stdlib;                    // empty: compiler::DefaultStdlibRoot()
  std::vector<std::string> module_path;  // more folders for imports
};

// Where an offset of the document sits in the tree: the statements that enclose it, outermost
// first, and the kind of the innermost block (nullopt where the schema does not know it).
struct TreeContext {
  std::vector<const lang::ast::Statement*> statements;
  std::optional<compiler::BlockKind> block;
  bool at_top_level = true;  // the offset is in no statement's block
};

class Analysis {
 public:
  // Checks `text` as the file at `path` (imports resolve from its folder).
  Analysis(const std::string& text, const std::string& path, const AnalysisOptions& options);

  const sled::Compilation& compiled() const { return compiled_; }
  const lang::SourceManager& sources() const { return compiled_.sources(); }
  lang::FileId file() const { return file_; }
  const lang::ast::File* tree() const { return compiled_.ast(); }

  // The name reference (declaration or use) in the document whose range holds `offset`, the
  // narrowest when several do.
  const compiler::NameReference* ReferenceAt(std::uint32_t offset) const;
  // The statements around `offset` in the document's tree.
  TreeContext ContextAt(std::uint32_t offset) const;
  // The block kind a statement's block is checked as, inside a block of kind `outer`.
  static std::optional<compiler::BlockKind> BlockOpenedBy(const lang::ast::Statement& statement,
                                                          compiler::BlockKind outer);

 private:
  sled::Compilation compiled_;
  lang::FileId file_;
};

// Whether `range` is in `file` and holds `offset` (its end included: the cursor after a word
// is on it).
bool Holds(const lang::SourceRange& range, lang::FileId file, std::uint32_t offset);

}  // namespace sled::lsp
