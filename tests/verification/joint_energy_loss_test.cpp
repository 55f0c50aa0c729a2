// Joint energy loss (runtime/forces/joint_hysteresis.h) against closed forms. A disc on a joint
// with a linear spring k and no gravity starts at zero angle with rate w0: it loads to the largest
// angle a = w0 / sqrt(k / I) (the turn is an event), then unloads along the straight line to zero
// torque at G a (G the energy loss; an unloading slope s unloads likewise with G = 1 - 1/s),
// which gives back (1 - G) of the spring energy E0 = I w0^2 / 2: between G a and zero the disc
// turns freely at w0 sqrt(1 - G), and the energy account holds the dissipated G E0 there (nothing
// is stored at zero torque). Past zero the other side of the angle loads afresh to
// a sqrt(1 - G); a ball joint's flexure angle is a size, so its free zone reaches across zero.
// Every integrator.
#include <cmath>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "runtime/run/energy.h"
#include "tests/runtime/model_fixtures.h"
#include "tests/verification/verification.h"

namespace sled::verification {
namespace {

using runtime::JointKind;
using runtime::Vec3;

enum class Law {
  kEnergyLoss,     // the joint's energy_loss, as the compiler lowers it: the function's
  kMirroredTable,  // energy loss, on a table that covers negative angles
  kUnloadSlope,    // the function's own unload_slope s
  kBallFlexure,    // a ball joint's flexure
};

struct Case {
  std::string method;
  Law law;
};

class JointEnergyLoss : public ::testing::TestWithParam<Case> {};

TEST_P(JointEnergyLoss, ReturnsTheRestOfItsSpringEnergy) {
  const Case c = GetParam();
  const double inertia = 0.02, k = 50.0, w0 = 3.0;
  const double loss = 0.4, slope = 2.5;
  const double g = c.law == Law::kUnloadSlope ? 1 - 1 / slope : loss;
  runtime::Model model;
  model.gravity.setZero();
  const bool ball = c.law == Law::kBallFlexure;
  runtime::testing::AddSegment(model, "disc", -1, ball ? JointKind::kBall : JointKind::kPin, 1.0,
                               Vec3(inertia, inertia, inertia));
  const std::int32_t f =
      c.law == Law::kMirroredTable
          ? runtime::testing::AddTableFunction(model.functions, {{-1, -k}, {0, 0}, {1, k}}, loss)
          : runtime::testing::AddTableFunction(model.functions, {{0, 0}, {1, k}},
                                               c.law == Law::kUnloadSlope ? 0.0 : loss);
  if (c.law == Law::kUnloadSlope) model.functions.unload_slope = {slope};
  model.joint_function[0] = {f, -1, -1};
  model.v0[0] = w0;  // the pin's rate, or the ball's angular velocity about x (a flexure)
  runtime::Data data = runtime::MakeData(model);
  ASSERT_EQ(data.joint_histories.size(), 1u);

  const double w = std::sqrt(k / inertia);
  const double largest = w0 / w;
  const double w_unload = std::sqrt(k / (1 - g) / inertia);  // the unloading line's stiffness
  const double w_free = w0 * std::sqrt(1 - g);
  const double energy = 0.5 * inertia * w0 * w0;
  const double t_free = std::numbers::pi / 2 / w + std::numbers::pi / 2 / w_unload;
  const double free_width = (ball ? 2 : 1) * g * largest;
  const double t_other = t_free + free_width / w_free;
  int free_samples = 0;
  runtime::IntegratorStats stats;
  ASSERT_TRUE(Simulate(
      model, data, c.method, 1e-10, Linspace(0, t_other + 0.75 * std::numbers::pi / w, 400),
      [&](const runtime::Data& d) {
        const double kinetic = runtime::KineticEnergy(model, d);
        // The energy balance closes: what the disc lost, the joint absorbed.
        EXPECT_NEAR(kinetic + d.energy.Absorbed(), energy, 1e-7 * energy) << d.time;
        if (d.time > t_free + 1e-4 && d.time < t_other - 1e-4) {
          ++free_samples;
          EXPECT_NEAR(d.v[0], -w_free, 1e-6 * w0) << d.time;
          EXPECT_NEAR(kinetic, (1 - g) * energy, 1e-6 * energy) << d.time;
          EXPECT_NEAR(d.energy.Absorbed(), g * energy, 1e-6 * energy) << d.time;
        }
      },
      &stats));
  EXPECT_GT(free_samples, 10);
  EXPECT_NEAR(data.joint_histories.positive[0].max_deflection, largest, 1e-7 * largest);
  EXPECT_NEAR(data.joint_histories.positive[0].permanent, g * largest, 1e-7 * largest);
  if (!ball) {
    // The other side loaded afresh, to the angle the energy left gives.
    EXPECT_NEAR(data.joint_histories.negative[0].max_deflection, largest * std::sqrt(1 - g),
                1e-7 * largest);
  }
  EXPECT_GE(stats.events, ball ? 1 : 2);  // the turns
}

std::vector<Case> Cases() {
  std::vector<Case> cases;
  for (const std::string& method : AllIntegrators()) {
    for (Law law : {Law::kEnergyLoss, Law::kMirroredTable, Law::kUnloadSlope, Law::kBallFlexure}) {
      cases.push_back({method, law});
    }
  }
  return cases;
}

std::string Name(const ::testing::TestParamInfo<Case>& info) {
  const char* laws[] = {"EnergyLoss", "MirroredTable", "UnloadSlope", "BallFlexure"};
  return info.param.method + "_" + laws[static_cast<int>(info.param.law)];
}

INSTANTIATE_TEST_SUITE_P(EveryIntegrator, JointEnergyLoss, ::testing::ValuesIn(Cases()), Name);

TEST(JointEnergyLoss, AJointReleasedFromAnAngleDissipatesItsShare) {
  // Held at a0 at the start (the history starts loaded there) and released: the disc reaches
  // the free zone with (1 - G) of the spring energy k a0^2 / 2, which the energy account (that
  // starts without the spring's energy) shows as absorbed work -(1 - G) E.
  const double inertia = 0.02, k = 50.0, a0 = 0.6, loss = 0.3;
  runtime::Model model;
  model.gravity.setZero();
  runtime::testing::AddSegment(model, "disc", -1, JointKind::kPin, 1.0,
                               Vec3(inertia, inertia, inertia));
  const std::int32_t f =
      runtime::testing::AddTableFunction(model.functions, {{0, 0}, {1, k}}, loss);
  model.joint_function[0] = {f, -1, -1};
  model.q0[0] = a0;
  runtime::Data data = runtime::MakeData(model);
  EXPECT_EQ(data.joint_histories.positive[0].max_deflection, a0);
  const double spring = 0.5 * k * a0 * a0;
  const double w_unload = std::sqrt(k / (1 - loss) / inertia);
  const double t_free = std::numbers::pi / 2 / w_unload;
  const double w_free = std::sqrt(2 * (1 - loss) * spring / inertia);
  ASSERT_TRUE(
      Simulate(model, data, "auto", 1e-10, Linspace(0, t_free + 0.5 * loss * a0 / w_free, 50),
               [&](const runtime::Data& d) {
                 if (d.time < t_free + 1e-4) return;
                 EXPECT_NEAR(d.q[0], loss * a0 - w_free * (d.time - t_free), 1e-7);
                 EXPECT_NEAR(runtime::KineticEnergy(model, d), (1 - loss) * spring, 1e-7 * spring);
                 EXPECT_NEAR(d.energy.Absorbed(), -(1 - loss) * spring, 1e-7 * spring);
               }));
}

}  // namespace
}  // namespace sled::verification
