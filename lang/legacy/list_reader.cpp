#include "lang/legacy/list_reader.h"

#include <algorithm>
#include <cctype>
#include <utility>

#include <fmt/format.h>

namespace sled::lang::legacy {
namespace {

bool IsBlank(char c) { return c == ' ' || c == '\t' || c == '\r'; }
bool EndsValue(char c) { return IsBlank(c) || c == ',' || c == '/'; }

}  // namespace

ListReader::ListReader(const SourceManager& sources, FileId file, DiagnosticConsumer& diagnostics)
    : DeckSource(sources, file, BlankMode::kIgnore, diagnostics) {}

std::size_t ListReader::NextUnreadLine() const { return started_ ? line_ + 1 : line_; }

std::string_view ListReader::PlacementHint() const {
  return "separate the items by blanks or commas and check that no item before it is missing, "
         "split or unquoted";
}

bool ListReader::AtLineEnd() const {
  return line_ >= lines_.size() || column_ >= lines_[line_].text.size();
}

bool ListReader::SkipBlanks() {
  while (line_ < lines_.size()) {
    const std::string_view text = lines_[line_].text;
    if (column_ == 0 && IsComment(line_)) {
      ++line_;
      continue;
    }
    while (column_ < text.size() && IsBlank(text[column_])) ++column_;
    if (column_ < text.size()) return true;
    ++line_;
    column_ = 0;
  }
  return false;
}

Card ListReader::Next(std::string label, const CardSpec& spec) {
  if (!spec.continues) {
    if (repeat_left_ > 0) {
      ReportAt(DiagnosticKind::kDeckBadListItem, {file_, repeat_item_.begin, repeat_item_.end},
               fmt::format("the repeat count gives {} more value{} than its READ takes",
                           repeat_left_, repeat_left_ == 1 ? "" : "s"),
               "a repeat `r*value` stays within one card's items; lower the count");
      repeat_left_ = 0;
    }
    // A new READ starts on a new line: the rest of the previous one's last line is ignored.
    if (started_) {
      ++line_;
      column_ = 0;
      started_ = false;
    }
    slash_ = false;
    separator_pending_ = false;
  }
  Card card;
  card.label = std::move(label);
  card.fields = &FieldsOf(spec.fortran);
  card.ain_only_column = spec.ain_only_column;
  card.first_item = static_cast<std::uint32_t>(items_.size());
  int count = spec.items;
  if (count < 0) {
    count = static_cast<int>(card.fields->size());
    if (spec.ain_only_column != 0) --count;
  }
  ReadItems(card, count);
  if (card.line == 0 && !truncated_ && line_ < lines_.size()) {
    card.line = static_cast<std::uint32_t>(line_ + 1);  // a READ that took nothing (all after `/`)
  }
  if (card.line != 0) card.text = lines_[card.line - 1].text;
  return card;
}

void ListReader::Extend(Card& card, int items) {
  if (card.first_item + static_cast<std::uint32_t>(card.item_count) != items_.size()) return;
  ReadItems(card, items);
}

void ListReader::ReadItems(Card& card, int count) {
  for (int k = 0; k < count; ++k) {
    Item item = ReadItem(card, card.item_count + k);
    if (card.line == 0 && item.end > item.begin) card.line = static_cast<std::uint32_t>(line_ + 1);
    items_.push_back(std::move(item));
  }
  card.item_count += count;
  card.end_offset = line_ < lines_.size() ? Offset() : size_;
}

ListReader::Item ListReader::ReadItem(const Card& card, int number) {
  Item item;
  if (slash_ || truncated_) return item;
  if (repeat_left_ > 0) {
    --repeat_left_;
    return repeat_item_;
  }
  if (!SkipBlanks()) {
    ReportTruncated(fmt::format("item {} of card {}", number + 1, card.label));
    return item;
  }
  started_ = true;
  if (separator_pending_) {
    separator_pending_ = false;
    if (Current() == ',') {
      ++column_;
      if (!SkipBlanks()) {
        ReportTruncated(fmt::format("item {} of card {}", number + 1, card.label));
        return item;
      }
    }
  }
  const std::string_view text = lines_[line_].text;
  item.begin = Offset();
  const char c = Current();
  if (c == ',') {  // an empty value between two separators
    ++column_;
    item.end = item.begin + 1;
    return item;
  }
  if (c == '/') {
    slash_ = true;
    ++column_;
    return Item{};
  }
  separator_pending_ = true;
  // The repeat count of `r*value` or `r*`.
  std::size_t digits = column_;
  while (digits < text.size() && std::isdigit(static_cast<unsigned char>(text[digits]))) ++digits;
  int repeat = 1;
  if (digits > column_ && digits < text.size() && text[digits] == '*') {
    const std::string_view count = text.substr(column_, digits - column_);
    repeat = count.size() > 6 ? 0 : std::stoi(std::string(count));
    column_ = digits + 1;
    if (repeat == 0) {
      ReportAt(DiagnosticKind::kDeckBadListItem, {file_, item.begin, Offset()},
               fmt::format("card {}, item {}: the repeat count `{}*` is not a positive number "
                           "below a million",
                           card.label, number + 1, count),
               "write `r*value` with r from 1, or give the values one by one");
      repeat = 1;
    }
    if (AtLineEnd() || EndsValue(Current())) {  // `r*`: r null values
      item.end = Offset();
      item.state = Item::State::kNull;
      repeat_item_ = item;
      repeat_left_ = repeat - 1;
      return item;
    }
  }
  const char open = Current();
  if (open == '"' || open == '\'') {
    ++column_;
    std::string contents;
    bool closed = false;
    while (column_ < text.size()) {
      const char ch = text[column_++];
      if (ch != open) {
        contents += ch;
      } else if (column_ < text.size() && text[column_] == open) {
        contents += open;  // a doubled quote is one quote
        ++column_;
      } else {
        closed = true;
        break;
      }
    }
    item.end = Offset();
    if (!closed) {
      ReportAt(DiagnosticKind::kDeckBadListItem, {file_, item.begin, item.end},
               fmt::format("card {}, item {}: the string is not closed on its line", card.label,
                           number + 1),
               fmt::format("end the string with {} before the end of the line", open));
      item.state = Item::State::kBad;
    } else {
      item.state = Item::State::kString;
      item.text = std::move(contents);
    }
  } else {
    const std::size_t start = column_;
    while (column_ < text.size() && !EndsValue(text[column_])) ++column_;
    item.end = Offset();
    item.state = Item::State::kValue;
    item.text = std::string(text.substr(start, column_ - start));
  }
  if (repeat > 1) {
    repeat_item_ = item;
    repeat_left_ = repeat - 1;
  }
  return item;
}

int ListReader::ItemNumber(const Card& card, int field) const {
  const FieldSpan& span = (*card.fields)[static_cast<std::size_t>(field)];
  if (card.ain_only_column == 0) return field;
  if (span.first == card.ain_only_column) return -1;
  return span.first > card.ain_only_column ? field - 1 : field;
}

const ListReader::Item* ListReader::ItemAt(const Card& card, int first, int last) {
  const int field = FieldIndex(card, first, last);
  if (field < 0) return nullptr;
  const int number = ItemNumber(card, field);
  if (number < 0 || number >= card.item_count) return nullptr;
  return &items_[card.first_item + static_cast<std::uint32_t>(number)];
}

double ListReader::Number(const Card& card, int first, int last, std::string_view what,
                          bool integer) {
  const Item* item = ItemAt(card, first, last);
  if (item == nullptr) return 0.0;
  if (item->state == Item::State::kString) {
    ReportBadNumber(card, first, last, what, fmt::format("\"{}\"", item->text),
                    FieldProblem::kNotANumber, integer);
    return 0.0;
  }
  if (item->state != Item::State::kValue) return 0.0;
  const FieldValue value = integer ? ReadIntegerField(item->text, BlankMode::kIgnore)
                                   : ReadRealField(item->text, BlankMode::kIgnore);
  if (value.problem == FieldProblem::kNone) return value.number;
  ReportBadNumber(card, first, last, what, item->text, value.problem, integer);
  return 0.0;
}

double ListReader::Real(const Card& card, int first, int last, std::string_view what) {
  return Number(card, first, last, what, false);
}

int ListReader::Integer(const Card& card, int first, int last, std::string_view what) {
  return static_cast<int>(Number(card, first, last, what, true));
}

std::string ListReader::Text(const Card& card, int first, int last) {
  const Item* item = ItemAt(card, first, last);
  if (item == nullptr) return {};
  if (item->state != Item::State::kString && item->state != Item::State::kValue) return {};
  const std::size_t begin = item->text.find_first_not_of(' ');
  const std::size_t end = item->text.find_last_not_of(' ');
  return begin == std::string::npos ? std::string() : item->text.substr(begin, end - begin + 1);
}

bool ListReader::ItemsWithin(const Card& card, int first, int last, int* low, int* high) const {
  *low = -1;
  *high = -1;
  if (card.fields == nullptr) return false;
  for (std::size_t f = 0; f < card.fields->size(); ++f) {
    const FieldSpan& span = (*card.fields)[f];
    if (span.last < first || span.first > last) continue;
    const int number = ItemNumber(card, static_cast<int>(f));
    if (number < 0 || number >= card.item_count) continue;
    if (*low < 0) *low = number;
    *high = number;
  }
  return *low >= 0;
}

SourceRange ListReader::Range(const Card& card, int first, int last) const {
  int low = 0, high = 0;
  std::uint32_t begin = 0, end = 0;
  if (ItemsWithin(card, first, last, &low, &high)) {
    for (int n = low; n <= high; ++n) {
      const Item& item = items_[card.first_item + static_cast<std::uint32_t>(n)];
      if (item.end <= item.begin) continue;
      if (end == 0) begin = item.begin;
      end = item.end;
    }
  }
  if (end > 0) return {file_, begin, end};
  if (card.line == 0) return EndOfDeck();
  return {file_, card.end_offset, card.end_offset};  // not given: where the READ stopped
}

std::string ListReader::Where(const Card& card, int first, int last) const {
  int low = 0, high = 0;
  if (!ItemsWithin(card, first, last, &low, &high)) return "(not an item of the .lin card)";
  return low == high ? fmt::format("item {}", low + 1)
                     : fmt::format("items {}-{}", low + 1, high + 1);
}

}  // namespace sled::lang::legacy
