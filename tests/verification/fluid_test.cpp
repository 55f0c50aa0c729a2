// Wind and water (`wind`, `water`; runtime/forces/fluid_forces.h) against closed forms: a sphere
// falling through a steady updraft follows w(t) = -vt tanh(g t / vt + atanh(W / vt)) relative to
// the air (vt its terminal speed); a sphere released in a steady side wind without gravity lags
// the air by W / (1 + k W t / m); an ellipsoid of half the water's density for its volume floats
// with its centre at the surface and heaves with the period 2 pi sqrt(2 c / (3 g)) of the
// waterplane area pi a b; one of a quarter of it floats at the depth of the cubic
// (1 + t)^2 (2 - t) = 1; and the energy balance closes with the fluids' work (counted with the
// applied loads') for a sphere dropped into water with drag.
#include <cmath>
#include <numbers>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "tests/verification/compile.h"

namespace sled::verification {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kG = 9.80665;

// A free sphere of radius r [m] and mass m [kg] with `fluid` (a wind or water block) acting on
// it, starting at `position` [m].
std::string Sphere(double m, double r, const std::string& gravity, const std::string& fluid,
                   const std::string& position, double end) {
  const double inertia = 0.4 * m * r * r;
  return fmt::format(R"(scenario "fluid" {{
  gravity = {}
  time {{ end = {} s  output_every = 1 ms }}
  integrator dopri5 {{ tolerance = 1e-10 }}
  body b {{
    segment s {{
      mass = {} kg  inertia = ({}, {}, {}) kg*m^2
      ellipsoid {{ semi_axes = ({}, {}, {}) m }}
    }}
  }}
  initial b {{ position = {} m }}
  {}
  output {{
    position b.s at (0, 0, 0) m
    velocity b.s at (0, 0, 0) m
  }}
}}
)",
                     gravity, end, m, inertia, inertia, inertia, r, r, r, position, fluid);
}

TEST(Wind, ASphereFallsThroughASteadyUpdraftAtItsTerminalSpeedRelativeToTheAir) {
  const double m = 0.1, r = 0.1, rho = 1.225, cd = 0.5, wind = 4.0;
  const SceneRun run = RunText(
      Sphere(m, r, "(0, 0, -9.80665) m/s^2",
             fmt::format("wind {{ speed = {} m/s  direction = z  density = {} kg/m^3  drag = {}  "
                         "segments = b.s }}",
                         wind, rho, cd),
             "(0, 0, 0)", 3.0));
  ASSERT_EQ(run.errors, "");
  ASSERT_FALSE(run.summary.failed);
  const double k = 0.5 * rho * cd * kPi * r * r;  // drag = k u^2
  const double terminal = std::sqrt(m * kG / k);  // 10.1 m/s
  double largest = 0.0;
  for (std::size_t row = 0; row < run.series.rows(); ++row) {
    const double t = TimeAt(run.series, row);
    const double expected =
        wind - terminal * std::tanh(kG * t / terminal + std::atanh(wind / terminal));
    const double v = ChannelAt(run.series, "b.s.velocity.z [m/s]", row);
    largest = std::max(largest, std::abs(v - expected));
  }
  EXPECT_LT(largest, 1e-7 * terminal);
  // By 3 s the sphere falls at 99.6 % of its terminal speed relative to the air.
  const double last = ChannelAt(run.series, "b.s.velocity.z [m/s]", run.series.rows() - 1);
  EXPECT_NEAR(last - wind, -terminal, 0.005 * terminal);
}

TEST(Wind, ASphereInASideWindLagsTheAirAsTheQuadraticLawSays) {
  const double m = 0.2, r = 0.05, rho = 1.2, cd = 1.0, wind = 20.0;
  const SceneRun run = RunText(Sphere(
      m, r, "(0, 0, 0) m/s^2",
      fmt::format("wind {{ speed = {} m/s  direction = (0, 1, 0)  density = {} kg/m^3  drag = "
                  "{}  segments = b.s }}",
                  wind, rho, cd),
      "(0, 0, 0)", 1.0));
  ASSERT_EQ(run.errors, "");
  const double c = 0.5 * rho * cd * kPi * r * r / m;
  for (std::size_t row = 0; row < run.series.rows(); row += 50) {
    const double t = TimeAt(run.series, row);
    const double lag = wind / (1 + c * wind * t);
    const double y = wind * t - std::log(1 + c * wind * t) / c;
    EXPECT_NEAR(ChannelAt(run.series, "b.s.velocity.y [m/s]", row), wind - lag, 1e-8 * wind) << t;
    EXPECT_NEAR(ChannelAt(run.series, "b.s.position.y [m]", row), y, 1e-8) << t;
    EXPECT_NEAR(ChannelAt(run.series, "b.s.velocity.x [m/s]", row), 0.0, 1e-12) << t;
  }
  // The air's work is the sphere's kinetic energy.
  EXPECT_GT(run.summary.energy.applied_work, 1.0);
  EXPECT_LT(run.summary.energy.relative(), 1e-8);
}

