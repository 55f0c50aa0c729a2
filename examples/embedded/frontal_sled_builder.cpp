// A frontal sled test built in C++ with sled::lang::build instead of written as a .sled file: a
// two-segment occupant on a seat pan, restrained by a lap belt, on a sled with a 56 km/h
// half-sine pulse. The program compiles the scene through the public API (sled/sled.h), prints
// the diagnostics (pointing at the lines of this file) to standard error and the scene as .sled
// text to standard output; with --run DIR it also simulates it and writes the folder `sled run`
// writes.
//
//   frontal_sled_builder [--speed KM_PER_H] [--run DIR] > frontal_sled.sled
//
// Exit status: 0 when the scene compiles without errors (and the run completes), 1 otherwise, 2
// on a usage error, 3 when the run fails numerically.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <system_error>
#include <utility>

#include <sled/sled.h>

#include "lang/builder/builder.h"
#include "lang/format/formatter.h"

namespace {

namespace build = sled::lang::build;
using build::Arrow;
using build::Call;
using build::Q;
using build::Ref;
using build::Table;
using build::V;

// One half of the occupant's body; a C++ function is a reusable piece of a scene.
void AddSegment(build::Statement& body, std::string_view name, double mass_kg, build::Value inertia,
                build::Value semi_axes) {
  body.Declare("segment", name)
      .Set("mass", Q(mass_kg, "kg"))
      .Set("inertia", inertia)
      .Block("ellipsoid")
      .Set("semi_axes", semi_axes);
}

void BuildScene(build::Scene& scene, double speed_km_h) {
  scene.Param("speed", Q(speed_km_h, "km/h"));
  scene.Set("gravity", V(0, 0, -9.81, "m/s^2"));
  scene.Block("time").Set("end", Q(200, "ms")).Set("output_every", Q(0.1, "ms"));
  scene.Declare("integrator", "auto").Set("tolerance", 1e-5).Set("max_step", Q(1, "ms"));

  auto& occupant = scene.Declare("body", "occupant");
  AddSegment(occupant, "pelvis", 11.7, V(0.10, 0.09, 0.11, "kg*m^2"), V(110, 170, 120, "mm"));
  AddSegment(occupant, "torso", 17.0, V(0.35, 0.30, 0.20, "kg*m^2"), V(120, 180, 250, "mm"));
  occupant.Joint("lumbar", "ball", "pelvis", "torso")
      .Set("at", "pelvis", V(0, 0, 120, "mm"))
      .Set("at", "torso", V(0, 0, -200, "mm"))
      .Set("flexure", Call("polynomial", {0, Q(2.5, "N*m/deg")}))
      .Set("stop", Q(45, "deg"))
      .Set("viscous", Q(1.5, "N*m*s/rad"));

  scene.Declare("vehicle", "sled")
      .Set("motion",
           Call("half_sine",
                {{"delta_v", Ref("speed")}, {"duration", Q(100, "ms")}, {"axis", -Ref("x")}}));
  scene.Declare("plane", "seat_pan")
      .On(Ref("sled"))
      .Set("corners", {V(0, -250, 0, "mm"), V(500, -250, 0, "mm"), V(0, 250, 0, "mm")});
  scene.Function("foam", Table("deflection", "force"))
      .Row(Q(0, "mm"), Q(0, "N"))
      .Row(Q(25, "mm"), Q(2, "kN"))
      .Row(Q(60, "mm"), Q(12, "kN"))
      .Set("energy_loss", 0.4);
  scene.Declare("contact", Ref("occupant.pelvis"))
      .With(Ref("seat_pan"))
      .Set("force", Ref("foam"))
      .Set("friction", 0.4);

  auto& lap = scene.Declare("belt", "lap").On(Ref("sled"));
  lap.Set("path", Arrow({V(-200, -230, 50, "mm"), Ref("occupant.pelvis"), V(-200, 230, 50, "mm")}));
  lap.Attribute("force", Table("strain", "force")).Row(0, Q(0, "N")).Row(0.1, Q(8, "kN"));
  lap.Set("slack", Q(5, "mm"));

  scene.Declare("initial", "occupant").Set("position", V(250, 0, 300, "mm"));
  auto& output = scene.Block("output");
  output.Add("acceleration", "occupant.torso").At(V(0, 0, 0, "mm"));
  output.Add("joint_torque", "occupant.lumbar");
  output.Add("contact_force", "occupant.pelvis").With(Ref("seat_pan"));
  output.Add("belt_force", "lap");
  output.Set("criteria", Call("chest_3ms", {Ref("occupant.torso")}));
}

}  // namespace

int main(int argc, char** argv) {
  double speed = 56.0;
  const char* run_directory = nullptr;
  for (int i = 1; i < argc; ++i) {
    const std::string_view argument = argv[i];
    if (argument == "--run" && i + 1 < argc) {
      run_directory = argv[++i];
    } else if (argument == "--speed" && i + 1 < argc) {
      char* end = nullptr;
      speed = std::strtod(argv[++i], &end);
      if (end == argv[i] || *end != '\0' || !std::isfinite(speed)) {
        std::fprintf(stderr, "frontal_sled_builder: --speed takes a number, found `%s`\n", argv[i]);
        return 2;
      }
    } else {
      std::fprintf(stderr, "usage: frontal_sled_builder [--speed KM_PER_H] [--run DIR]\n");
      return 2;
    }
  }

  // The scene's buffers (this file, for diagnostics) belong to the compilation.
  auto sources = std::make_unique<sled::lang::SourceManager>();
  build::Scene scene(*sources, "frontal sled, belted occupant (built in C++)");
  BuildScene(scene, speed);
  sled::lang::ast::File file = scene.Finish();
  const std::string text = sled::lang::Format(file);

  sled::CompileOptions options;
#ifdef SLED_STDLIB_DIR
  options.stdlib = SLED_STDLIB_DIR;  // the package's standard library (CMakeLists.txt)
#endif
  options.lower = run_directory != nullptr;
  const sled::Compilation compiled =
      sled::Compile(sled::Source::Tree(std::move(sources), std::move(file)), options);
  std::fputs(compiled.Render(sled::lang::DiagnosticStyle::kRich).c_str(), stderr);
  std::fputs(text.c_str(), stdout);
  if (!compiled.ok()) return 1;
  if (run_directory == nullptr) return 0;

  // --run DIR: simulate the scene and write the folder `sled run` writes.
  std::error_code error;
  std::filesystem::create_directories(run_directory, error);
  sled::OutputFolderOptions folder_options;
  folder_options.directory = run_directory;
  folder_options.notes = compiled.Notes();
  sled::OutputFolder folder(compiled.model(), folder_options);
  const sled::RunResult run = sled::Simulate(compiled.model(), {}, {&folder});
  for (const std::string& why : run.sink_errors) std::fprintf(stderr, "%s\n", why.c_str());
  if (run.failed()) {
    std::fprintf(stderr, "the run failed %s\n",
                 sled::DescribeFailure(compiled.model(), run.summary.failure).c_str());
    return 3;
  }
  std::fprintf(stderr, "%zu rows to %s\n", run.series.rows(), run_directory);
  return run.sink_errors.empty() ? 0 : 1;
}
