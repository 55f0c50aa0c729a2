// A torque-free asymmetric rigid body: kinetic energy and the world-frame angular momentum are
// conserved (to 1e-9 relative at tight tolerance), and rotation about the intermediate axis is
// unstable (the tennis-racket flip) while rotation about the major axis is not.
#include <cmath>

#include <gtest/gtest.h>

#include "tests/runtime/model_fixtures.h"
#include "tests/verification/verification.h"

namespace sled::verification {
namespace {

runtime::Model FreeBody(const runtime::Vec3& inertia) {
  runtime::Model model;
  model.gravity.setZero();
  runtime::testing::AddSegment(model, "body", -1, runtime::JointKind::kFree, 3.0, inertia);
  return model;
}

class TorqueFreeBody : public ::testing::TestWithParam<std::string> {};

TEST_P(TorqueFreeBody, ConservesEnergyAndAngularMomentum) {
  const runtime::Vec3 I(0.2, 0.5, 0.7);
  runtime::Model model = FreeBody(I);
  const runtime::Vec3 w0(0.3, 4.0, 0.2);  // near the intermediate axis
  for (int k = 0; k < 3; ++k) model.v0[static_cast<std::size_t>(k)] = w0[k];
  model.v0[3] = 1.0;  // a drifting centre of mass, too
  runtime::Data data = runtime::MakeData(model);
  auto energy = [&](const runtime::Data& d) {
    const runtime::Vec3 w = d.velocity[0].head<3>();
    return 0.5 * w.dot(I.asDiagonal() * w) + 0.5 * 3.0 * d.velocity[0].tail<3>().squaredNorm();
  };
  auto momentum = [&](const runtime::Data& d) -> runtime::Vec3 {
    return d.rotation[0] * (I.asDiagonal() * d.velocity[0].head<3>());
  };
  ASSERT_TRUE(runtime::Forward(model, data, nullptr));
  const double e0 = energy(data);
  const runtime::Vec3 h0 = momentum(data);
  double worst_energy = 0, worst_momentum = 0, min_wy = 1e9;
  ASSERT_TRUE(
      Simulate(model, data, GetParam(), 1e-12, Linspace(0, 10, 200), [&](const runtime::Data& d) {
        worst_energy = std::max(worst_energy, std::abs(energy(d) - e0) / e0);
        worst_momentum = std::max(worst_momentum, (momentum(d) - h0).norm() / h0.norm());
        min_wy = std::min(min_wy, d.velocity[0][1]);
      }));
  EXPECT_LT(worst_energy, 1e-9);
  EXPECT_LT(worst_momentum, 1e-9);
  // The intermediate axis flips: the spin about y reverses within 10 s.
  EXPECT_LT(min_wy, -3.0);
}

TEST_P(TorqueFreeBody, SpinAboutTheMajorAxisIsStable) {
  const runtime::Vec3 I(0.2, 0.5, 0.7);
  runtime::Model model = FreeBody(I);
  model.v0[0] = 0.3;
  model.v0[1] = 0.2;
  model.v0[2] = 4.0;
  runtime::Data data = runtime::MakeData(model);
  double min_wz = 1e9;
  ASSERT_TRUE(
      Simulate(model, data, GetParam(), 1e-9, Linspace(0, 10, 100),
               [&](const runtime::Data& d) { min_wz = std::min(min_wz, d.velocity[0][2]); }));
  EXPECT_GT(min_wz, 3.8);
}

INSTANTIATE_TEST_SUITE_P(EveryIntegrator, TorqueFreeBody, ::testing::ValuesIn(AllIntegrators()));

}  // namespace
}  // namespace sled::verification
