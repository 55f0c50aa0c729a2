#include "compiler/lsp/completion.h"

#include <fmt/format.h>

#include <cctype>
#include <set>

#include "compiler/units/unit_table.h"

namespace sled::lsp {
namespace {

// The LSP CompletionItemKind numbers.
enum ItemKind {
  kFunctionItem = 3,
  kVariableItem = 6,
  kClassItem = 7,
  kModuleItem = 9,
  kPropertyItem = 10,
  kUnitItem = 11,
  kValueItem = 12,
  kKeywordItem = 14,
  kReferenceItem = 18,
  kConstantItem = 21,
  kStructItem = 22,
  kEventItem = 23,
};

bool IsWordChar(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.';
}

std::string FirstWord(std::string_view header) {
  std::size_t begin = 0;
  while (begin < header.size() && std::isspace(static_cast<unsigned char>(header[begin]))) {
    ++begin;
  }
  std::size_t end = begin;
  while (end < header.size() &&
         (std::isalnum(static_cast<unsigned char>(header[end])) || header[end] == '_')) {
    ++end;
  }
  return std::string(header.substr(begin, end - begin));
}

int ItemKindOfEntity(std::string_view kind) {
  if (kind == "segment") return kStructItem;
  if (kind == "body" || kind == "vehicle") return kClassItem;
  if (kind == "module") return kModuleItem;
  if (kind == "function") return kFunctionItem;
  if (kind == "parameter") return kConstantItem;
  if (kind == "joint") return kReferenceItem;
  return kVariableItem;
}

Json Item(std::string label, int kind, std::string detail, std::string_view documentation = {}) {
  Json item = {{"label", std::move(label)}, {"kind", kind}, {"detail", std::move(detail)}};
  if (!documentation.empty()) item["documentation"] = std::string(documentation);
  return item;
}

void AddKeywords(compiler::BlockKind kind, Json& items) {
  const compiler::BlockSpec& spec = compiler::SpecOf(kind);
  for (const compiler::AttributeSpec& attribute : spec.attributes) {
    std::string detail = std::string(compiler::BlockName(kind)) + " attribute";
    if (attribute.type == compiler::ValueType::kQuantity ||
        attribute.type == compiler::ValueType::kVector) {
      detail += ", " + compiler::DescribeDimension(attribute.dimension);
    }
    if (attribute.required) detail += ", required";
    items.push_back(Item(std::string(attribute.name), kPropertyItem, detail, attribute.doc));
  }
  for (const compiler::DeclarationSpec& declaration : spec.declarations) {
    items.push_back(
        Item(std::string(declaration.keyword), kKeywordItem, "declaration", declaration.doc));
  }
  if (kind == compiler::BlockKind::kOutput) {
    for (const compiler::OutputSpec& output : compiler::AllOutputSpecs()) {
      items.push_back(Item(std::string(output.keyword), kEventItem,
                           fmt::format("output of a {}", output.target_kind), output.doc));
    }
  }
}

void AddUnits(Json& items) {
  for (const compiler::UnitInfo& unit : compiler::AllUnits()) {
    items.push_back(Item(std::string(unit.symbol), kUnitItem,
                         compiler::DescribeDimension(unit.dimension), unit.description));
  }
}

// Names the checker declared, once each, optionally only those of the given kinds.
void AddNames(const Analysis& analysis, const std::set<std::string>& kinds, Json& items) {
  std::set<std::string> seen;
  for (const compiler::NameReference& reference : analysis.compiled().scenario().references) {
    if (!reference.is_declaration) continue;
    if (!kinds.empty() && !kinds.contains(reference.kind)) continue;
    if (!seen.insert(reference.name).second) continue;
    items.push_back(Item(reference.name, ItemKindOfEntity(reference.kind), reference.kind));
  }
}

std::set<std::string> Words(std::string_view text) {
  std::set<std::string> words;
  std::size_t i = 0;
  while (i < text.size()) {
    while (i < text.size() && text[i] == ' ') ++i;
    const std::size_t begin = i;
    while (i < text.size() && text[i] != ' ') ++i;
    if (i > begin) words.emplace(text.substr(begin, i - begin));
  }
  return words;
}

}  // namespace

BlockChain BlockChainAt(std::string_view text, std::uint32_t offset) {
  BlockChain chain;
  offset = std::min<std::uint32_t>(offset, static_cast<std::uint32_t>(text.size()));
  std::size_t statement_start = 0;  // where the current statement's text began
  bool in_string = false;
  for (std::size_t i = 0; i < offset; ++i) {
    const char c = text[i];
    if (in_string) {
      if (c == '"' || c == '\n') in_string = false;
      continue;
    }
    if (c == '"') {
      in_string = true;
    } else if (c == '/' && i + 1 < offset && text[i + 1] == '/') {
      while (i < offset && text[i] != '\n') ++i;
      statement_start = i + 1;
    } else if (c == '\n') {
      // A statement ends at a line break unless a value list goes on after a comma.
      std::size_t last = i;
      while (last > statement_start && std::isspace(static_cast<unsigned char>(text[last - 1]))) {
        --last;
      }
      if (last == statement_start || text[last - 1] != ',') statement_start = i + 1;
    } else if (c == '{') {
      const std::string_view header = text.substr(statement_start, i - statement_start);
      chain.keywords.push_back(FirstWord(header));
      chain.has_value.push_back(header.find('=') != std::string_view::npos);
      statement_start = i + 1;
    } else if (c == '}') {
      if (!chain.keywords.empty()) {
        chain.keywords.pop_back();
        chain.has_value.pop_back();
      }
      statement_start = i + 1;
    }
  }
  std::optional<compiler::BlockKind> kind = compiler::BlockKind::kFile;
  for (std::size_t i = 0; i < chain.keywords.size() && kind; ++i) {
    const std::string& keyword = chain.keywords[i];
    const compiler::DeclarationSpec* declaration = compiler::FindDeclaration(*kind, keyword);
    if (!declaration && i == 0) {
      declaration = compiler::FindDeclaration(compiler::BlockKind::kModule, keyword);
    }
    if (declaration) {
      kind = declaration->opens;
    } else if (chain.has_value[i]) {
      kind = compiler::BlockKind::kTable;
    } else {
      kind = std::nullopt;
    }
  }
  chain.kind = kind;
  return chain;
}

Json Completions(const Analysis& analysis, std::string_view text, std::uint32_t offset) {
  Json items = Json::array();
  offset = std::min<std::uint32_t>(offset, static_cast<std::uint32_t>(text.size()));
  // The word being typed, and what comes before it on its line.
  std::size_t word_begin = offset;
  while (word_begin > 0 && IsWordChar(text[word_begin - 1])) --word_begin;
  std::size_t line_begin = text.rfind('\n', word_begin == 0 ? 0 : word_begin - 1);
  line_begin = line_begin == std::string_view::npos || word_begin == 0 ? 0 : line_begin + 1;
  std::string_view before = text.substr(line_begin, word_begin - line_begin);
  // In a one-line block, the statement begins after the last brace.
  if (const std::size_t brace = before.find_last_of("{}"); brace != std::string_view::npos) {
    before = before.substr(brace + 1);
  }
  std::size_t end = before.size();
  while (end > 0 && before[end - 1] == ' ') --end;
  const std::string_view trimmed = before.substr(0, end);
  const bool spaced = end < before.size();

  // A unit: after a number, a closing parenthesis of a vector, or a unit operator.
  if (!trimmed.empty()) {
    const char last = trimmed.back();
    const bool after_number =
        spaced && (std::isdigit(static_cast<unsigned char>(last)) || last == ')' || last == '.');
    const bool in_unit = !spaced && (last == '*' || last == '/') && trimmed.size() >= 2 &&
                         std::isalpha(static_cast<unsigned char>(trimmed[trimmed.size() - 2]));
    // `) ` also ends a call (`half_sine(...) `), where no unit follows; a vector's `)` has
    // numbers before it, which a unit needs anyway.
    if (after_number || in_unit) {
      AddUnits(items);
      return items;
    }
  }

  const BlockChain chain = BlockChainAt(text, static_cast<std::uint32_t>(word_begin));
  // The start of a statement: the block's keywords.
  if (trimmed.find_first_not_of(" \t") == std::string_view::npos) {
    if (chain.kind) AddKeywords(*chain.kind, items);
    return items;
  }

  // In a value: what the statement's keyword takes.
  const std::string keyword = FirstWord(trimmed);
  const compiler::AttributeSpec* attribute =
      chain.kind ? compiler::FindAttribute(*chain.kind, keyword) : nullptr;
  if (keyword == "criteria" || (attribute && attribute->type == compiler::ValueType::kCriteria)) {
    for (const compiler::CriterionSpec& criterion : compiler::AllCriterionSpecs()) {
      items.push_back(Item(std::string(criterion.name), kFunctionItem,
                           fmt::format("criterion of a {}", criterion.target_kind), criterion.doc));
    }
    AddNames(analysis, {"segment", "joint"}, items);
    return items;
  }
  if (attribute && attribute->type == compiler::ValueType::kWord) {
    for (const std::string& word : Words(attribute->choices)) {
      items.push_back(Item(word, kValueItem, std::string(attribute->name)));
    }
    return items;
  }
  std::set<std::string> kinds;
  if (attribute && (attribute->type == compiler::ValueType::kReference ||
                    attribute->type == compiler::ValueType::kReferences)) {
    kinds = Words(attribute->choices);
  }
  AddNames(analysis, kinds, items);
  if (attribute && attribute->type == compiler::ValueType::kBool) {
    items.push_back(Item("true", kValueItem, "bool"));
    items.push_back(Item("false", kValueItem, "bool"));
  }
  return items;
}

}  // namespace sled::lsp
