// Diagnostics: what a stage found wrong with its input, where, and what to do about it.
// Libraries report through a DiagnosticConsumer and never print; the driver renders.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "lang/source/source_range.h"

namespace sled::lang {

enum class Severity { kError, kWarning, kNote };

enum class DiagnosticKind {
#define SLED_DIAGNOSTIC(name, code, severity, summary) k##name,
#include "lang/diagnostics/diagnostic_kinds.def"
#undef SLED_DIAGNOSTIC
};

// The registry: one entry per kind, in declaration order.
struct DiagnosticInfo {
  DiagnosticKind kind;
  std::string_view name;
  std::string_view code;
  Severity severity;
  std::string_view summary;
};
const std::vector<DiagnosticInfo>& AllDiagnostics();
const DiagnosticInfo& InfoOf(DiagnosticKind kind);
std::optional<DiagnosticKind> FindDiagnosticByCode(std::string_view code);
std::string_view SeverityName(Severity severity);

// A labelled range: the primary label gets carets, secondary ones get dashes.
struct Label {
  SourceRange range;
  std::string message;
  bool primary = true;
};

struct Diagnostic {
  DiagnosticKind kind{};
  Severity severity = Severity::kError;
  std::string message;
  std::vector<Label> labels;  // labels[0] is the primary location when present
  std::vector<std::string> notes;
  std::string help;  // empty when there is nothing useful to suggest

  // When set, the location is shown as columns BEGIN-END (legacy decks name the card's columns).
  bool show_column_range = false;

  const SourceRange* primary_range() const { return labels.empty() ? nullptr : &labels[0].range; }
  std::string_view code() const { return InfoOf(kind).code; }
};

// Builds a diagnostic of a registered kind with its registered severity.
Diagnostic MakeDiagnostic(DiagnosticKind kind, SourceRange range, std::string message,
                          std::string label = {});

class DiagnosticConsumer {
 public:
  virtual ~DiagnosticConsumer() = default;
  virtual void Consume(Diagnostic diagnostic) = 0;
};

// Keeps every diagnostic, counts errors, and sorts by position on request.
class DiagnosticCollector : public DiagnosticConsumer {
 public:
  void Consume(Diagnostic diagnostic) override;

  const std::vector<Diagnostic>& diagnostics() const { return diagnostics_; }
  int error_count() const { return errors_; }
  int warning_count() const { return warnings_; }
  bool has_errors() const { return errors_ > 0; }
  // Orders by file and position, keeping the report order of diagnostics at the same place.
  void SortByPosition();
  void Clear();

 private:
  std::vector<Diagnostic> diagnostics_;
  int errors_ = 0;
  int warnings_ = 0;
};

// Forwards to another consumer and counts errors, for stages that must know whether to go on.
class ErrorTrackingConsumer : public DiagnosticConsumer {
 public:
  explicit ErrorTrackingConsumer(DiagnosticConsumer& next) : next_(next) {}
  void Consume(Diagnostic diagnostic) override;
  bool seen_error() const { return seen_error_; }

 private:
  DiagnosticConsumer& next_;
  bool seen_error_ = false;
};

// "Did you mean" support: the candidate closest to `word` by edit distance, if close enough.
std::optional<std::string> ClosestMatch(std::string_view word,
                                        const std::vector<std::string>& candidates);
// "did you mean `x`?" for the closest candidate; without a close one, the candidates themselves
// when there are at most eight ("one of: `ball`, `pin`, ..."); else empty.
std::string DidYouMean(std::string_view word, const std::vector<std::string>& candidates);
// The names a help text made by DidYouMean suggests, in its order (empty for any other help):
// what an editor offers as replacements of the diagnostic's primary range.
std::vector<std::string> SuggestedNames(std::string_view help);

}  // namespace sled::lang
