// Mirror symmetry against the full model: a trunk with two arms, each a ball-jointed upper arm
// and a pinned forearm, started in a mirror-symmetric, three-dimensional posture. Run once with
// every degree of freedom and once with `symmetry mirror`, which leaves the right arm out and
// hands the trunk the mirror image of the left arm's articulated inertia and bias. Every output
// — the trunk, the left arm, and the right arm's outputs mirrored from the left — must agree
// with the full model to the integrators' tolerance.
#include <cmath>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "runtime/run/run.h"
#include "tests/verification/compile.h"

namespace sled::verification {
namespace {

std::string Scene(const std::string& symmetry) {
  return fmt::format(R"(scenario "two arms" {{
  time {{ end = 600 ms  output_every = 5 ms }}
  integrator dopri5 {{ tolerance = 1e-10  abs_tolerance = 1e-12 }}
  {0}
  function shoulder = table(angle -> torque) {{ -3 rad -> -60 N*m  0 rad -> 0 N*m  3 rad -> 60 N*m }}
  body b {{
    segment trunk {{ mass = 30 kg  inertia = (1.2, 1.0, 0.4) kg*m^2 }}
    segment arm_l {{ mass = 2 kg  inertia = (0.012, 0.012, 0.003) kg*m^2 }}
    segment arm_r {{ mass = 2 kg  inertia = (0.012, 0.012, 0.003) kg*m^2 }}
    segment hand_l {{ mass = 1.5 kg  inertia = (0.008, 0.009, 0.002) kg*m^2 }}
    segment hand_r {{ mass = 1.5 kg  inertia = (0.008, 0.009, 0.002) kg*m^2 }}
    joint shoulder_l : ball(trunk -> arm_l) {{ at trunk = (0.05, 0.2, 0.3) m  at arm_l = (0, 0, 0.15) m
                                              flexure = shoulder  viscous = 0.3 N*m*s/rad }}
    joint shoulder_r : ball(trunk -> arm_r) {{ at trunk = (0.05, -0.2, 0.3) m  at arm_r = (0, 0, 0.15) m
                                              flexure = shoulder  viscous = 0.3 N*m*s/rad }}
    joint elbow_l : pin(arm_l -> hand_l) {{ at arm_l = (0, 0.02, -0.15) m  at hand_l = (0, 0, 0.12) m
                                           axis = (1, 0, 1)  viscous = 0.1 N*m*s/rad }}
    joint elbow_r : pin(arm_r -> hand_r) {{ at arm_r = (0, -0.02, -0.15) m  at hand_r = (0, 0, 0.12) m
                                           axis = (-1, 0, -1)  viscous = 0.1 N*m*s/rad }}
  }}
  initial b {{ position = (0, 0, 1) m  orientation = (0, 10, 0) deg  velocity = (2, 0, 1) m/s
              angular_velocity = (0, 1.5, 0) rad/s }}
  initial b.shoulder_l {{ angles = (25, -40, 30) deg }}
  initial b.shoulder_r {{ angles = (-25, -40, -30) deg }}
  initial b.elbow_l {{ angles = (50, 0, 0) deg }}
  initial b.elbow_r {{ angles = (50, 0, 0) deg }}
  output {{
    position b.trunk
    angular_velocity b.trunk
    position b.hand_l at (0, 0.03, -0.1) m
    position b.hand_r at (0, -0.03, -0.1) m
    velocity b.arm_r
    acceleration b.hand_r at (0.02, -0.01, 0) m
    angular_velocity b.hand_r
    angular_acceleration b.arm_r
    orientation b.hand_r
    joint_torque b.shoulder_r
    joint_force b.elbow_r
    joint_angle b.elbow_r
  }}
}}
)",
                     symmetry);
}

runtime::TimeSeries RunScene(const std::string& text, std::size_t* nv) {
  SceneRun run = RunText(text);
  EXPECT_EQ(run.errors, "");
  EXPECT_FALSE(run.summary.failed)
      << run.summary.failure.where << ": " << run.summary.failure.cause;
  *nv = run.nv;
  return std::move(run.series);
}

TEST(MirrorSymmetry, AgreesWithTheFullModelOnBothSides) {
  std::size_t full_nv = 0, mirror_nv = 0;
  const runtime::TimeSeries full = RunScene(Scene(""), &full_nv);
  const runtime::TimeSeries mirror = RunScene(
      Scene("symmetry mirror { pair = b.arm_l, b.arm_r  pair = b.hand_l, b.hand_r }"), &mirror_nv);
  // Trunk 6 + two arms (3 + 1 each) = 14; with the mirror: trunk in the plane (3) + left arm.
  EXPECT_EQ(full_nv, 14u);
  EXPECT_EQ(mirror_nv, 7u);
  ASSERT_EQ(full.names, mirror.names);
  ASSERT_EQ(full.rows(), mirror.rows());
  ASSERT_GT(full.rows(), 100u);
  // Each channel against the full model, relative to the channel's largest value.
  for (std::size_t c = 1; c < full.columns; ++c) {
    double scale = 0.0, worst = 0.0;
    for (std::size_t r = 0; r < full.rows(); ++r) {
      scale = std::max(scale, std::abs(full.values[r * full.columns + c]));
    }
    for (std::size_t r = 0; r < full.rows(); ++r) {
      worst = std::max(worst, std::abs(full.values[r * full.columns + c] -
                                       mirror.values[r * mirror.columns + c]));
    }
    EXPECT_LE(worst, 1e-6 * std::max(scale, 1e-3))
        << full.names[c - 1] << " (scale " << scale << ")";
  }
}

