// A scene file compiled and simulated through the public API (sled/sled.h): what `sled run`
// does, in a program of your own. Prints the diagnostics, runs the scene, writes the folder
// `sled run` writes and prints the injury criteria.
//
//   run_scene SCENE.sled OUTPUT_DIR [NAME=VALUE]...
//
// NAME=VALUE overrides a `param` of the scene (`speed=40 km/h`), as `sled run --set` does.
// Exit status: 0 done, 1 input errors or an output that could not be written, 2 a usage error,
// 3 a numerical failure (the outputs up to it are written).
#include <cstdio>
#include <filesystem>
#include <string>
#include <string_view>
#include <system_error>

#include <sled/sled.h>

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: run_scene SCENE.sled OUTPUT_DIR [NAME=VALUE]...\n");
    return 2;
  }
  sled::CompileOptions options;
#ifdef SLED_STDLIB_DIR
  options.stdlib = SLED_STDLIB_DIR;  // the package's standard library (CMakeLists.txt)
#endif
  for (int i = 3; i < argc; ++i) {
    const std::string_view item = argv[i];
    const std::size_t equals = item.find('=');
    if (equals == std::string_view::npos || equals == 0) {
      std::fprintf(stderr, "run_scene: write an override as NAME=VALUE, found `%s`\n", argv[i]);
      return 2;
    }
    options.overrides.emplace_back(item.substr(0, equals), item.substr(equals + 1));
  }

  const sled::Compilation compiled = sled::Compile(sled::Source::File(argv[1]), options);
  std::fputs(compiled.Render(sled::lang::DiagnosticStyle::kCompact).c_str(), stderr);
  if (!compiled.ok()) return 1;
  const sled::runtime::Model& model = compiled.model();

  std::error_code error;
  std::filesystem::create_directories(argv[2], error);
  sled::OutputFolderOptions folder_options;
  folder_options.directory = argv[2];
  folder_options.notes = compiled.Notes();
  sled::OutputFolder folder(model, folder_options);
  const sled::RunResult run = sled::Simulate(model, {}, {&folder});

  for (const std::string& why : run.sink_errors)
    std::fprintf(stderr, "run_scene: %s\n", why.c_str());
  for (const sled::runtime::post::CriterionValue& criterion : run.criteria) {
    if (criterion.computed) {
      std::printf("%s(%s)%s%s = %.6g %s\n", criterion.name.c_str(), criterion.target.c_str(),
                  criterion.variant.empty() ? "" : " ", criterion.variant.c_str(), criterion.value,
                  criterion.unit.c_str());
    }
  }
  if (run.failed()) {
    std::fprintf(stderr, "run_scene: the run failed %s\n",
                 sled::DescribeFailure(model, run.summary.failure).c_str());
    return 3;
  }
  std::fprintf(stderr, "run_scene: %zu rows to %s in %.3f s\n", run.series.rows(), argv[2],
               run.summary.wall_seconds);
  return run.sink_errors.empty() ? 0 : 1;
}
