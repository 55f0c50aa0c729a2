// The public C++ API of sled (docs/architecture.md): compile a scene, simulate the Model, hand
// the run to sinks.
//
//   #include <sled/sled.h>
//
//   sled::Compilation compiled = sled::Compile(sled::Source::File("frontal_sled.sled"));
//   std::cerr << compiled.Render();                      // diagnostics, one line each
//   if (!compiled.ok()) return 1;
//   sled::OutputFolder folder(compiled.model(), {.directory = "out"});
//   sled::RunResult run = sled::Simulate(compiled.model(), {}, {&folder});
//
// From another CMake project: find_package(sled) and link sled::sled.
#pragma once

#include "sled/compile.h"        // IWYU pragma: export
#include "sled/output_folder.h"  // IWYU pragma: export
#include "sled/simulate.h"       // IWYU pragma: export
