// The `sled` command: check, fmt, run, convert, explain and lsp (README.md). Libraries report;
// this prints.
#include <unistd.h>

#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "compiler/check/check.h"
#include "compiler/driver/command_help.h"
#include "compiler/driver/driver_diagnostics.h"
#include "compiler/driver/explain_pages.h"
#include "compiler/driver/progress_line.h"
#include "compiler/driver/report_command.h"
#include "compiler/driver/run_command.h"
#include "compiler/driver/study_command.h"
#include "compiler/driver/sweep_command.h"
#include "compiler/lsp/server.h"
#include "lang/diagnostics/load_file.h"
#include "lang/diagnostics/render.h"
#include "lang/format/formatter.h"
#include "lang/legacy/convert.h"
#include "lang/syntax/parser.h"
#include "output/atomic_file.h"
#include "sled/compile.h"

namespace {

using sled::driver::PrintDiagnostics;
using sled::lang::DiagnosticCollector;
using sled::lang::SourceManager;

constexpr int kExitOk = 0;
constexpr int kExitInputErrors = 1;
constexpr int kExitUsage = 2;

struct Options {
  std::string command;
  std::vector<std::string> files;
  bool compact = false;
  bool check_only = false;
  bool dump_ast = false;
  bool dump_checked = false;
  bool dump_model = false;
  bool lints = true;
  std::string stdlib;
  std::string output_directory;
  std::vector<std::pair<std::string, std::string>> overrides;
  bool iso_mme = false;
  bool blank_zero = false;
  bool approximate_airbags = false;
  std::string deck_format;  // "ain", "lin" or empty (by the extension)
  std::vector<double> dump_times;
  double checkpoint_every = 0.0;
  std::string resume;
  bool report = false;
  bool error_estimate = false;
  bool single_thread = false;
  std::vector<double> tolerances;
  int jobs = 0;  // study: worker processes; 0: every core
};

// The message, then how to get help: the command's own options when there is a command.
int UsageError(const std::string& message, const std::string& command = "") {
  std::cerr << "sled: " << message << '\n';
  if (const auto* help = sled::driver::FindCommand(command)) {
    std::cerr << fmt::format("usage: {}\n`sled {} --help` lists its options\n", help->synopsis,
                             help->name);
  } else {
    std::cerr << '\n' << sled::driver::OverviewText();
  }
  return kExitUsage;
}

std::vector<std::string> CommandNames() {
  std::vector<std::string> names;
  for (const auto& command : sled::driver::Commands()) names.emplace_back(command.name);
  return names;
}

bool ColorWanted() { return isatty(STDERR_FILENO) && std::getenv("NO_COLOR") == nullptr; }

int RunCheck(const Options& options) {
  if (options.files.empty()) return UsageError("`check` needs at least one file", options.command);
  bool errors = false;
  for (const std::string& path : options.files) {
    sled::CompileOptions compile_options;
    compile_options.stdlib = options.stdlib;
    compile_options.overrides = options.overrides;
    compile_options.lints = options.lints;
    compile_options.lower = options.dump_model;
    const sled::Compilation compiled = sled::Compile(sled::Source::File(path), compile_options);
    if (options.dump_ast && compiled.ast()) std::cout << sled::lang::ast::Dump(*compiled.ast());
    if (options.dump_checked && compiled.ok()) {
      std::cout << sled::compiler::Dump(compiled.scenario());
    }
    if (compiled.has_model()) std::cout << sled::runtime::DumpModel(compiled.model());
    std::cerr << compiled.Render(options.compact ? sled::lang::DiagnosticStyle::kCompact
                                                 : sled::lang::DiagnosticStyle::kRich,
                                 ColorWanted());
    errors |= !compiled.ok();
  }
  return errors ? kExitInputErrors : kExitOk;
}

int RunFormat(const Options& options) {
  if (options.files.empty()) return UsageError("`fmt` needs at least one file", options.command);
  bool changed_or_failed = false;
  for (const std::string& path : options.files) {
    SourceManager sources;
    DiagnosticCollector collector;
    auto file = sled::lang::LoadFileOrReport(sources, path, collector);
    if (!file) {
      PrintDiagnostics(sources, collector, options.compact, ColorWanted());
      changed_or_failed = true;
      continue;
    }
    const std::optional<std::string> formatted =
        sled::lang::FormatBuffer(sources, *file, collector);
    if (!formatted) {
      PrintDiagnostics(sources, collector, options.compact, ColorWanted());
      std::cerr << fmt::format("sled: `{}` has syntax errors and was left unchanged\n", path);
      changed_or_failed = true;
      continue;
    }
    const bool differs = *formatted != sources.buffer(*file).text();
    if (options.check_only) {
      if (differs) {
        std::cout << fmt::format("{}: would be reformatted\n", path);
        changed_or_failed = true;
      }
      continue;
    }
    std::string why;
    if (differs && !sled::runtime::ReplaceFile(path, *formatted, &why)) {
      std::cerr << fmt::format("sled: {}; `{}` was left unchanged\n", why, path);
      changed_or_failed = true;
    }
  }
  return changed_or_failed ? kExitInputErrors : kExitOk;
}

int RunConvert(const Options& options) {
  if (options.files.size() != 1) return UsageError("`convert` takes one deck", options.command);
  std::optional<sled::lang::legacy::DeckFormat> format =
      sled::lang::legacy::DeckFormatOfPath(options.files[0]);
  if (options.deck_format == "ain") format = sled::lang::legacy::DeckFormat::kFixed;
  if (options.deck_format == "lin") format = sled::lang::legacy::DeckFormat::kList;
  if (!format) {
    return UsageError(
        fmt::format(
            "`{}` is neither an .ain nor a .lin deck; say which with --deck=ain or --deck=lin",
            options.files[0]),
        options.command);
  }
  if (options.blank_zero && *format == sled::lang::legacy::DeckFormat::kList) {
    return UsageError("--blank-zero applies to fixed-column (.ain) decks only", options.command);
  }
  SourceManager sources;
  DiagnosticCollector collector;
  const auto file = sled::lang::LoadFileOrReport(sources, options.files[0], collector);
  std::string text;
  if (file) {
    sled::lang::legacy::ConvertOptions convert;
    convert.diagnostics = &collector;
    convert.format = *format;
    convert.blanks = options.blank_zero ? sled::lang::legacy::BlankMode::kZero
                                        : sled::lang::legacy::BlankMode::kIgnore;
    const auto ast = sled::lang::legacy::ConvertDeck(sources, *file, convert);
    if (!collector.has_errors()) text = sled::lang::Format(ast);
  }
  if (options.approximate_airbags) {
    std::fputs(
        "sled convert: warning: --approximate-airbags is deprecated and does nothing: D.4 "
        "airbags convert to ATB's free bag (`model = atb_free`) by default\n",
        stderr);
  }
  PrintDiagnostics(sources, collector, options.compact, ColorWanted());
  if (collector.has_errors()) return kExitInputErrors;
  if (options.output_directory.empty()) {
    std::cout << text;
    return kExitOk;
  }
  std::string why;
  if (!sled::runtime::ReplaceFile(options.output_directory, text, &why)) {
    std::cerr << fmt::format("sled: {}\n", why);
    return kExitInputErrors;
  }
  return kExitOk;
}

int RunExplain(const Options& options) {
  if (options.files.size() != 1)
    return UsageError("`explain` takes one diagnostic code", options.command);
  std::string code = options.files[0];
  for (char& c : code) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  if (auto page = sled::driver::ExplainPage(code)) {
    std::cout << *page;
    return kExitOk;
  }
  std::vector<std::string> codes;
  for (const auto& info : sled::lang::AllDiagnostics()) codes.emplace_back(info.code);
  const std::string hint = sled::lang::DidYouMean(code, codes);
  std::cerr << fmt::format("sled: no diagnostic `{}`{}\n", code, hint.empty() ? "" : "; " + hint);
  return kExitUsage;
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  std::vector<std::string> args(argv + 1, argv + argc);
  if (args.empty()) return UsageError("no command given");
  if (args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
    // `sled help run` is `sled run --help`.
    const auto* command = args.size() > 1 ? sled::driver::FindCommand(args[1]) : nullptr;
    std::cout << (command ? sled::driver::CommandHelpText(*command) : sled::driver::OverviewText());
    return kExitOk;
  }
  if (args[0] == "--version" || args[0] == "-V" || args[0] == "version") {
    std::cout << sled::driver::VersionText();
    return kExitOk;
  }
  options.command = args[0];
  const sled::driver::CommandHelp* command = sled::driver::FindCommand(options.command);
  if (!command) {
    const std::string hint = sled::lang::DidYouMean(options.command, CommandNames());
    return UsageError(
        fmt::format("unknown command `{}`{}", options.command, hint.empty() ? "" : "; " + hint));
  }
  // `sweep` reads its own options (compiler/driver/sweep_command.cpp).
  if (options.command == "sweep") {
    try {
      return sled::driver::SweepCommand({args.begin() + 1, args.end()}, ColorWanted());
    } catch (const std::exception& error) {
      std::cerr << fmt::format("sled: internal error: {} (please report this with the input)\n",
                               error.what());
      return kExitInputErrors;
    }
  }
  for (std::size_t i = 1; i < args.size(); ++i) {
    const std::string& arg = args[i];
    if (arg == "--help" || arg == "-h") {
      std::cout << sled::driver::CommandHelpText(*command);
      return kExitOk;
    }
    // An option of another command is refused, not ignored: `sled check -o out` writes nothing.
    if (arg.size() > 1 && arg[0] == '-' &&
        !sled::driver::TakesOption(*command, sled::driver::OptionName(arg))) {
      const bool known = std::any_of(
          sled::driver::Commands().begin(), sled::driver::Commands().end(), [&](const auto& other) {
            return sled::driver::TakesOption(other, sled::driver::OptionName(arg));
          });
      return UsageError(known ? fmt::format("`sled {}` takes no option `{}`", command->name,
                                            sled::driver::OptionName(arg))
                              : fmt::format("unknown option `{}`", arg),
                        options.command);
    }
    if (arg == "--diagnostics=compact") {
      options.compact = true;
    } else if (arg == "--diagnostics=rich") {
      options.compact = false;
    } else if (arg == "--check") {
      options.check_only = true;
    } else if (arg == "--stdio") {
      // `sled lsp --stdio`, as editor clients start servers: stdio is the only transport.
    } else if (arg == "--dump-ast") {
      options.dump_ast = true;
    } else if (arg == "--dump-checked") {
      options.dump_checked = true;
    } else if (arg == "--dump-model") {
      options.dump_model = true;
    } else if (arg == "--blank-zero") {
      options.blank_zero = true;
    } else if (arg == "--approximate-airbags") {
      options.approximate_airbags = true;
    } else if (arg.rfind("--deck=", 0) == 0) {
      options.deck_format = arg.substr(7);
      if (options.deck_format != "ain" && options.deck_format != "lin") {
        return UsageError(fmt::format("`{}`: the deck format is `ain` or `lin`", arg),
                          options.command);
      }
    } else if (arg == "--no-lints") {
      options.lints = false;
    } else if (arg == "-o" || arg == "--output") {
      // `-o ""` is a mistake (an unset shell variable), not a request for the default.
      if (i + 1 >= args.size() || args[i + 1].empty()) {
        return UsageError(
            fmt::format("`{}` needs a {}", arg,
                        options.command == "run" || options.command == "study" ? "folder" : "file"),
            options.command);
      }
      options.output_directory = args[++i];
    } else if (arg == "--format" || arg == "--dump-at") {
      if (i + 1 >= args.size())
        return UsageError(fmt::format("`{}` needs a value", arg), options.command);
      std::string error;
      const bool parsed =
          arg == "--format" ? sled::driver::ParseFormats(args[++i], &options.iso_mme, &error)
                            : sled::driver::ParseDumpTimes(args[++i], &options.dump_times, &error);
      if (!parsed) return UsageError(error, options.command);
    } else if (arg == "--checkpoint-every") {
      if (i + 1 >= args.size())
        return UsageError(fmt::format("`{}` needs a time", arg), options.command);
      const std::string& value = args[++i];
      if (!sled::driver::ParseTime(value, &options.checkpoint_every) ||
          !(options.checkpoint_every > 0)) {
        return UsageError(
            fmt::format(
                "`--checkpoint-every {}`: write a positive time in seconds or with ms (50ms)",
                value),
            options.command);
      }
    } else if (arg == "--jobs") {
      int jobs = 0;
      const std::string value = i + 1 < args.size() ? args[++i] : "";
      const auto [end, status] = std::from_chars(value.data(), value.data() + value.size(), jobs);
      if (status != std::errc() || end != value.data() + value.size() || jobs < 1) {
        return UsageError(fmt::format("`--jobs {}`: write a positive count", value),
                          options.command);
      }
      options.jobs = jobs;
    } else if (arg == "--tolerances") {
      if (i + 1 >= args.size())
        return UsageError(fmt::format("`{}` needs a list", arg), options.command);
      std::string error;
      if (!sled::driver::ParseTolerances(args[++i], &options.tolerances, &error)) {
        return UsageError(error, options.command);
      }
    } else if (arg == "--report") {
      options.report = true;
    } else if (arg == "--error-estimate") {
      options.error_estimate = true;
    } else if (arg == "--single-thread") {
      options.single_thread = true;
    } else if (arg == "--resume") {
      if (i + 1 >= args.size())
        return UsageError(fmt::format("`{}` needs a checkpoint file", arg), options.command);
      options.resume = args[++i];
    } else if (arg == "--stdlib" || arg == "--set") {
      if (i + 1 >= args.size())
        return UsageError(fmt::format("`{}` needs a value", arg), options.command);
      const std::string& value = args[++i];
      if (arg == "--stdlib") {
        options.stdlib = value;
      } else {
        const auto equals = value.find('=');
        if (equals == std::string::npos || equals == 0) {
          return UsageError(fmt::format("`--set {}`: write NAME=VALUE", value), options.command);
        }
        options.overrides.emplace_back(value.substr(0, equals), value.substr(equals + 1));
      }
    } else if (arg.size() > 1 && arg[0] == '-') {
      return UsageError(
          fmt::format("`{}`: write the option as `sled {} --help` shows", arg, options.command),
          options.command);
    } else {
      options.files.push_back(arg);
    }
  }
  try {
    if (options.command == "check") return RunCheck(options);
    if (options.command == "fmt") return RunFormat(options);
    if (options.command == "explain") return RunExplain(options);
    if (options.command == "lsp") {
      if (!options.files.empty()) return UsageError("`lsp` takes no file", options.command);
      return sled::lsp::RunLanguageServer({.stdlib = options.stdlib, .module_path = {}});
    }
    if (options.command == "convert") return RunConvert(options);
    if (options.command == "report") {
      if (options.files.size() != 1)
        return UsageError("`report` takes one run folder", options.command);
      return sled::driver::ReportCommand(options.files[0], options.output_directory);
    }
    if (options.command == "run" || options.command == "study") {
      if (options.files.size() != 1) {
        return UsageError(fmt::format("`{}` takes one scenario file", options.command),
                          options.command);
      }
      sled::driver::RunCommandOptions run;
      run.file = options.files[0];
      run.output_directory = options.output_directory;
      run.stdlib = options.stdlib;
      run.overrides = options.overrides;
      run.compact_diagnostics = options.compact;
      run.color = ColorWanted();
      run.progress = sled::driver::ProgressLine::Wanted();
      run.iso_mme = options.iso_mme;
      run.dump_times = options.dump_times;
      run.checkpoint_every = options.checkpoint_every;
      run.resume = options.resume;
      run.report = options.report;
      run.error_estimate = options.error_estimate;
      run.threaded = !options.single_thread;
      if (options.command == "study")
        return sled::driver::StudyCommand({run, options.tolerances, options.jobs});
      return sled::driver::RunCommand(run);
    }
  } catch (const std::exception& error) {
    // A programming error, never the user's (the fuzzers look for these): say so plainly, and
    // keep to the documented exit codes rather than crash.
    std::cerr << fmt::format("sled: internal error: {} (please report this with the input)\n",
                             error.what());
    return kExitInputErrors;
  }
  return UsageError(fmt::format("unknown command `{}`", options.command));
}
