#include "lang/legacy/card_reader.h"

#include <algorithm>
#include <utility>

#include <fmt/format.h>

namespace sled::lang::legacy {
namespace {

std::string Trimmed(std::string_view text) {
  const std::size_t first = text.find_first_not_of(' ');
  const std::size_t last = text.find_last_not_of(' ');
  return first == std::string_view::npos ? std::string()
                                         : std::string(text.substr(first, last - first + 1));
}

}  // namespace

Card CardReader::Next(std::string label, const CardSpec& spec) {
  while (next_ < lines_.size() && IsComment(next_)) ++next_;
  Card card;
  card.label = std::move(label);
  card.fields = &FieldsOf(spec.fortran);
  card.ain_only_column = spec.ain_only_column;
  if (next_ >= lines_.size()) {
    ReportTruncated("card " + card.label);
    return card;
  }
  const std::size_t index = next_++;
  card.line = static_cast<std::uint32_t>(index + 1);
  card.text = lines_[index].text;
  const std::size_t tab = card.text.find('\t');
  if (tab != std::string_view::npos) {
    const int column = static_cast<int>(tab) + 1;
    Report(DiagnosticKind::kDeckTabCharacter, card, column, column,
           fmt::format("card {} holds a tab in column {}", card.label, column),
           "fixed-column cards are read by column; replace the tab by spaces");
  }
  return card;
}

std::string_view CardReader::Columns(const Card& card, int first, int last) const {
  const auto begin = static_cast<std::size_t>(first - 1);
  if (begin >= card.text.size()) return {};
  return card.text.substr(begin, static_cast<std::size_t>(last) - begin);
}

std::string_view CardReader::PlacementHint() const {
  return "write it within its columns and check that the fields before it are in their columns";
}

double CardReader::Real(const Card& card, int first, int last, std::string_view what) {
  if (FieldIndex(card, first, last) < 0) return 0.0;
  const std::string_view text = Columns(card, first, last);
  const FieldValue value = ReadRealField(text, blanks_);
  if (value.problem == FieldProblem::kNone) return value.number;
  ReportBadNumber(card, first, last, what, Trimmed(text), value.problem, false);
  return 0.0;
}

int CardReader::Integer(const Card& card, int first, int last, std::string_view what) {
  if (FieldIndex(card, first, last) < 0) return 0;
  const std::string_view text = Columns(card, first, last);
  const FieldValue value = ReadIntegerField(text, blanks_);
  if (value.problem == FieldProblem::kNone) return static_cast<int>(value.number);
  ReportBadNumber(card, first, last, what, Trimmed(text), value.problem, true);
  return 0;
}

std::string CardReader::Text(const Card& card, int first, int last) {
  if (FieldIndex(card, first, last) < 0) return {};
  return Trimmed(Columns(card, first, last));
}

SourceRange CardReader::Range(const Card& card, int first, int last) const {
  if (card.line == 0) return EndOfDeck();
  const Line& line = lines_[card.line - 1];
  const auto length = static_cast<std::uint32_t>(line.text.size());
  const std::uint32_t begin = std::min(static_cast<std::uint32_t>(first - 1), length);
  const std::uint32_t end = std::max(begin, std::min(static_cast<std::uint32_t>(last), length));
  return {file_, line.offset + begin, line.offset + end};
}

std::string CardReader::Where(const Card&, int first, int last) const {
  return ColumnsText(first, last);
}

}  // namespace sled::lang::legacy
