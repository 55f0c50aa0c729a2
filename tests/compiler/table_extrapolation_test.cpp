// Table functions left at run time are reported, once per element, with when and how far, on
// standard error and in summary.json: against the closed form of a ball on a linear contact
// whose table ends before the ball stops, and for a joint swinging past its table's rows.
#include <cmath>
#include <numbers>
#include <string>

#include <fmt/format.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/compiler/sled_process.h"

namespace sled {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using testing::ReadText;
using testing::SledResult;

using TableExtrapolation = testing::SledProcessTest;

// A 2 kg ball at 3 m/s, without gravity (the default is -9.81 m/s^2 along z), onto a floor whose
// contact force is 200 kN/m written as a table that ends at `rows_to` mm. The extrapolation
// continues the same line, so the motion is a linear spring's: contact at t0 = gap / v, deflection
// x(t) = X sin(w (t - t0)) with w = sqrt(k / m) and X = v / w.
std::string Ball(double rows_to_mm) {
  return fmt::format(R"(scenario "ball" {{
  gravity = (0, 0, 0) m/s^2
  time {{ end = 40 ms  output_every = 0.1 ms }}
  integrator dopri5 {{ tolerance = 1e-9 }}
  body ball {{
    segment s {{
      mass = 2 kg
      inertia = (0.002, 0.002, 0.002) kg*m^2
      ellipsoid {{ semi_axes = (50, 50, 50) mm }}
    }}
  }}
  plane floor on ground {{ corners = (-1, -1, 0) m, (1, -1, 0) m, (-1, 1, 0) m }}
  function stiff = table(deflection -> force) {{
    0 mm -> 0 N
    {0} mm -> {1} N
  }}
  contact ball.s with floor {{ force = stiff }}
  initial ball {{ position = (0, 0, 80) mm  velocity = (0, 0, -3) m/s }}
  output {{ position ball.s at (0, 0, 0) mm }}
}}
)",
                     rows_to_mm, 200e3 * rows_to_mm * 1e-3);
}

TEST_F(TableExtrapolation, AContactPastItsTableIsReportedOnceWithTimeAndDepth) {
  const double k = 200e3, m = 2.0, v = 3.0, gap = 0.030;
  const double w = std::sqrt(k / m), depth = v / w;  // 9.49 mm
  const double rows_to = 0.005;
  const double first_time = gap / v + std::asin(rows_to / depth) / w;
  const fs::path scene = temp() / "ball.sled";
  testing::WriteText(scene, Ball(rows_to * 1e3));
  const fs::path out = temp() / "out";
  const SledResult result = Sled({"run", scene.string(), "-o", out.string()});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  // Once, however many steps run past the row.
  const std::string line = "contact `ball.s` with `floor` left its table's rows";
  EXPECT_EQ(result.err.find(line), result.err.rfind(line)) << result.err;
  EXPECT_THAT(result.err, HasSubstr("sled: warning: " + line + " (deflection [m] 0 to 0.005)"));
  const auto summary = nlohmann::json::parse(ReadText(out / "summary.json"));
  ASSERT_EQ(summary["table_extrapolations"].size(), 1u);
  const auto& e = summary["table_extrapolations"][0];
  EXPECT_EQ(e["element"], "contact `ball.s` with `floor`");
  EXPECT_EQ(e["rows_to"].get<double>(), rows_to);
  // Watched at every accepted step and at every output row, 0.1 ms apart: the first crossing is
  // reported at the first row or step end after it, and the deepest point as the deepest of
  // them, at most half a row h from the peak: X (1 - cos(w h / 2)) below it.
  const double row = 1e-4;
  EXPECT_GE(e["first_time"].get<double>(), first_time - 1e-9);
  EXPECT_LE(e["first_time"].get<double>(), first_time + row);
  EXPECT_LE(e["farthest_argument"].get<double>(), depth * (1 + 1e-6));
  EXPECT_GE(e["farthest_argument"].get<double>(), depth * std::cos(w * row / 2) - 1e-9);
  EXPECT_THAT(ReadText(out / "summary.json"), HasSubstr("left its table's rows"));  // a warning
}

TEST_F(TableExtrapolation, AContactWithinItsTableIsNotReported) {
  const fs::path scene = temp() / "ball.sled";
  testing::WriteText(scene, Ball(20.0));  // deeper than the 9.49 mm the ball reaches
  const fs::path out = temp() / "out";
  const SledResult result = Sled({"run", scene.string(), "-o", out.string()});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_EQ(result.err.find("left its table"), std::string::npos) << result.err;
  const auto summary = nlohmann::json::parse(ReadText(out / "summary.json"));
  EXPECT_TRUE(summary["table_extrapolations"].empty());
}

TEST_F(TableExtrapolation, AJointSwingingPastItsTableIsReported) {
  // A pendulum released at 60 degrees from a pin whose flexure table spans +-20 degrees.
  const fs::path scene = temp() / "swing.sled";
  testing::WriteText(scene, R"(scenario "swing" {
  gravity = (0, 0, -9.81) m/s^2
  time { end = 1 s  output_every = 1 ms }
  body arm {
    reference = base
    segment base { mass = 100 kg  inertia = (1, 1, 1) kg*m^2 }
    segment link { mass = 1 kg  inertia = (0.01, 0.01, 0.001) kg*m^2 }
    joint hinge : pin(base -> link) {
      at base = (0, 0, 0) mm
      at link = (0, 0, 200) mm
      axis = y
      flexure = table(angle -> torque) { -20 deg -> -0.1 N*m  20 deg -> 0.1 N*m }
    }
  }
  constraint hold : fixed_point(ground -> arm.base) {
    at ground = (0, 0, 0) mm
    at arm.base = (0, 0, 0) mm
  }
  initial arm.hinge { angles = (60, 0, 0) deg }
  output { joint_angle arm.hinge }
}
)");
  const SledResult result = Sled({"run", scene.string(), "-o", (temp() / "out").string()});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_THAT(result.err, HasSubstr("joint `arm.hinge` flexure left its table's rows (angle [rad] "
                                    "-0.349066 to 0.349066) at t = 0 s, at 1.0472"));
}

}  // namespace
}  // namespace sled
