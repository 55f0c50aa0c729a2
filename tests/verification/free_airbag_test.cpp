// ATB's free airbag (`model = atb_free`) against laws computed here independently of the runtime:
// a closed bag of fixed volume holds the integral of its inflow at p_a (m R T / (p_a V))^gamma;
// a vented bag at fixed volume empties as dm/dt = -C_d A sqrt(2 rho (p(m) - p_a)), integrated
// here with small Runge-Kutta steps, down to the mass at which the vent's opening pressure
// closes it, and the gas inside plus the gas vented is always the gas delivered; a full bag
// hanging on its spring moves as M(t) z'' = -k z - M g (integrated here); and a ball thrown into
// a free bag, with no spring and no gravity, keeps the momentum of ball and bag and the energy of
// their motion plus the work stored in the gas.
#include <cmath>
#include <functional>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "runtime/dynamics/dynamics.h"
#include "runtime/forces/forces.h"
#include "runtime/model/data.h"
#include "tests/verification/compile.h"
#include "tests/verification/verification.h"

namespace sled::verification {
namespace {

using runtime::Data;
using runtime::Model;
using runtime::Vec3;

constexpr double kAmbient = 101325.0;
constexpr double kGamma = 1.3;
constexpr double kGasConstant = 300.0;
constexpr double kTemperature = 400.0;
constexpr double kRadius = 0.2;  // the test bags are spheres of this radius
const double kFullVolume = 4.0 / 3.0 * std::numbers::pi * kRadius * kRadius * kRadius;
// The gas mass that takes the full bag's volume at the ambient pressure.
const double kFillMass = kAmbient * kFullVolume / (kGasConstant * kTemperature);

// A spherical free bag whose back pole is at the origin, deploying up (+z), filled from 0 by a
// constant mass flow `flow` until `fill`, and a ball of `mass` kg and radius `ball` at `height`
// moving at `speed` along z.
struct FreeBagScene {
  double flow = 10.0;  // kg/s
  double fill = 0.02;
  double vent = 0.0;
  double discharge = 0.7;
  double opening = 0.0;
  double bag_mass = 0.2;
  double mass_factor = 1.5;
  double tether = 0.0;
  double gravity = 0.0;
  double mass = 5.0;
  double ball = 0.1;
  double height = 5.0;
  double speed = 0.0;
};

std::string SceneText(const FreeBagScene& s) {
  return fmt::format(R"(scenario "free airbag" {{
  gravity = (0, 0, {gravity}) m/s^2
  time {{ end = 1 s  output_every = 1 ms }}
  function inflator = table(time -> mass_flow) {{ 0 s -> {flow} kg/s  {fill} s -> {flow} kg/s }}
  body ball {{
    segment core {{ mass = {mass} kg  inertia = (1, 1, 1) kg*m^2
                   ellipsoid {{ semi_axes = ({ball}, {ball}, {ball}) m }} }}
  }}
  initial ball {{ position = (0, 0, {height}) m  velocity = (0, 0, {speed}) m/s }}
  airbag bag {{
    model = atb_free
    position = (0, 0, 0) m
    orientation = (0, -90, 0) deg
    semi_axes = ({r}, {r}, {r}) m
    deploy_at = 0 s
    inflow = inflator
    vent_area = {vent} m^2
    discharge_coefficient = {discharge}
    vent_opening_pressure = {opening} Pa
    gas_temperature = {temperature} K
    gamma = {gamma}
    gas_constant = {R} J/kg/K
    bag_mass = {bag_mass} kg
    mass_factor = {factor}
    tether_stiffness = {tether} N/m
    contacts = ball.core
  }}
}}
)",
                     fmt::arg("gravity", s.gravity), fmt::arg("flow", s.flow),
                     fmt::arg("fill", s.fill), fmt::arg("mass", s.mass), fmt::arg("ball", s.ball),
                     fmt::arg("height", s.height), fmt::arg("speed", s.speed),
                     fmt::arg("r", kRadius), fmt::arg("vent", s.vent),
                     fmt::arg("discharge", s.discharge), fmt::arg("opening", s.opening),
                     fmt::arg("temperature", kTemperature), fmt::arg("gamma", kGamma),
                     fmt::arg("R", kGasConstant), fmt::arg("bag_mass", s.bag_mass),
                     fmt::arg("factor", s.mass_factor), fmt::arg("tether", s.tether));
}

