// The list-directed `.lin` source: the same cards as an `.ain` deck, read the way a Fortran
// list-directed READ (`READ (unit, *)`) reads them. Items are separated by blanks or a comma;
// strings stand in double quotes or apostrophes (a doubled quote inside is one quote); `r*value`
// repeats a value and `r*` gives r null values; two commas in a row give a null value; `/` ends
// the READ, and every item not yet read keeps its default (zero, or blank text). One READ takes
// as many lines as its items need; whatever follows its last item on its last line is ignored
// (ATB's converter writes labels such as `Card B.2.a` there). A blank line holds no items, so a
// READ goes on to the next line; `#` lines are comments, as in `.ain` decks.
#pragma once

#include <string>
#include <vector>

#include "lang/legacy/deck_source.h"

namespace sled::lang::legacy {

class ListReader final : public DeckSource {
 public:
  ListReader(const SourceManager& sources, FileId file, DiagnosticConsumer& diagnostics);

  Card Next(std::string label, const CardSpec& spec) override;
  void Extend(Card& card, int items) override;
  double Real(const Card& card, int first, int last, std::string_view what) override;
  int Integer(const Card& card, int first, int last, std::string_view what) override;
  std::string Text(const Card& card, int first, int last) override;
  SourceRange Range(const Card& card, int first, int last) const override;
  std::string Where(const Card& card, int first, int last) const override;

 private:
  struct Item {
    enum class State { kValue, kString, kNull, kBad } state = State::kNull;
    std::string text;                  // a value's characters, a string's contents
    std::uint32_t begin = 0, end = 0;  // offsets in the file; begin == end: nothing was read
  };

  std::size_t NextUnreadLine() const override;
  std::string_view PlacementHint() const override;

  // Reads `count` items of the current READ into the store.
  void ReadItems(Card& card, int count);
  Item ReadItem(const Card& card, int number);
  // Moves to the next character that is not a blank, across line ends (skipping comment lines);
  // false at the end of the deck.
  bool SkipBlanks();
  bool AtLineEnd() const;
  char Current() const { return lines_[line_].text[column_]; }
  std::uint32_t Offset() const {
    return lines_[line_].offset + static_cast<std::uint32_t>(column_);
  }
  // The 0-based item of the field at these columns (-1 when the field is not an item).
  int ItemNumber(const Card& card, int field) const;
  const Item* ItemAt(const Card& card, int first, int last);
  // The item of the field as a number (a whole one when `integer`); a bad one is reported and
  // reads as zero, an empty one as zero.
  double Number(const Card& card, int first, int last, std::string_view what, bool integer);
  // The items whose fields lie within `first`..`last`, as 0-based numbers [low, high].
  bool ItemsWithin(const Card& card, int first, int last, int* low, int* high) const;

  std::vector<Item> items_;
  std::size_t line_ = 0;  // the reading position
  std::size_t column_ = 0;
  bool started_ = false;            // a READ has taken something from line_
  bool separator_pending_ = false;  // a value was read: one comma may follow as its separator
  bool slash_ = false;              // the current READ met `/`
  int repeat_left_ = 0;             // items still to give from an `r*` repeat
  Item repeat_item_;
};

}  // namespace sled::lang::legacy
