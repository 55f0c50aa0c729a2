// Belts against independent answers. A small sphere (the "point mass", radius 2 cm) sits in
// front of a straight belt between two anchors, (0, -L, 0) and (0, L, 0), and moves into it
// along x. The webbing wraps the sphere's far side; its length with the centre at x is, by
// circle geometry,
//
//   l(x) = 2 sqrt(d^2 - r^2) + r (2 pi - gamma - 2 alpha),
//   d = sqrt(L^2 + x^2),  gamma = 2 atan(L / x) (the angle P-C-Q),  alpha = acos(r / d),
//
// and a linear webbing function f = K strain stores K (l - l_rest)^2 / (2 l_rest). The tests
// check: the largest excursion against the energy balance solved for x by bisection; the speed
// after a rebound against the energy the unloading parameters leave; the onset of force with
// slack against l(x) = l(x0) + slack; the initial tension with pretension, and the conservation of
// energy while the pretensioned belt pulls; the capstan law exp(mu theta) when a spinning,
// wrapped sphere drags the webbing; and a harness whose two belts share a frictionless tie point.
#include <cmath>
#include <numbers>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "runtime/forces/forces.h"
#include "runtime/run/outputs.h"
#include "tests/verification/compile.h"
#include "tests/verification/verification.h"

namespace sled::verification {
namespace {

using runtime::Data;
using runtime::Model;
using runtime::Vec3;
constexpr double kPi = std::numbers::pi;

struct Scene {
  double radius = 0.02;
  double mass = 1.0;
  double inertia = 0.4 * 1.0 * 0.02 * 0.02;
  double half_length = 0.5;
  double x0 = 0.05;
  double speed = 2.0;
  double spin = 0.0;
  double stiffness = 20000.0;  // N per unit strain
  double slack = 0.0;
  double pretension = 0.0;
  double friction = 0.0;
  double energy_loss = 0.0;
  double permanent_set = 0.0;
  std::string atb;  // `atb(...)` of ATB's law instead of energy_loss and permanent_set
};

std::string Text(const Scene& s) {
  return fmt::format(
      R"(scenario "belt" {{
  gravity = (0, 0, 0) m/s^2
  time {{ end = 1 s  output_every = 1 ms }}
  function webbing = table(strain -> force) {{
    0 -> 0 N
    1 -> {} N
    {}
  }}
  body ball {{
    segment s {{
      mass = {} kg
      inertia = ({}, {}, {}) kg*m^2
      ellipsoid {{ semi_axes = ({}, {}, {}) m }}
    }}
  }}
  belt strap {{
    path = (0, {}, 0) m -> ball.s -> (0, {}, 0) m
    force = webbing
    slack = {} m
    pretension = {} N
    friction = {}
  }}
  initial ball {{
    position = ({}, 0, 0) m
    velocity = ({}, 0, 0) m/s
    angular_velocity = (0, 0, {}) rad/s
  }}
  output {{ belt_force strap }}
}}
)",
      s.stiffness,
      s.atb.empty()
          ? fmt::format("energy_loss = {}  permanent_set = {}", s.energy_loss, s.permanent_set)
          : "unloading = " + s.atb,
      s.mass, s.inertia, s.inertia, s.inertia, s.radius, s.radius, s.radius, -s.half_length,
      s.half_length, s.slack, s.pretension, s.friction, s.x0, s.speed, s.spin);
}

// Compiles a scene; an empty model (and a test failure) when it does not compile.
Model Compile(const std::string& text) {
  const Compiled compiled = CompileText(text);
  if (!compiled.errors.empty()) {
    ADD_FAILURE() << "the scene does not check:\n" << compiled.errors << text;
    return Model{};
  }
  return compiled.model();
}

// The webbing's length with the sphere's centre at x > 0 (circle geometry, above).
double WrappedLength(const Scene& s, double x) {
  const double r = s.radius, half = s.half_length;
  const double d = std::hypot(half, x);
  const double gamma = 2 * std::atan2(half, x), alpha = std::acos(r / d);
  return 2 * std::sqrt(d * d - r * r) + r * (2 * kPi - gamma - 2 * alpha);
}

