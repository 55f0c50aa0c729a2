// The energy balance (runtime/run/energy.h). At single instants: the rate of change of kinetic and
// potential energy, computed from the accelerations the dynamics produced, equals the power the
// force elements, joint characteristics and constraints deliver to the segments; no integration
// is involved, so the identity holds to rounding, and it fails if a force is applied at the
// wrong point, a torque is counted twice, gravity is left in, or a mirror twin is weighted
// wrongly. Over whole runs: the balance closes to the integration error, and its terms match
// closed forms (a lossless spring's stored energy). contact_test.cpp checks the impulse losses
// and the work contacts absorb against the rebound speeds.
#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "runtime/run/energy.h"
#include "tests/verification/compile.h"
#include "tests/verification/verification.h"

namespace sled::verification {
namespace {

using runtime::Vec3;
using runtime::Vec6;

// d/dt (KE + PE) from the state and the accelerations: in each segment's frame at its centre of
// mass, d/dt (1/2 V.I V) = V.I A with A the spatial acceleration.
double EnergyRate(const runtime::Model& model, const runtime::Data& data) {
  double rate = 0.0;
  for (std::size_t s = 0; s < model.nsegment(); ++s) {
    const Vec6& v = data.velocity[s];
    const Vec6& a = data.acceleration[s];
    const Vec3 w = v.head<3>(), linear = v.tail<3>();
    const double kinetic = w.dot(model.segment_inertia[s] * a.head<3>()) +
                           model.segment_mass[s] * linear.dot(a.tail<3>());
    const double potential = -model.segment_mass[s] * model.gravity.dot(data.rotation[s] * linear);
    rate += runtime::MirrorWeight(model, s) * (kinetic + potential);
  }
  return rate;
}

// Runs the scene to each time and compares the two sides there.
void ExpectPowerMatches(const std::string& text, const std::vector<double>& times) {
  const Compiled compiled = CompileText(text);
  ASSERT_EQ(compiled.errors, "");
  const runtime::Model& model = compiled.model();
  runtime::Data data = runtime::MakeData(model);
  int samples = 0;
  const bool ok = Simulate(model, data, "exponential", 1e-6, times, [&](const runtime::Data& d) {
    const runtime::SegmentPower power = runtime::PowerIntoSegments(model, d);
    const double rate = EnergyRate(model, d);
    const double total = power.elements + power.constraints;
    // Rounding of sums of terms of the size of the largest single power.
    double scale = 1.0;
    for (std::size_t s = 0; s < model.nsegment(); ++s) {
      scale = std::max(scale, std::abs(d.external[s].dot(d.velocity[s])));
    }
    EXPECT_NEAR(rate, total, 1e-9 * scale) << "at t = " << d.time;
    EXPECT_GT(std::abs(total), 1e-3) << "nothing acts at t = " << d.time;
    ++samples;
  });
  ASSERT_TRUE(ok);
  EXPECT_EQ(samples, static_cast<int>(times.size()));
}

std::string ReadExample(const std::string& name) {
  std::ifstream in(std::filesystem::path(SLED_SOURCE_ROOT) / "examples" / name);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(EnergyPower, FlagshipContactsAndBeltsOnAMovingSled) {
  ExpectPowerMatches(ReadExample("frontal_sled.sled"), {0.02, 0.06, 0.09, 0.15});
}

TEST(EnergyPower, SpringsToAMovingVehicle) {
  ExpectPowerMatches(R"(scenario "springs" {
  import std.humans.male50 as occupant
  time { end = 100 ms  output_every = 1 ms }
  vehicle sled { motion = half_sine(delta_v = 30 km/h, duration = 80 ms, axis = -x) }
  spring tether : occupant.lower_leg_l -> sled {
    at occupant.lower_leg_l = (0, 0, 150) mm
    at sled = (600, 85, 0) mm
    stiffness = 20 kN/m
    damping = 100 N*s/m
    free_length = 400 mm
  }
  tension strap : occupant.pelvis -> sled {
    at occupant.pelvis = (-100, 0, 0) mm
    at sled = (-300, 0, 150) mm
    stiffness = table(elongation -> force) { 0 mm -> 0 N  10 mm -> 5 kN }
  }
  initial occupant { position = (0, 0, 150) mm }
})",
                     {0.01, 0.04, 0.07});
}

TEST(EnergyPower, ConstraintToAMovingVehicle) {
  ExpectPowerMatches(R"(scenario "hung bar" {
  time { end = 100 ms  output_every = 1 ms }
  vehicle sled { motion = half_sine(delta_v = 30 km/h, duration = 80 ms, axis = -x) }
  body bar {
    segment rod { mass = 1 kg  inertia = (0.02, 0.02, 0.0001) kg*m^2 }
  }
  constraint pivot : fixed_point(sled -> bar.rod) {
    at sled = (0, 0, 2) m
    at bar.rod = (0, 0, 250) mm
  }
  initial bar { position = (0, 0, 1.75) m }
})",
                     {0.01, 0.04, 0.07});
}

