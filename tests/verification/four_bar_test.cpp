// A planar four-bar linkage (loop closure and energy), on every integrator. The ground link runs
// from pivot A to pivot B; the crank turns on a pin at A, the coupler on a pin at the crank's
// tip, the rocker on a pin at B, and a fixed-point constraint joins the coupler's tip to the
// rocker's (its out-of-plane row is redundant: the pins are parallel). Two variants close the
// same chain differently: the rocker replaced by a fixed distance from B, and a slider-crank whose
// rod end slides along a line of the ground. Each starts closed, turning, and runs for 2 s under
// gravity without damping: the loop must stay closed to 1e-9 m and the mechanical energy must
// stay constant to 1e-6 of the largest kinetic energy. The example examples/four_bar.sled must
// keep its loop closed too.
#include <cmath>
#include <filesystem>
#include <numbers>

#include <gtest/gtest.h>

#include "compiler/check/check.h"
#include "compiler/lower/lower.h"
#include "lang/syntax/parser.h"
#include "runtime/dynamics/constraints.h"
#include "runtime/forces/forces.h"
#include "runtime/run/run.h"
#include "tests/runtime/model_fixtures.h"
#include "tests/verification/compile.h"
#include "tests/verification/verification.h"

namespace sled::verification {
namespace {

using runtime::FrameRef;
using runtime::JointKind;
using runtime::Model;
using runtime::Vec3;
using runtime::testing::AddConstraint;

// Lengths [m] (Grashof: 0.1 + 0.3 <= 0.2 + 0.25, so the crank turns fully), aluminium bars of
// 0.54 kg/m.
constexpr double kCrank = 0.1, kCoupler = 0.3, kRocker = 0.2;
const Vec3 kA(0, 0, 0), kB(0.25, 0, 0);
constexpr double kLinearDensity = 0.54;
constexpr double kCrankAngle = std::numbers::pi / 3;  // from the x axis toward z
constexpr double kCrankRate = 2 * std::numbers::pi;   // rad/s
constexpr double kSliderHeight = -0.05;               // the slider's line: z = -0.05, along x

enum class Closure { kFixedPoint, kFixedDistance, kSliding };

// The direction of a bar at angle phi in the xz plane, and its derivative.
Vec3 Direction(double phi) { return {std::cos(phi), 0, std::sin(phi)}; }
Vec3 DirectionRate(double phi) { return {-std::sin(phi), 0, std::cos(phi)}; }

// A bar along its x axis, its frame at its centre, its joints at the ends.
std::size_t AddBar(Model& model, std::string name, int parent, double length,
                   const Vec3& point_in_parent) {
  const double mass = kLinearDensity * length;
  const double across = mass * length * length / 12, along = mass * 2e-4 / 12;
  return runtime::testing::AddSegment(model, std::move(name), parent, JointKind::kPin, mass,
                                      Vec3(along, across, across), point_in_parent,
                                      Vec3(-length / 2, 0, 0), Vec3::UnitY());
}

// The linkage closed at the crank angle kCrankAngle and turning at kCrankRate, the other angles
// and rates solved from the loop (an elbow-up assembly). A pin's coordinate is the rotation
// about y, which turns x toward -z: minus the bar's angle.
Model MakeLinkage(Closure closure) {
  Model model;
  AddBar(model, "crank", -1, kCrank, kA);
  AddBar(model, "coupler", 0, kCoupler, Vec3(kCrank / 2, 0, 0));
  const Vec3 tip = kA + kCrank * Direction(kCrankAngle);
  const Vec3 tip_rate = kCrank * kCrankRate * DirectionRate(kCrankAngle);
  double coupler_angle = 0.0, coupler_rate = 0.0;
  const FrameRef coupler{FrameRef::Kind::kSegment, 1};
  const Vec3 coupler_tip(kCoupler / 2, 0, 0);
  if (closure == Closure::kSliding) {
    // The rod's end on z = kSliderHeight, ahead of the crank.
    const double dz = kSliderHeight - tip.z();
    coupler_angle = std::atan2(dz, std::sqrt(kCoupler * kCoupler - dz * dz));
    // d/dt of the end's height is zero.
    coupler_rate = -tip_rate.z() / (kCoupler * DirectionRate(coupler_angle).z());
    AddConstraint(model, "slider", Model::ConstraintKind::kSliding, coupler, coupler_tip, {},
                  Vec3(0, 0, kSliderHeight), 0.0, Vec3::UnitX());
  } else {
    // The coupler's tip C: |C - tip| = coupler, |C - B| = rocker, above the line tip-B.
    const Vec3 base = kB - tip;
    const double d = base.norm();
    const double along = (d * d + kCoupler * kCoupler - kRocker * kRocker) / (2 * d);
    const double across = std::sqrt(kCoupler * kCoupler - along * along);
    const Vec3 u = base / d, normal(-u.z(), 0, u.x());  // u turned by +90 degrees in xz
    const Vec3 c = tip + along * u + across * normal;
    coupler_angle = std::atan2((c - tip).z(), (c - tip).x());
    const double rocker_angle = std::atan2((c - kB).z(), (c - kB).x());
    // Velocities: tip_rate + coupler * w2 u'(phi2) = rocker * w3 u'(phi3) (x and z rows).
    const Vec3 a = kCoupler * DirectionRate(coupler_angle);
    const Vec3 b = -kRocker * DirectionRate(rocker_angle);
    const double det = a.x() * b.z() - a.z() * b.x();
    coupler_rate = (-tip_rate.x() * b.z() + tip_rate.z() * b.x()) / det;
    const double rocker_rate = (-a.x() * tip_rate.z() + a.z() * tip_rate.x()) / det;
    if (closure == Closure::kFixedPoint) {
      AddBar(model, "rocker", -1, kRocker, kB);
      model.q0[2] = -rocker_angle;
      model.v0[2] = -rocker_rate;
      AddConstraint(model, "closure", Model::ConstraintKind::kFixedPoint, coupler, coupler_tip,
                    {FrameRef::Kind::kSegment, 2}, Vec3(kRocker / 2, 0, 0), 0.0, Vec3::UnitX());
    } else {
      AddConstraint(model, "closure", Model::ConstraintKind::kFixedDistance, coupler, coupler_tip,
                    {}, kB, kRocker, Vec3::UnitX());
    }
  }
  model.q0[0] = -kCrankAngle;
  model.v0[0] = -kCrankRate;
  model.q0[1] = -(coupler_angle - kCrankAngle);
  model.v0[1] = -(coupler_rate - kCrankRate);
  return model;
}

// The largest violation of any constraint [m], from the segments' poses alone.
double LoopError(const Model& model, const runtime::Data& data) {
  double error = 0.0;
  for (std::size_t c = 0; c < model.nconstraint(); ++c) {
    const Vec3 p1 =
        runtime::PointInFrame(data, model.constraint_first[c], model.constraint_point_first[c])
            .position;
    const Vec3 p2 =
        runtime::PointInFrame(data, model.constraint_second[c], model.constraint_point_second[c])
            .position;
    double e = 0.0;
    switch (model.constraint_kind[c]) {
      case Model::ConstraintKind::kFixedPoint:
        e = (p1 - p2).norm();
        break;
      case Model::ConstraintKind::kFixedDistance:
        e = std::abs((p1 - p2).norm() - model.constraint_distance[c]);
        break;
      default: {
        // Sliding along an axis of the ground (the only case here).
        const Vec3 axis = model.constraint_axis[c].normalized();
        e = ((p1 - p2) - axis * axis.dot(p1 - p2)).norm();
        break;
      }
    }
    error = std::max(error, e);
  }
  return error;
}

struct Energy {
  double kinetic = 0.0;
  double potential = 0.0;
};

Energy MechanicalEnergy(const Model& model, const runtime::Data& data) {
  Energy energy;
  for (std::size_t s = 0; s < model.nsegment(); ++s) {
    const runtime::Vec6& v = data.velocity[s];
    energy.kinetic += 0.5 * v.dot(runtime::SpatialInertia(model, s) * v);
    energy.potential -= model.segment_mass[s] * model.gravity.dot(data.position[s]);
  }
  return energy;
}

struct Case {
  const char* name;
  Closure closure;
  std::string method;
};

class FourBar : public ::testing::TestWithParam<Case> {};

TEST_P(FourBar, LoopStaysClosedAndEnergyIsConserved) {
  const Model model = MakeLinkage(GetParam().closure);
  runtime::Data data = runtime::MakeData(model);
  ASSERT_TRUE(data.constraints);
  // The analytic assembly is closed: the set-up's projection had nothing to correct.
  EXPECT_LT(data.constraints->initial_position_correction, 1e-15);
  EXPECT_LT(data.constraints->initial_velocity_correction, 1e-14);
  ASSERT_TRUE(runtime::Forward(model, data, nullptr));
  const Energy start = MechanicalEnergy(model, data);
  double worst_loop = LoopError(model, data), worst_energy = 0.0, largest_kinetic = 0.0;
  double crank_turned = 0.0;
  runtime::IntegratorStats stats;
  ASSERT_TRUE(Simulate(
      model, data, GetParam().method, 1e-10, Linspace(0, 2, 400),
      [&](const runtime::Data& d) {
        worst_loop = std::max(worst_loop, LoopError(model, d));
        const Energy e = MechanicalEnergy(model, d);
        worst_energy = std::max(
            worst_energy, std::abs(e.kinetic + e.potential - start.kinetic - start.potential));
        largest_kinetic = std::max(largest_kinetic, e.kinetic);
        crank_turned = std::max(crank_turned, std::abs(d.q[0] - model.q0[0]));
      },
      &stats));
  const double relative_energy = worst_energy / largest_kinetic;
  EXPECT_LT(worst_loop, 1e-9);
  EXPECT_LT(relative_energy, 1e-6);
  // The linkage really moved: the crank went round at least once.
  EXPECT_GT(crank_turned, 2 * std::numbers::pi);
  const runtime::ConstraintWorkspace& w = *data.constraints;
  EXPECT_EQ(w.analyses, 1);
  ::testing::Test::RecordProperty("loop_error", std::to_string(worst_loop));
  std::printf(
      "  %s/%s: loop %.2e m, energy %.2e relative, %ld steps, %ld evaluations, "
      "factorizations %ld fresh / %ld refactor\n",
      GetParam().name, GetParam().method.c_str(), worst_loop, relative_energy, stats.steps,
      stats.evaluations, static_cast<long>(w.factorizations),
      static_cast<long>(w.refactorizations));
}

std::vector<Case> AllCases() {
  std::vector<Case> cases;
  for (const std::string& method : AllIntegrators()) {
    cases.push_back({"FixedPoint", Closure::kFixedPoint, method});
    cases.push_back({"FixedDistance", Closure::kFixedDistance, method});
    cases.push_back({"SliderCrank", Closure::kSliding, method});
  }
  return cases;
}

INSTANTIATE_TEST_SUITE_P(EveryIntegrator, FourBar, ::testing::ValuesIn(AllCases()),
                         [](const ::testing::TestParamInfo<Case>& test) {
                           return std::string(test.param.name) + "_" + test.param.method;
                         });

// examples/four_bar.sled as `sled run` runs it: the loop stays closed at every output row.
TEST(FourBarExample, LoopStaysClosed) {
  const std::filesystem::path root = SLED_SOURCE_ROOT;
  const Compiled compiled = CompileFile(root / "examples" / "four_bar.sled");
  ASSERT_EQ(compiled.errors, "");
  const Model& model = compiled.model();
  ASSERT_EQ(model.nconstraint(), 1u);  // pivot A became the crank's joint to the ground
  runtime::Data data = runtime::MakeData(model);
  struct Watch {
    const Model* model;
    const runtime::Data* data;
    double worst = 0.0;
    long rows = 0;
  } watch{&model, &data};
  runtime::RunOptions options;
  options.progress_context = &watch;
  options.progress = [](double, void* context) {
    auto& w = *static_cast<Watch*>(context);
    w.worst = std::max(w.worst, LoopError(*w.model, *w.data));
    ++w.rows;
  };
  runtime::TimeSeries series;
  const runtime::RunSummary summary = runtime::Run(model, data, series, options);
  ASSERT_FALSE(summary.failed) << summary.failure.where << ": " << summary.failure.cause;
  EXPECT_EQ(watch.rows, 3000);
  for (double value : series.values) ASSERT_TRUE(std::isfinite(value));
  std::printf(
      "  example: loop %.2e m over %ld rows (%s, tolerance %g), %ld steps; the set-up "
      "corrected the initial state by %.1e m and %.2f m/s\n",
      watch.worst, watch.rows, model.integrator.c_str(), model.relative_tolerance,
      summary.stats.steps, data.constraints->initial_position_correction,
      data.constraints->initial_velocity_correction);
  EXPECT_LT(watch.worst, 1e-6);
}

}  // namespace
}  // namespace sled::verification
