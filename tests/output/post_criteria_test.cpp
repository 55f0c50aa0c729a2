// Injury criteria against the reference numbers of crash-conventions.md §2.2 (half-sine HIC
// values, the 3 ms clip) and closed forms: HIC and the severity index of rectangles and
// half-sines, the cumulative and continuous exceedance levels, Nij's quadrants and intercepts,
// the viscous criterion of a sinusoidal deflection.
#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "output/post/exceedance.h"
#include "output/post/head_injury_criterion.h"
#include "output/post/neck_injury_criterion.h"
#include "output/post/peak_load.h"
#include "output/post/severity_index.h"
#include "output/post/viscous_criterion.h"

namespace sled::runtime::post {
namespace {

constexpr double kDt = 1e-4;  // 0.1 ms, the reference's resolution

// A half-sine of `peak` g lasting `duration`, starting at sample `lead`, in a record of `total`
// seconds sampled every 0.1 ms.
std::vector<double> HalfSine(double peak, double duration, std::size_t lead = 0,
                             double total = 0.06) {
  std::vector<double> a(static_cast<std::size_t>(std::lround(total / kDt)) + 1, 0.0);
  for (std::size_t k = 0; k < a.size(); ++k) {
    const double t = (static_cast<double>(k) - static_cast<double>(lead)) * kDt;
    if (t >= 0 && t <= duration) a[k] = peak * std::sin(std::numbers::pi * t / duration);
  }
  return a;
}

std::vector<double> Rectangle(double level, double duration, std::size_t lead, double total) {
  std::vector<double> a(static_cast<std::size_t>(std::lround(total / kDt)) + 1, 0.0);
  const auto last = lead + static_cast<std::size_t>(std::lround(duration / kDt));
  for (std::size_t k = lead; k <= last && k < a.size(); ++k) a[k] = level;
  return a;
}

// The continuous HIC of a half-sine A sin(pi t / T): the best window is symmetric, [x, T - x] in
// units of T / pi, so HIC = T A^2.5 max_x (2 cos x / pi)^2.5 / (1 - 2x / pi)^1.5 (golden
// section on x).
double HalfSineHicClosedForm(double peak, double duration) {
  auto f = [&](double x) {
    return duration * std::pow(peak, 2.5) * std::pow(2 * std::cos(x) / std::numbers::pi, 2.5) /
           std::pow(1 - 2 * x / std::numbers::pi, 1.5);
  };
  double low = 0, high = std::numbers::pi / 2 - 1e-9;
  const double golden = (std::sqrt(5.0) - 1) / 2;
  for (int i = 0; i < 200; ++i) {
    const double a = high - golden * (high - low), b = low + golden * (high - low);
    (f(a) > f(b) ? high : low) = f(a) > f(b) ? b : a;
  }
  return f(0.5 * (low + high));
}

TEST(HeadInjuryCriterion, HalfSinesMatchTheReferenceTable) {
  struct Case {
    double peak, duration, hic;
  };
  for (const Case& c : {Case{60, 0.015, 173.4}, Case{80, 0.010, 237.3}, Case{100, 0.006, 248.6}}) {
    const std::vector<double> a = HalfSine(c.peak, c.duration);
    const HicResult hic15 = HeadInjuryCriterion(a, kDt, 0.0, 0.015);
    const HicResult hic36 = HeadInjuryCriterion(a, kDt, 0.0, 0.036);
    EXPECT_NEAR(hic15.value, c.hic, 0.05) << c.peak << " g";
    EXPECT_NEAR(hic36.value, c.hic, 0.05) << c.peak << " g";
    // The sampled search converges on the continuous optimum.
    EXPECT_NEAR(hic15.value / HalfSineHicClosedForm(c.peak, c.duration), 1.0, 2e-3) << c.peak;
  }
}

TEST(HeadInjuryCriterion, FindsTheInnerWindowNotTheLargestOne) {
  // 60 g over 15 ms: the best window is 2.5 to 12.5 ms. The "largest window" shortcut (the
  // whole 36 ms from the pulse start) gives 36.4, far below.
  const std::vector<double> a = HalfSine(60, 0.015, 50);
  const HicResult hic = HeadInjuryCriterion(a, kDt, 0.0, 0.036);
  EXPECT_NEAR(hic.t1, 0.005 + 0.0025, 1.5e-4);
  EXPECT_NEAR(hic.t2, 0.005 + 0.0125, 1.5e-4);
  double integral = 0;
  for (std::size_t k = 50; k < 50 + 360; ++k) integral += 0.5 * kDt * (a[k] + a[k + 1]);
  const double shortcut = 0.036 * std::pow(integral / 0.036, 2.5);
  EXPECT_NEAR(shortcut, 36.4, 0.05);
  EXPECT_GT(hic.value, 4 * shortcut);
}

TEST(HeadInjuryCriterion, ConstantAccelerationGivesItsPowerTimesTheWindow) {
  // a constant over T: any window inside gives dt * a^2.5, so HIC = a^2.5 min(T, W).
  const double a = 60;
  const std::vector<double> short_pulse = Rectangle(a, 0.015, 100, 0.08);
  EXPECT_NEAR(HeadInjuryCriterion(short_pulse, kDt, 0, 0.015).value, 0.015 * std::pow(a, 2.5),
              1e-9 * std::pow(a, 2.5));
  EXPECT_NEAR(HeadInjuryCriterion(short_pulse, kDt, 0, 0.036).value, 418.3, 0.05);
  const std::vector<double> long_pulse = Rectangle(a, 0.050, 100, 0.08);
  const HicResult hic15 = HeadInjuryCriterion(long_pulse, kDt, 0, 0.015);
  const HicResult hic36 = HeadInjuryCriterion(long_pulse, kDt, 0, 0.036);
  EXPECT_NEAR(hic15.value, 0.015 * std::pow(a, 2.5), 1e-9 * std::pow(a, 2.5));
  EXPECT_NEAR(hic36.value, 0.036 * std::pow(a, 2.5), 1e-9 * std::pow(a, 2.5));
  EXPECT_NEAR(hic36.t2 - hic36.t1, 0.036, 1e-12);
}

TEST(HeadInjuryCriterion, ReportsWindowsInRunTime) {
  const std::vector<double> a = HalfSine(60, 0.015);
  const HicResult hic = HeadInjuryCriterion(a, kDt, 0.25, 0.015);
  EXPECT_NEAR(hic.t1, 0.25 + 0.0025, 1.5e-4);
  EXPECT_NEAR(HeadInjuryCriterion(std::vector<double>(50, 0.0), kDt, 0, 0.015).value, 0.0, 0);
  EXPECT_EQ(HeadInjuryCriterion(std::vector<double>{}, kDt, 0, 0.015).value, 0.0);
}

TEST(Exceedance, ThreeMillisecondClipOfTheHalfSine) {
  // 60 g over 15 ms: the level held for 3 ms is 60 sin(pi (T - 3 ms) / (2T)) = 57.06 g, from 6
  // to 9 ms; with a single peak the cumulative and continuous levels agree.
  const std::vector<double> a = HalfSine(60, 0.015);
  const double expected = 60 * std::sin(std::numbers::pi * (0.015 - 0.003) / (2 * 0.015));
  EXPECT_NEAR(expected, 57.06, 0.005);
  for (const ExceedanceKind kind : {ExceedanceKind::kContinuous, ExceedanceKind::kCumulative}) {
    const ExceedanceResult clip = LevelExceededFor(a, kDt, 0.0, 0.003, kind);
    ASSERT_TRUE(clip.defined);
    EXPECT_NEAR(clip.level, expected, 1e-9);  // the window's ends fall on samples
    EXPECT_NEAR(clip.t_start, 0.006, 1e-9);
    EXPECT_NEAR(clip.t_end, 0.009, 1e-9);
  }
}

TEST(Exceedance, CumulativeAndContinuousDifferForTwoPeaks) {
  // Two 2 ms plateaus of 50 g on a 10 g floor: together they hold 50 g for 4 ms (cumulative),
  // but no single interval above 10 g lasts 3 ms except the floor's.
  std::vector<double> a(401, 10.0);
  for (std::size_t k = 50; k <= 70; ++k) a[k] = 50;
  for (std::size_t k = 200; k <= 220; ++k) a[k] = 50;
  const ExceedanceResult cumulative =
      LevelExceededFor(a, kDt, 0.0, 0.003, ExceedanceKind::kCumulative);
  const ExceedanceResult continuous =
      LevelExceededFor(a, kDt, 0.0, 0.003, ExceedanceKind::kContinuous);
  EXPECT_NEAR(cumulative.level, 50.0, 1e-9);
  EXPECT_NEAR(cumulative.t_start, 0.005, 1e-12);
  EXPECT_NEAR(cumulative.t_end, 0.022, 1e-12);
  EXPECT_NEAR(continuous.level, 10.0, 1e-9);
}

TEST(Exceedance, LinearRampsBetweenSamples) {
  // A triangle from 0 to 100 g and back over 10 ms: the time above L is 10 ms (1 - L/100), so
  // 3 ms holds L = 70 g.
  std::vector<double> a(101);
  for (std::size_t k = 0; k <= 100; ++k) a[k] = 100 - std::abs(static_cast<double>(k) - 50) * 2;
  const ExceedanceResult clip = LevelExceededFor(a, kDt, 0.0, 0.003, ExceedanceKind::kCumulative);
  EXPECT_NEAR(clip.level, 70.0, 1e-9);
  EXPECT_NEAR(clip.t_start, 0.0035, 1e-9);
  EXPECT_NEAR(clip.t_end, 0.0065, 1e-9);
  EXPECT_FALSE(LevelExceededFor(std::vector<double>(20, 1.0), kDt, 0, 0.003,
                                ExceedanceKind::kContinuous)
                   .defined);  // 1.9 ms of record
}

TEST(GaddSeverityIndex, RectangleAndHalfSineInClosedForm) {
  // a^2.5 T for a constant; for A sin(pi t/T): A^2.5 (T/pi) sqrt(pi) G(1.75) / G(2.25).
  const std::vector<double> rectangle = Rectangle(40, 0.02, 10, 0.05);
  EXPECT_NEAR(GaddSeverityIndex(rectangle, kDt),
              0.02 * std::pow(40.0, 2.5) + kDt * std::pow(40.0, 2.5),  // the two edges
              1e-9);
  const std::vector<double> half_sine = HalfSine(80, 0.01);
  const double closed = std::pow(80.0, 2.5) * 0.01 / std::numbers::pi *
                        std::sqrt(std::numbers::pi) * std::tgamma(1.75) / std::tgamma(2.25);
  EXPECT_NEAR(GaddSeverityIndex(half_sine, kDt) / closed, 1.0, 1e-4);
}

TEST(NeckInjuryCriterion, EachQuadrantUsesItsOwnIntercepts) {
  // One sample in each quadrant, at 0, 1, 2, 3 ms: tension-flexion, tension-extension,
  // compression-flexion, compression-extension.
  const std::vector<double> fz = {3403, 1361.2, -3080, -616};
  const std::vector<double> my = {62, -67.5, 155, -108};
  const std::vector<double> fx(4, 0.0);
  const NijResult nij = NeckInjuryCriterion(fz, fx, my, 0.0, kHybridIII50thMale, 1e-3, 0.0);
  auto at = [&](NeckQuadrant q) { return nij.quadrants[static_cast<std::size_t>(q)]; };
  EXPECT_NEAR(at(NeckQuadrant::kTensionFlexion).value, 3403 / 6806.0 + 62 / 310.0, 1e-12);
  EXPECT_NEAR(at(NeckQuadrant::kTensionExtension).value, 1361.2 / 6806.0 + 67.5 / 135.0, 1e-12);
  EXPECT_NEAR(at(NeckQuadrant::kCompressionFlexion).value, 3080 / 6160.0 + 155 / 310.0, 1e-12);
  EXPECT_NEAR(at(NeckQuadrant::kCompressionExtension).value, 616 / 6160.0 + 108 / 135.0, 1e-12);
  EXPECT_NEAR(at(NeckQuadrant::kCompressionFlexion).time, 0.002, 1e-15);
  // The largest is NCF = 0.5 + 0.5; the others are 0.7, 0.7 and 0.9.
  EXPECT_NEAR(nij.value, 1.0, 1e-12);
  EXPECT_EQ(QuadrantName(nij.quadrant), std::string("NCF"));
}

TEST(NeckInjuryCriterion, TensionFlexionIsNotDroppedAndNoTermCountsTwice) {
  // A pure tension-flexion history: NTF carries the value, the other three never occur (a known
  // bug summed NTE twice and left NTF out).
  const std::vector<double> fz = {0, 2000, 4000, 2000, 0};
  const std::vector<double> my = {0, 50, 100, 50, 0};
  const std::vector<double> fx(5, 0.0);
  const NijResult nij = NeckInjuryCriterion(fz, fx, my, 0.0, kHybridIII50thMale, 1e-3, 0.0);
  EXPECT_NEAR(nij.value, 4000 / 6806.0 + 100 / 310.0, 1e-12);
  EXPECT_EQ(QuadrantName(nij.quadrant), std::string("NTF"));
  EXPECT_TRUE(nij.quadrants[static_cast<std::size_t>(NeckQuadrant::kTensionFlexion)].reached);
  EXPECT_FALSE(nij.quadrants[static_cast<std::size_t>(NeckQuadrant::kTensionExtension)].reached);
  EXPECT_FALSE(nij.quadrants[static_cast<std::size_t>(NeckQuadrant::kCompressionFlexion)].reached);
}

TEST(NeckInjuryCriterion, TheCondyleMomentSubtractsTheShearLever) {
  // MOCy = My - D Fx: 10 N*m of flexion with 1000 N of shear and D = 17.78 mm leaves -7.78 N*m,
  // extension.
  const std::vector<double> fz = {1000}, fx = {1000}, my = {10};
  const NijResult nij =
      NeckInjuryCriterion(fz, fx, my, kHybridIIICondyleOffset, kHybridIII50thMale, 1e-3, 0.0);
  EXPECT_EQ(QuadrantName(nij.quadrant), std::string("NTE"));
  EXPECT_NEAR(nij.value, 1000 / 6806.0 + 7.78 / 135.0, 1e-12);
}

TEST(ViscousCriterion, SinusoidalDeflectionInClosedForm) {
  // D = D0 sin(w t): VC = SF D0^2 w sin(2 w t) / (2 Dc), largest at w t = pi/4.
  const double d0 = 0.04, w = 2 * std::numbers::pi * 10, dt = 1e-5;
  std::vector<double> d(5001);
  for (std::size_t k = 0; k < d.size(); ++k) d[k] = d0 * std::sin(w * static_cast<double>(k) * dt);
  const ViscousResult vc = ViscousCriterion(d, dt, 0.0, kHybridIII50thMaleVc);
  EXPECT_NEAR(vc.value, 1.3 * d0 * d0 * w / (2 * 0.229), 1e-7);
  EXPECT_NEAR(vc.time, std::numbers::pi / 4 / w, dt);
}

TEST(PeakLoad, LargestPositiveSampleAndItsTime) {
  const std::vector<double> load = {-50, 20, 900, 300, -4000};
  const PeakResult peak = PositivePeak(load, 1e-3, 0.1);
  EXPECT_EQ(peak.value, 900);
  EXPECT_NEAR(peak.time, 0.102, 1e-15);
  EXPECT_EQ(PositivePeak(std::vector<double>{-1, -2}, 1e-3, 0).value, 0);
}

}  // namespace
}  // namespace sled::runtime::post
