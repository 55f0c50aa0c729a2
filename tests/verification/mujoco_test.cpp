// sled's articulated-body dynamics against MuJoCo 2.2.2 (an independent implementation: reduced
// coordinates, composite rigid bodies and a sparse LDL^T of the mass matrix). The same body
// trees (tree_models.h) are built in both, set to the same random states, and the generalized
// accelerations and joint wrenches must agree to 1e-9 relative. No contacts, no joint forces:
// only gravity, gyroscopic and Coriolis terms and the joint constraints.
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "runtime/dynamics/dynamics.h"
#include "tests/verification/tree_models.h"

namespace sled::verification {
namespace {

constexpr int kStates = 20;
constexpr double kRelativeTolerance = 1e-9;

double MaxAbs(const std::vector<double>& x) {
  double out = 0.0;
  for (const double value : x) out = std::max(out, std::abs(value));
  return out;
}

// Both programs built from one description, plus the map between their coordinates.
struct Pair {
  explicit Pair(const BodyTree& tree_in)
      : tree(tree_in), model(BuildModel(tree)), data(runtime::MakeData(model)) {
    std::string error;
    m = LoadMjcf(BuildMjcf(tree), &error);
    if (!m) throw std::runtime_error("MuJoCo rejected the model: " + error);
    d.reset(mj_makeData(m.get()));
    map = MapToMujoco(tree, m.get());
  }
  // Sets state `seed` in both, runs both; false when sled fails.
  bool Run(std::uint64_t seed) {
    data.model = &model;
    SetRandomState(model, seed, data);
    CopyStateToMujoco(tree, model, data, map, m.get(), d.get());
    runtime::Failure failure;
    if (!runtime::Forward(model, data, &failure)) return false;
    mj_forward(m.get(), d.get());
    mj_rnePostConstraint(m.get(), d.get());  // cfrc_int
    return true;
  }

