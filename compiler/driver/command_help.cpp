#include "compiler/driver/command_help.h"

#include <algorithm>

#include <fmt/format.h>

#include "compiler/driver/build_info.h"

namespace sled::driver {
namespace {

// Options that several commands share, described once.
constexpr std::string_view kSceneOptions =
    R"(  --set NAME=VALUE       override a `param` of the scenario, with its unit
                         (--set "speed=50 km/h"); may repeat
  --stdlib DIR           the standard library folder (default: the one built in)
  --diagnostics=rich|compact
                         rich (default): source lines, carets and help; compact: one
                         line per diagnostic, PATH:LINE:COL: error[CODE]: message
)";

std::vector<CommandHelp> MakeCommands() {
  std::vector<CommandHelp> commands;
  commands.push_back(
      {"check",
       "sled check FILE... [options]",
       "parse, check and lint scenarios; print diagnostics",
       "Reads each scenario or module, checks names, units and the model, and runs the lints.\n"
       "Diagnostics go to standard error. Exit status: 0 clean or warnings only, 1 errors,\n"
       "2 a usage error.\n",
       {"--set", "--stdlib", "--diagnostics", "--no-lints", "--dump-ast", "--dump-checked",
        "--dump-model"},
       std::string_view(R"(  --no-lints             report errors only
  --dump-ast             print the syntax tree
  --dump-checked         print the checked scenario
  --dump-model           print the compiled runtime model (and, on standard error, what
                         it leaves out)
)"),
       "  sled check examples/frontal_sled.sled\n"
       "  sled check scene.sled --set \"speed=50 km/h\" --diagnostics=compact\n"});
  commands.push_back(
      {"fmt",
       "sled fmt FILE... [--check]",
       "rewrite files in canonical form",
       "Rewrites each file in sled's one layout, keeping every comment. A file with syntax\n"
       "errors is left unchanged. Exit status: 0 done (or, with --check, nothing to change),\n"
       "1 a file that would change or could not be formatted, 2 a usage error.\n",
       {"--check", "--diagnostics"},
       "  --check                only say which files would change; change nothing\n"
       "  --diagnostics=rich|compact\n"
       "                         the style of syntax errors\n",
       "  sled fmt scene.sled\n"
       "  sled fmt --check examples/*.sled\n"});
  commands.push_back(
      {"run",
       "sled run FILE [options]",
       "compile and simulate a scenario; write its outputs",
       "Compiles the scenario and simulates it. Writes into the output folder\n"
       "timeseries.csv, timeseries_filtered.csv (when a channel has a filter class),\n"
       "summary.json and animation.glb; the folder is the run's own: outputs of an earlier run\n"
       "there are removed (and named), and a second run into it at the same time is refused.\n"
       "On a terminal a progress line shows on standard error. SIGINT, SIGTERM or SIGHUP stop\n"
       "the run: the rows so far are written, summary.json says \"interrupted\".\n"
       "Exit status: 0 done, 1 input errors or an output that could not be written,\n"
       "2 a usage error, 3 a numerical failure (the outputs up to it are kept),\n"
       "129/130/143 stopped by SIGHUP/SIGINT/SIGTERM.\n",
       {"-o", "--output", "--set", "--stdlib", "--diagnostics", "--format", "--dump-at",
        "--checkpoint-every", "--resume", "--report", "--error-estimate", "--single-thread"},
       R"(  -o, --output DIR       the output folder (default: FILE's name with `-out`)
  --format csv|iso-mme   iso-mme: also write the ISO-MME data set into DIR/iso-mme
                         (the CSV files are always written)
  --dump-at T[,T...]     write every state variable and force at each time T (seconds,
                         or with ms: 0.05,80ms) into DIR/dump_<T>.txt
  --checkpoint-every T   write a checkpoint every T (a multiple of the output step)
                         into DIR/checkpoint_<t>s.bin
  --resume FILE          continue from a checkpoint, bit for bit as the run that wrote it
  --report               also write DIR/report.html, as `sled report DIR` does
  --error-estimate       also run the scene at a tenth of its tolerances and write the
                         difference as the global error estimate (summary.json)
  --single-thread        everything on one thread (by default a second one evaluates the
                         output rows and writes files; the outputs are the same)
)",
       "  sled run examples/frontal_sled.sled -o out\n"
       "  sled run examples/frontal_sled.sled -o out --set \"speed=50 km/h\" --format iso-mme\n"
       "  sled run examples/frontal_sled.sled -o later --resume out/checkpoint_0.100000s.bin\n"});
  commands.push_back(
      {"report",
       "sled report DIR [-o FILE]",
       "one HTML page of the run in DIR",
       "Turns the folder `sled run` wrote into one self-contained HTML page: summary,\n"
       "criteria against limits, plots of the channels, the animation. Exit status: 0 written,\n"
       "1 DIR holds no readable summary.json or the page cannot be written, 2 a usage error.\n",
       {"-o", "--output"},
       "  -o, --output FILE      the page (default: DIR/report.html)\n",
       "  sled report out\n"
       "  sled report out -o frontal.html\n"});
  commands.push_back(
      {"study",
       "sled study FILE [options]",
       "the scene with every integrator over a ladder of tolerances",
       "Runs the scene with each integrator over a ladder of tolerances against a tight\n"
       "reference and prints error against run time as a table; writes DIR/study.csv and the\n"
       "work-precision plot DIR/study.svg, and states the error of the scene's own settings.\n"
       "The runs go to worker processes, every core busy (--jobs). On a terminal a progress\n"
       "line counts the runs done. Exit status: 0 done, 1 input errors or a reference run that\n"
       "failed, 2 a usage error, 130 interrupted.\n",
       {"-o", "--output", "--tolerances", "--jobs", "--set", "--stdlib", "--diagnostics"},
       R"(  -o, --output DIR       the output folder (default: FILE's name with `-study`)
  --tolerances T,T,...   the relative tolerances of the ladder (default 1e-3 to 1e-7)
  --jobs N               runs at a time, each in a worker process (default: every core);
                         the errors are the same whatever N, the run times are cleanest
                         with 1 on a busy machine
)",
       "  sled study examples/numerics/pendulum_chain.sled -o study\n"
       "  sled study scene.sled --tolerances 1e-4,1e-6\n"});
  commands.push_back(
      {"sweep",
       "sled sweep FILE (--vary SPEC... | --design POINTS.csv) [options]\n"
       "       sled sweep resume DIR [--jobs N] [--slice K/T] [--retry-failed]\n"
       "       sled sweep collect DIR",
       "the scene over a design of param values, on every core or a Slurm cluster",
       "Runs FILE once per point of a design of its `param` values, each run `sled run` in a\n"
       "worker process with its own folder DIR/runs/NNNN; DIR/sweep.csv holds every run's\n"
       "inputs, status, injury criteria and channel peaks, DIR/sweep.html plots them. The design\n"
       "is checked, and the scene at every point, before anything runs. An interrupted sweep\n"
       "resumes: run the same command again, or `sled sweep resume DIR`. Exit status: 0 every\n"
       "run done, 1 input errors (scene or design), 2 a usage error, 3 a run failed or did not\n"
       "run (the table says which), 130 interrupted. See docs/sweeps.md.\n",
       {"-o",        "--output",       "--vary",
        "--design",  "--sample",       "--seed",
        "--jobs",    "--set",          "--stdlib",
        "--format",  "--report",       "--check",
        "--restart", "--retry-failed", "--slice",
        "--slurm",   "--partition",    "--account",
        "--time",    "--tasks",        "--cpus-per-task",
        "--sbatch",  "--wait",         "--diagnostics"},
       R"(  --vary "NAME=A..B UNIT step S"   a grid from A to B (speed=40..64 km/h step 8)
  --vary "NAME=A..B UNIT count N"  N values from A to B, evenly spaced
  --vary "NAME=A,B,C UNIT"         a list (pretension=0,1,2 kN)
  --vary "NAME=A..B UNIT"          a range, sampled by --sample; several --vary make
                                   every combination (the first varies slowest)
  --sample lhs=N | sobol=N         N points of a Latin hypercube or a Sobol sequence in the
                                   ranges (with every grid point, if any)
  --seed S                         the sampling's seed (default 1; Sobol with 0: unshifted)
  --design POINTS.csv              the points from a file: a header `speed [km/h],slack [mm]`,
                                   then a row of numbers per run
  -o, --output DIR                 the sweep folder (default: FILE's name with `-sweep`)
  --jobs N                         worker processes (default: every core)
  --set NAME=VALUE                 fix a parameter for every run
  --stdlib DIR                     the standard library folder
  --format iso-mme, --report       passed to every run
  --check                          check the design and the scene at every point, print the
                                   design, run nothing
  --restart                        discard the runs of an earlier sweep in DIR
  --retry-failed                   also run again the runs that failed
  --slice K/T                      (resume) only the runs i with i % T == K
  --slurm                          submit the runs as a Slurm job array instead
  --partition P, --account A       where the array's tasks run and who pays
  --time T                         each task's time limit (sbatch --time)
  --tasks N                        array tasks (default one per run, at most 1000)
  --cpus-per-task N                runs at a time inside each task (default 1)
  --sbatch ARG                     any other sbatch option, as it is (repeatable)
  --wait                           wait for the array, then report the table
)",
       "  sled sweep examples/frontal_sled.sled --vary \"speed=40..64 km/h step 8\"\n"
       "  sled sweep scene.sled --vary \"speed=40..64 km/h\" --vary \"belt_slack=0..20 mm\" "
       "--sample lhs=32 --seed 7\n"
       "  sled sweep scene.sled --design points.csv -o /shared/sweep --slurm --partition short\n"
       "  sled sweep resume frontal_sled-sweep\n"});
  commands.push_back(
      {"convert",
       "sled convert DECK [options]",
       "translate a CVS-III/ATB deck into a scenario",
       "Translates a fixed-column (.ain) or list-directed (.lin) CVS-III/ATB card deck into a\n"
       ".sled scenario, to standard output or to FILE. Exit status: 0 done, 1 errors in the\n"
       "deck or a file that cannot be written, 2 a usage error.\n",
       {"-o", "--output", "--blank-zero", "--deck", "--approximate-airbags", "--diagnostics"},
       R"(  -o, --output FILE      write the scenario here (default: standard output)
  --deck=ain|lin         read a deck of another extension as this format
  --blank-zero           read blank columns as zeros (FORTRAN IV decks; .ain only)
  --approximate-airbags  deprecated, does nothing: D.4 airbags convert to ATB's free
                         bag (`model = atb_free`) by default
  --diagnostics=rich|compact
                         the style of diagnostics
)",
       "  sled convert examples/legacy/pedestrian.ain -o pedestrian.sled\n"
       "  sled convert old.dat --deck=lin\n"});
  commands.push_back({"explain",
                      "sled explain CODE",
                      "the long explanation of a diagnostic code",
                      "Prints the page of a diagnostic code (E0204, W0004, ...). Exit status: 0,\n"
                      "2 an unknown code.\n",
                      {},
                      "",
                      "  sled explain E0302\n"});
  commands.push_back(
      {"lsp",
       "sled lsp [--stdlib DIR]",
       "the language server for editors (Language Server Protocol over stdio)",
       "Serves the Language Server Protocol on standard input and output: diagnostics as you\n"
       "type, hover, go to definition, references, completion, formatting, the outline and\n"
       "quick fixes. Editors start it themselves (docs/editors.md). Exit status: 0 after the\n"
       "client's shutdown and exit, 1 when the input ends without them.\n",
       {"--stdlib", "--stdio"},
       "  --stdlib DIR           the standard library folder for `import std...`\n"
       "  --stdio                accepted for editor clients; stdio is the only transport\n",
       "  sled lsp\n"});
  return commands;
}

