// What `sled --help`, `sled COMMAND --help` and `sled --version` print, and which options each
// command takes. One table of commands serves the overview, each command's page and the option
// check, so a new command (or option) is added in one place.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace sled::driver {

struct CommandHelp {
  std::string_view name;
  std::string_view synopsis;              // `sled run FILE [options]`
  std::string_view summary;               // one line for the overview
  std::string_view details;               // what it does, what it writes, its exit status
  std::vector<std::string_view> options;  // the options it takes, as written: "-o", "--set"
  std::string_view option_help;           // their descriptions
  std::string_view examples;
};

// Every command, in the order the overview lists them.
const std::vector<CommandHelp>& Commands();
const CommandHelp* FindCommand(std::string_view name);

// The overview: usage, the commands with their one-line summaries, where to read more.
std::string OverviewText();
// One command's page: synopsis, details, options and examples.
std::string CommandHelpText(const CommandHelp& command);

// The name of an option as a command line spells it, without a value given with `=`:
// `--diagnostics=compact` is `--diagnostics`, `-o` is `-o`.
std::string_view OptionName(std::string_view argument);
bool TakesOption(const CommandHelp& command, std::string_view option);

// `sled 0.1.0 (commit 1a2b3c4d5e6f, built 2024-...)`: the version of the project and the commit
// the program was built from.
std::string VersionText();

}  // namespace sled::driver