  BodyTree tree;
  runtime::Model model;
  runtime::Data data;
  MujocoModelPtr m;
  MujocoDataPtr d;
  MujocoMap map;
};

void ExpectSameShape(const Pair& pair) {
  EXPECT_EQ(pair.m->nq, pair.model.nq);
  EXPECT_EQ(pair.m->nv, pair.model.nv);
  EXPECT_EQ(static_cast<std::size_t>(pair.m->nbody), pair.model.nsegment() + 1);  // + world
  for (std::size_t s = 0; s < pair.model.nsegment(); ++s) {
    EXPECT_NEAR(pair.m->body_mass[pair.map.body[s]], pair.model.segment_mass[s], 1e-12) << s;
  }
}

// Accelerations at kStates random states; returns the largest acceleration seen, so callers can
// check the comparison was not of near-zero numbers.
double ExpectAccelerationsAgree(Pair& pair) {
  double largest = 0.0;
  for (int state = 0; state < kStates; ++state) {
    const auto seed = static_cast<std::uint64_t>(1000 + state);
    if (!pair.Run(seed)) {
      ADD_FAILURE() << pair.tree.name << ": sled's Forward failed at state " << state;
      return largest;
    }
    const std::vector<double> sled =
        AccelerationsAsMujocoQacc(pair.model, pair.data, pair.map, pair.m.get());
    const std::vector<double> mujoco(pair.d->qacc, pair.d->qacc + pair.m->nv);
    const double scale = std::max(1.0, MaxAbs(mujoco));
    largest = std::max(largest, MaxAbs(mujoco));
    // One expectation per state, at the worst degree of freedom.
    std::size_t worst = 0;
    for (std::size_t k = 0; k < sled.size(); ++k) {
      if (std::abs(sled[k] - mujoco[k]) > std::abs(sled[worst] - mujoco[worst])) worst = k;
    }
    EXPECT_NEAR(sled[worst], mujoco[worst], kRelativeTolerance * scale)
        << pair.tree.name << " state " << state << ", MuJoCo dof " << worst << " of "
        << sled.size();
  }
  return largest;
}

TEST(MuJoCoComparison, CvsBodyHasTheSameShapeInBoth) {
  Pair pair(CvsBody());
  EXPECT_EQ(pair.model.nsegment(), 15u);
  EXPECT_EQ(pair.model.nv, 40);
  EXPECT_EQ(pair.model.nq, 51);
  double total = 0.0;
  for (const double mass : pair.model.segment_mass) total += mass;
  EXPECT_NEAR(total, 78.0, 1e-12);
  ExpectSameShape(pair);
}

TEST(MuJoCoComparison, CvsBodyAccelerationsAgree) {
  Pair pair(CvsBody());
  const double largest = ExpectAccelerationsAgree(pair);
  EXPECT_GT(largest, 10.0);  // the states are far from static equilibrium
}

TEST(MuJoCoComparison, ThirtySegmentChainAccelerationsAgree) {
  Pair pair(Chain(30));
  ExpectSameShape(pair);
  const double largest = ExpectAccelerationsAgree(pair);
  EXPECT_GT(largest, 10.0);
}

// The force and moment each joint transmits (constraint forces only: no joint torques act), at
// every joint, against MuJoCo's cfrc_int; relative to the largest component at that state.
void ExpectJointWrenchesAgree(Pair& pair) {
  for (int state = 0; state < kStates; ++state) {
    if (!pair.Run(static_cast<std::uint64_t>(2000 + state))) {
      ADD_FAILURE() << pair.tree.name << ": sled's Forward failed at state " << state;
      return;
    }
    double scale = 1.0;
    for (std::size_t s = 1; s < pair.model.nsegment(); ++s) {
      for (int k = 0; k < 6; ++k) {
        scale = std::max(scale, std::abs(pair.d->cfrc_int[6 * pair.map.body[s] + k]));
      }
    }
    // One expectation per state, at the worst joint and component.
    double worst_error = -1.0, worst_sled = 0.0, worst_mujoco = 0.0;
    std::string worst_where;
    for (std::size_t s = 1; s < pair.model.nsegment(); ++s) {
      const runtime::Vec6 sled =
          JointWrenchAsMujocoCfrcInt(pair.data, pair.map, pair.m.get(), pair.d.get(), s);
      const double* mujoco = pair.d->cfrc_int + 6 * pair.map.body[s];
      for (int k = 0; k < 6; ++k) {
        if (std::abs(sled[k] - mujoco[k]) > worst_error) {
          worst_error = std::abs(sled[k] - mujoco[k]);
          worst_sled = sled[k];
          worst_mujoco = mujoco[k];
          worst_where = pair.model.joint_name[s] + " component " + std::to_string(k);
        }
      }
    }
    EXPECT_NEAR(worst_sled, worst_mujoco, kRelativeTolerance * scale)
        << pair.tree.name << " state " << state << ", joint " << worst_where;
  }
}

TEST(MuJoCoComparison, CvsBodyJointWrenchesAgree) {
  Pair pair(CvsBody());
  ExpectJointWrenchesAgree(pair);
}

TEST(MuJoCoComparison, ThirtySegmentChainJointWrenchesAgree) {
  Pair pair(Chain(30));
  ExpectJointWrenchesAgree(pair);
}

// A negative control: the comparison notices a 1% change in one segment's inertia.
TEST(MuJoCoComparison, DetectsADifferentInertia) {
  Pair pair(CvsBody());
  BodyTree changed = CvsBody();
  changed.segments[4].inertia *= 1.01;  // the head
  std::string error;
  MujocoModelPtr m = LoadMjcf(BuildMjcf(changed), &error);
  ASSERT_TRUE(m) << error;
  MujocoDataPtr d(mj_makeData(m.get()));
  ASSERT_TRUE(pair.Run(1000));
  CopyStateToMujoco(pair.tree, pair.model, pair.data, pair.map, m.get(), d.get());
  mj_forward(m.get(), d.get());
  const std::vector<double> sled =
      AccelerationsAsMujocoQacc(pair.model, pair.data, pair.map, m.get());
  double difference = 0.0;
  for (std::size_t k = 0; k < sled.size(); ++k) {
    difference = std::max(difference, std::abs(sled[k] - d->qacc[k]));
  }
  EXPECT_GT(difference, 1e-4);
}

}  // namespace
}  // namespace sled::verification