bool SharesSceneOptions(const CommandHelp& command) {
  return TakesOption(command, "--set") && TakesOption(command, "--stdlib");
}

}  // namespace

const std::vector<CommandHelp>& Commands() {
  static const std::vector<CommandHelp> commands = MakeCommands();
  return commands;
}

const CommandHelp* FindCommand(std::string_view name) {
  for (const CommandHelp& command : Commands()) {
    if (command.name == name) return &command;
  }
  return nullptr;
}

std::string OverviewText() {
  std::string text =
      "usage: sled <command> [options] [files]\n       sled --version\n\ncommands:\n";
  for (const CommandHelp& command : Commands()) {
    text += fmt::format("  {:<10} {}\n", command.name, command.summary);
  }
  text +=
      "\n`sled COMMAND --help` shows a command's options and examples; docs/tutorial.md starts\n"
      "from an empty folder.\n";
  return text;
}

std::string CommandHelpText(const CommandHelp& command) {
  std::string text =
      fmt::format("usage: {}\n\n{}.\n\n{}\n", command.synopsis, command.summary, command.details);
  if (!command.options.empty()) {
    text += "options:\n";
    text += command.option_help;
    if (SharesSceneOptions(command)) text += kSceneOptions;
    text += "  -h, --help             this text\n";
  }
  if (!command.examples.empty()) text += fmt::format("\nexamples:\n{}", command.examples);
  return text;
}

std::string_view OptionName(std::string_view argument) {
  if (argument.rfind("--", 0) != 0) return argument;
  return argument.substr(0, argument.find('='));
}

bool TakesOption(const CommandHelp& command, std::string_view option) {
  return std::find(command.options.begin(), command.options.end(), option) != command.options.end();
}

std::string VersionText() {
  return fmt::format("sled {} (commit {})\n", kSledVersion, BuildCommit());
}

}  // namespace sled::driver
