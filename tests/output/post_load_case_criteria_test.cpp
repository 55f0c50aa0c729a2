// The criteria of rear, side and lower-leg load cases against closed forms on synthetic signals:
// NIC of a constant and of a sinusoidal relative acceleration, the Tibia Index of a turning
// moment and a ramp force, TTI of two signed pulses.
#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "output/post/thoracic_trauma_index.h"
#include "output/post/tibia_index.h"
#include "output/post/whiplash_criterion.h"

namespace sled::runtime::post {
namespace {

constexpr double kDt = 1e-4;

// A constant relative acceleration A for T: v_rel = A t, so NIC(t) = 0.2 A + A^2 t^2, largest at
// T. The head's acceleration is subtracted from T1's.
TEST(NeckInjuryCriterionOfRearImpact, ConstantRelativeAccelerationInClosedForm) {
  const double a = 40.0;  // m/s^2
  const double duration = 0.05;
  const auto n = static_cast<std::size_t>(std::lround(duration / kDt)) + 1;
  std::vector<double> t1(n, a + 3.0), head(n, 3.0);
  const NicResult nic = NeckInjuryCriterionOfRearImpact(t1, head, kDt, 0.01);
  EXPECT_NEAR(nic.value, 0.2 * a + a * a * duration * duration, 1e-9);
  EXPECT_NEAR(nic.time, 0.01 + duration, 1e-12);
}

// a_rel = A sin(w t): v_rel = (A / w)(1 - cos w t) and NIC(t) = 0.2 A sin w t + v_rel^2. The
// trapezoid rule's error at 0.1 ms is far below the tolerance.
TEST(NeckInjuryCriterionOfRearImpact, SinusoidalRelativeAccelerationInClosedForm) {
  const double a = 60.0, w = 2 * std::numbers::pi / 0.1;
  const auto n = static_cast<std::size_t>(std::lround(0.04 / kDt)) + 1;
  std::vector<double> t1(n), head(n, 0.0);
  double expected = -1e300;
  for (std::size_t k = 0; k < n; ++k) {
    const double t = static_cast<double>(k) * kDt;
    t1[k] = a * std::sin(w * t);
    const double v = a / w * (1 - std::cos(w * t));
    expected = std::max(expected, 0.2 * a * std::sin(w * t) + v * v);
  }
  EXPECT_NEAR(NeckInjuryCriterionOfRearImpact(t1, head, kDt, 0.0).value, expected, 1e-6 * expected);
}

// |M_R| = m constant while F_z ramps to F: TI = m / M_c + F / F_c at the end; the sign of the
// axial force does not matter.
TEST(TibiaIndex, TurningMomentAndRampForceInClosedForm) {
  const double m = 90.0, f = -6000.0;
  const std::size_t n = 201;
  std::vector<double> mx(n), my(n), fz(n);
  for (std::size_t k = 0; k < n; ++k) {
    const double phase = static_cast<double>(k) / 50.0;
    mx[k] = m * std::cos(phase);
    my[k] = m * std::sin(phase);
    fz[k] = f * static_cast<double>(k) / static_cast<double>(n - 1);
  }
  const TibiaResult ti = TibiaIndex(mx, my, fz, kDt, 0.0, kHybridIII50thMaleTibia);
  EXPECT_NEAR(ti.value, m / 225.0 + 6000.0 / 35900.0, 1e-12);
  EXPECT_NEAR(ti.time, 200 * kDt, 1e-12);
}

// TTI = (G_R + G_LS) / 2 of the peak magnitudes, whatever their signs (the struck side's lateral
// axis points either way).
TEST(ThoracicTraumaIndex, MeanOfThePeakMagnitudes) {
  std::vector<double> rib(300, 0.0), spine(300, 0.0);
  for (std::size_t k = 0; k < 100; ++k) {
    rib[50 + k] = -70.0 * std::sin(std::numbers::pi * static_cast<double>(k) / 100.0);
    spine[80 + k] = 40.0 * std::sin(std::numbers::pi * static_cast<double>(k) / 100.0);
  }
  const TtiResult tti = ThoracicTraumaIndex(rib, spine, kDt, 0.0);
  EXPECT_NEAR(tti.rib_peak, 70.0, 1e-9);
  EXPECT_NEAR(tti.spine_peak, 40.0, 1e-9);
  EXPECT_NEAR(tti.value, 55.0, 1e-9);
  EXPECT_NEAR(tti.rib_time, 100 * kDt, 1e-12);
}

}  // namespace
}  // namespace sled::runtime::post