// The x > x0 at which the webbing is `length` long (the length grows with x).
double PositionAtLength(const Scene& s, double length) {
  double low = s.x0, high = 10 * s.half_length;
  for (int k = 0; k < 200; ++k) {
    const double mid = 0.5 * (low + high);
    (WrappedLength(s, mid) < length ? low : high) = mid;
  }
  return 0.5 * (low + high);
}

Vec3 BallVelocity(const Data& data) {
  return runtime::PointInFrame(data, {runtime::FrameRef::Kind::kSegment, 0}, Vec3::Zero()).velocity;
}

// Elastic energy of the webbing for a linear function K strain, from the spans' state.
double WebbingEnergy(const Data& data, double stiffness) {
  double energy = 0.0;
  for (std::size_t i = 0; i < data.belts.length.size(); ++i) {
    const double rest = data.belts.rest_length[i];
    const double strain = std::max(data.belts.length[i] / rest - 1.0, 0.0);
    energy += 0.5 * stiffness * strain * strain * rest;
  }
  return energy;
}

class BeltExcursion : public ::testing::TestWithParam<std::string> {};

TEST_P(BeltExcursion, MatchesTheEnergyBalance) {
  const Scene scene;
  const Model model = Compile(Text(scene));
  ASSERT_EQ(model.belts.size(), 1u);
  Data data = runtime::MakeData(model);
  // All the kinetic energy ends in the webbing: K (l - l0)^2 / (2 l0) = m v^2 / 2.
  const double rest = WrappedLength(scene, scene.x0);
  const double longest = rest + scene.speed * std::sqrt(scene.mass * rest / scene.stiffness);
  const double expected = PositionAtLength(scene, longest);
  EXPECT_NEAR(data.belts.rest_length[0] + data.belts.rest_length[1], rest, 1e-12);
  double furthest = 0.0, largest_tension = 0.0;
  ASSERT_TRUE(Simulate(model, data, GetParam(), 1e-10, Linspace(0, 0.1, 5000), [&](const Data& d) {
    furthest = std::max(furthest, d.position[0].x());
    largest_tension = std::max(largest_tension, d.belts.tension[0]);
    // Symmetric: both spans carry the same tension.
    EXPECT_NEAR(d.belts.tension[0], d.belts.tension[1], 1e-8 * d.belts.tension[0] + 1e-9);
  }));
  std::printf("  %s: excursion %.9f m, energy balance %.9f m, peak tension %.1f N\n",
              GetParam().c_str(), furthest, expected, largest_tension);
  EXPECT_NEAR(furthest, expected, 1e-6);
  EXPECT_NEAR(largest_tension, scene.stiffness * (longest - rest) / rest, 1e-3);
}

INSTANTIATE_TEST_SUITE_P(EveryIntegrator, BeltExcursion, ::testing::ValuesIn(AllIntegrators()));

TEST(BeltUnloading, ReboundKeepsWhatTheUnloadingReturns) {
  struct Case {
    double loss, set, kept;  // kept: the fraction of the kinetic energy after the rebound
  };
  // A linear function loaded once: energy loss G keeps 1 - G; a permanent set p alone unloads
  // along a straight line to p x_max, which keeps 1 - p of a linear spring's energy.
  for (const Case c :
       {Case{0.0, 0.0, 1.0}, Case{0.4, 0.0, 0.6}, Case{0.0, 0.3, 0.7}, Case{0.4, 0.2, 0.6}}) {
    Scene scene;
    scene.energy_loss = c.loss;
    scene.permanent_set = c.set;
    const Model model = Compile(Text(scene));
    Data data = runtime::MakeData(model);
    Vec3 last = Vec3::Zero();
    // The largest strain is taken at the end of accepted steps, so a peak inside a step is
    // missed by O(h^2): a tight tolerance keeps that below the comparison.
    ASSERT_TRUE(Simulate(model, data, "dopri5", 1e-12, Linspace(0, 0.2, 200),
                         [&](const Data& d) { last = BallVelocity(d); }));
    EXPECT_NEAR(last.x(), -scene.speed * std::sqrt(c.kept), 1e-6)
        << "energy_loss " << c.loss << " permanent_set " << c.set;
    EXPECT_NEAR(last.y(), 0.0, 1e-9);
  }
}

