// Settling against closed forms: a ball settled on a linear foam floor starts the run at the
// static deflection m g / k, slower than the settling tolerance, with the contact force equal to
// its weight, and stays there through the (undamped) run; a ball settled in a vehicle moving at
// a steady speed starts with the velocity the scene gave it; a scene that cannot settle in its
// settling time fails the run, saying what still moved.
#include <cmath>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "tests/verification/compile.h"

namespace sled::verification {
namespace {

constexpr double kMass = 10.0;        // kg
constexpr double kRadius = 0.1;       // m
constexpr double kStiffness = 2.0e4;  // N/m
constexpr double kGravity = 9.81;     // m/s^2

// The ball starts 2 cm above its resting height, so settling has a drop and a rebound to damp.
std::string BallOnFoam(const std::string& settle, const std::string& vehicle = "",
                       const std::string& velocity = "(0, 0, 0) m/s") {
  return R"(scenario "settle" {
  gravity = (0, 0, -9.81) m/s^2
  time { end = 100 ms  output_every = 1 ms }
  )" + settle +
         "\n" + vehicle + R"(
  body ball {
    segment s {
      mass = 10 kg
      inertia = (0.04, 0.04, 0.04) kg*m^2
      ellipsoid { semi_axes = (100, 100, 100) mm }
    }
  }
  plane floor )" +
         (vehicle.empty() ? "" : "on cart ") +
         R"({ corners = (-1, -1, 0) m, (1, -1, 0) m, (-1, 1, 0) m }
  contact ball.s with floor { force = 20 kN/m  damping = 50 N*s/m }
  initial ball { position = (0, 0, 120) mm  velocity = )" +
         velocity + R"( }
  output {
    position ball.s at (0, 0, 0) mm
    velocity ball.s at (0, 0, 0) mm
    acceleration ball.s at (0, 0, 0) mm
    contact_force ball.s with floor
  }
}
)";
}

double At(const SceneRun& run, std::size_t row, const std::string& column) {
  const auto& names = run.series.names;
  for (std::size_t c = 0; c < names.size(); ++c) {
    if (names[c] == column) return run.series.values[row * run.series.columns + 1 + c];
  }
  ADD_FAILURE() << "no column " << column;
  return NAN;
}

TEST(Settle, ABallOnFoamStartsAtRestAtTheStaticDeflection) {
  const SceneRun run = RunText(BallOnFoam("settle { duration = 3 s  velocity = 0.2 mm/s }"));
  ASSERT_TRUE(run.errors.empty()) << run.errors;
  ASSERT_FALSE(run.summary.failed) << run.summary.failure.cause;
  ASSERT_TRUE(run.summary.settle.converged);
  EXPECT_GT(run.summary.settle.time, 0.0);
  EXPECT_LE(run.summary.settle.largest_velocity, 2e-4);

  // The stated threshold, read from the run's first row: every velocity below 0.2 mm/s.
  const double vx = At(run, 0, "ball.s.velocity.x [m/s]");
  const double vy = At(run, 0, "ball.s.velocity.y [m/s]");
  const double vz = At(run, 0, "ball.s.velocity.z [m/s]");
  EXPECT_LT(std::sqrt(vx * vx + vy * vy + vz * vz), 2e-4);

  // Static equilibrium: k d = m g. The test holds with a speed below v = 0.2 mm/s and an
  // acceleration below v per 10 ms, 0.02 m/s^2; at omega = sqrt(k/m) = 44.7 rad/s that leaves
  // the ball at most a / omega^2 = 1.0e-5 m from equilibrium, oscillating with an amplitude of
  // at most hypot(v / omega, a / omega^2) = 1.1e-5 m: 0.23 % of d.
  const double deflection = kMass * kGravity / kStiffness;  // 4.905 mm
  const double amplitude = std::hypot(2e-4 / 44.72, 0.02 / 2000.0);
  const double z0 = At(run, 0, "ball.s.position.z [m]");
  EXPECT_NEAR(kRadius - z0, deflection, amplitude);
  EXPECT_NEAR(At(run, 0, "ball.s.floor.contact_force.z [N]"), kMass * kGravity,
              kStiffness * amplitude);
  // The run itself is not damped (but for the contact's own 50 N*s/m), and the ball stays where
  // it settled: within twice the amplitude.
  for (std::size_t row = 0; row < run.series.rows(); ++row) {
    ASSERT_NEAR(At(run, row, "ball.s.position.z [m]"), z0, 2 * amplitude) << "row " << row;
  }
}

TEST(Settle, TheRunKeepsTheVelocityTheSceneGives) {
  // A cart moving steadily at 10 m/s with the ball on it: the ball settles in the cart's frame
  // and starts the run at the cart's speed, resting on its floor.
  const SceneRun run = RunText(BallOnFoam(
      "settle { duration = 3 s }", "vehicle cart { velocity = (10, 0, 0) m/s }", "(10, 0, 0) m/s"));
  ASSERT_TRUE(run.errors.empty()) << run.errors;
  ASSERT_FALSE(run.summary.failed) << run.summary.failure.cause;
  const std::size_t last = run.series.rows() - 1;
  EXPECT_NEAR(At(run, 0, "ball.s.velocity.x [m/s]"), 10.0, 1e-9);
  EXPECT_NEAR(At(run, last, "ball.s.velocity.x [m/s]"), 10.0, 1e-6);
  EXPECT_NEAR(At(run, last, "ball.s.position.x [m]") - At(run, 0, "ball.s.position.x [m]"),
              10.0 * 0.1, 1e-6);
  // Settled to 1 mm/s and 0.1 m/s^2: within 0.1 / omega^2 + 1e-3 / omega = 7.2e-5 m of the
  // static deflection.
  EXPECT_NEAR(kRadius - At(run, 0, "ball.s.position.z [m]"), kMass * kGravity / kStiffness, 7.2e-5);
}

TEST(Settle, ASceneThatCannotSettleInTimeFailsTheRun) {
  const SceneRun run = RunText(BallOnFoam("settle { duration = 20 ms }"));
  ASSERT_TRUE(run.errors.empty()) << run.errors;
  EXPECT_TRUE(run.summary.failed);
  EXPECT_FALSE(run.summary.settle.converged);
  EXPECT_THAT(run.summary.failure.cause, ::testing::HasSubstr("did not settle in 0.02 s"));
  EXPECT_EQ(run.series.rows(), 0u);
}

}  // namespace
}  // namespace sled::verification
