// Where the card reader gets its fields: the lines of a deck, read either by column (`.ain`,
// CardReader) or list-directed (`.lin`, ListReader). The card groups are read once, in
// deck_reader.cpp, through this interface; every card declares its fields by its Fortran FORMAT
// (CardSpec), which gives the fixed-column reader the columns and the list-directed reader the
// order of the items.
//
// Comment lines (first non-blank character `#`) may stand anywhere and are skipped. Every problem
// is reported as a diagnostic that names the file, line, card and columns (of the field on an
// `.ain` card, of the item on a `.lin` line). At the end of the deck a card asked for is reported
// once (E0501) and read as blank, so the reader can go on without special cases; `truncated()`
// tells loops that have no count to stop.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "lang/diagnostics/diagnostic.h"
#include "lang/legacy/card_format.h"
#include "lang/legacy/fortran_field.h"
#include "lang/source/source_manager.h"

namespace sled::lang::legacy {

struct Card {
  std::uint32_t line = 0;  // 1-based; 0 when the deck ended before it
  std::string_view text;   // the line (a `.lin` READ's first line), without the terminator
  std::string label;       // such as "B.2.a (segment 3)"
  const std::vector<FieldSpan>* fields = nullptr;
  int ain_only_column = 0;
  // List-directed cards: this record's items in the reader's store, and where its READ stopped.
  std::uint32_t first_item = 0;
  int item_count = 0;
  std::uint32_t end_offset = 0;
};

class DeckSource {
 public:
  DeckSource(const SourceManager& sources, FileId file, BlankMode blanks,
             DiagnosticConsumer& diagnostics);
  virtual ~DeckSource() = default;
  DeckSource(const DeckSource&) = delete;
  DeckSource& operator=(const DeckSource&) = delete;

  // The next card (one record of a READ), labelled for messages.
  virtual Card Next(std::string label, const CardSpec& spec) = 0;
  // `items` more items of the same READ, whose count an earlier item gave (F.6's NK pairs). The
  // fixed-column card already holds them in its columns.
  virtual void Extend(Card& card, int items) = 0;

  // Fields by their declared 1-based inclusive columns; `what` says what the field holds
  // ("WEIGHT, the segment's weight"). A bad field is reported and reads as zero.
  virtual double Real(const Card& card, int first, int last, std::string_view what) = 0;
  virtual int Integer(const Card& card, int first, int last, std::string_view what) = 0;
  virtual std::string Text(const Card& card, int first, int last) = 0;

  // The source range of the fields within columns `first`..`last`, for diagnostics, and how a
  // message names them ("columns 13-18" on a fixed-column card, "item 3" on a list-directed one).
  virtual SourceRange Range(const Card& card, int first, int last) const = 0;
  virtual std::string Where(const Card& card, int first, int last) const = 0;

  // True when only comment lines and blank lines remain.
  bool OnlyBlankLinesRemain() const;

  SourceRange EndOfDeck() const;
  void Report(DiagnosticKind kind, const Card& card, int first, int last, std::string message,
              std::string help = {});
  void ReportAt(DiagnosticKind kind, SourceRange range, std::string message, std::string help = {});

  bool truncated() const { return truncated_; }
  bool has_errors() const { return errors_ > 0; }
  BlankMode blanks() const { return blanks_; }
  std::uint32_t line_count() const { return static_cast<std::uint32_t>(lines_.size()); }

 protected:
  struct Line {
    std::uint32_t offset = 0;
    std::string_view text;
  };
  bool IsComment(std::size_t index) const;
  // The first line the next card may come from.
  virtual std::size_t NextUnreadLine() const = 0;
  // Reports E0501 once; `what` names what was missing ("card B.2.a").
  void ReportTruncated(const std::string& what);
  // The declared field at exactly these columns, or -1 (reported: a reader bug, not bad input).
  int FieldIndex(const Card& card, int first, int last);
  // A numeric field that did not read: E0502 or E0503 with what the field should hold.
  void ReportBadNumber(const Card& card, int first, int last, std::string_view what,
                       std::string_view found, FieldProblem problem, bool integer);
  virtual std::string_view PlacementHint() const = 0;

  FileId file_;
  std::uint32_t size_ = 0;
  BlankMode blanks_;
  DiagnosticConsumer& diagnostics_;
  std::vector<Line> lines_;
  bool truncated_ = false;
  int errors_ = 0;
};

// `first`..`last` as a message names columns: "column 7" or "columns 7-12".
std::string ColumnsText(int first, int last);

}  // namespace sled::lang::legacy