TEST(BeltUnloading, AtbsLawKeepsRWhereItsQuadraticIsNotClamped) {
  // A linear webbing loaded once and unloaded along ATB's quadratic (R = 0.6, G = 0.25: A1 =
  // 0.533 k and A2 > 0, not clamped; R = 0.8 alone: A1 = 0.4 k, A2 = 0.6 k / x_max) gives back R
  // of the loading energy: the ball leaves with sqrt(R) of its speed. The strain's turns are
  // events, found with every span's strain rate.
  for (const auto& [atb, kept] : {std::pair{"atb(energy_return = 0.6, permanent_set = 0.25)", 0.6},
                                  std::pair{"atb(energy_return = 0.8)", 0.8}}) {
    Scene scene;
    scene.atb = atb;
    const Model model = Compile(Text(scene));
    Data data = runtime::MakeData(model);
    Vec3 last = Vec3::Zero();
    ASSERT_TRUE(Simulate(model, data, "dopri5", 1e-10, Linspace(0, 0.2, 200),
                         [&](const Data& d) { last = BallVelocity(d); }));
    EXPECT_NEAR(last.x(), -scene.speed * std::sqrt(kept), 1e-6) << atb;
    EXPECT_NEAR(last.y(), 0.0, 1e-9);
  }
}

TEST(BeltSlack, DelaysTheForceToWhereTheSlackIsTakenUp) {
  Scene scene;
  scene.slack = 0.005;
  const Model model = Compile(Text(scene));
  Data data = runtime::MakeData(model);
  const double onset_x = PositionAtLength(scene, WrappedLength(scene, scene.x0) + scene.slack);
  const double onset = (onset_x - scene.x0) / scene.speed;
  const double step = 1e-5;
  double before = -1.0, after = -1.0, furthest = 0.0;
  ASSERT_TRUE(Simulate(model, data, "dopri5", 1e-10, Linspace(0, 0.12, 12000), [&](const Data& d) {
    furthest = std::max(furthest, d.position[0].x());
    if (after >= 0) return;
    if (d.belts.tension[0] > 0) {
      after = d.time;
      return;
    }
    before = d.time;
    // Until then the sphere coasts.
    EXPECT_NEAR(d.position[0].x(), scene.x0 + scene.speed * d.time, 1e-9);
  }));
  std::printf("  onset %.7f s (samples %.5f, %.5f s)\n", onset, before, after);
  EXPECT_LT(before, onset);
  EXPECT_GE(after, onset);
  EXPECT_NEAR(after - before, step, 1e-9);
  // And the excursion follows from the longer rest length.
  const double rest = WrappedLength(scene, scene.x0) + scene.slack;
  const double longest = rest + scene.speed * std::sqrt(scene.mass * rest / scene.stiffness);
  EXPECT_NEAR(furthest, PositionAtLength(scene, longest), 1e-6);
}

