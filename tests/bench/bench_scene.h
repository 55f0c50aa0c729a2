// The generated 1,000-line scene of the front-end benchmarks: a chain body of segments and
// joints with torque functions, contact ellipsoids, a vehicle with surfaces and contacts, and
// outputs, so every checker stage is exercised. 80 segments give just over 1,000 lines.
#pragma once

#include <algorithm>
#include <string>

#include <benchmark/benchmark.h>
#include <fmt/format.h>

#include "compiler/check/check.h"
#include "lang/syntax/parser.h"

namespace sled::bench {

inline std::string MakeScenario(int segments) {
  std::string text = "// generated benchmark scene\nscenario \"bench\" {\n";
  text += "  param speed = 56 km/h\n  time { end = 200 ms  output_every = 0.1 ms }\n";
  text += "  integrator exponential { tolerance = 1e-5 }\n";
  text += "  vehicle sled { motion = half_sine(delta_v = speed, duration = 100 ms, axis = -x) }\n";
  text +=
      "  plane floor on sled { corners = (-2000, -1000, 0) mm, (2000, -1000, 0) mm, "
      "(-2000, 1000, 0) mm }\n";
  text +=
      "  function foam = table(deflection -> force) {\n    0 mm -> 0 N\n    25 mm -> 2 kN\n"
      "    60 mm -> 12 kN\n    energy_loss = 0.4\n  }\n";
  text += "  body chain {\n";
  for (int i = 0; i < segments; ++i) {
    text += fmt::format(
        "    segment s{0} {{\n      mass = {1} kg\n      inertia = (0.10, 0.09, 0.11) kg*m^2\n"
        "      ellipsoid {{ semi_axes = (60, 60, 120) mm  center = (0, 0, 10) mm }}\n    }}\n",
        i, 2.0 + 0.01 * i);
  }
  for (int i = 1; i < segments; ++i) {
    text += fmt::format(
        "    joint j{0} : ball(s{1} -> s{0}) {{\n      at s{1} = (0, 0, 150) mm\n"
        "      at s{0} = (0, 0, -150) mm\n      flexure = polynomial(0, 2.5 N*m/deg, "
        "0.01 N*m/deg^2)\n      viscous = 1.5 N*m*s/rad\n      stop = 45 deg\n    }}\n",
        i, i - 1);
  }
  text += "  }\n  initial chain { position = (0, 0, 3000) mm }\n";
  for (int i = 0; i < segments; i += 4) {
    text += fmt::format("  contact chain.s{} with floor {{ force = foam  friction = 0.4 }}\n", i);
  }
  text += "  output {\n";
  for (int i = 0; i < segments; i += 4) {
    text += fmt::format("    acceleration chain.s{} at (0, 0, 0) mm\n", i);
  }
  text += "    criteria = hic15(chain.s0)\n  }\n}\n";
  return text;
}

inline int CountLines(const std::string& text) {
  return static_cast<int>(std::count(text.begin(), text.end(), '\n'));
}

// Parses and checks `text` as a new file, as `sled check` does; true when it has errors.
inline bool ParseAndCheck(const std::string& text) {
  lang::SourceManager sources;
  const lang::FileId file = sources.Add("bench.sled", text);
  lang::DiagnosticCollector diagnostics;
  compiler::CheckOptions options;
  options.diagnostics = &diagnostics;
  auto scenario = compiler::ParseAndCheck(sources, file, options);
  benchmark::DoNotOptimize(scenario);
  return diagnostics.has_errors();
}

}  // namespace sled::bench
