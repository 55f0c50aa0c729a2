#include "compiler/lsp/navigation.h"

#include <set>
#include <tuple>

namespace sled::lsp {
namespace {

namespace ast = lang::ast;

// The LSP SymbolKind numbers.
enum SymbolKind {
  kFile = 1,
  kModule = 2,
  kNamespace = 3,
  kClass = 5,
  kField = 8,
  kFunction = 12,
  kVariable = 13,
  kConstant = 14,
  kObject = 19,
  kEvent = 24,
  kStruct = 23,
};

int SymbolKindOf(std::string_view keyword) {
  if (keyword == "scenario") return kNamespace;
  if (keyword == "import") return kModule;
  if (keyword == "body" || keyword == "vehicle") return kClass;
  if (keyword == "segment") return kStruct;
  if (keyword == "function") return kFunction;
  if (keyword == "param") return kConstant;
  if (keyword == "let") return kVariable;
  if (keyword == "contact" || keyword == "output") return kEvent;
  return kObject;
}

// Statements that make the outline: declarations with a name, and blocks.
bool IsOutlined(const ast::Statement& statement) {
  if (statement.kind != ast::StatementKind::kHeader) return false;
  if (statement.keyword == "import" || statement.keyword == "param" || statement.keyword == "let" ||
      statement.keyword == "function") {
    return statement.target.has_value();
  }
  return statement.block != nullptr && (statement.target.has_value() || !statement.has_value);
}

std::string SymbolName(const ast::Statement& statement) {
  if (!statement.target) return statement.keyword;
  // `import std.humans.male50 as occupant`: the scene knows it as its alias.
  if (const ast::Clause* as = statement.FindClause("as")) return as->value.PathText();
  if (statement.target->kind == ast::ExprKind::kString) return statement.target->text;
  std::string name = statement.target->PathText();
  // `contact occupant.head with windshield`: the pair is its name.
  if (const ast::Clause* with = statement.FindClause("with")) {
    name += " with " + with->value.PathText();
  }
  return name;
}

Json SymbolsOf(const ast::Block& block, RangeConverter& ranges, int depth) {
  Json symbols = Json::array();
  constexpr int kMaxDepth = 64;  // the parser's own nesting limit
  if (depth > kMaxDepth) return symbols;
  for (const ast::Statement& statement : block.statements) {
    if (!IsOutlined(statement) || !statement.range.valid()) continue;
    Json symbol = {
        {"name", SymbolName(statement)},
        {"detail", statement.keyword},
        {"kind", SymbolKindOf(statement.keyword)},
        {"range", RangeJson(ranges.RangeOf(statement.range))},
        {"selectionRange", RangeJson(ranges.RangeOf(statement.target ? statement.target->range
                                                                     : statement.keyword_range))}};
    if (statement.block) {
      Json children = SymbolsOf(*statement.block, ranges, depth + 1);
      if (!children.empty()) symbol["children"] = std::move(children);
    }
    symbols.push_back(std::move(symbol));
  }
  return symbols;
}

// A declaration's identity across the buffers of one compilation.
using DeclarationKey = std::tuple<std::uint32_t, std::uint32_t, std::uint32_t>;
DeclarationKey KeyOf(const lang::SourceRange& range) {
  return {range.file.value, range.begin, range.end};
}

}  // namespace

Json Definition(const Analysis& analysis, RangeConverter& ranges, std::uint32_t offset) {
  const compiler::NameReference* reference = analysis.ReferenceAt(offset);
  if (!reference || !reference->declaration.valid()) return nullptr;
  return ranges.LocationOf(reference->declaration);
}

Json References(const Analysis& analysis, RangeConverter& ranges, std::uint32_t offset,
                bool include_declaration) {
  const compiler::NameReference* target = analysis.ReferenceAt(offset);
  if (!target) return Json::array();
  const DeclarationKey declaration = KeyOf(target->declaration);
  // An imported body checked twice records its names twice: report each place once.
  std::set<DeclarationKey> seen;
  Json locations = Json::array();
  for (const compiler::NameReference& reference : analysis.compiled().scenario().references) {
    if (KeyOf(reference.declaration) != declaration) continue;
    if (reference.is_declaration && !include_declaration) continue;
    if (!seen.insert(KeyOf(reference.use)).second) continue;
    locations.push_back(ranges.LocationOf(reference.use));
  }
  return locations;
}

Json DocumentSymbols(const Analysis& analysis, RangeConverter& ranges) {
  if (!analysis.tree()) return Json::array();
  return SymbolsOf(analysis.tree()->body, ranges, 0);
}

}  // namespace sled::lsp
