// The tolerances a scene gives (issue 14, item 4): the absolute tolerance follows the relative one
// unless the scene gives it, so tightening `tolerance` tightens the control of states near zero
// too (with a fixed 1e-9 a tolerance below it barely tightened anything); a tolerance no double
// can meet is an error (E0419). Checked on the numerics suite's stiff viscous decay against its
// closed form, and on the Euler joint near gimbal lock against its.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "tests/verification/compile.h"

namespace sled::verification {
namespace {

// examples/numerics/NAME.sled with its integrator line replaced by `integrator`.
std::string SceneWith(const std::string& name, const std::string& integrator) {
  std::ifstream in(std::filesystem::path(SLED_SOURCE_ROOT) / "examples" / "numerics" /
                   (name + ".sled"));
  std::stringstream text;
  text << in.rdbuf();
  std::string scene = text.str();
  const std::string standard = "integrator auto { tolerance = 1e-6 }";
  const auto at = scene.find(standard);
  EXPECT_NE(at, std::string::npos);
  if (at != std::string::npos) scene.replace(at, standard.size(), integrator);
  return scene;
}

std::string StiffDecayWith(const std::string& integrator) {
  return SceneWith("stiff_decay", integrator);
}

TEST(NumericsSuiteTolerance, TheAbsoluteToleranceFollowsTheRelativeOneUnlessGiven) {
  for (const double tolerance : {1e-4, 1e-8, 1e-11}) {
    const Compiled compiled = CompileText(
        StiffDecayWith(fmt::format("integrator dopri5 {{ tolerance = {} }}", tolerance)));
    ASSERT_EQ(compiled.errors, "");
    EXPECT_DOUBLE_EQ(compiled.model().relative_tolerance, tolerance);
    EXPECT_DOUBLE_EQ(compiled.model().absolute_tolerance, 1e-3 * tolerance);
  }
  const Compiled given =
      CompileText(StiffDecayWith("integrator dopri5 { tolerance = 1e-8  abs_tolerance = 1e-6 }"));
  ASSERT_EQ(given.errors, "");
  EXPECT_DOUBLE_EQ(given.model().absolute_tolerance, 1e-6);
}

TEST(NumericsSuiteTolerance, ATolerancePastWhatDoublesCanMeetIsAnError) {
  // 100 times the machine epsilon, 2.2e-14, is the floor.
  for (const char* tolerance : {"1e-15", "1e-18", "2e-14"}) {
    const Compiled compiled = CompileText(
        StiffDecayWith(std::string("integrator dopri5 { tolerance = ") + tolerance + " }"));
    EXPECT_NE(compiled.errors.find("E0419"), std::string::npos) << tolerance;
  }
  EXPECT_EQ(CompileText(StiffDecayWith("integrator dopri5 { tolerance = 3e-14 }")).errors, "");
}

// The largest distance of the point 100 mm along the head's x axis from its circle
// (numerics_suite_cases_test.cpp), over the rows, on gimbal_lock.sled at 0.8 degrees from the lock.
double GimbalError(const std::string& integrator) {
  const Compiled compiled =
      CompileSource(Source::Text(SceneWith("gimbal_lock", integrator), "gimbal.sled"),
                    {{"precession", "89.2 deg"}});
  EXPECT_EQ(compiled.errors, "");
  if (!compiled.errors.empty()) return NAN;
  const RunResult run = sled::Simulate(compiled.model());
  EXPECT_TRUE(run.summary.complete());
  const double p = 89.2 * M_PI / 180, w = 2 * M_PI;
  double worst = 0;
  for (std::size_t row = 0; row < run.series.rows(); ++row) {
    const double t = TimeAt(run.series, row);
    const double dx = ChannelAt(run.series, "rig.head.position.x [m]", row) - 0.1 * std::cos(p);
    const double dy =
        ChannelAt(run.series, "rig.head.position.y [m]", row) - 0.1 * std::sin(p) * std::cos(w * t);
    const double dz =
        ChannelAt(run.series, "rig.head.position.z [m]", row) - 0.1 * std::sin(p) * std::sin(w * t);
    worst = std::max(worst, std::sqrt(dx * dx + dy * dy + dz * dz));
  }
  return worst;
}

TEST(NumericsSuiteTolerance, TighteningTheToleranceTightensTheAnswer) {
  // Three decades of tolerance below the old fixed absolute tolerance of 1e-9: at least two of
  // error.
  const double loose = GimbalError("integrator dopri5 { tolerance = 1e-6 }");
  const double tight = GimbalError("integrator dopri5 { tolerance = 1e-9 }");
  std::printf("  gimbal_0p8, dopri5: error %.2e m at 1e-6, %.2e m at 1e-9\n", loose, tight);
  EXPECT_LT(tight, 0.01 * loose);
}

}  // namespace
}  // namespace sled::verification
