#include "lang/diagnostics/diagnostic.h"

#include <algorithm>
#include <stdexcept>

#include <fmt/format.h>

namespace sled::lang {

const std::vector<DiagnosticInfo>& AllDiagnostics() {
  static const std::vector<DiagnosticInfo> kAll = {
#define SLED_DIAGNOSTIC(name, code, severity, summary) \
  {DiagnosticKind::k##name, #name, code, Severity::k##severity, summary},
#include "lang/diagnostics/diagnostic_kinds.def"
#undef SLED_DIAGNOSTIC
  };
  return kAll;
}

const DiagnosticInfo& InfoOf(DiagnosticKind kind) {
  const auto& all = AllDiagnostics();
  const auto index = static_cast<std::size_t>(kind);
  if (index >= all.size()) throw std::logic_error("lang: unregistered diagnostic kind");
  return all[index];
}

std::optional<DiagnosticKind> FindDiagnosticByCode(std::string_view code) {
  for (const auto& info : AllDiagnostics()) {
    if (info.code == code) return info.kind;
  }
  return std::nullopt;
}

std::string_view SeverityName(Severity severity) {
  switch (severity) {
    case Severity::kError:
      return "error";
    case Severity::kWarning:
      return "warning";
    case Severity::kNote:
      return "note";
  }
  return "error";
}

Diagnostic MakeDiagnostic(DiagnosticKind kind, SourceRange range, std::string message,
                          std::string label) {
  Diagnostic diagnostic;
  diagnostic.kind = kind;
  diagnostic.severity = InfoOf(kind).severity;
  diagnostic.message = std::move(message);
  diagnostic.labels.push_back({range, std::move(label), true});
  return diagnostic;
}

void DiagnosticCollector::Consume(Diagnostic diagnostic) {
  if (diagnostic.severity == Severity::kError) ++errors_;
  if (diagnostic.severity == Severity::kWarning) ++warnings_;
  diagnostics_.push_back(std::move(diagnostic));
}

void DiagnosticCollector::SortByPosition() {
  std::stable_sort(diagnostics_.begin(), diagnostics_.end(),
                   [](const Diagnostic& a, const Diagnostic& b) {
                     const SourceRange* ra = a.primary_range();
                     const SourceRange* rb = b.primary_range();
                     if (!ra || !rb) return ra != nullptr && rb == nullptr;
                     if (ra->file.value != rb->file.value) return ra->file.value < rb->file.value;
                     return ra->begin < rb->begin;
                   });
}

void DiagnosticCollector::Clear() {
  diagnostics_.clear();
  errors_ = 0;
  warnings_ = 0;
}

void ErrorTrackingConsumer::Consume(Diagnostic diagnostic) {
  if (diagnostic.severity == Severity::kError) seen_error_ = true;
  next_.Consume(std::move(diagnostic));
}

namespace {

// Edits to turn `a` into `b`: insertions, deletions, substitutions and swaps of two neighbouring
// characters (the optimal-string-alignment distance), since swapped letters are the commonest
// typo (`widht`, `pelivs`).
std::size_t EditDistance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> before(b.size() + 1);    // row i - 2
  std::vector<std::size_t> previous(b.size() + 1);  // row i - 1
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    before.swap(previous);
    previous.swap(row);
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
      row[j] = std::min({previous[j] + 1, row[j - 1] + 1, previous[j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) {
        row[j] = std::min(row[j], before[j - 2] + 1);
      }
    }
  }
  return row[b.size()];
}

}  // namespace

std::optional<std::string> ClosestMatch(std::string_view word,
                                        const std::vector<std::string>& candidates) {
  // Allow about one edit in three characters, as rustc does, so hints stay plausible.
  const std::size_t limit = std::max<std::size_t>(1, word.size() / 3);
  std::optional<std::string> best;
  std::size_t best_distance = limit + 1;
  for (const auto& candidate : candidates) {
    if (candidate == word) continue;
    const std::size_t distance = EditDistance(word, candidate);
    if (distance < best_distance) {
      best_distance = distance;
      best = candidate;
    }
  }
  return best;
}

namespace {
constexpr std::string_view kDidYouMean = "did you mean ";
constexpr std::string_view kOnlyChoice = "the only choice here is ";
constexpr std::string_view kOneOf = "one of: ";
}  // namespace

std::string DidYouMean(std::string_view word, const std::vector<std::string>& candidates) {
  if (auto match = ClosestMatch(word, candidates)) {
    return fmt::format("{}`{}`?", kDidYouMean, *match);
  }
  // No close match: a short list of choices is itself the hint (joint types, integrators, axes).
  constexpr std::size_t kListed = 8;
  if (candidates.empty() || candidates.size() > kListed) return {};
  std::string list;
  for (const std::string& candidate : candidates) {
    list += (list.empty() ? "`" : ", `") + candidate + "`";
  }
  return fmt::format("{}{}", candidates.size() == 1 ? kOnlyChoice : kOneOf, list);
}

std::vector<std::string> SuggestedNames(std::string_view help) {
  // Each form quotes its names in backticks: `did you mean `x`?` (other hints that start the
  // same way go on after the name, and suggest that name too), or a list of choices.
  const bool single = help.starts_with(kDidYouMean);
  if (!single && !help.starts_with(kOnlyChoice) && !help.starts_with(kOneOf)) return {};
  std::vector<std::string> names;
  std::size_t at = 0;
  while (true) {
    const std::size_t open = help.find('`', at);
    if (open == std::string_view::npos) break;
    const std::size_t close = help.find('`', open + 1);
    if (close == std::string_view::npos) break;
    names.emplace_back(help.substr(open + 1, close - open - 1));
    at = close + 1;
    if (single) break;
  }
  return names;
}

}  // namespace sled::lang