TEST(EnergyPower, MirrorTwinsCountTwice) {
  ExpectPowerMatches(R"(scenario "two arms" {
  time { end = 300 ms  output_every = 5 ms }
  symmetry mirror { pair = b.arm_l, b.arm_r }
  function shoulder = table(angle -> torque) { -3 rad -> -60 N*m  0 rad -> 0 N*m  3 rad -> 60 N*m }
  body b {
    segment trunk { mass = 30 kg  inertia = (1.2, 1.0, 0.4) kg*m^2 }
    segment arm_l { mass = 2 kg  inertia = (0.012, 0.012, 0.003) kg*m^2 }
    segment arm_r { mass = 2 kg  inertia = (0.012, 0.012, 0.003) kg*m^2 }
    joint shoulder_l : ball(trunk -> arm_l) { at trunk = (0.05, 0.2, 0.3) m  at arm_l = (0, 0, 0.15) m
                                              flexure = shoulder  viscous = 0.3 N*m*s/rad }
    joint shoulder_r : ball(trunk -> arm_r) { at trunk = (0.05, -0.2, 0.3) m  at arm_r = (0, 0, 0.15) m
                                              flexure = shoulder  viscous = 0.3 N*m*s/rad }
  }
  initial b { position = (0, 0, 1) m  orientation = (0, 10, 0) deg  velocity = (2, 0, 1) m/s
              angular_velocity = (0, 1.5, 0) rad/s }
  initial b.shoulder_l { angles = (25, -40, 30) deg }
  initial b.shoulder_r { angles = (-25, -40, -30) deg }
})",
                     {0.05, 0.15, 0.25});
}

// Two-segment arms under a pinned trunk on a pulsed sled, the forearms striking a table on the
// sled: the forearms hang below the twins' top segments, where the mirror image enters the
// dynamics; they stand for their right twins all the same, in their energy and in the work the
// table does through them.
std::string ArmsOnATable(bool mirror) {
  return std::string(R"(scenario "two-segment arms on a table" {
  time { end = 150 ms  output_every = 1 ms }
  gravity = (0, 0, 9.81) m/s^2
  vehicle sled { motion = half_sine(delta_v = 20 km/h, duration = 80 ms, axis = -x) }
  plane table on sled { corners = (0, -0.5, -0.22) m, (0, 0.5, -0.22) m, (0.5, -0.5, -0.22) m }
  )") +
         (mirror ? "symmetry mirror { pair = b.upper_l, b.upper_r  pair = b.fore_l, b.fore_r }"
                 : "") +
         R"(
  function shoulder = table(angle -> torque) { -3 rad -> -60 N*m  0 rad -> 0 N*m  3 rad -> 60 N*m }
  function elbow = polynomial(angle -> torque, 0 N*m, 15 N*m/rad)
  function pad = polynomial(deflection -> force, 0 N, 30 kN/m)
  body b {
    segment trunk { mass = 30 kg  inertia = (1.2, 1.0, 0.4) kg*m^2 }
    segment upper_l { mass = 2 kg  inertia = (0.012, 0.012, 0.003) kg*m^2 }
    segment upper_r { mass = 2 kg  inertia = (0.012, 0.012, 0.003) kg*m^2 }
    segment fore_l { mass = 1.5 kg  inertia = (0.002, 0.009, 0.009) kg*m^2
                     ellipsoid { semi_axes = (0.13, 0.04, 0.04) m } }
    segment fore_r { mass = 1.5 kg  inertia = (0.002, 0.009, 0.009) kg*m^2
                     ellipsoid { semi_axes = (0.13, 0.04, 0.04) m } }
    joint shoulder_l : ball(trunk -> upper_l) { at trunk = (0, 0.2, -0.25) m  at upper_l = (0, 0, -0.14) m
                                                flexure = shoulder  viscous = 0.3 N*m*s/rad }
    joint shoulder_r : ball(trunk -> upper_r) { at trunk = (0, -0.2, -0.25) m  at upper_r = (0, 0, -0.14) m
                                                flexure = shoulder  viscous = 0.3 N*m*s/rad }
    joint elbow_l : ball(upper_l -> fore_l) { at upper_l = (0, 0, 0.14) m  at fore_l = (-0.12, 0, 0) m
                                              flexure = elbow  viscous = 0.1 N*m*s/rad  stop = 30 deg }
    joint elbow_r : ball(upper_r -> fore_r) { at upper_r = (0, 0, 0.14) m  at fore_r = (-0.12, 0, 0) m
                                              flexure = elbow  viscous = 0.1 N*m*s/rad  stop = 30 deg }
  }
  constraint hip : fixed_point(sled -> b.trunk) {
    at sled = (0, 0, 0) m
    at b.trunk = (0, 0, 0.3) m
  }
  contact b.fore_l with table { force = pad  friction = 0.4 }
  contact b.fore_r with table { force = pad  friction = 0.4 }
  initial b { position = (0, 0, -0.3) m }
})";
}

