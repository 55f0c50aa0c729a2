// Contacts never tunnel (docs/runtime.md, "Contacts that never tunnel"): a small fast sphere
// shot at a rigid wall from several distances, with coarse and fine output steps, bounces off it
// with every method and tolerance, at the speed the conservation of energy (no damping) or an
// independent integration of the contact's force law (with damping) gives; a chain of 1 mm, 1 g
// links dropped on a floor stays on it; and a contact too soft to stop its sphere says so (W0010)
// instead of letting it pass silently. Every method but `cvs` runs with the default minimum step
// (1 ns), and every one closes its energy balance.
#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "tests/verification/compile.h"
#include "tests/verification/verification.h"

namespace sled::verification {
namespace {

// A 20 mm (radius) sphere of 0.1 kg flying along -x at `speed` towards the wall x = 0, its
// surface `distance` from it; the contact is a linear spring of 1e8 N/m (a peak deflection of
// 2.6 mm at 300 km/h, 4.4 mm at 500 km/h) with `damping`.
std::string SphereAtWall(const std::string& method) {
  return R"(scenario "fast sphere at a wall" {
  param speed = 300 km/h
  param distance = 1.09 m
  param step = 2 ms
  param tol = 1e-6
  param damping = 0 N*s/m
  param stiffness = 1e8 N/m
  param smallest = 1e-9 s
  time { end = 40 ms  output_every = step }
  integrator )" +
         method +
         R"( { tolerance = tol  min_step = smallest }
  plane wall on ground { corners = (0, -1, -1) m, (0, 1, -1) m, (0, -1, 1) m }
  body ball {
    segment sphere {
      mass = 0.1 kg
      inertia = (1.6e-5, 1.6e-5, 1.6e-5) kg*m^2
      ellipsoid { semi_axes = (20, 20, 20) mm }
    }
  }
  contact ball.sphere with wall { force = stiffness  damping = damping }
  initial ball { position = (distance + 20 mm, 0 m, 0 m)  velocity = (-speed, 0 km/h, 0 km/h) }
  output {
    position ball.sphere at (0, 0, 0) mm
    velocity ball.sphere
  }
})";
}

struct Shot {
  RunResult result;
  std::string errors;
};

Shot Fire(const std::string& method, std::vector<std::pair<std::string, std::string>> set) {
  // CVS-III's method fails its error test in the velocity at 1 ns (300 and 500 km/h from 0.05 m
  // at 1e-8); the others need no more than the default.
  if (method == "cvs") set.emplace_back("smallest", "1e-12 s");
  const Compiled compiled =
      CompileSource(Source::Text(SphereAtWall(method), "sphere_at_wall.sled"), set);
  if (!compiled.errors.empty()) return {{}, compiled.errors};
  return {sled::Simulate(compiled.model()), {}};
}

// The column of `name` in a series (time is column 0).
std::size_t Column(const runtime::TimeSeries& series, const std::string& name) {
  const auto at = std::find(series.names.begin(), series.names.end(), name);
  EXPECT_NE(at, series.names.end()) << name;
  return 1 + static_cast<std::size_t>(at - series.names.begin());
}

double Last(const runtime::TimeSeries& series, std::size_t column) {
  return series.values[(series.rows() - 1) * series.columns + column];
}

// The speed at which a sphere of mass m meeting the wall at v leaves it, from the force law
// itself: F = max(0, k d + min(1, d / depth) c d') over the deflection d (the damping ramps in
// over the first millimetre, runtime/contact/contact_table.h), integrated by the classical
// fourth-order Runge-Kutta method at 1 ns, far finer than the contact's 0.1 ms.
double ReboundSpeed(double m, double k, double c, double v) {
  constexpr double kDepth = 1e-3;
  const auto accel = [&](double d, double rate) {
    return -std::max(0.0, k * d + std::min(1.0, d / kDepth) * c * rate) / m;
  };
  double d = 0.0, rate = v;
  const double h = 1e-9;
  while (d >= 0.0) {
    const double k1d = rate, k1v = accel(d, rate);
    const double k2d = rate + h / 2 * k1v, k2v = accel(d + h / 2 * k1d, rate + h / 2 * k1v);
    const double k3d = rate + h / 2 * k2v, k3v = accel(d + h / 2 * k2d, rate + h / 2 * k2v);
    const double k4d = rate + h * k3v, k4v = accel(d + h * k3d, rate + h * k3v);
    d += h / 6 * (k1d + 2 * k2d + 2 * k3d + k4d);
    rate += h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
  }
  return -rate;
}