Model CompileScene(const FreeBagScene& scene) {
  const Compiled compiled = CompileText(SceneText(scene));
  if (!compiled.errors.empty()) {
    ADD_FAILURE() << "the scene does not check:\n" << compiled.errors;
    return Model{};
  }
  return compiled.model();
}

// The bag's states in data.w: gas mass, mass vented, centre, velocity.
struct BagStates {
  double mass = 0, vented = 0;
  Vec3 centre = Vec3::Zero(), velocity = Vec3::Zero();
};
BagStates StatesOf(const Model& model, const Data& data) {
  const auto a = static_cast<std::size_t>(model.airbags.state_address[0]);
  return {data.w[a], data.w[a + 1], Vec3(data.w[a + 2], data.w[a + 3], data.w[a + 4]),
          Vec3(data.w[a + 5], data.w[a + 6], data.w[a + 7])};
}

// The polytropic pressure of `mass` in the full, untouched bag.
double FullBagPressure(double mass) { return kAmbient * std::pow(mass / kFillMass, kGamma); }

// Runs `scene` with `method` and calls `sample` at `times` with the Model and the Data.
void RunSamples(const FreeBagScene& scene, const std::string& method,
                const std::vector<double>& times,
                const std::function<void(const Model&, const Data&)>& sample) {
  const Model model = CompileScene(scene);
  ASSERT_GT(model.airbags.size(), 0u);
  ASSERT_TRUE(model.airbags.free_bag[0]);
  Data data = runtime::MakeData(model);
  ASSERT_TRUE(Simulate(model, data, method, 1e-10, times, [&](const Data& sampled) {
    sample(model, sampled);
  })) << method;
}

TEST(FreeAirbag, ClosedBagHoldsItsInflowAtThePolytropicPressure) {
  FreeBagScene scene;
  scene.flow = 2.0;  // full at kFillMass / 2 kg/s, 14.1 ms; 1.41 times the fill mass at 20 ms
  for (const std::string& method : AllIntegrators()) {
    double largest_error = 0.0;
    int unfolding = 0, full = 0;
    const std::vector<double> times = Linspace(0.0, 0.03, 60);
    RunSamples(scene, method, times, [&](const Model& model, const Data& data) {
      const BagStates states = StatesOf(model, data);
      const double delivered = scene.flow * std::min(data.time, scene.fill);
      EXPECT_NEAR(states.mass, delivered, 1e-7 * delivered) << method << " t " << data.time;
      EXPECT_EQ(states.vented, 0.0);
      if (delivered < kFillMass * (1 - 1e-6)) {
        // Unfolding: the gas at the ambient pressure, its volume m R T / p_a.
        ++unfolding;
        EXPECT_EQ(data.airbags.pressure[0], kAmbient);
        EXPECT_NEAR(data.airbags.volume[0], delivered * kGasConstant * kTemperature / kAmbient,
                    1e-6 * kFullVolume);
      } else if (delivered > kFillMass * (1 + 1e-6)) {
        ++full;
        const double expected = FullBagPressure(delivered);
        largest_error =
            std::max(largest_error, std::abs(data.airbags.pressure[0] - expected) / expected);
        EXPECT_NEAR(data.airbags.volume[0], kFullVolume, 1e-12);
        EXPECT_NEAR(data.airbags.temperature[0],
                    kTemperature * std::pow(expected / kAmbient, (kGamma - 1) / kGamma),
                    1e-6 * kTemperature);
      }
    });
    EXPECT_GT(unfolding, 5) << method;
    EXPECT_GT(full, 5) << method;
    EXPECT_LT(largest_error, 1e-6) << method;
  }
}