TEST(BeltPretension, StartsAtItsPretensionAndKeepsEnergy) {
  Scene scene;
  scene.pretension = 200.0;
  scene.speed = 0.0;
  scene.x0 = 0.1;
  const Model model = Compile(Text(scene));
  Data data = runtime::MakeData(model);
  ASSERT_TRUE(runtime::Forward(model, data, nullptr));
  EXPECT_NEAR(data.belts.tension[0], scene.pretension, 1e-9);
  EXPECT_NEAR(data.belts.tension[1], scene.pretension, 1e-9);
  EXPECT_NEAR(data.belts.start_anchor_force[0].norm(), scene.pretension, 1e-9);
  // The webbing is l(x0) long at a strain of pretension / K.
  const double rest = WrappedLength(scene, scene.x0) / (1 + scene.pretension / scene.stiffness);
  auto energy = [&](const Data& d) {
    const double x = d.position[0].x();
    const double stretch = x > 0 ? std::max(WrappedLength(scene, x) - rest, 0.0) : 0.0;
    const Vec3 w = d.rotation[0] * d.velocity[0].head<3>();
    return 0.5 * scene.mass * BallVelocity(d).squaredNorm() +
           0.5 * scene.inertia * w.squaredNorm() + scene.stiffness * stretch * stretch / (2 * rest);
  };
  const double initial = energy(data);
  double worst = 0.0, slowest_x = scene.x0;
  ASSERT_TRUE(Simulate(model, data, "dopri5", 1e-10, Linspace(0, 0.05, 500), [&](const Data& d) {
    worst = std::max(worst, std::abs(energy(d) - initial));
    slowest_x = std::min(slowest_x, d.position[0].x());
  }));
  std::printf("  pretension: energy %.6e J kept to %.1e J\n", initial, worst);
  EXPECT_LT(slowest_x, scene.x0 - 0.01);  // it did pull the sphere back
  EXPECT_LT(worst, 1e-7 * initial);
}

// A sphere held in place by its mass (1e9 kg) and spun about the normal of the webbing's plane
// drags the webbing around with it until the tensions on its two sides differ by the capstan
// ratio; then the webbing slips at that ratio, which brakes the spin.
TEST(BeltFriction, SlipsAtTheCapstanRatio) {
  Scene scene;
  scene.radius = 0.05;
  scene.mass = 1e9;
  scene.inertia = 1e-3;
  scene.x0 = 0.3;
  scene.speed = 0.0;
  scene.spin = 60.0;
  scene.stiffness = 50000.0;
  scene.pretension = 500.0;
  scene.friction = 0.5;
  const double distance = std::hypot(scene.half_length, scene.x0);
  const double turning = 2 * kPi - 2 * std::atan2(scene.half_length, scene.x0) -
                         2 * std::acos(scene.radius / distance);
  const double ratio = std::exp(scene.friction * turning);
  for (double friction : {0.0, scene.friction}) {
    scene.friction = friction;
    const Model model = Compile(Text(scene));
    Data data = runtime::MakeData(model);
    ASSERT_TRUE(runtime::Forward(model, data, nullptr));
    auto energy = [&](const Data& d) {
      const Vec3 w = d.velocity[0].head<3>();
      return 0.5 * scene.inertia * w.squaredNorm() + WebbingEnergy(d, scene.stiffness);
    };
    const double initial = energy(data);
    double previous = initial, rise = 0.0, largest_ratio = 1.0, spin = 0.0;
    ASSERT_TRUE(Simulate(model, data, "dopri5", 1e-10, Linspace(0, 0.02, 2000), [&](const Data& d) {
      const double now = energy(d);
      rise = std::max(rise, now - previous);
      previous = now;
      const double a = d.belts.tension[0], b = d.belts.tension[1];
      largest_ratio = std::max(largest_ratio, std::max(a / b, b / a));
      spin = d.velocity[0].z();
    }));
    std::printf(
        "  friction %.1f: largest tension ratio %.9f (capstan %.9f), spin %.3f rad/s, "
        "energy %.4f -> %.4f J\n",
        friction, largest_ratio, friction > 0 ? ratio : 1.0, spin, initial, previous);
    if (friction == 0) {
      // No friction: the webbing slides, nothing brakes the spin.
      EXPECT_NEAR(largest_ratio, 1.0, 1e-9);
      EXPECT_NEAR(spin, scene.spin, 1e-6);
      continue;
    }
    EXPECT_LE(largest_ratio, ratio * (1 + 1e-9));
    EXPECT_GE(largest_ratio, ratio * (1 - 1e-6));
    // Sticking stores energy, slipping dissipates it: it never grows (beyond the integration
    // error), and the slip has braked the spin.
    EXPECT_LT(rise, 1e-8 * initial);
    EXPECT_LT(std::abs(spin), 0.5 * scene.spin);
    EXPECT_LT(previous, initial - 0.5 * 0.5 * scene.inertia * scene.spin * scene.spin);
  }
}

