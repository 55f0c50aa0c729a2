#include "compiler/lsp/diagnostics.h"

#include <cctype>
#include <filesystem>
#include <fstream>

#include <fmt/format.h>
#include <unistd.h>

#include "compiler/check/library_paths.h"
#include "compiler/driver/explain_pages.h"

namespace sled::lsp {
namespace {

namespace fs = std::filesystem;

int SeverityNumber(lang::Severity severity) {
  switch (severity) {
    case lang::Severity::kError:
      return 1;
    case lang::Severity::kWarning:
      return 2;
    case lang::Severity::kNote:
      return 3;
  }
  return 1;
}

Json DiagnosticJson(const lang::Diagnostic& diagnostic, RangeConverter& ranges,
                    ExplainLinks& links) {
  const lang::SourceRange* primary = diagnostic.primary_range();
  std::string message = diagnostic.message;
  if (primary && !diagnostic.labels[0].message.empty()) {
    message += fmt::format(" ({})", diagnostic.labels[0].message);
  }
  for (const std::string& note : diagnostic.notes) message += "\nnote: " + note;
  if (!diagnostic.help.empty()) message += "\nhelp: " + diagnostic.help;
  Json json = {{"range", RangeJson(primary ? ranges.RangeOf(*primary) : Range{})},
               {"severity", SeverityNumber(diagnostic.severity)},
               {"code", std::string(diagnostic.code())},
               {"source", "sled"},
               {"message", message}};
  const std::string link = links.LinkOf(diagnostic.code());
  if (!link.empty()) json["codeDescription"] = {{"href", link}};
  Json related = Json::array();
  for (std::size_t i = 1; i < diagnostic.labels.size(); ++i) {
    const lang::Label& label = diagnostic.labels[i];
    if (!label.range.valid()) continue;
    related.push_back({{"location", ranges.LocationOf(label.range)},
                       {"message", label.message.empty() ? "related" : label.message}});
  }
  if (!related.empty()) json["relatedInformation"] = std::move(related);
  return json;
}

// The part of `range` a suggested name replaces: the leading name (a dotted path or a unit
// symbol), so `^2` after a misspelled unit or a call's arguments stay.
lang::SourceRange ReplacedRange(const lang::SourceManager& sources, lang::SourceRange range) {
  const std::string_view text = sources.Text(range);
  std::size_t length = 0;
  while (length < text.size() && (std::isalnum(static_cast<unsigned char>(text[length])) ||
                                  text[length] == '_' || text[length] == '.')) {
    ++length;
  }
  if (length > 0) range.end = range.begin + static_cast<std::uint32_t>(length);
  return range;
}

}  // namespace

std::string ExplainLinks::LinkOf(std::string_view code) {
  if (const auto it = links_.find(code); it != links_.end()) return it->second;
  std::string link;
  const std::optional<std::string_view> page = driver::ExplainPage(code);
  if (page) {
    std::error_code error;
    const fs::path docs = fs::path(compiler::DefaultStdlibRoot()).parent_path() / "docs" /
                          "diagnostics" / (std::string(code) + ".md");
    if (fs::is_regular_file(docs, error)) {
      link = UriOfPath(docs.string());
    } else {
      const fs::path folder =
          fs::temp_directory_path(error) / fmt::format("sled-explain-{}", getuid());
      fs::create_directories(folder, error);
      const fs::path file = folder / (std::string(code) + ".md");
      std::ofstream out(file, std::ios::binary | std::ios::trunc);
      out << *page;
      if (out.good()) link = UriOfPath(file.string());
    }
  }
  links_.emplace(std::string(code), link);
  return link;
}

std::map<std::string, Json> DiagnosticsByUri(const Analysis& analysis, RangeConverter& ranges,
                                             ExplainLinks& links) {
  std::map<std::string, Json> by_uri;
  const std::string document_uri = ranges.UriOf(analysis.file());
  by_uri[document_uri] = Json::array();
  for (const lang::Diagnostic& diagnostic : analysis.compiled().diagnostics()) {
    const lang::SourceRange* primary = diagnostic.primary_range();
    // A diagnostic of no file (an unreadable import is reported at the import) or of an
    // override belongs to the document.
    std::string uri = document_uri;
    if (primary && primary->valid() && primary->file != analysis.file()) {
      const std::string& path = analysis.sources().buffer(primary->file).path();
      if (fs::path(path).is_absolute() || fs::exists(path)) uri = ranges.UriOf(primary->file);
    }
    Json json = DiagnosticJson(diagnostic, ranges, links);
    if (uri == document_uri && primary && primary->file != analysis.file()) {
      json["range"] = RangeJson(Range{});
    }
    by_uri[uri].push_back(std::move(json));
  }
  return by_uri;
}

Json CodeActions(const Analysis& analysis, RangeConverter& ranges, const std::string& uri,
                 std::uint32_t begin, std::uint32_t end, ExplainLinks& links) {
  Json actions = Json::array();
  for (const lang::Diagnostic& diagnostic : analysis.compiled().diagnostics()) {
    const lang::SourceRange* primary = diagnostic.primary_range();
    if (!primary || primary->file != analysis.file()) continue;
    if (primary->end < begin || primary->begin > end) continue;
    const std::vector<std::string> names = lang::SuggestedNames(diagnostic.help);
    const lang::SourceRange replaced = ReplacedRange(analysis.sources(), *primary);
    for (const std::string& name : names) {
      if (name == analysis.sources().Text(replaced)) continue;
      Json edit = {{"range", RangeJson(ranges.RangeOf(replaced))}, {"newText", name}};
      actions.push_back({{"title", fmt::format("Replace with `{}`", name)},
                         {"kind", "quickfix"},
                         {"isPreferred", names.size() == 1},
                         {"diagnostics", Json::array({DiagnosticJson(diagnostic, ranges, links)})},
                         {"edit", {{"changes", {{uri, Json::array({edit})}}}}}});
    }
  }
  return actions;
}

}  // namespace sled::lsp