// The arms of a trunk swing into a block in the plane: the Model leaves the right arm's contact
// out, and the block must feel it all the same (the mirror image of the left arm's push), or the
// block moves on as if struck by one arm and the contact does work the arms do not lose.
std::string ArmsStrikeABlock(const std::string& symmetry) {
  return fmt::format(R"(scenario "arms strike a block" {{
  time {{ end = 200 ms  output_every = 2 ms }}
  integrator dopri5 {{ tolerance = 1e-10  abs_tolerance = 1e-12 }}
  gravity = (0, 0, 0) m/s^2
  {0}
  function soft = polynomial(deflection -> force, 0 N, 20 kN/m)
  body b {{
    segment trunk {{ mass = 30 kg  inertia = (1.2, 1.0, 0.4) kg*m^2 }}
    segment arm_l {{ mass = 2 kg  inertia = (0.012, 0.012, 0.003) kg*m^2
                    ellipsoid {{ semi_axes = (0.05, 0.05, 0.15) m }} }}
    segment arm_r {{ mass = 2 kg  inertia = (0.012, 0.012, 0.003) kg*m^2
                    ellipsoid {{ semi_axes = (0.05, 0.05, 0.15) m }} }}
    joint shoulder_l : ball(trunk -> arm_l) {{ at trunk = (0, 0.2, 0.3) m  at arm_l = (0, 0, 0.15) m }}
    joint shoulder_r : ball(trunk -> arm_r) {{ at trunk = (0, -0.2, 0.3) m  at arm_r = (0, 0, 0.15) m }}
  }}
  body k {{
    segment block {{ mass = 5 kg  inertia = (0.1, 0.1, 0.1) kg*m^2
                    ellipsoid {{ semi_axes = (0.1, 0.4, 0.1) m }} }}
  }}
  contact b.arm_l with k.block {{ force = soft  friction = 0.3 }}
  contact b.arm_r with k.block {{ force = soft  friction = 0.3 }}
  initial b.shoulder_l {{ angles = (10, 15, 0) deg }}
  initial b.shoulder_r {{ angles = (-10, 15, 0) deg }}
  initial k {{ position = (0.3, 0, 0.13) m  velocity = (-2, 0, 0.2) m/s
              angular_velocity = (0, 3, 0) rad/s }}
  output {{
    position k.block
    velocity k.block
    angular_velocity k.block
    position b.trunk
    position b.arm_r at (0, 0, -0.1) m
    velocity b.arm_r
  }}
}}
)",
                     symmetry);
}

TEST(MirrorSymmetry, ABlockInThePlaneFeelsBothTwinsContacts) {
  std::size_t full_nv = 0, mirror_nv = 0;
  const runtime::TimeSeries full = RunScene(ArmsStrikeABlock(""), &full_nv);
  const runtime::TimeSeries mirror =
      RunScene(ArmsStrikeABlock("symmetry mirror { pair = b.arm_l, b.arm_r }"), &mirror_nv);
  EXPECT_LT(mirror_nv, full_nv);
  ASSERT_EQ(full.names, mirror.names);
  ASSERT_EQ(full.rows(), mirror.rows());
  // The block is struck: its x velocity turns from -2 m/s.
  const std::size_t vx = 4;  // time, position x y z, velocity x
  ASSERT_EQ(full.names[vx - 1].rfind("k.block.velocity.x", 0), 0u) << full.names[vx - 1];
  EXPECT_GT(full.values[(full.rows() - 1) * full.columns + vx], -1.0);
  for (std::size_t c = 1; c < full.columns; ++c) {
    double scale = 0.0, worst = 0.0;
    for (std::size_t r = 0; r < full.rows(); ++r) {
      scale = std::max(scale, std::abs(full.values[r * full.columns + c]));
      worst = std::max(worst, std::abs(full.values[r * full.columns + c] -
                                       mirror.values[r * mirror.columns + c]));
    }
    EXPECT_LE(worst, 1e-6 * std::max(scale, 1e-3))
        << full.names[c - 1] << " (scale " << scale << ")";
  }
}

}  // namespace
}  // namespace sled::verification
