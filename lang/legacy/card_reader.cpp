#include "lang/legacy/card_reader.h"

#include <algorithm>
#include <utility>

#include <fmt/format.h>

namespace sled::lang::legacy {

CardReader::CardReader(const SourceManager& sources, FileId file, BlankMode blanks,
                       DiagnosticConsumer& diagnostics)
    : file_(file), blanks_(blanks), diagnostics_(diagnostics) {
  const std::string_view text = sources.buffer(file).text();
  size_ = static_cast<std::uint32_t>(text.size());
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(start, end - start);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    lines_.push_back({static_cast<std::uint32_t>(start), line});
    start = end + 1;
  }
}

bool CardReader::IsComment(std::size_t index) const {
  const std::string_view text = lines_[index].text;
  const std::size_t first = text.find_first_not_of(" \t");
  return first != std::string_view::npos && text[first] == '#';
}

Card CardReader::Next(std::string label) {
  while (next_ < lines_.size() && IsComment(next_)) ++next_;
  if (next_ >= lines_.size()) {
    if (!truncated_) {
      truncated_ = true;
      ReportAt(DiagnosticKind::kDeckTruncated, EndOfDeck(),
               fmt::format("the deck ends before card {}", label),
               "a deck lists every card its counts announce; add the missing cards or correct the "
               "count that asks for them");
    }
    return Card{0, {}, std::move(label)};
  }
  const std::size_t index = next_++;
  Card card{static_cast<std::uint32_t>(index + 1), lines_[index].text, std::move(label)};
  const std::size_t tab = card.text.find('\t');
  if (tab != std::string_view::npos) {
    const int column = static_cast<int>(tab) + 1;
    Report(DiagnosticKind::kDeckTabCharacter, card, column, column,
           fmt::format("card {} holds a tab in column {}", card.label, column),
           "fixed-column cards are read by column; replace the tab by spaces");
  }
  return card;
}

bool CardReader::OnlyBlankLinesRemain() const {
  for (std::size_t i = next_; i < lines_.size(); ++i) {
    if (IsComment(i)) continue;
    if (lines_[i].text.find_first_not_of(" \t") != std::string_view::npos) return false;
  }
  return true;
}

std::string_view CardReader::Peek() const {
  std::size_t i = next_;
  while (i < lines_.size() && IsComment(i)) ++i;
  return i < lines_.size() ? lines_[i].text : std::string_view();
}

std::string_view CardReader::Columns(const Card& card, int first, int last) const {
  const auto begin = static_cast<std::size_t>(first - 1);
  if (begin >= card.text.size()) return {};
  return card.text.substr(begin, static_cast<std::size_t>(last - first + 1));
}

namespace {

std::string Quoted(std::string_view text) {
  const std::size_t first = text.find_first_not_of(' ');
  const std::size_t last = text.find_last_not_of(' ');
  return first == std::string_view::npos ? std::string()
                                         : std::string(text.substr(first, last - first + 1));
}

}  // namespace

double CardReader::Real(const Card& card, int first, int last, std::string_view what) {
  const std::string_view text = Columns(card, first, last);
  const FieldValue value = ReadRealField(text, blanks_);
  if (value.problem == FieldProblem::kNone) return value.number;
  const std::string found = Quoted(text);
  Report(DiagnosticKind::kDeckBadNumber, card, first, last,
         fmt::format("card {}, columns {}-{} ({}): `{}` is not a number", card.label, first, last,
                     what, found),
         value.problem == FieldProblem::kOutOfRange
             ? "the value is too large to represent"
             : "the field holds a number such as `12.5`, `-0.25` or `1.5E-3`, within its columns; "
               "check that the fields before it are in their columns");
  return 0.0;
}

int CardReader::Integer(const Card& card, int first, int last, std::string_view what) {
  const std::string_view text = Columns(card, first, last);
  const FieldValue value = ReadIntegerField(text, blanks_);
  if (value.problem == FieldProblem::kNone) return static_cast<int>(value.number);
  const std::string found = Quoted(text);
  if (value.problem == FieldProblem::kNotAnInteger) {
    Report(DiagnosticKind::kDeckIntegerExpected, card, first, last,
           fmt::format("card {}, columns {}-{} ({}): `{}` is not a whole number", card.label, first,
                       last, what, found),
           "this field is an integer (Fortran I format): write it without a decimal point, "
           "right-justified in its columns");
  } else {
    Report(DiagnosticKind::kDeckBadNumber, card, first, last,
           fmt::format("card {}, columns {}-{} ({}): `{}` is not a whole number", card.label, first,
                       last, what, found),
           value.problem == FieldProblem::kOutOfRange
               ? "the value is too large for an integer field"
               : "the field holds a whole number such as `15`, right-justified in its columns; "
                 "check that the fields before it are in their columns");
  }
  return 0;
}

std::string CardReader::Text(const Card& card, int first, int last) const {
  return Quoted(Columns(card, first, last));
}

bool CardReader::Blank(const Card& card, int first, int last) const {
  return Columns(card, first, last).find_first_not_of(' ') == std::string_view::npos;
}

SourceRange CardReader::Range(const Card& card, int first, int last) const {
  if (card.line == 0) return EndOfDeck();
  const Line& line = lines_[card.line - 1];
  const auto length = static_cast<std::uint32_t>(line.text.size());
  const std::uint32_t begin = std::min(static_cast<std::uint32_t>(first - 1), length);
  const std::uint32_t end = std::max(begin, std::min(static_cast<std::uint32_t>(last), length));
  return {file_, line.offset + begin, line.offset + end};
}

SourceRange CardReader::EndOfDeck() const { return {file_, size_, size_}; }

void CardReader::Report(DiagnosticKind kind, const Card& card, int first, int last,
                        std::string message, std::string help) {
  ReportAt(kind, Range(card, first, last), std::move(message), std::move(help));
}

void CardReader::ReportAt(DiagnosticKind kind, SourceRange range, std::string message,
                          std::string help) {
  Diagnostic diagnostic = MakeDiagnostic(kind, range, std::move(message));
  diagnostic.help = std::move(help);
  diagnostic.show_column_range = true;
  if (diagnostic.severity == Severity::kError) ++errors_;
  diagnostics_.Consume(std::move(diagnostic));
}

}  // namespace sled::lang::legacy