TEST(EnergyPower, MirrorTwinsCountTwiceBelowTheirTopSegment) {
  ExpectPowerMatches(ArmsOnATable(true), {0.03, 0.07, 0.12});
}

TEST(EnergyBalance, MirrorTwinLimbsOfTwoSegmentsCloseAndMatchTheFullModel) {
  const SceneRun mirrored = RunText(ArmsOnATable(true));
  const SceneRun full = RunText(ArmsOnATable(false));
  ASSERT_EQ(mirrored.errors, "");
  ASSERT_EQ(full.errors, "");
  ASSERT_FALSE(mirrored.summary.failed) << mirrored.summary.failure.cause;
  ASSERT_FALSE(full.summary.failed) << full.summary.failure.cause;
  ASSERT_LT(mirrored.nv, full.nv);  // the right arm is left out
  const runtime::EnergySummary& m = mirrored.summary.energy;
  const runtime::EnergySummary& f = full.summary.energy;
  EXPECT_LT(m.relative(), 1e-4) << m.largest_residual << " J of " << m.scale;
  // The table and the joints take work: the forearms strike it.
  EXPECT_GT(m.absorbed, 0.05 * m.scale);
  // The same scene computed whole: the mirrored terms are its terms, to the integration error.
  const double tolerance = 1e-4 * f.scale;
  EXPECT_NEAR(m.kinetic, f.kinetic, tolerance);
  EXPECT_NEAR(m.potential, f.potential, tolerance);
  EXPECT_NEAR(m.absorbed, f.absorbed, tolerance);
  EXPECT_NEAR(m.prescribed_work, f.prescribed_work, tolerance);
}

TEST(EnergyBalance, AMirroredPairOfBodiesCountsTwice) {
  // Two separate bodies as a mirror pair: the left one is the top of its own subtree (it hangs
  // from nothing) and stands for the right one. The kinetic and potential energies are those of
  // the whole scene.
  auto scene = [](bool mirror) {
    return std::string(R"(scenario "thrown pair" {
  time { end = 100 ms  output_every = 1 ms }
  gravity = (0, 0, 9.81) m/s^2
  )") + (mirror ? "symmetry mirror { pair = l.s, r.s }" : "") +
           R"(
  body c { segment s { mass = 5 kg  inertia = (0.1, 0.1, 0.1) kg*m^2 } }
  body l { segment s { mass = 1 kg  inertia = (0.01, 0.02, 0.03) kg*m^2 } }
  body r { segment s { mass = 1 kg  inertia = (0.01, 0.02, 0.03) kg*m^2 } }
  initial c { velocity = (1, 0, -2) m/s }
  initial l { position = (0, 0.5, 0) m  velocity = (3, 1, -1) m/s  angular_velocity = (1, 0, 2) rad/s }
  initial r { position = (0, -0.5, 0) m  velocity = (3, -1, -1) m/s  angular_velocity = (-1, 0, -2) rad/s }
})";
  };
  const SceneRun mirrored = RunText(scene(true));
  const SceneRun full = RunText(scene(false));
  ASSERT_EQ(mirrored.errors, "");
  ASSERT_EQ(full.errors, "");
  ASSERT_LT(mirrored.nv, full.nv);  // the right body is left out
  // Closed form at the end (free flight): 1/2 m v^2 + 1/2 w.I w with v = v0 + g t, per body.
  const double t = 0.1, g = 9.81;
  auto flight = [&](double m, double vx, double vy, double vz) {
    const double vz_end = vz + g * t;
    return 0.5 * m * (vx * vx + vy * vy + vz_end * vz_end);
  };
  const double spin = 0.5 * (0.01 * 1 + 0.03 * 4);
  const double kinetic = flight(5, 1, 0, -2) + 2 * (flight(1, 3, 1, -1) + spin);
  EXPECT_NEAR(mirrored.summary.energy.kinetic, kinetic, 1e-6 * kinetic);
  EXPECT_NEAR(full.summary.energy.kinetic, kinetic, 1e-6 * kinetic);
  EXPECT_NEAR(mirrored.summary.energy.potential, full.summary.energy.potential, 1e-6 * kinetic);
}

