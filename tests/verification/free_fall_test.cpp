// A free-falling, tumbling chain: the centre of mass of the whole chain follows the parabola
// p0 + v0 t + g t^2 / 2 exactly, whatever the joints do, and the joints never separate.
#include <cmath>

#include <gtest/gtest.h>

#include "tests/runtime/model_fixtures.h"
#include "tests/verification/verification.h"

namespace sled::verification {
namespace {

class FreeFallingChain : public ::testing::TestWithParam<std::string> {};

TEST_P(FreeFallingChain, CentreOfMassFollowsTheParabola) {
  runtime::Model model;
  using runtime::JointKind;
  using runtime::Vec3;
  runtime::testing::AddSegment(model, "a", -1, JointKind::kFree, 3.0, Vec3(0.05, 0.06, 0.07));
  runtime::testing::AddSegment(model, "b", 0, JointKind::kBall, 2.0, Vec3(0.03, 0.02, 0.04),
                               Vec3(0, 0, -0.2), Vec3(0, 0, 0.15));
  runtime::testing::AddSegment(model, "c", 1, JointKind::kPin, 1.0, Vec3(0.01, 0.01, 0.005),
                               Vec3(0, 0, -0.15), Vec3(0, 0, 0.1), Vec3::UnitX());
  runtime::testing::AddSegment(model, "d", 1, JointKind::kEuler, 1.5, Vec3(0.02, 0.01, 0.02),
                               Vec3(0.1, 0, 0), Vec3(-0.1, 0, 0));
  // Spin and swing everything.
  for (std::size_t k = 0; k < model.v0.size(); ++k)
    model.v0[k] = 0.5 + 0.3 * std::sin(3.0 * static_cast<double>(k));
  runtime::Data data = runtime::MakeData(model);
  ASSERT_TRUE(runtime::Forward(model, data, nullptr));
  double total = 0;
  Vec3 p0 = Vec3::Zero(), v0 = Vec3::Zero();
  for (std::size_t s = 0; s < model.nsegment(); ++s) {
    total += model.segment_mass[s];
    p0 += model.segment_mass[s] * data.position[s];
    v0 += model.segment_mass[s] * (data.rotation[s] * data.velocity[s].tail<3>());
  }
  p0 /= total;
  v0 /= total;
  double worst = 0;
  ASSERT_TRUE(
      Simulate(model, data, GetParam(), 1e-10, Linspace(0, 1.0, 50), [&](const runtime::Data& d) {
        Vec3 p = Vec3::Zero();
        for (std::size_t s = 0; s < model.nsegment(); ++s) {
          p += model.segment_mass[s] * d.position[s];
        }
        p /= total;
        const Vec3 expected = p0 + v0 * d.time + 0.5 * model.gravity * d.time * d.time;
        worst = std::max(worst, (p - expected).norm());
      }));
  EXPECT_LT(worst, 1e-6);
}

INSTANTIATE_TEST_SUITE_P(EveryIntegrator, FreeFallingChain, ::testing::ValuesIn(AllIntegrators()));

}  // namespace
}  // namespace sled::verification