// The start of a scene of two free spheres of radius 2 cm and 1 kg, `one.s` and `two.s`, without
// gravity, and a linear webbing of 20 kN per unit strain; the test adds its belts and closes it.
std::string TwoSpheres(const std::string& name) {
  return "scenario \"" + name + R"(" {
  gravity = (0, 0, 0) m/s^2
  time { end = 1 s  output_every = 1 ms }
  function webbing = table(strain -> force) { 0 -> 0 N  1 -> 20000 N }
  body one { segment s { mass = 1 kg  inertia = (1e-4, 1e-4, 1e-4) kg*m^2
                         ellipsoid { semi_axes = (0.02, 0.02, 0.02) m } } }
  body two { segment s { mass = 1 kg  inertia = (1e-4, 1e-4, 1e-4) kg*m^2
                         ellipsoid { semi_axes = (0.02, 0.02, 0.02) m } } }
)";
}

// A harness of two belts joined at a tie point (0, 0, 0), each wrapping its own sphere: only the
// first sphere moves, and webbing runs through the frictionless tie point into the first belt,
// so the second belt carries the same tension and pulls the second sphere.
TEST(BeltHarness, FrictionlessTiePointPassesTheTension) {
  const std::string text = TwoSpheres("harness") + R"(
  harness straps {
    friction = 0
    belt left { path = (0, -1, 0) m -> one.s -> (0, 0, 0) m  force = webbing }
    belt right { path = (0, 0, 0) m -> two.s -> (0, 1, 0) m  force = webbing }
  }
  initial one { position = (0.05, -0.5, 0) m  velocity = (2, 0, 0) m/s }
  initial two { position = (0.05, 0.5, 0) m }
}
)";
  const Model model = Compile(text);
  ASSERT_EQ(model.belts.size(), 2u);
  ASSERT_EQ(model.belts.tie_points.size(), 1u);
  Data data = runtime::MakeData(model);
  auto energy = [&](const Data& d) {
    double kinetic = 0.0;
    for (std::size_t s = 0; s < 2; ++s) {
      const Vec3 v =
          runtime::PointInFrame(
              d, {runtime::FrameRef::Kind::kSegment, static_cast<std::int32_t>(s)}, Vec3::Zero())
              .velocity;
      kinetic += 0.5 * v.squaredNorm() + 0.5 * 1e-4 * d.velocity[s].head<3>().squaredNorm();
    }
    return kinetic + WebbingEnergy(d, 20000.0);
  };
  const double initial = energy(data);
  double worst = 0.0, largest = 0.0, pulled = 0.0;
  ASSERT_TRUE(Simulate(model, data, "dopri5", 1e-10, Linspace(0, 0.05, 500), [&](const Data& d) {
    // Spans: left 0, 1; right 2, 3. The tie joins left's last span to right's first.
    EXPECT_NEAR(d.belts.tension[1], d.belts.tension[2], 1e-8 * d.belts.tension[1] + 1e-9);
    largest = std::max(largest, d.belts.tension[2]);
    const Vec3 second =
        runtime::PointInFrame(d, {runtime::FrameRef::Kind::kSegment, 1}, Vec3::Zero()).velocity;
    pulled = std::min(pulled, second.x());
    worst = std::max(worst, std::abs(energy(d) - initial));
  }));
  std::printf(
      "  harness: right belt up to %.1f N, second sphere pulled to %.4f m/s, energy kept "
      "to %.1e J\n",
      largest, pulled, worst);
  EXPECT_GT(largest, 100.0);
  EXPECT_LT(pulled, -0.1);
  EXPECT_LT(worst, 1e-7 * initial);
}

