// The concrete syntax tree the PEGTL control builds while parsing: one node per selected rule,
// with byte offsets into the buffer. syntax_to_ast.cpp turns it into the AST; the parser then
// drops it.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

namespace sled::lang::syntax {

enum class NodeType : std::uint8_t {
  kNone,
  kHeader,
  kRow,
  kKeyword,
  kTarget,
  kWordClause,
  kColonClause,
  kClauseWord,
  kStatementValue,
  kBlock,
  kArrow,
  kSum,
  kProduct,
  kPower,
  kNegate,
  kOperator,
  kQuantity,
  kNumber,
  kUnit,
  kUnitSymbol,
  kUnitPower,
  kUnitDivide,
  kVector,  // also a parenthesised value: one element, no trailing comma, no unit
  kTupleComma,
  kCall,
  kNamedArgument,
  kArgumentName,
  kPositionalArgument,
  kPath,
  kString,
  kBoolean,
};

struct Node {
  NodeType type = NodeType::kNone;
  std::uint32_t begin = 0;
  std::uint32_t end = 0;
  std::vector<std::unique_ptr<Node>> children;
};

}  // namespace sled::lang::syntax
