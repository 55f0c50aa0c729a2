// Contacts against closed-form answers: a sphere dropped on a floor with the first-contact
// impulse rebounds with the restitution times its impact speed; with an energy-losing force
// function it rebounds with sqrt(1 - energy_loss) of it (the unloading curve returns that share
// of the work), and under ATB's law with sqrt(R); a linear spring–damper contact (its damping
// also given as ATB's rate-dependent terms) follows the damped oscillator during contact and
// releases when its force falls to zero; a block sliding under Coulomb friction stops after
// v^2 / (2 mu g).
#include <cmath>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "tests/runtime/model_fixtures.h"
#include "tests/verification/verification.h"

namespace sled::verification {
namespace {

using runtime::ContactTable;
using runtime::FrameRef;
using runtime::JointKind;
using runtime::Mat3;
using runtime::Vec3;

struct Contact {
  double stiffness = 1e5;  // N/m, linear
  double damping = 0.0;
  double damping_depth = 0.0;  // Kelvin–Voigt: full damping from first touch
  double friction = 0.0;
  bool impulse = false;
  double restitution = 0.0;
  double energy_loss = 0.0;
  double permanent_set = 0.0;
  double atb_return = -1.0;  // ATB's law with these constant R and G when R >= 0
  double atb_set = 0.0;
  double atb_spike = 0.0;  // ATB's inertial spike, a constant force, until atb_spike_end (m)
  double atb_spike_end = 0.0;
  bool damping_as_rate_terms = false;  // the damping given as ATB's rate-dependent force
};

// A free sphere (a segment with one spherical ellipsoid at its centre of mass) above the floor
// z = 0, a 20 m square on the ground. The sphere starts at height z0 with velocity v0.
runtime::Model SphereOnFloor(double mass, double radius, double inertia, const Contact& c,
                             double z0, const Vec3& v0) {
  runtime::Model model;
  runtime::testing::AddSegment(model, "ball", -1, JointKind::kFree, mass, Vec3::Constant(inertia));
  model.q0[2] = z0;
  for (int i = 0; i < 3; ++i) model.v0[3 + static_cast<std::size_t>(i)] = v0[i];
  // Function 0 the force; then ATB's R and G, and ATB's rate terms, when asked for.
  runtime::FunctionTable& f = model.functions;
  auto append = [&f](std::vector<double> coefficients, std::int32_t atb_return = -1,
                     std::int32_t atb_set = -1) {
    f.kind.push_back(runtime::FunctionTable::Kind::kPolynomial);
    f.constant.push_back(0);
    f.first.push_back(static_cast<std::int32_t>(f.coefficients.size()));
    f.count.push_back(static_cast<std::int32_t>(coefficients.size()));
    f.coefficients.insert(f.coefficients.end(), coefficients.begin(), coefficients.end());
    f.energy_loss.push_back(0);
    f.permanent_set.push_back(0);
    f.atb_return.push_back(atb_return);
    f.atb_set.push_back(atb_set);
    return static_cast<std::int32_t>(f.size() - 1);
  };
  const bool atb = c.atb_return >= 0;
  append({0.0, c.stiffness}, atb ? 1 : -1, atb ? 2 : -1);
  f.energy_loss[0] = c.energy_loss;
  f.permanent_set[0] = c.permanent_set;
  if (atb) {
    append({c.atb_return});
    append({c.atb_set});
  }
  if (atb && c.atb_spike != 0) {
    const std::int32_t spike = append({c.atb_spike});
    f.atb_spike.assign(f.size(), -1);
    f.atb_spike_end.assign(f.size(), 0.0);
    f.atb_origin.assign(f.size(), 0.0);
    f.atb_spike[0] = spike;
    f.atb_spike_end[0] = c.atb_spike_end;
  }
  // The damping as ATB's rate terms: F2(d) F3(d') + F4(d') = 2 N * (c/4 d' / N) + c/2 d'.
  const double damping = c.damping_as_rate_terms ? 0.0 : c.damping;
  std::int32_t scaled = -1, scale = -1, rate_force = -1;
  if (c.damping_as_rate_terms) {
    scaled = append({2.0});
    scale = append({0.0, c.damping / 4});
    rate_force = append({0.0, c.damping / 2});
  }
  ContactTable& t = model.contacts;
  t.ellipsoid_name = {"ball"};
  t.ellipsoid_frame = {{FrameRef::Kind::kSegment, 0}};
  t.ellipsoid_center = {Vec3::Zero()};
  t.ellipsoid_axes = {Mat3::Identity()};
  t.ellipsoid_semi_axes = {Vec3::Constant(radius)};
  t.ellipsoid_degree = {2.0};
  t.ellipsoid_radius = {radius};
  t.plane_name = {"floor"};
  t.plane_frame = {{FrameRef::Kind::kGround, -1}};
  t.plane_origin = {Vec3(-10, -10, 0)};
  t.plane_edge_u = {Vec3(20, 0, 0)};
  t.plane_edge_v = {Vec3(0, 20, 0)};
  t.plane_normal = {Vec3::UnitZ()};
  t.pair_kind = {ContactTable::PairKind::kPlaneEllipsoid};
  t.pair_first = {0};
  t.pair_second = {0};
  t.pair_function = {0};
  t.pair_damping = {damping};
  t.pair_rate_scaled_force = {scaled};
  t.pair_rate_scale = {scale};
  t.pair_rate_force = {rate_force};
  t.pair_damping_depth = {c.damping_depth};
  t.pair_friction = {c.friction};
  t.pair_impulse = {static_cast<std::uint8_t>(c.impulse ? 1 : 0)};
  t.pair_restitution = {c.restitution};
  t.pair_source = {{}};
  return model;
}

// The sphere's velocity in the world frame (a free joint's coordinates are in its own frame).
Vec3 Velocity(const runtime::Data& d) { return d.rotation[0] * d.velocity[0].tail<3>(); }

// A 1 kg sphere of radius 0.1 m meeting the floor at 2 m/s 10 mm away, without gravity.
runtime::Model ImpactAt2MetresPerSecond(const Contact& c) {
  runtime::Model model = SphereOnFloor(1.0, 0.1, 0.004, c, 0.11, Vec3(0, 0, -2));
  model.gravity.setZero();
  return model;
}

// Runs to 50 ms (long after the rebound) with `method` at 1e-10; the sphere's vertical speed.
double SpeedAfter50ms(const runtime::Model& model, runtime::Data& data, const std::string& method) {
  double speed = 0;
  EXPECT_TRUE(Simulate(model, data, method, 1e-10, {0.05},
                       [&](const runtime::Data& d) { speed = Velocity(d).z(); }));
  return speed;
}

class ContactVerification : public ::testing::TestWithParam<std::string> {};

TEST_P(ContactVerification, FirstContactImpulseReboundsWithTheRestitution) {
  // Dropped from 0.5 m: it meets the floor at t1 = sqrt(2 h / g) with v1 = g t1 and leaves with
  // e v1; it is back at t2 = t1 + 2 e v1 / g and leaves again with e^2 v1 (each new contact has
  // its impulse). The force law waits for the impulse, so it adds nothing.
  const double g = 9.81, h = 0.5, r = 0.1, e = 0.7;
  Contact c;
  c.impulse = true;
  c.restitution = e;
  runtime::Model model = SphereOnFloor(1.0, r, 0.004, c, r + h, Vec3::Zero());
  model.gravity = Vec3(0, 0, -g);
  runtime::Data data = runtime::MakeData(model);
  const double t1 = std::sqrt(2 * h / g), v1 = g * t1, t2 = t1 + 2 * e * v1 / g;
  double worst_z = 0, worst_v = 0;
  runtime::IntegratorStats stats;
  ASSERT_TRUE(Simulate(
      model, data, GetParam(), 1e-10, Linspace(0, 1.0, 100),
      [&](const runtime::Data& d) {
        const double t = d.time;
        // Height and velocity after leaving the floor at `t0` with `v0`.
        auto flight_z = [&](double t0, double v0) {
          return r + v0 * (t - t0) - 0.5 * g * (t - t0) * (t - t0);
        };
        const double z = t < t1   ? r + h - 0.5 * g * t * t
                         : t < t2 ? flight_z(t1, e * v1)
                                  : flight_z(t2, e * e * v1);
        const double v = t < t1   ? -g * t
                         : t < t2 ? e * v1 - g * (t - t1)
                                  : e * e * v1 - g * (t - t2);
        worst_z = std::max(worst_z, std::abs(d.position[0].z() - z));
        worst_v = std::max(worst_v, std::abs(Velocity(d).z() - v));
      },
      &stats));
  EXPECT_LT(worst_z, 1e-8);
  EXPECT_LT(worst_v, 1e-8);
  EXPECT_EQ(stats.events, 2);
  // The energy balance books each impulse's loss, (1 - e^2) of the kinetic energy it met.
  EXPECT_NEAR(data.energy.impulses, -0.5 * (1 - e * e) * (v1 * v1 + e * e * v1 * v1), 1e-8);
}

TEST_P(ContactVerification, EnergyLossGivesTheSquareRootRestitution) {
  // No gravity: a sphere meets the floor at 2 m/s; the unloading curve returns (1 - loss) of
  // the loading work, so it leaves at sqrt(1 - loss) * 2 m/s whatever the permanent set. The
  // largest deflection is taken at step ends, which misses the true peak by a little: 2.6e-5 m/s
  // with dopri5's long steps, 4e-9 with the others.
  for (const double set : {0.0, 0.3}) {
    Contact c;
    c.energy_loss = 0.36;
    c.permanent_set = set;
    const runtime::Model model = ImpactAt2MetresPerSecond(c);
    runtime::Data data = runtime::MakeData(model);
    const double speed = SpeedAfter50ms(model, data, GetParam());
    EXPECT_NEAR(speed, 0.8 * 2.0, 1e-4) << set;
    // The work the contact absorbed (its power integrated with the state) is the kinetic energy
    // the sphere lost.
    EXPECT_NEAR(data.energy.Absorbed(), 0.5 * (2.0 * 2.0 - speed * speed), 1e-7) << set;
    // The deflection left behind: set * the largest, which k delta^2 / 2 = m v^2 / 2 gives.
    EXPECT_NEAR(data.contacts.history[0].max_deflection, 2.0 / std::sqrt(1e5), 1e-4 * 0.0063)
        << set;
  }
}

TEST_P(ContactVerification, AtbUnloadingReturnsRAndLeavesAtThePermanentSet) {
  // No gravity: a 1 kg sphere meets a 1e5 N/m floor at 2 m/s, so x_max = 2 / sqrt(1e5) and the
  // loading energy is 2 J. ATB's quadratic with R = 0.6 and G = 0.25 (not clamped: A1 = 0.533 k,
  // A2 = 0.8 k / d) returns 0.6 of it and reaches zero force at 0.25 x_max, where the sphere
  // leaves at sqrt(0.6) * 2 m/s.
  Contact c;
  c.atb_return = 0.6;
  c.atb_set = 0.25;
  const runtime::Model model = ImpactAt2MetresPerSecond(c);
  runtime::Data data = runtime::MakeData(model);
  const double speed = SpeedAfter50ms(model, data, GetParam());
  const double x_max = 2.0 / std::sqrt(1e5);
  EXPECT_NEAR(speed, std::sqrt(0.6) * 2.0, 1e-6);
  EXPECT_NEAR(data.contacts.history[0].max_deflection, x_max, 1e-6 * x_max);
  EXPECT_NEAR(data.contacts.history[0].permanent, 0.25 * x_max, 1e-6 * x_max);
  EXPECT_NEAR(data.energy.Absorbed(), 0.4 * 2.0, 1e-6);
}

TEST_P(ContactVerification, AtbSpikeTakesItsWorkOnceAndDropsAtItsEnd) {
  // No gravity: a 1 kg sphere meets a 1e5 N/m floor at 2 m/s (2 J) with an elastic ATB law
  // (R = 1) and an inertial spike of 500 N. Ending at 2 mm, the spike takes 500 N * 2 mm = 1 J
  // and drops: x_max = sqrt(2 * 1 J / k), and the function alone gives back k x_max^2 / 2 = 1 J,
  // so the sphere leaves at sqrt(2) m/s. Ending at 10 mm, beyond x_max = (sqrt(s^2 + 4 k J) - s)
  // / k for k x^2 / 2 + s x = 2 J, the spike stays and gives its work back: it leaves at 2 m/s.
  const double k = 1e5, s = 500.0;
  for (const double end : {0.002, 0.01}) {
    Contact c;
    c.atb_return = 1.0;
    c.atb_spike = s;
    c.atb_spike_end = end;
    const runtime::Model model = ImpactAt2MetresPerSecond(c);
    runtime::Data data = runtime::MakeData(model);
    const double speed = SpeedAfter50ms(model, data, GetParam());
    const bool drops = end < 0.005;
    const double x_max =
        drops ? std::sqrt(2 * 1.0 / k) : (std::sqrt(s * s + 4 * 0.5 * k * 2.0) - s) / k;
    EXPECT_NEAR(speed, drops ? std::sqrt(2.0) : 2.0, 1e-6) << end;
    EXPECT_NEAR(data.contacts.history[0].max_deflection, x_max, 1e-6 * x_max) << end;
    EXPECT_EQ(data.contacts.history[0].spike_dropped, drops) << end;
    EXPECT_NEAR(data.energy.Absorbed(), drops ? 1.0 : 0.0, 1e-6) << end;
  }
}

TEST_P(ContactVerification, SpringDamperContactFollowsTheDampedOscillator) {
  // No gravity: m = 2 kg meets a contact k = 2e4 N/m, c = 40 N s/m (w = 100 rad/s, zeta = 0.1)
  // at 1 m/s after 10 ms. During contact delta = (v / wd) e^(-zeta w tau) sin(wd tau); the force
  // k delta + c delta' reaches zero while delta > 0, at wd tau = pi - atan(c wd / (k - c s)),
  // s = zeta w, and the sphere leaves with the rate it has there.
  // The damping given as ATB's rate-dependent terms F2(d) F3(d') + F4(d') (FUNC_RATE_DEP) that
  // sum to c d' follows the same closed form.
  for (const bool as_rate_terms : {false, true}) {
    SCOPED_TRACE(as_rate_terms ? "ATB's rate terms" : "damping");
    const double m = 2, k = 2e4, cd = 40, v = 1, r = 0.1, approach = 0.01;
    Contact c;
    c.stiffness = k;
    c.damping = cd;
    c.damping_as_rate_terms = as_rate_terms;
    runtime::Model model = SphereOnFloor(m, r, 0.01, c, r + v * approach, Vec3(0, 0, -v));
    model.gravity.setZero();
    runtime::Data data = runtime::MakeData(model);
    const double w = std::sqrt(k / m), zeta = cd / (2 * std::sqrt(k * m)), s = zeta * w;
    const double wd = w * std::sqrt(1 - zeta * zeta);
    const double release = (std::numbers::pi - std::atan(cd * wd / (k - cd * s))) / wd;
    auto deflection = [&](double tau) { return v / wd * std::exp(-s * tau) * std::sin(wd * tau); };
    auto rate = [&](double tau) {
      return v / wd * std::exp(-s * tau) * (wd * std::cos(wd * tau) - s * std::sin(wd * tau));
    };
    const double peak = deflection(std::atan(wd / s) / wd);  // where the rate is zero
    double worst = 0;
    std::vector<double> times = Linspace(approach, approach + release, 200);
    times.pop_back();  // the release itself is checked through the exit speed
    times.push_back(approach + release + 0.005);
    ASSERT_TRUE(Simulate(model, data, GetParam(), 1e-10, times, [&](const runtime::Data& d) {
      const double tau = d.time - approach;
      const double expected =
          tau < release ? deflection(tau)
                        : deflection(release) + rate(release) * (tau - release);  // free flight
      worst = std::max(worst, std::abs((r - d.position[0].z()) - expected));
      if (tau < release) {
        EXPECT_NEAR(d.contacts.normal_force[0], k * expected + cd * rate(tau), 1e-7 * k * peak);
      } else {
        EXPECT_EQ(d.contacts.normal_force[0], 0.0);
        EXPECT_NEAR(Velocity(d).z(), -rate(release), 1e-7);  // the exit speed fixes the duration
      }
    }));
    EXPECT_LT(worst, 1e-7 * peak);
  }
}

TEST_P(ContactVerification, SlidingBlockStopsAfterTheCoulombDistance) {
  // A sphere resting on the floor (at its equilibrium deflection m g / k) pushed at 2 m/s along
  // x with friction 0.4 stops after v^2 / (2 mu g). A large rotational inertia keeps it from
  // rolling (the friction torque turns it by less than 1e-4 rad), so it slides as a block. The
  // smoothed friction (full above 1 cm/s) adds a creep of the order of v0^2 / (mu g) = 3e-5 m.
  const double g = 9.81, m = 1, k = 1e5, mu = 0.4, v = 2, r = 0.05;
  Contact c;
  c.stiffness = k;
  c.damping = 2 * std::sqrt(k * m);  // critically damped: no vertical ringing
  c.friction = mu;
  runtime::Model model = SphereOnFloor(m, r, 1e3, c, r - m * g / k, Vec3(v, 0, 0));
  model.gravity = Vec3(0, 0, -g);
  runtime::Data data = runtime::MakeData(model);
  const double distance = v * v / (2 * mu * g), stop = v / (mu * g);
  double x_mid = 0, x_end = 0, v_end = 1;
  ASSERT_TRUE(Simulate(model, data, GetParam(), 1e-9, {0.5 * stop, stop + 0.3},
                       [&](const runtime::Data& d) {
                         if (d.time < stop) {
                           x_mid = d.position[0].x();
                         } else {
                           x_end = d.position[0].x();
                           v_end = Velocity(d).x();
                         }
                       }));
  const double t = 0.5 * stop;
  EXPECT_NEAR(x_mid, v * t - 0.5 * mu * g * t * t, 1e-9);
  EXPECT_NEAR(x_end, distance, 1e-4);
  // What is left is the spin the friction torque gave it, r w = 5e-6 m/s, rolling on.
  EXPECT_NEAR(v_end, 0.0, 1e-5);
  // Friction took the kinetic energy (the spin keeps 1e-3 * (5e-6 / 0.05)^2 / 2 of it, and the
  // contact's spring holds the same m g / k deflection at the end as at the start).
  EXPECT_NEAR(data.energy.Absorbed(), 0.5 * m * v * v, 1e-5);
}

INSTANTIATE_TEST_SUITE_P(EveryIntegrator, ContactVerification,
                         ::testing::ValuesIn(AllIntegrators()));

}  // namespace
}  // namespace sled::verification
