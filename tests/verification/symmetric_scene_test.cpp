// A scene that is its own mirror image gives mirror-image results: a trunk with two arms, each
// with a contact ellipsoid, drops at an angle onto a floor with friction and damping, so both
// hands strike, slide and bounce. Every left channel must equal its right twin's mirror image
// (y and the moments about x and z change sign), at every output row, on every integrator: the
// contact geometry, the force law, friction and the dynamics may not favour one side.
#include <cmath>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "runtime/run/run.h"
#include "tests/verification/compile.h"
#include "tests/verification/verification.h"

namespace sled::verification {
namespace {

std::string Scene(const std::string& method) {
  return fmt::format(R"(scenario "symmetric drop" {{
  time {{ end = 400 ms  output_every = 2 ms }}
  integrator {0} {{ tolerance = 1e-9  abs_tolerance = 1e-12 }}
  plane floor {{ corners = (-2, -2, 0) m, (2, -2, 0) m, (-2, 2, 0) m }}
  body b {{
    segment trunk {{ mass = 30 kg  inertia = (1.2, 1.0, 0.4) kg*m^2
                    ellipsoid {{ semi_axes = (120, 150, 150) mm }} }}
    segment arm_l {{ mass = 2 kg  inertia = (0.012, 0.012, 0.003) kg*m^2
                    ellipsoid {{ semi_axes = (50, 50, 180) mm }} }}
    segment arm_r {{ mass = 2 kg  inertia = (0.012, 0.012, 0.003) kg*m^2
                    ellipsoid {{ semi_axes = (50, 50, 180) mm }} }}
    joint shoulder_l : ball(trunk -> arm_l) {{ at trunk = (0, 0.22, 0.25) m  at arm_l = (0, 0, 0.17) m
                                              viscous = 0.5 N*m*s/rad }}
    joint shoulder_r : ball(trunk -> arm_r) {{ at trunk = (0, -0.22, 0.25) m  at arm_r = (0, 0, 0.17) m
                                              viscous = 0.5 N*m*s/rad }}
  }}
  initial b {{ position = (0, 0, 0.75) m  orientation = (0, 25, 0) deg  velocity = (1.5, 0, -1) m/s }}
  initial b.shoulder_l {{ angles = (20, -30, 15) deg }}
  initial b.shoulder_r {{ angles = (-20, -30, -15) deg }}
  function foam = table(deflection -> force) {{ 0 mm -> 0 N  10 mm -> 2 kN  30 mm -> 12 kN }}
  contact b.arm_l with floor {{ force = foam  damping = 200 N*s/m  friction = 0.4 }}
  contact b.arm_r with floor {{ force = foam  damping = 200 N*s/m  friction = 0.4 }}
  output {{
    position b.arm_l at (0, 0.02, -0.15) m
    position b.arm_r at (0, -0.02, -0.15) m
    angular_velocity b.arm_l
    angular_velocity b.arm_r
    contact_force b.arm_l with floor
    contact_force b.arm_r with floor
  }}
}}
)",
                     method);
}

class SymmetricScene : public ::testing::TestWithParam<std::string> {};

TEST_P(SymmetricScene, GivesMirrorImageResults) {
  const SceneRun run = RunText(Scene(GetParam()));
  ASSERT_EQ(run.errors, "");
  ASSERT_FALSE(run.summary.failed)
      << run.summary.failure.where << ": " << run.summary.failure.cause;
  const runtime::TimeSeries& series = run.series;
  auto column = [&](const std::string& name) {
    for (std::size_t c = 0; c < series.names.size(); ++c) {
      if (series.names[c] == name) return c + 1;
    }
    ADD_FAILURE() << "no channel " << name;
    return std::size_t{0};
  };
  // (left channel, right channel, sign of the right one's mirror image)
  struct Pair {
    std::string left, right;
    double sign;
  };
  const std::vector<Pair> pairs = {
      {"b.arm_l.position.x [m]", "b.arm_r.position.x [m]", 1},
      {"b.arm_l.position.y [m]", "b.arm_r.position.y [m]", -1},
      {"b.arm_l.position.z [m]", "b.arm_r.position.z [m]", 1},
      {"b.arm_l.angular_velocity.x [rad/s]", "b.arm_r.angular_velocity.x [rad/s]", -1},
      {"b.arm_l.angular_velocity.y [rad/s]", "b.arm_r.angular_velocity.y [rad/s]", 1},
      {"b.arm_l.angular_velocity.z [rad/s]", "b.arm_r.angular_velocity.z [rad/s]", -1},
      {"b.arm_l.floor.contact_force.x [N]", "b.arm_r.floor.contact_force.x [N]", 1},
      {"b.arm_l.floor.contact_force.y [N]", "b.arm_r.floor.contact_force.y [N]", -1},
      {"b.arm_l.floor.contact_force.z [N]", "b.arm_r.floor.contact_force.z [N]", 1},
  };
  double peak_force = 0.0;
  for (const Pair& pair : pairs) {
    const std::size_t l = column(pair.left), r = column(pair.right);
    ASSERT_GT(l, 0u);
    ASSERT_GT(r, 0u);
    double scale = 0.0, worst = 0.0;
    for (std::size_t row = 0; row < series.rows(); ++row) {
      const double left = series.values[row * series.columns + l];
      const double right = series.values[row * series.columns + r];
      scale = std::max(scale, std::abs(left));
      worst = std::max(worst, std::abs(left - pair.sign * right));
    }
    if (pair.left.find("contact_force.z") != std::string::npos) peak_force = scale;
    EXPECT_LE(worst, 1e-6 * std::max(scale, 1e-3)) << pair.left << " (range " << scale << ")";
  }
  // The hands do strike the floor.
  EXPECT_GT(peak_force, 10.0);
}

INSTANTIATE_TEST_SUITE_P(EveryIntegrator, SymmetricScene, ::testing::ValuesIn(AllIntegrators()));

}  // namespace
}  // namespace sled::verification
