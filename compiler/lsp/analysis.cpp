#include "compiler/lsp/analysis.h"

namespace sled::lsp {
namespace {

sled::Compilation CompileDocument(const std::string& text, const std::string& path,
                                  const AnalysisOptions& options) {
  sled::CompileOptions compile_options;
  compile_options.stdlib = options.stdlib;
  compile_options.module_path = options.module_path;
  compile_options.lower = false;
  return sled::Compile(sled::Source::Text(text, path), compile_options);
}

}  // namespace

bool Holds(const lang::SourceRange& range, lang::FileId file, std::uint32_t offset) {
  return range.file == file && range.begin <= offset && offset <= range.end;
}

Analysis::Analysis(const std::string& text, const std::string& path, const AnalysisOptions& options)
    : compiled_(CompileDocument(text, path, options)),
      file_(compiled_.ast() ? compiled_.ast()->file : lang::FileId{1}) {}

const compiler::NameReference* Analysis::ReferenceAt(std::uint32_t offset) const {
  const compiler::NameReference* best = nullptr;
  for (const compiler::NameReference& reference : compiled_.scenario().references) {
    if (!Holds(reference.use, file_, offset)) continue;
    if (!best || reference.use.size() < best->use.size()) best = &reference;
  }
  return best;
}

std::optional<compiler::BlockKind> Analysis::BlockOpenedBy(const lang::ast::Statement& statement,
                                                           compiler::BlockKind outer) {
  if (const compiler::DeclarationSpec* declaration =
          compiler::FindDeclaration(outer, statement.keyword)) {
    return declaration->opens;
  }
  // Attributes that take a block: a table function's rows (`force = table(...) { ... }`).
  if (statement.has_value) return compiler::BlockKind::kTable;
  return std::nullopt;
}

TreeContext Analysis::ContextAt(std::uint32_t offset) const {
  TreeContext context;
  const lang::ast::File* file = tree();
  if (!file) return context;
  bool has_scenario = false;
  for (const lang::ast::Statement& statement : file->body.statements) {
    has_scenario |= statement.keyword == "scenario";
  }
  std::optional<compiler::BlockKind> kind =
      has_scenario ? compiler::BlockKind::kFile : compiler::BlockKind::kModule;
  const lang::ast::Block* block = &file->body;
  while (block) {
    const lang::ast::Block* inner = nullptr;
    for (const lang::ast::Statement& statement : block->statements) {
      if (!Holds(statement.range, file_, offset)) continue;
      context.statements.push_back(&statement);
      // Inside the braces of its block: the cursor is in that block's kind.
      if (statement.block && statement.block->range.begin < offset &&
          offset < statement.block->range.end + (statement.block->range.size() > 0 ? 0 : 1)) {
        inner = statement.block.get();
        kind = kind ? BlockOpenedBy(statement, *kind) : std::nullopt;
        context.at_top_level = false;
      }
      break;
    }
    block = inner;
  }
  context.block = kind;
  return context;
}

}  // namespace sled::lsp
