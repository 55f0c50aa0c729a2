// The cards of a fixed-column deck, one line each, with the fields read by column and every
// problem reported as a diagnostic that names the file, line, card and columns.
//
// Comment lines (first non-blank character `#`) may stand anywhere and are skipped; an all-blank
// line is a card like any other (zeros in old decks), never swallowed. At the end of the deck a
// card asked for is reported once (E0501) and read as blank, so the reader can go on without
// special cases; `truncated()` tells loops that have no count to stop.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "lang/diagnostics/diagnostic.h"
#include "lang/legacy/fortran_field.h"
#include "lang/source/source_manager.h"

namespace sled::lang::legacy {

struct Card {
  std::uint32_t line = 0;  // 1-based; 0 when the deck ended before it
  std::string_view text;   // without the line terminator
  std::string label;       // such as "B.2.a (segment 3)"
};

class CardReader {
 public:
  CardReader(const SourceManager& sources, FileId file, BlankMode blanks,
             DiagnosticConsumer& diagnostics);

  // The next card, labelled for messages.
  Card Next(std::string label);
  // True when only comment lines and blank lines remain.
  bool OnlyBlankLinesRemain() const;
  // The next non-comment line's text, without consuming it (empty at the end).
  std::string_view Peek() const;

  // Fields by 1-based inclusive columns; `what` says what the field holds ("WEIGHT, the segment's
  // weight"). A bad field is reported and reads as zero.
  double Real(const Card& card, int first, int last, std::string_view what);
  int Integer(const Card& card, int first, int last, std::string_view what);
  std::string Text(const Card& card, int first, int last) const;
  bool Blank(const Card& card, int first, int last) const;

  // The range of a field on its card (clamped to the line), for diagnostics.
  SourceRange Range(const Card& card, int first, int last) const;
  SourceRange EndOfDeck() const;
  void Report(DiagnosticKind kind, const Card& card, int first, int last, std::string message,
              std::string help = {});
  void ReportAt(DiagnosticKind kind, SourceRange range, std::string message, std::string help = {});

  bool truncated() const { return truncated_; }
  bool has_errors() const { return errors_ > 0; }
  BlankMode blanks() const { return blanks_; }
  std::uint32_t line_count() const { return static_cast<std::uint32_t>(lines_.size()); }

 private:
  struct Line {
    std::uint32_t offset = 0;
    std::string_view text;
  };
  bool IsComment(std::size_t index) const;
  std::string_view Columns(const Card& card, int first, int last) const;

  FileId file_;
  std::uint32_t size_ = 0;
  BlankMode blanks_;
  DiagnosticConsumer& diagnostics_;
  std::vector<Line> lines_;
  std::size_t next_ = 0;
  bool truncated_ = false;
  int errors_ = 0;
};

}  // namespace sled::lang::legacy