class ContactTunnelling : public ::testing::TestWithParam<std::string> {};

// How far the energy balance may be off (largest residual over the largest term), in tolerances:
// as far as the speed may be. The exponential method and Rosenbrock, which measure the work in
// their error test, close it to 0.2 and 20 tolerances; dopri5 (and `auto`, which is dopri5 here)
// is 0.19 off at 1e-3 and 500 km/h from 1.09 m, its rebound speed as far off as that.
constexpr double kBalance = 300.0;

TEST_P(ContactTunnelling, FastSphereBouncesOffTheWallAtEveryDistanceStepAndTolerance) {
  // Before contacts were bounded, every method carried the sphere straight through the wall at
  // every tolerance: free flight has no error, so one step spanned the 40 mm contact zone.
  for (const char* speed : {"300", "500"}) {
    const double v = std::stod(speed) / 3.6;
    for (const char* distance : {"0.05", "0.3", "1.09"}) {
      for (const char* step : {"0.1", "2", "10"}) {
        for (const double tolerance : {1e-3, 1e-5, 1e-8}) {
          const Shot shot = Fire(GetParam(), {{"speed", std::string(speed) + " km/h"},
                                              {"distance", std::string(distance) + " m"},
                                              {"step", std::string(step) + " ms"},
                                              {"tol", fmt::format("{}", tolerance)}});
          const std::string where = fmt::format("{} km/h from {} m, rows every {} ms, tol {}",
                                                speed, distance, step, tolerance);
          ASSERT_TRUE(shot.errors.empty()) << shot.errors;
          ASSERT_TRUE(shot.result.summary.complete())
              << where << ": " << shot.result.summary.failure.cause;
          const runtime::TimeSeries& series = shot.result.series;
          // Elastic: the sphere leaves with the speed it came with (energy is conserved), and
          // flies back out in front of the wall.
          const double out = Last(series, Column(series, "ball.sphere.velocity.x [m/s]"));
          EXPECT_NEAR(out / v, 1.0, std::max(300 * tolerance, 1e-6)) << where;
          EXPECT_GT(Last(series, Column(series, "ball.sphere.position.x [m]")), 0.02) << where;
          // The contact's work: the energy it stored is what it gave back.
          EXPECT_LT(shot.result.summary.energy.relative(), kBalance * tolerance) << where;
        }
      }
    }
  }
}

TEST_P(ContactTunnelling, DampedBounceLeavesWithTheForceLawsRestitution) {
  // 2,000 N s/m against 1e8 N/m and 0.1 kg: a damping ratio of 0.32.
  const double m = 0.1, k = 1e8, c = 2000;
  for (const char* speed : {"300", "500"}) {
    const double v = std::stod(speed) / 3.6;
    const double expected = ReboundSpeed(m, k, c, v);
    ASSERT_LT(expected, 0.6 * v);  // (a real loss: the restitution is far from 1)
    for (const double tolerance : {1e-3, 1e-5, 1e-8}) {
      const Shot shot = Fire(GetParam(), {{"speed", std::string(speed) + " km/h"},
                                          {"damping", "2000 N*s/m"},
                                          {"step", "10 ms"},
                                          {"tol", fmt::format("{}", tolerance)}});
      ASSERT_TRUE(shot.result.summary.complete()) << shot.result.summary.failure.cause;
      const runtime::TimeSeries& series = shot.result.series;
      const double out = Last(series, Column(series, "ball.sphere.velocity.x [m/s]"));
      EXPECT_NEAR(out / expected, 1.0, std::max(300 * tolerance, 1e-6))
          << speed << " km/h, tol " << tolerance;
      EXPECT_LT(shot.result.summary.energy.relative(), kBalance * tolerance)
          << speed << " km/h, tol " << tolerance;
    }
  }
}