TEST(EnergyBalance, FlagshipClosesWithinATenthOfAPercent) {
  const SceneRun run = RunText(ReadExample("frontal_sled.sled"));
  ASSERT_EQ(run.errors, "");
  ASSERT_FALSE(run.summary.failed) << run.summary.failure.cause;
  const runtime::EnergySummary& energy = run.summary.energy;
  EXPECT_LT(energy.relative(), 1e-3) << energy.largest_residual << " J of " << energy.scale;
  // The sled brings the occupant to 56 km/h: the prescribed motion does work, and the belts,
  // contacts and joints absorb part of it.
  EXPECT_GT(energy.prescribed_work, 0.5 * 77 * 15.5 * 15.5);
  EXPECT_GT(energy.absorbed, 0.0);
}

TEST(EnergyBalance, TheAirbagFlagshipClosesToo) {
  // The gas's work on the head and thorax, and the wheel's reaction on the moving sled, are
  // element work like any other: the balance closes with the bag as without.
  const SceneRun run = RunText(ReadExample("frontal_sled_airbag.sled"));
  ASSERT_EQ(run.errors, "");
  ASSERT_FALSE(run.summary.failed) << run.summary.failure.cause;
  EXPECT_LT(run.summary.energy.relative(), 1e-3)
      << run.summary.energy.largest_residual << " J of " << run.summary.energy.scale;
}

TEST(EnergyBalance, ALosslessSpringStoresWhatItAbsorbs) {
  // A bob hangs from a sled on a linear spring; the sled is pulsed sideways. Nothing dissipates,
  // so the absorbed work is the spring's energy F^2 / (2 k) at every row, while the sled's work
  // goes into the bob's motion.
  for (const std::string& method : AllIntegrators()) {
    const SceneRun run = RunText(R"(scenario "bob on a spring" {
  time { end = 150 ms  output_every = 1 ms }
  integrator )" + method + R"( { tolerance = 1e-8 }
  vehicle sled { motion = half_sine(delta_v = 30 km/h, duration = 80 ms, axis = -x) }
  body bob { segment mass { mass = 2 kg  inertia = (0.01, 0.01, 0.01) kg*m^2 } }
  spring hanger : sled -> bob.mass {
    at sled = (0, 0, 1) m
    at bob.mass = (0, 0, 0) m
    stiffness = 2 kN/m
    free_length = 500 mm
  }
  initial bob { position = (0, 0, 0.5) m }
  output { spring_force hanger }
})");
    ASSERT_EQ(run.errors, "");
    ASSERT_FALSE(run.summary.failed) << run.summary.failure.cause;
    const runtime::EnergySummary& energy = run.summary.energy;
    const double force = run.series.values.back();  // the last row's spring force
    EXPECT_NEAR(energy.absorbed, force * force / (2 * 2000.0), 1e-6 * energy.scale) << method;
    EXPECT_LT(energy.relative(), 1e-6) << method;
    EXPECT_GT(energy.prescribed_work, 1.0) << method;
  }
}

}  // namespace
}  // namespace sled::verification
