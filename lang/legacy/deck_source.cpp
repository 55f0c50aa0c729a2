#include "lang/legacy/deck_source.h"

#include <utility>

#include <fmt/format.h>

namespace sled::lang::legacy {

std::string ColumnsText(int first, int last) {
  return first == last ? fmt::format("column {}", first)
                       : fmt::format("columns {}-{}", first, last);
}

DeckSource::DeckSource(const SourceManager& sources, FileId file, BlankMode blanks,
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

bool DeckSource::IsComment(std::size_t index) const {
  const std::string_view text = lines_[index].text;
  const std::size_t first = text.find_first_not_of(" \t");
  return first != std::string_view::npos && text[first] == '#';
}

bool DeckSource::OnlyBlankLinesRemain() const {
  for (std::size_t i = NextUnreadLine(); i < lines_.size(); ++i) {
    if (IsComment(i)) continue;
    if (lines_[i].text.find_first_not_of(" \t") != std::string_view::npos) return false;
  }
  return true;
}

SourceRange DeckSource::EndOfDeck() const { return {file_, size_, size_}; }

void DeckSource::ReportTruncated(const std::string& what) {
  if (truncated_) return;
  truncated_ = true;
  ReportAt(DiagnosticKind::kDeckTruncated, EndOfDeck(),
           fmt::format("the deck ends before {}", what),
           "a deck lists every card its counts announce; add the missing cards or correct the "
           "count that asks for them");
}

int DeckSource::FieldIndex(const Card& card, int first, int last) {
  if (card.fields != nullptr) {
    for (std::size_t i = 0; i < card.fields->size(); ++i) {
      const FieldSpan& field = (*card.fields)[i];
      if (field.first == first && field.last == last) return static_cast<int>(i);
    }
  }
  ReportAt(DiagnosticKind::kDeckInvalidValue, Range(card, first, last),
           fmt::format("card {} declares no field at {} (a defect of sled's card declarations)",
                       card.label, ColumnsText(first, last)),
           "please report this deck; the field reads as zero");
  return -1;
}

void DeckSource::ReportBadNumber(const Card& card, int first, int last, std::string_view what,
                                 std::string_view found, FieldProblem problem, bool integer) {
  const std::string where = Where(card, first, last);
  const char* expected = integer ? "a whole number" : "a number";
  if (problem == FieldProblem::kNotAnInteger) {
    Report(
        DiagnosticKind::kDeckIntegerExpected, card, first, last,
        fmt::format("card {}, {} ({}): `{}` is not a whole number", card.label, where, what, found),
        "this field is an integer (Fortran I format): write it without a decimal point");
    return;
  }
  std::string help;
  if (problem == FieldProblem::kOutOfRange) {
    help = integer ? "the value is too large for an integer field"
                   : "the value is too large to represent";
  } else {
    help = fmt::format("the field holds {} such as `{}`; {}", expected,
                       integer ? "15" : "12.5`, `-0.25` or `1.5E-3", PlacementHint());
  }
  Report(DiagnosticKind::kDeckBadNumber, card, first, last,
         fmt::format("card {}, {} ({}): `{}` is not {}", card.label, where, what, found, expected),
         std::move(help));
}

void DeckSource::Report(DiagnosticKind kind, const Card& card, int first, int last,
                        std::string message, std::string help) {
  ReportAt(kind, Range(card, first, last), std::move(message), std::move(help));
}

void DeckSource::ReportAt(DiagnosticKind kind, SourceRange range, std::string message,
                          std::string help) {
  Diagnostic diagnostic = MakeDiagnostic(kind, range, std::move(message));
  diagnostic.help = std::move(help);
  diagnostic.show_column_range = true;
  if (diagnostic.severity == Severity::kError) ++errors_;
  diagnostics_.Consume(std::move(diagnostic));
}

}  // namespace sled::lang::legacy