// A guide ring: webbing over a point R fixed in the ground, as the converter writes an ATB
// harness point in a vehicle (two belts of a harness tied at R). At the start, with each sphere
// (radius r, centre C) where the scene puts it, the webbing runs from R to its tangent point on the
// sphere's far side, the direction from R turned from R->C by asin(r / |C - R|) away from the
// belt's straight line. With 100 N of pretension and a frictionless ring both spans carry 100 N,
// each pulls R toward its tangent point, and the ring's reaction is their sum: 2 T cos(phi / 2),
// phi the angle between the spans.
TEST(BeltGuideRing, TheRingTakesTheSumOfTheTwoSpansAlongTheirDirections) {
  const std::string text = TwoSpheres("guide ring") + R"(
  harness ring {
    belt lead { path = (0, -1, 0) m -> one.s -> (0, 0, 0) m  force = webbing  pretension = 100 N }
    belt rest { path = (0, 0, 0) m -> two.s -> (0.3, 1, 0) m  force = webbing  pretension = 100 N }
  }
  initial one { position = (0.05, -0.5, 0) m }
  initial two { position = (0.2, 0.5, 0) m }
  output {
    belt_force ring.lead
    belt_force ring.rest
  }
}
)";
  const Model model = Compile(text);
  ASSERT_EQ(model.belts.tie_points.size(), 1u);
  Data data = runtime::MakeData(model);
  ASSERT_TRUE(runtime::Forward(model, data, nullptr));
  const std::vector<std::string> names = runtime::ChannelNames(model);
  std::vector<double> values(names.size());
  runtime::EvaluateChannels(model, data, values);
  // Channels: lead's span1, span2, start xyz, end xyz (the ring); rest's span1, span2, start
  // xyz (the ring), end xyz.
  ASSERT_EQ(names.size(), 16u);
  ASSERT_EQ(names[5], "ring.lead.belt_force.end.x [N]");
  ASSERT_EQ(names[10], "ring.rest.belt_force.start.x [N]");
  const double tension = 100.0, r = 0.02;
  // The direction from R = 0 to the tangent point on a sphere at C, turned away from the line
  // through R and the belt's other anchor A (the side the webbing lies on).
  auto tangent_direction = [&](Vec3 c, Vec3 a) {
    const double d = c.norm();
    const double turn = std::asin(r / d);
    const Vec3 along = c / d;
    Vec3 away = c - a.normalized() * c.dot(a.normalized());  // C's offset from the line R-A
    away = (away - along * away.dot(along)).normalized();    // its part normal to R->C
    return Vec3(std::cos(turn) * along + std::sin(turn) * away);
  };
  const Vec3 u_in = tangent_direction({0.05, -0.5, 0}, {0, -1, 0});
  const Vec3 u_out = tangent_direction({0.2, 0.5, 0}, {0.3, 1, 0});
  const Vec3 on_ring_in(values[5], values[6], values[7]);
  const Vec3 on_ring_out(values[10], values[11], values[12]);
  EXPECT_NEAR(values[1], tension, 1e-6);  // lead's span at the ring
  EXPECT_NEAR(values[8], tension, 1e-6);  // rest's span at the ring
  EXPECT_LT((on_ring_in - tension * u_in).norm(), 1e-6) << on_ring_in.transpose();
  EXPECT_LT((on_ring_out - tension * u_out).norm(), 1e-6) << on_ring_out.transpose();
  const double phi = std::acos(u_in.dot(u_out));
  const Vec3 reaction = on_ring_in + on_ring_out;
  EXPECT_NEAR(reaction.norm(), 2 * tension * std::cos(phi / 2), 1e-6);
  std::printf(
      "  guide ring: reaction %.4f N at %.2f deg between the spans (2 T cos(phi/2) = %.4f)\n",
      reaction.norm(), phi * 180 / kPi, 2 * tension * std::cos(phi / 2));
}