// A chain of five 1 mm links of 1 g on pin joints, dropped flat (pitched 10 degrees) from 2 mm
// onto a floor, each link's ellipsoid (1 x 0.5 x 0.5 mm) in contact with it.
std::string ChainOnFloor(const std::string& method) {
  std::string text = R"(scenario "tiny chain on a floor" {
  param tol = 1e-6
  time { end = 200 ms  output_every = 10 ms }
  integrator )" + method +
                     R"( { tolerance = tol }
  plane floor on ground { corners = (-1, -1, 0) m, (1, -1, 0) m, (-1, 1, 0) m }
  body chain {
)";
  for (int i = 1; i <= 5; ++i) {
    text += fmt::format(
        "    segment link_{} {{ mass = 1 gram  inertia = (3e-11, 8e-11, 8e-11) kg*m^2\n"
        "      ellipsoid {{ semi_axes = (0.5, 0.25, 0.25) mm }} }}\n",
        i);
  }
  for (int i = 2; i <= 5; ++i) {
    text += fmt::format(
        "    joint hinge_{0} : pin(link_{1} -> link_{0}) {{\n"
        "      at link_{1} = (0.5, 0, 0) mm  at link_{0} = (-0.5, 0, 0) mm  axis = (0, 1, 0) }}\n",
        i, i - 1);
  }
  text += "  }\n";
  for (int i = 1; i <= 5; ++i) {
    text += fmt::format(
        "  contact chain.link_{} with floor {{ force = 1e4 N/m  damping = 5 N*s/m }}\n", i);
  }
  text += "  initial chain { position = (0, 0, 2) mm  orientation = (0, 10, 0) deg }\n  output {\n";
  for (int i = 1; i <= 5; ++i) {
    text += fmt::format("    position chain.link_{} at (0, 0, 0) mm\n", i);
  }
  return text + "  }\n}\n";
}

TEST_P(ContactTunnelling, ChainOfMillimetreLinksStaysOnTheFloor) {
  for (const double tolerance : {1e-3, 1e-6}) {
    const Compiled compiled = CompileSource(Source::Text(ChainOnFloor(GetParam()), "chain.sled"),
                                            {{"tol", fmt::format("{}", tolerance)}});
    ASSERT_TRUE(compiled.errors.empty()) << compiled.errors;
    const RunResult result = sled::Simulate(compiled.model());
    ASSERT_TRUE(result.summary.complete()) << result.summary.failure.cause;
    const runtime::TimeSeries& series = result.series;
    // However a link lies or tilts, its centre is at least its smallest semi-axis (0.25 mm)
    // above the floor less the contact's deflection, which its landing at under 0.2 m/s keeps
    // below v sqrt(m / k) = 0.06 mm (and its weight alone at m g / k = 1 um): at every row it
    // stays above 0.15 mm. Before the fix the links sank 1.5 mm through the floor.
    for (int i = 1; i <= 5; ++i) {
      const std::size_t z = Column(series, fmt::format("chain.link_{}.position.z [m]", i));
      for (std::size_t row = 0; row < series.rows(); ++row) {
        EXPECT_GT(series.values[row * series.columns + z], 0.15e-3)
            << "link " << i << " row " << row << ", tol " << tolerance;
      }
    }
    for (const std::string& warning : result.warnings) {
      EXPECT_EQ(warning.find("W0010"), std::string::npos) << warning;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(EveryIntegrator, ContactTunnelling, ::testing::ValuesIn(AllIntegrators()));

TEST(ContactReach, TooSoftAContactSaysTheSphereWentPastItsForceLaw) {
  // 1e5 N/m cannot stop 0.1 kg at 300 km/h within the sphere (it would need 83 mm): the
  // deflection passes the 20 mm semi-axis; at 10 N/m the sphere ends wholly behind the wall.
  const Shot deep = Fire("auto", {{"stiffness", "1e5 N/m"}});
  ASSERT_TRUE(deep.result.summary.complete());
  std::string all;
  for (const std::string& warning : deep.result.warnings) all += warning + "\n";
  EXPECT_NE(all.find("warning[W0010]: contact `ball.sphere` with `wall`: the deflection passed "
                     "the smallest semi-axis (20 mm)"),
            std::string::npos)
      << all;
  const Shot through = Fire("auto", {{"stiffness", "10 N/m"}});
  ASSERT_TRUE(through.result.summary.complete());
  all.clear();
  for (const std::string& warning : through.result.warnings) all += warning + "\n";
  EXPECT_NE(all.find("the ellipsoid went wholly behind the plane"), std::string::npos) << all;
}

}  // namespace
}  // namespace sled::verification
