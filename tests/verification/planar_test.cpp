// Planar (2-D) symmetry in the runtime: a floating two-link body whose reference segment has a
// planar joint (x, z and a turn about y) tumbles under gravity. Whatever the links do, the
// centre of mass of the whole body follows the parabola of free fall, the angular momentum
// about it stays constant, and so does the energy: three conservation laws that check the
// planar joint's motion subspace and its velocity-product term.
#include <cmath>

#include <gtest/gtest.h>

#include "tests/runtime/model_fixtures.h"
#include "tests/verification/verification.h"

namespace sled::verification {
namespace {

using runtime::Mat3;
using runtime::Vec3;

struct Totals {
  double mass = 0.0;
  Vec3 centre = Vec3::Zero();
  Vec3 momentum = Vec3::Zero();
  double energy = 0.0;
  Vec3 angular_momentum = Vec3::Zero();  // about the centre of mass
};

Totals TotalsOf(const runtime::Model& model, const runtime::Data& data) {
  Totals totals;
  for (std::size_t s = 0; s < model.nsegment(); ++s) {
    const double m = model.segment_mass[s];
    const Mat3& R = data.rotation[s];
    const Vec3 v = R * data.velocity[s].tail<3>();
    totals.mass += m;
    totals.centre += m * data.position[s];
    totals.momentum += m * v;
    const Vec3 w = data.velocity[s].head<3>();
    totals.energy += 0.5 * m * v.squaredNorm() + 0.5 * w.dot(model.segment_inertia[s] * w) -
                     m * model.gravity.dot(data.position[s]);
  }
  totals.centre /= totals.mass;
  for (std::size_t s = 0; s < model.nsegment(); ++s) {
    const Mat3& R = data.rotation[s];
    const Vec3 v = R * data.velocity[s].tail<3>();
    const Vec3 w = R * data.velocity[s].head<3>();
    totals.angular_momentum += R * model.segment_inertia[s] * R.transpose() * w +
                               model.segment_mass[s] * (data.position[s] - totals.centre).cross(v);
  }
  return totals;
}

class PlanarBody : public ::testing::TestWithParam<std::string> {};

TEST_P(PlanarBody, TumblesWithTheCentreOfMassOnAParabolaAndItsMomentaKept) {
  runtime::Model model;
  model.gravity = Vec3(0, 0, -9.80665);
  runtime::testing::AddSegment(model, "trunk", -1, runtime::JointKind::kPlanar, 30.0,
                               Vec3(1.2, 1.0, 0.4), Vec3(0, 0.25, 0));
  runtime::testing::AddSegment(model, "leg", 0, runtime::JointKind::kPin, 8.0,
                               Vec3(0.15, 0.14, 0.02), Vec3(0.05, 0, -0.3), Vec3(0, 0, 0.25),
                               Vec3::UnitY());
  // x, z, pitch and their rates; the leg starts bent and swinging.
  model.q0 = {0.4, 1.1, 0.3, 0.7};
  model.v0 = {2.0, 1.5, -3.0, 6.0};
  runtime::Data data = runtime::MakeData(model);
  ASSERT_TRUE(runtime::Forward(model, data, nullptr));
  const Totals start = TotalsOf(model, data);
  // The plane: y stays at the joint point's 0.25 m.
  ASSERT_NEAR(data.position[0].y(), 0.25, 1e-15);
  double worst_centre = 0, worst_momentum = 0, worst_energy = 0, worst_y = 0;
  ASSERT_TRUE(
      Simulate(model, data, GetParam(), 1e-10, Linspace(0, 1.0, 50), [&](const runtime::Data& d) {
        const Totals now = TotalsOf(model, d);
        const double t = d.time;
        const Vec3 parabola =
            start.centre + start.momentum / start.mass * t + 0.5 * model.gravity * t * t;
        worst_centre = std::max(worst_centre, (now.centre - parabola).norm());
        worst_momentum =
            std::max(worst_momentum, (now.angular_momentum - start.angular_momentum).norm());
        worst_energy = std::max(worst_energy, std::abs(now.energy - start.energy));
        for (std::size_t s = 0; s < model.nsegment(); ++s) {
          worst_y = std::max(worst_y, std::abs(d.position[s].y() - 0.25));
        }
      }));
  // The legs swing through more than a turn meanwhile: the test is not a trivial one.
  EXPECT_GT(std::abs(data.q[3] - model.q0[3]), 2.0);
  EXPECT_LT(worst_centre, 1e-7);
  EXPECT_LT(worst_momentum, 1e-7 * start.angular_momentum.norm());
  EXPECT_LT(worst_energy, 1e-7 * std::abs(start.energy));
  EXPECT_LT(worst_y, 1e-12);
}

INSTANTIATE_TEST_SUITE_P(EveryIntegrator, PlanarBody, ::testing::ValuesIn(AllIntegrators()));

}  // namespace
}  // namespace sled::verification