// The same ring with friction 0.3: the first sphere runs into its belt at 2 m/s and draws
// webbing through the ring from the second belt, whose sphere is too heavy to follow. The ring
// holds while the lead span's tension is below exp(mu theta) times the other's, theta the angle
// the webbing turns at the ring, computed here from the two spans' ends; once it slips the ratio
// is exactly that (the capstan law), and the ring lets webbing through.
TEST(BeltGuideRing, SlipsThroughTheRingAtTheCapstanRatio) {
  const std::string text = TwoSpheres("guide ring with friction") + R"(
  body heavy { segment s { mass = 1e6 kg  inertia = (1, 1, 1) kg*m^2
                           ellipsoid { semi_axes = (0.02, 0.02, 0.02) m } } }
  harness ring {
    friction = 0.3
    belt lead { path = (0, -1, 0) m -> one.s -> (0, 0, 0) m  force = webbing  pretension = 50 N }
    belt rest { path = (0, 0, 0) m -> heavy.s -> (0.3, 1, 0) m  force = webbing
                pretension = 50 N }
  }
  initial one { position = (0.05, -0.5, 0) m  velocity = (2, 0, 0) m/s }
  initial heavy { position = (0.2, 0.5, 0) m }
}
)";
  const Model model = Compile(text);
  ASSERT_EQ(model.belts.tie_points.size(), 1u);
  Data data = runtime::MakeData(model);
  const double mu = 0.3;
  double largest_ratio_error = 0.0, slipping_ratio_error = 0.0;
  int slipping = 0;
  ASSERT_TRUE(Simulate(model, data, "dopri5", 1e-10, Linspace(0, 0.02, 200), [&](const Data& d) {
    // Spans: lead 0 (anchor to sphere), 1 (sphere to ring); rest 2 (ring to sphere), 3.
    const Vec3 in = (d.belts.end[1] - d.belts.start[1]).normalized();   // toward the ring
    const Vec3 out = (d.belts.end[2] - d.belts.start[2]).normalized();  // away from it
    const double theta = std::acos(std::clamp(in.dot(out), -1.0, 1.0));
    const double bound = std::exp(mu * theta);
    const double ratio = d.belts.tension[1] / d.belts.tension[2];
    largest_ratio_error = std::max(largest_ratio_error, ratio / bound - 1.0);
    for (std::size_t j = 0; j < d.belts.mode.size(); ++j) {
      if (d.belts.junction_tie[j] < 0 || d.belts.mode[j] == runtime::JunctionMode::kStick) continue;
      ++slipping;
      slipping_ratio_error = std::max(slipping_ratio_error, std::abs(ratio / bound - 1.0));
    }
  }));
  std::printf(
      "  guide ring: slipping at %d of 201 samples, tension ratio within %.1e of exp(mu "
      "theta) there, never above it by more than %.1e\n",
      slipping, slipping_ratio_error, largest_ratio_error);
  EXPECT_GT(slipping, 10);
  EXPECT_LT(slipping_ratio_error, 1e-8);
  EXPECT_LT(largest_ratio_error, 1e-8);
}

TEST(BeltOutputs, ChannelsNameEachSpanAndAnchor) {
  Scene scene;
  scene.pretension = 150.0;
  const Model model = Compile(Text(scene));
  Data data = runtime::MakeData(model);
  ASSERT_TRUE(runtime::Forward(model, data, nullptr));
  const std::vector<std::string> names = runtime::ChannelNames(model);
  ASSERT_EQ(names.size(), 8u);
  EXPECT_EQ(names[0], "strap.belt_force.span1 [N]");
  EXPECT_EQ(names[1], "strap.belt_force.span2 [N]");
  EXPECT_EQ(names[2], "strap.belt_force.start.x [N]");
  EXPECT_EQ(names[7], "strap.belt_force.end.z [N]");
  std::vector<double> values(names.size());
  runtime::EvaluateChannels(model, data, values);
  EXPECT_NEAR(values[0], 150.0, 1e-9);
  // The first anchor (0, -L, 0) is pulled toward the sphere's side of it: +y and +x.
  EXPECT_NEAR(std::hypot(values[2], values[3], values[4]), 150.0, 1e-9);
  EXPECT_GT(values[2], 0.0);
  EXPECT_GT(values[3], 0.0);
  EXPECT_LT(values[6], 0.0);  // the last anchor (0, L, 0) toward -y
}

}  // namespace
}  // namespace sled::verification