TEST(Wind, TwoWindsEachDragTheirOwnSphere) {
  // Sphere b in 20 m/s along y (Cd 1), sphere c in 10 m/s along x (Cd 0.5, air of 1.0 kg/m^3),
  // no gravity: each lags its own air as W / (1 + k W t / m), k = 0.5 rho Cd pi r^2, and feels
  // nothing of the other's.
  const double m = 0.2, r = 0.05;
  const std::string sphere = fmt::format(
      "segment s {{ mass = {} kg  inertia = ({}, {}, {}) kg*m^2  ellipsoid {{ semi_axes = ({}, "
      "{}, {}) m }} }}",
      m, 0.4 * m * r * r, 0.4 * m * r * r, 0.4 * m * r * r, r, r, r);
  const SceneRun run = RunText(fmt::format(R"(scenario "two winds" {{
  gravity = (0, 0, 0) m/s^2
  time {{ end = 1 s  output_every = 1 ms }}
  integrator dopri5 {{ tolerance = 1e-10 }}
  body b {{ {0} }}
  body c {{ {0} }}
  initial c {{ position = (0, 1, 0) m }}
  wind {{ speed = 20 m/s  direction = (0, 1, 0)  density = 1.2 kg/m^3  segments = b.s }}
  wind {{ speed = 10 m/s  direction = x  density = 1.0 kg/m^3  drag = 0.5  segments = c.s }}
  output {{
    velocity b.s at (0, 0, 0) m
    velocity c.s at (0, 0, 0) m
  }}
}}
)",
                                           sphere));
  ASSERT_EQ(run.errors, "");
  ASSERT_EQ(run.series.rows(), 1001u);
  struct Air {
    const char* along;
    const char* across;
    double speed, rho, cd;
  };
  for (const auto& [along, across, speed, rho, cd] :
       {Air{"b.s.velocity.y [m/s]", "b.s.velocity.x [m/s]", 20.0, 1.2, 1.0},
        Air{"c.s.velocity.x [m/s]", "c.s.velocity.y [m/s]", 10.0, 1.0, 0.5}}) {
    const double k = 0.5 * rho * cd * kPi * r * r / m;
    for (std::size_t row = 0; row < run.series.rows(); row += 50) {
      const double t = TimeAt(run.series, row);
      EXPECT_NEAR(ChannelAt(run.series, along, row), speed - speed / (1 + k * speed * t),
                  1e-8 * speed)
          << along << " " << t;
      EXPECT_NEAR(ChannelAt(run.series, across, row), 0.0, 1e-12) << across << " " << t;
    }
  }
}

TEST(Wind, AirCarriedByAVehicleMovesWithItAndTurnsWithIt) {
  // A car at 15 m/s along x, its air still in it (`speed = 0`): the sphere, at rest in the
  // ground, lags the car's air as W / (1 + k W t / m) with W = 15 m/s.
  const double m = 0.2, r = 0.05, rho = 1.2, w = 15.0;
  const SceneRun carried = RunText(
      Sphere(m, r, "(0, 0, 0) m/s^2",
             fmt::format("vehicle car {{ velocity = ({}, 0, 0) m/s }}\n"
                         "  wind {{ speed = 0 m/s  direction = x  carried_by = car  density = {} "
                         "kg/m^3  segments = b.s }}",
                         w, rho),
             "(0, 0, 0)", 1.0));
  ASSERT_EQ(carried.errors, "");
  ASSERT_EQ(carried.series.rows(), 1001u);
  const double k = 0.5 * rho * kPi * r * r / m;
  for (std::size_t row = 0; row < carried.series.rows(); row += 50) {
    const double t = TimeAt(carried.series, row);
    EXPECT_NEAR(ChannelAt(carried.series, "b.s.velocity.x [m/s]", row), w - w / (1 + k * w * t),
                1e-8 * w)
        << t;
  }
  // A blast of 2 kPa along the x of a car yawed 90 degrees pushes along the ground's y with
  // Cd p pi r^2: y = p pi r^2 t^2 / (2 m).
  const double p = 2000.0;
  const SceneRun blast = RunText(Sphere(
      m, r, "(0, 0, 0) m/s^2",
      fmt::format("vehicle car {{ velocity = (0, 0, 0) m/s }}\n"
                  "  initial car {{ orientation = (90, 0, 0) deg }}\n"
                  "  wind {{ pressure = {} Pa  direction = x  carried_by = car  segments = b.s }}",
                  p),
      "(0, 0, 0)", 0.2));
  ASSERT_EQ(blast.errors, "");
  ASSERT_EQ(blast.series.rows(), 201u);
  for (std::size_t row = 0; row < blast.series.rows(); row += 50) {
    const double t = TimeAt(blast.series, row);
    EXPECT_NEAR(ChannelAt(blast.series, "b.s.position.y [m]", row),
                p * kPi * r * r * t * t / (2 * m), 1e-9)
        << t;
    EXPECT_NEAR(ChannelAt(blast.series, "b.s.position.x [m]", row), 0.0, 1e-9) << t;
  }
}