// dm/dt of the vented bag at its full volume, the independent reference.
double VentRate(const FreeBagScene& s, double mass) {
  const double gauge = FullBagPressure(mass) - kAmbient;
  if (gauge <= s.opening) return 0.0;
  const double density = kAmbient / (kGasConstant * kTemperature);
  return -s.discharge * s.vent * std::sqrt(2 * density * gauge);
}

TEST(FreeAirbag, VentedBagEmptiesAsTheSquareRootLawAndConservesItsGas) {
  for (const double opening : {0.0, 20e3}) {
    FreeBagScene scene;
    scene.flow = 10.0;
    scene.fill = 0.01;  // 0.1 kg: 3.5 times the fill mass
    scene.vent = 4e-3;
    scene.opening = opening;
    // The reference: RK4 with 1 us steps of dm/dt = inflow + vent rate from the vent's opening
    // (the fill, when the bag holds kFillMass at the ambient pressure, for no opening pressure).
    const double full_time = kFillMass / scene.flow;
    // The vent flows above the mass whose gauge pressure is the opening pressure: the
    // reference fills to it exactly (no vent below it), and closes the vent there exactly.
    const double opening_mass = kFillMass * std::pow(1 + opening / kAmbient, 1 / kGamma);
    // The inflow by phase, not by time, so a stage at the inflow's end takes the phase's flow.
    auto rate = [&](double inflow, double m) {
      return inflow + (m > opening_mass ? VentRate(scene, m) : 0.0);
    };
    std::vector<double> times = Linspace(0.011, 0.06, 49);
    std::vector<double> expected;
    double t = full_time + (opening_mass - kFillMass) / scene.flow, m = opening_mass;
    const double h = 1e-6;
    for (double target : times) {
      // Stop on the inflow's end so RK4 never straddles it.
      for (const auto& [stop, inflow] :
           {std::pair{std::min(scene.fill, target), scene.flow}, std::pair{target, 0.0}}) {
        while (t < stop - 1e-15) {
          const double step = std::min(h, stop - t);
          const double k1 = rate(inflow, m), k2 = rate(inflow, m + step / 2 * k1);
          const double k3 = rate(inflow, m + step / 2 * k2), k4 = rate(inflow, m + step * k3);
          m = std::max(m + step / 6 * (k1 + 2 * k2 + 2 * k3 + k4), opening_mass);
          t += step;
        }
      }
      expected.push_back(m);
    }
    for (const std::string& method : {std::string("dopri5"), std::string("rosenbrock")}) {
      std::size_t k = 0;
      RunSamples(scene, method, times, [&](const Model& model, const Data& data) {
        const BagStates states = StatesOf(model, data);
        const double delivered = scene.flow * std::min(data.time, scene.fill);
        EXPECT_NEAR(states.mass + states.vented, delivered, 1e-9 * delivered)
            << method << " t " << data.time;
        EXPECT_NEAR(states.mass, expected[k], 1e-6 * expected[k])
            << method << " opening " << opening << " t " << data.time;
        ++k;
      });
    }
    if (opening > 0) {
      // The vent has closed where the gauge pressure falls to the opening pressure.
      EXPECT_EQ(expected.back(), opening_mass);
    } else {
      EXPECT_LT(expected.back(), 1.1 * kFillMass);  // from 3.5 times at the inflow's end
    }
  }
}

