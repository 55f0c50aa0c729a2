// A tumbling 15-segment body (the CVS topology: a free pelvis, ball joints at the spine, neck,
// shoulders, hips and ankles, pins at the elbows and knees) thrown spinning for one second: each
// joint's point, computed from the parent and from the child, stays in one place. In joint
// coordinates the tree cannot come apart, so the separation is at rounding level (issue: below
// 1e-9 m).
#include <cmath>

#include <gtest/gtest.h>

#include "tests/runtime/model_fixtures.h"
#include "tests/verification/verification.h"

namespace sled::verification {
namespace {

using runtime::JointKind;
using runtime::Vec3;

runtime::Model CvsBody() {
  runtime::Model model;
  using runtime::testing::AddSegment;
  AddSegment(model, "pelvis", -1, JointKind::kFree, 11.0, Vec3(0.10, 0.09, 0.11));
  AddSegment(model, "abdomen", 0, JointKind::kBall, 12.0, Vec3(0.12, 0.08, 0.10), Vec3(0, 0, 0.10),
             Vec3(0, 0, -0.10));
  AddSegment(model, "thorax", 1, JointKind::kBall, 12.5, Vec3(0.14, 0.09, 0.13), Vec3(0, 0, 0.10),
             Vec3(0, 0, -0.15));
  AddSegment(model, "neck", 2, JointKind::kBall, 1.1, Vec3(0.002, 0.002, 0.0015), Vec3(0, 0, 0.20),
             Vec3(0, 0, -0.05));
  AddSegment(model, "head", 3, JointKind::kBall, 4.3, Vec3(0.022, 0.024, 0.017), Vec3(0, 0, 0.05),
             Vec3(0, 0, -0.08));
  for (double side : {1.0, -1.0}) {
    const std::size_t arm =
        AddSegment(model, "upper_arm", 2, JointKind::kBall, 2.1, Vec3(0.014, 0.012, 0.004),
                   Vec3(0, 0.2 * side, 0.15), Vec3(0, 0, 0.15));
    AddSegment(model, "lower_arm", static_cast<int>(arm), JointKind::kPin, 1.7,
               Vec3(0.025, 0.024, 0.002), Vec3(0, 0, -0.15), Vec3(0, 0, 0.15), Vec3::UnitY());
    const std::size_t leg =
        AddSegment(model, "upper_leg", 0, JointKind::kBall, 11.0, Vec3(0.22, 0.22, 0.044),
                   Vec3(0, 0.09 * side, -0.08), Vec3(0, 0, 0.20));
    const std::size_t shank =
        AddSegment(model, "lower_leg", static_cast<int>(leg), JointKind::kPin, 3.4,
                   Vec3(0.042, 0.040, 0.007), Vec3(0, 0, -0.22), Vec3(0, 0, 0.20), Vec3::UnitY());
    AddSegment(model, "foot", static_cast<int>(shank), JointKind::kBall, 1.1,
               Vec3(0.001, 0.004, 0.005), Vec3(0, 0, -0.22), Vec3(-0.05, 0, 0.04));
  }
  return model;
}

TEST(JointSeparation, ATumblingFifteenSegmentBodyStaysTogether) {
  runtime::Model model = CvsBody();
  ASSERT_EQ(model.nsegment(), 15u);
  ASSERT_EQ(model.nv, 40);
  // Spinning and flailing: every joint rate in +-3 rad/s, the pelvis at 5 rad/s.
  for (std::size_t k = 0; k < model.v0.size(); ++k) {
    model.v0[k] = 3.0 * std::sin(1.7 * static_cast<double>(k) + 0.3);
  }
  model.v0[0] = 5.0;
  runtime::Data data = runtime::MakeData(model);
  double worst = 0;
  ASSERT_TRUE(
      Simulate(model, data, "dopri5", 1e-8, Linspace(0, 1.0, 200), [&](const runtime::Data& d) {
        for (std::size_t s = 1; s < model.nsegment(); ++s) {
          const auto p = static_cast<std::size_t>(model.segment_parent[s]);
          const Vec3 from_parent = d.position[p] + d.rotation[p] * model.joint_point_in_parent[s];
          const Vec3 from_child = d.position[s] + d.rotation[s] * model.joint_point_in_child[s];
          worst = std::max(worst, (from_parent - from_child).norm());
        }
      }));
  EXPECT_LT(worst, 1e-9);
}

}  // namespace
}  // namespace sled::verification
