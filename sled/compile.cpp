#include "sled/compile.h"

#include <stdexcept>

#include <fmt/format.h>

#include "compiler/check/check.h"
#include "compiler/check/library_paths.h"
#include "compiler/lower/lower.h"
#include "lang/diagnostics/load_file.h"
#include "lang/syntax/parser.h"

namespace sled {

Source::Source() = default;
Source::Source(Source&&) noexcept = default;
Source& Source::operator=(Source&&) noexcept = default;
Source::~Source() = default;

Source Source::File(std::string path) {
  Source source;
  source.kind_ = Kind::kFile;
  source.path_ = std::move(path);
  return source;
}

Source Source::Text(std::string text, std::string name) {
  Source source;
  source.kind_ = Kind::kText;
  source.path_ = std::move(name);
  source.text_ = std::move(text);
  return source;
}

Source Source::Tree(std::unique_ptr<lang::SourceManager> sources, lang::ast::File tree) {
  if (!sources) throw std::invalid_argument("sled::Source::Tree: no SourceManager");
  Source source;
  source.kind_ = Kind::kTree;
  source.sources_ = std::move(sources);
  source.tree_ = std::make_unique<lang::ast::File>(std::move(tree));
  return source;
}

Compilation::Compilation() = default;
Compilation::Compilation(Compilation&&) noexcept = default;
Compilation& Compilation::operator=(Compilation&&) noexcept = default;
Compilation::~Compilation() = default;

const runtime::Model& Compilation::model() const {
  if (!model_) {
    throw std::logic_error(fmt::format("sled::Compilation::model: there is no Model ({} error{}{})",
                                       error_count(), error_count() == 1 ? "" : "s",
                                       ok() ? "; CompileOptions::lower was false" : ""));
  }
  return *model_;
}

runtime::Model& Compilation::model() {
  return const_cast<runtime::Model&>(static_cast<const Compilation&>(*this).model());
}

std::string Compilation::Render(lang::DiagnosticStyle style, bool color) const {
  return lang::RenderAll(*sources_, collector_.diagnostics(), style, {color});
}

std::vector<std::string> Compilation::Notes() const {
  std::vector<std::string> notes;
  for (const lang::Diagnostic& diagnostic : collector_.diagnostics()) {
    if (diagnostic.severity == lang::Severity::kNote) {
      notes.push_back(lang::RenderCompact(*sources_, diagnostic));
    }
  }
  return notes;
}

Compilation Compile(Source source, const CompileOptions& options) {
  Compilation compiled;
  lang::DiagnosticCollector& collector = compiled.collector_;
  std::optional<lang::FileId> file;
  switch (source.kind_) {
    case Source::Kind::kFile:
      compiled.sources_ = std::make_unique<lang::SourceManager>();
      file = lang::LoadFileOrReport(*compiled.sources_, source.path_, collector);
      break;
    case Source::Kind::kText:
      compiled.sources_ = std::make_unique<lang::SourceManager>();
      file = compiled.sources_->Add(source.path_, std::move(source.text_));
      break;
    case Source::Kind::kTree:
      compiled.sources_ = std::move(source.sources_);
      compiled.ast_ = std::move(source.tree_);
      file = compiled.ast_->file;
      break;
  }
  if (!file) return compiled;
  lang::SourceManager& sources = *compiled.sources_;
  if (!compiled.ast_) {
    lang::ParseOptions parse_options;
    parse_options.diagnostics = &collector;
    compiled.ast_ = std::make_unique<lang::ast::File>(lang::Parse(sources, *file, parse_options));
  }

  compiler::CheckOptions check_options;
  check_options.diagnostics = &collector;
  check_options.stdlib_root = options.stdlib;
  check_options.module_path = options.module_path;
  for (std::string& folder : compiler::ModulePathFromEnvironment()) {
    check_options.module_path.push_back(std::move(folder));
  }
  check_options.overrides = options.overrides;
  check_options.lints = options.lints;
  compiled.scenario_ = compiler::Check(sources, *compiled.ast_, check_options);

  if (options.lower && !compiled.scenario_.has_scenario && !collector.has_errors()) {
    // A module for `import` checks clean but holds nothing to simulate.
    auto diagnostic = lang::MakeDiagnostic(
        lang::DiagnosticKind::kMissingAttribute, lang::SourceRange{*file, 0, 0},
        fmt::format("`{}` has no `scenario` to run", sources.buffer(*file).path()),
        "no `scenario` block");
    diagnostic.help =
        "a file to run holds `scenario \"name\" { ... }`; a file without one is a module that "
        "scenarios `import`";
    collector.Consume(std::move(diagnostic));
  }
  if (options.lower && !collector.has_errors()) {
    compiler::LowerOptions lower_options;
    lower_options.diagnostics = &collector;
    compiled.model_ = compiler::Lower(compiled.scenario_, sources, lower_options);
  }
  collector.SortByPosition();
  return compiled;
}

}  // namespace sled
