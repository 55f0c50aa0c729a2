// W0004 (an ellipsoid that starts buried) against the runtime: the lint fires exactly when the
// simulation's own contact geometry, at the run's initial state, finds the ellipsoid more than a
// millimetre into the surface with a force acting. Vehicles yawed and pitched, bodies turned,
// joints bent, ellipsoids beside finite planes and against other ellipsoids.
#include <cmath>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "lang/diagnostics/diagnostic.h"
#include "runtime/dynamics/dynamics.h"
#include "sled/compile.h"

namespace sled::compiler {
namespace {

struct Verdict {
  bool checked = false;
  int lint_warnings = 0;            // W0004
  int runtime_buried = 0;           // pairs deeper than 1 mm with a force at the start
  std::vector<std::string> errors;  // of the check
};

Verdict Judge(const std::string& text) {
  CompileOptions options;
  options.stdlib = std::string(SLED_SOURCE_ROOT) + "/stdlib";
  const Compilation compiled = Compile(Source::Text(text), options);
  Verdict verdict;
  for (const auto& d : compiled.diagnostics()) {
    if (d.code() == "W0004") ++verdict.lint_warnings;
    if (d.severity == lang::Severity::kError) verdict.errors.push_back(d.message);
  }
  if (!compiled.ok()) return verdict;
  const runtime::Model& model = compiled.model();
  runtime::Data data = runtime::MakeData(model);
  runtime::Failure failure;
  if (!runtime::Forward(model, data, &failure)) return verdict;
  verdict.checked = true;
  for (std::size_t k = 0; k < model.contacts.npair(); ++k) {
    if (data.contacts.deflection[k] > 1e-3 && data.contacts.normal_force[k] > 0) {
      ++verdict.runtime_buried;
    }
  }
  return verdict;
}

// A hood (a finite plane on a car turned by `yaw` and `pitch`), and an occupant whose upper arm
// hangs from a shoulder pin bent by `bend` (an ellipsoid 300 mm long) and a head ellipsoid,
// placed at `at` in the ground frame; the car's nose holds an ellipsoid the head may touch.
std::string Scene(double yaw, double pitch, double bend, double x, double y, double z) {
  return fmt::format(R"(scenario "hood" {{
  time {{ end = 10 ms  output_every = 1 ms }}
  vehicle car {{ orientation = ({0}, {1}, 0) deg  position = (100, -50, 0) mm }}
  plane hood on car {{ corners = (-500, -300, 500) mm, (500, -300, 500) mm, (-500, 300, 500) mm }}
  ellipsoid nose on car {{ semi_axes = (80, 200, 60) mm  center = (700, 0, 600) mm }}
  body p {{
    segment torso {{
      mass = 30 kg
      inertia = (1, 1, 0.3) kg*m^2
      ellipsoid {{ semi_axes = (100, 150, 250) mm }}
    }}
    segment arm {{
      mass = 2 kg
      inertia = (0.02, 0.02, 0.002) kg*m^2
      ellipsoid {{ semi_axes = (45, 45, 150) mm }}
    }}
    joint shoulder : pin(torso -> arm) {{
      at torso = (0, 200, 200) mm
      at arm = (0, 0, 150) mm
      axis = y
    }}
  }}
  contact p.arm with hood {{ force = 10 kN/m }}
  contact p.torso with hood {{ force = 10 kN/m }}
  contact p.torso with nose {{ force = 10 kN/m }}
  initial p {{ position = ({3}, {4}, {5}) mm  orientation = (30, 0, 0) deg }}
  initial p.shoulder {{ angles = ({2}, 0, 0) deg }}
}}
)",
                     yaw, pitch, bend, x, y, z);
}

TEST(LintBuried, AnArmBesideTheHoodOfAYawedCarIsNotBuried) {
  // The car yawed 90 degrees: the hood spans x = -300..300 mm, y = -400..600 mm in the ground
  // frame, 500 mm up. The arm hangs 230 mm clear of its side edge, below its level: the runtime
  // finds no contact (the old lint took the arm's height as a margin beside the plane).
  const std::string scene = R"(scenario "hood" {
  time { end = 10 ms  output_every = 1 ms }
  vehicle car { orientation = (90, 0, 0) deg }
  plane hood on car { corners = (-500, -300, 500) mm, (500, -300, 500) mm, (-500, 300, 500) mm }
  body p {
    segment arm {
      mass = 2 kg
      inertia = (0.02, 0.02, 0.002) kg*m^2
      ellipsoid { semi_axes = (45, 45, 300) mm }
    }
  }
  contact p.arm with hood { force = 10 kN/m }
  initial p { position = (575, 0, 450) mm }
}
)";
  const Verdict verdict = Judge(scene);
  ASSERT_TRUE(verdict.errors.empty()) << verdict.errors.front();
  ASSERT_TRUE(verdict.checked);
  EXPECT_EQ(verdict.runtime_buried, 0);
  EXPECT_EQ(verdict.lint_warnings, 0);
}

TEST(LintBuried, TheLintFiresExactlyWhereTheRuntimeStartsWithABuriedContact) {
  int scenes = 0, buried = 0;
  for (const double yaw : {0.0, 90.0, 37.0, -120.0}) {
    for (const double pitch : {0.0, 15.0}) {
      for (const double bend : {0.0, 60.0}) {
        for (double x = -700; x <= 700; x += 140) {
          for (double z = 500; z <= 1000; z += 125) {
            const Verdict verdict = Judge(Scene(yaw, pitch, bend, x, 0.4 * x, z));
            ASSERT_TRUE(verdict.errors.empty()) << verdict.errors.front();
            ASSERT_TRUE(verdict.checked);
            EXPECT_EQ(verdict.lint_warnings, verdict.runtime_buried)
                << "yaw " << yaw << ", pitch " << pitch << ", bend " << bend << ", at (" << x
                << ", " << 0.4 * x << ", " << z << ") mm";
            ++scenes;
            buried += verdict.runtime_buried > 0;
          }
        }
      }
    }
  }
  // The sweep has scenes of both kinds.
  EXPECT_GT(buried, scenes / 10);
  EXPECT_LT(buried, scenes - scenes / 10);
}

}  // namespace
}  // namespace sled::compiler