TEST(Wind, ASegmentInTwoWindsIsRefused) {
  const SceneRun run = RunText(Sphere(0.2, 0.05, "(0, 0, 0) m/s^2",
                                      "wind { speed = 20 m/s  direction = y  segments = b.s }\n"
                                      "  wind { speed = 10 m/s  direction = x  segments = b.s }",
                                      "(0, 0, 0)", 0.1));
  EXPECT_NE(run.errors.find("E0425"), std::string::npos) << run.errors;
  EXPECT_NE(run.errors.find("two winds"), std::string::npos) << run.errors;
}

// An upright ellipsoid (c vertical) of mass m floating in water of level 0.
std::string Floating(double m, double z0, double drag) {
  return fmt::format(R"(scenario "float" {{
  time {{ end = 3 s  output_every = 1 ms }}
  integrator dopri5 {{ tolerance = 1e-11 }}
  body b {{
    segment s {{
      mass = {} kg  inertia = (0.1, 0.1, 0.1) kg*m^2
      ellipsoid {{ semi_axes = (0.2, 0.15, 0.1) m }}
    }}
  }}
  initial b {{ position = (0, 0, {}) m }}
  water {{ level = 0 m  density = 1000 kg/m^3  drag = {}  segments = b.s }}
  output {{ position b.s at (0, 0, 0) m }}
}}
)",
                     m, z0, drag);
}

constexpr double kVolume = 4.0 / 3.0 * kPi * 0.2 * 0.15 * 0.1;

TEST(Water, AnEllipsoidOfHalfTheWatersMassHeavesAboutTheSurfaceWithItsWaterplanePeriod) {
  const double m = 1000 * kVolume / 2, amplitude = 1e-3;
  const SceneRun run = RunText(Floating(m, amplitude, 0.0));
  ASSERT_EQ(run.errors, "");
  ASSERT_FALSE(run.summary.failed);
  // Upward zero crossings, linearly interpolated between output rows.
  std::vector<double> crossings;
  double low = 0.0, high = 0.0;
  for (std::size_t row = 1; row < run.series.rows(); ++row) {
    const double z0 = ChannelAt(run.series, "b.s.position.z [m]", row - 1);
    const double z1 = ChannelAt(run.series, "b.s.position.z [m]", row);
    low = std::min(low, z1);
    high = std::max(high, z1);
    if (z0 < 0 && z1 >= 0) {
      const double t0 = TimeAt(run.series, row - 1), t1 = TimeAt(run.series, row);
      crossings.push_back(t0 + (t1 - t0) * (-z0) / (z1 - z0));
    }
  }
  ASSERT_GE(crossings.size(), 5u);
  const double period = (crossings.back() - crossings.front()) / double(crossings.size() - 1);
  const double expected = 2 * kPi * std::sqrt(2 * 0.1 / (3 * kG));  // 0.518 s
  EXPECT_NEAR(period, expected, 1e-4 * expected);
  // The restoring force is odd about the surface: the heave is symmetric about it.
  EXPECT_NEAR(high, amplitude, 1e-7);
  EXPECT_NEAR(low, -amplitude, 1e-7);
}

TEST(Water, AnEllipsoidOfAQuarterOfTheWatersMassFloatsAtTheDepthOfTheCubic) {
  // (1 + t)^2 (2 - t) / 4 = 1/4: t, the surface's height above the centre over c, by bisection.
  double a = -1.0, b = 1.0;
  for (int i = 0; i < 200; ++i) {
    const double t = (a + b) / 2;
    ((1 + t) * (1 + t) * (2 - t) < 1 ? a : b) = t;
  }
  const double t = (a + b) / 2;  // -0.3473
  const double z = -t * 0.1;     // the centre 34.7 mm above the surface
  const SceneRun run = RunText(Floating(1000 * kVolume / 4, z, 1.0));
  ASSERT_EQ(run.errors, "");
  for (std::size_t row = 0; row < run.series.rows(); row += 100) {
    EXPECT_NEAR(ChannelAt(run.series, "b.s.position.z [m]", row), z, 1e-9);
  }
}

TEST(Water, TheEnergyBalanceClosesWithTheWorkOfBuoyancyAndDrag) {
  const double m = 0.5, r = 0.06;  // 0.55 of the water's mass for its volume
  const SceneRun run =
      RunText(Sphere(m, r, "(0, 0, -9.80665) m/s^2",
                     "water { level = 0 m  density = 1000 kg/m^3  drag = 0.5  segments = b.s }",
                     "(0, 0, 0.3)", 3.0));
  ASSERT_EQ(run.errors, "");
  ASSERT_FALSE(run.summary.failed);
  // The water takes the fall's energy: its work is negative and the balance closes with it.
  EXPECT_LT(run.summary.energy.applied_work, -0.5 * m * kG * 0.3);
  EXPECT_LT(run.summary.energy.relative(), 1e-7);
}

}  // namespace
}  // namespace sled::verification
