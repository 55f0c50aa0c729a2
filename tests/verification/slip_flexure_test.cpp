// A slip joint's own `flexure` is a force against its displacement (docs/language.md §8), its
// `viscous` a force per speed: two floating segments on a slip joint with a linear flexure k and a
// constant force F across the joint from rest oscillate as x(t) = (F / k)(1 - cos w t) with
// w = sqrt(k / mu), mu the reduced mass; with the damping ratio zeta they come to rest at the
// static deflection F / k and ring as the damped closed form. The same spring written as a table of
// deflection -> force gives the same motion. A torque law, a rotational damping or a torque of
// friction on a slip joint is refused (E0302), since the runtime would read its numbers as forces.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "tests/verification/compile.h"

namespace sled::verification {
namespace {

constexpr double kMassA = 3.0;  // [kg]
constexpr double kMassB = 1.0;
constexpr double kReducedMass = kMassA * kMassB / (kMassA + kMassB);
constexpr double kStiffness = 400.0;  // [N/m]
constexpr double kForce = 6.0;        // [N]

// The joint's displacement at `row`.
double Displacement(const runtime::TimeSeries& series, std::size_t row) {
  return ChannelAt(series, "pair.j.joint_displacement.axis [m]", row);
}

// The two segments on a slip joint along x, floating without gravity, pushed apart by kForce.
std::string Slide(const std::string& joint_lines, const std::string& end = "1 s") {
  return R"(scenario "slide" {
  gravity = (0, 0, 0) m/s^2
  time { end = )" +
         end + R"(  output_every = 2 ms }
  integrator dopri5 { tolerance = 1e-10 }
  body pair {
    reference = a
    segment a { mass = 3 kg  inertia = (0.15, 0.2, 0.15) kg*m^2 }
    segment b { mass = 1 kg  inertia = (0.03, 0.05, 0.03) kg*m^2 }
    joint j : slip(a -> b) {
      at a = (0, 0, 0) mm
      at b = (0, 0, 0) mm
      axis = x
      )" +
         joint_lines +
         R"(
    }
  }
  load push on pair.j { force = 6 N }
  output { joint_angle pair.j }
}
)";
}

void ExpectUndampedClosedForm(const SceneRun& run) {
  ASSERT_EQ(run.errors, "");
  ASSERT_FALSE(run.summary.failed);
  const double w = std::sqrt(kStiffness / kReducedMass);
  const double period = 2 * std::acos(-1.0) / w;
  double largest = 0;
  double at_largest = 0;
  for (std::size_t row = 0; row < run.series.rows(); ++row) {
    const double t = TimeAt(run.series, row);
    const double expected = kForce / kStiffness * (1 - std::cos(w * t));
    EXPECT_NEAR(Displacement(run.series, row), expected, 1e-8) << t;
    if (t < period && Displacement(run.series, row) > largest) {
      largest = Displacement(run.series, row);
      at_largest = t;
    }
  }
  // The first swing reaches twice the static deflection (30 mm) half a period in (136 ms), to
  // the output step of 2 ms.
  EXPECT_NEAR(largest, 2 * kForce / kStiffness, 1e-5);
  EXPECT_NEAR(at_largest, period / 2, 1e-3);
  EXPECT_LT(run.summary.energy.relative(), 1e-8);
}

TEST(SlipFlexure, ALinearFlexureIsASpringOfThePeriodOfTheReducedMass) {
  ExpectUndampedClosedForm(RunText(Slide("flexure = 400 N/m")));
}

TEST(SlipFlexure, ATableOfForceAgainstDeflectionIsTheSameSpring) {
  // Given for positive deflections only: read against the displacement's size, restoring.
  ExpectUndampedClosedForm(
      RunText(Slide("flexure = table(deflection -> force) { 0 mm -> 0 N  100 mm -> 40 N }")));
}

TEST(SlipFlexure, ADampedFlexureComesToRestAtTheStaticDeflection) {
  const double zeta = 0.2;
  const double c = 2 * zeta * std::sqrt(kStiffness * kReducedMass);  // 6.928 N*s/m
  const SceneRun run =
      RunText(Slide("flexure = 400 N/m\n      viscous = " + std::to_string(c) + " N*s/m", "3 s"));
  ASSERT_EQ(run.errors, "");
  const double wn = std::sqrt(kStiffness / kReducedMass);
  const double wd = wn * std::sqrt(1 - zeta * zeta);
  const double static_deflection = kForce / kStiffness;
  for (std::size_t row = 0; row < run.series.rows(); ++row) {
    const double t = TimeAt(run.series, row);
    const double expected =
        static_deflection *
        (1 - std::exp(-zeta * wn * t) *
                 (std::cos(wd * t) + zeta / std::sqrt(1 - zeta * zeta) * std::sin(wd * t)));
    EXPECT_NEAR(Displacement(run.series, row), expected, 1e-7) << t;
  }
  const std::size_t last = run.series.rows() - 1;
  // Three seconds are 14 time constants 1 / (zeta wn): at rest at F / k = 15 mm.
  EXPECT_NEAR(Displacement(run.series, last), static_deflection, 1e-6);
}

TEST(SlipFlexure, RotationalLawsOnASlipJointAreRefused) {
  for (const std::string& line :
       {std::string("flexure = 2 N*m/deg"), std::string("viscous = 1 N*m*s/rad"),
        std::string("coulomb = 2 N*m"), std::string("stop = 10 deg"),
        std::string("flexure = table(angle -> torque) { 0 deg -> 0 N*m  10 deg -> 5 N*m }")}) {
    SCOPED_TRACE(line);
    const SceneRun run = RunText(Slide(line));
    EXPECT_NE(run.errors.find("E0302"), std::string::npos) << run.errors;
  }
}

}  // namespace
}  // namespace sled::verification