TEST(FreeAirbag, FullBagHangsOnItsSpringAsAMassOfGasAndFabric) {
  FreeBagScene scene;
  scene.gravity = -9.81;
  scene.tether = 200.0;
  scene.bag_mass = 0.3;
  scene.mass_factor = 1.2;
  // Reference: z'' = -k z / M(t) + g from the fill (z the centre's drop from its attached
  // place), M = factor (m(t) + bag mass), the gas mass m(t) the integral of the inflow.
  const double full_time = kFillMass / scene.flow;
  auto mass_at = [&](double t) {
    return scene.mass_factor * (scene.flow * std::min(t, scene.fill) + scene.bag_mass);
  };
  const std::vector<double> times = Linspace(0.02, 0.3, 28);
  std::vector<double> expected;
  double t = full_time, z = 0, v = 0;
  const double h = 1e-6;
  auto acceleration = [&](double time, double position) {
    return -scene.tether * position / mass_at(time) + scene.gravity;
  };
  for (double target : times) {
    for (double stop : {std::min(scene.fill, target), target}) {
      while (t < stop - 1e-15) {
        const double step = std::min(h, stop - t);
        const double a1 = acceleration(t, z);
        const double a2 = acceleration(t + step / 2, z + step / 2 * v);
        const double a3 = acceleration(t + step / 2, z + step / 2 * (v + step / 2 * a1));
        const double a4 = acceleration(t + step, z + step * (v + step / 2 * a2));
        // RK4 for z' = v, v' = a(t, z).
        const double z1 = v, z2 = v + step / 2 * a1, z3 = v + step / 2 * a2, z4 = v + step * a3;
        z += step / 6 * (z1 + 2 * z2 + 2 * z3 + z4);
        v += step / 6 * (a1 + 2 * a2 + 2 * a3 + a4);
        t += step;
      }
    }
    expected.push_back(z);
  }
  for (const std::string& method : AllIntegrators()) {
    std::size_t k = 0;
    RunSamples(scene, method, times, [&](const Model& model, const Data& data) {
      const BagStates states = StatesOf(model, data);
      EXPECT_NEAR(states.centre.z() - kRadius, expected[k], 1e-6) << method << " t " << data.time;
      EXPECT_NEAR(states.centre.x(), 0.0, 1e-12);
      ++k;
    });
  }
}

TEST(FreeAirbag, BallThrownIntoAFreeBagKeepsMomentumAndEnergy) {
  FreeBagScene scene;  // closed, no spring, no gravity: ball and bag are alone
  scene.fill = 0.005;  // 0.05 kg, full at 2.8 ms: the bag's mass is constant from 5 ms
  scene.height = 0.75;
  scene.speed = -20.0;  // reaches the bag (top at 0.4 m, ball radius 0.1) at about 12.5 ms
  const double gas = scene.flow * scene.fill;
  const double bag = scene.mass_factor * (gas + scene.bag_mass);
  // The work stored in the gas compressed from the full volume: the integral of the gauge
  // pressure over the volume lost, with p V^gamma = p_f V_f^gamma.
  const double full_pressure = FullBagPressure(gas);
  auto stored = [&](double volume) {
    const double pressure = full_pressure * std::pow(kFullVolume / volume, kGamma);
    return (pressure * volume - full_pressure * kFullVolume) / (kGamma - 1) -
           kAmbient * (kFullVolume - volume);
  };
  const double momentum = scene.mass * scene.speed;
  const double energy = 0.5 * scene.mass * scene.speed * scene.speed;
  for (const std::string& method : AllIntegrators()) {
    double deepest = 0.0;
    RunSamples(
        scene, method, Linspace(0.0125, 0.06, 95), [&](const Model& model, const Data& data) {
          const BagStates states = StatesOf(model, data);
          const Vec3 ball =
              runtime::PointInFrame(data, {runtime::FrameRef::Kind::kSegment, 0}, Vec3::Zero())
                  .velocity;
          EXPECT_NEAR(scene.mass * ball.z() + bag * states.velocity.z(), momentum,
                      1e-6 * std::abs(momentum))
              << method << " t " << data.time;
          const double kinetic =
              0.5 * scene.mass * ball.squaredNorm() + 0.5 * bag * states.velocity.squaredNorm();
          EXPECT_NEAR(kinetic + stored(data.airbags.volume[0]), energy, 1e-5 * energy)
              << method << " t " << data.time;
          deepest = std::max(deepest, kFullVolume - data.airbags.volume[0]);
        });
    // The ball did push into the bag, and gave it momentum.
    EXPECT_GT(deepest, 0.005 * kFullVolume) << method;
  }
}

}  // namespace
}  // namespace sled::verification
