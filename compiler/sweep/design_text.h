// The small grammar of a design's values, shared by `--vary` texts and CSV design files:
//
//   vary     = NAME "=" values
//   values   = quantity ".." quantity [("step" quantity) | ("count" INTEGER)]   a range
//            | quantity {"," quantity}                                          a list
//   quantity = NUMBER [UNIT]                  (a unit as in .sled files: km/h, N*m/deg, m/s^2)
//
// A range with `step` or `count` is a grid of values; one without is sampled (--sample).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "lang/ast/ast.h"
#include "lang/diagnostics/diagnostic.h"
#include "lang/source/source_manager.h"

namespace sled::compiler {

// A number as written, with its unit when one follows it.
struct WrittenQuantity {
  double number = 0.0;
  std::optional<lang::ast::Unit> unit;
  lang::SourceRange range;  // the number and its unit
};

struct VarySpec {
  enum class Kind { kList, kStep, kCount, kInterval };
  std::string name;
  lang::SourceRange name_range;
  lang::SourceRange values_range;  // everything after `=`
  Kind kind = Kind::kList;
  std::vector<WrittenQuantity> values;  // kList: every value; a range: its two ends
  std::optional<WrittenQuantity> step;  // kStep
  long long count = 0;                  // kCount
  lang::SourceRange count_range;
};

// Reads characters of one buffer from an offset, for the design parsers.
class DesignScanner {
 public:
  DesignScanner(const lang::SourceManager& sources, lang::FileId file, std::uint32_t begin,
                std::uint32_t end);

  void SkipSpaces();
  bool AtEnd() const { return at_ >= end_; }
  std::uint32_t at() const { return at_; }
  char Peek(std::uint32_t ahead = 0) const;
  bool Consume(std::string_view text);  // true (and moves past it) when the text comes next
  // A keyword: the word followed by a space or the end.
  bool ConsumeWord(std::string_view word);
  std::optional<std::string> Name();  // [A-Za-z_][A-Za-z0-9_]*
  std::optional<double> Number();     // -12.5e3; never eats the first `.` of `..`
  std::optional<lang::ast::Unit> Unit();
  // A number with an optional unit after optional spaces.
  std::optional<WrittenQuantity> Quantity();
  lang::SourceRange Range(std::uint32_t from) const { return {file_, from, at_}; }
  lang::SourceRange Here() const;  // the next character, or the end
  // What comes next, for a message: "`x`" or "the end".
  std::string Found() const;

 private:
  std::string_view text_;
  lang::FileId file_;
  std::uint32_t at_;
  std::uint32_t end_;
};

// Parses a whole `--vary` text; reports E0601 and returns nullopt when it is malformed.
std::optional<VarySpec> ParseVary(const lang::SourceManager& sources, lang::FileId file,
                                  lang::DiagnosticConsumer& diagnostics);

// Reports a design diagnostic (E0601 to E0605) at `range`.
void ReportDesign(lang::DiagnosticConsumer& diagnostics, lang::DiagnosticKind kind,
                  lang::SourceRange range, std::string message, std::string label,
                  std::string help);

}  // namespace sled::compiler
