// The SAE J211-1 Appendix C filter against the reference coefficients of
// crash-conventions.md §2.5, its frequency response against J211's corridor and the closed form
// of a two-pass bilinear Butterworth, zero phase, the start-up rule and the sample-rate check.
#include <cmath>
#include <numbers>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "output/post/j211_filter.h"

namespace sled::runtime::post {
namespace {

using ::testing::HasSubstr;

struct ReferenceRow {
  double cfc, rate, a0, a1, a2, b1, b2;
};

TEST(J211Filter, CoefficientsMatchTheReferenceTable) {
  const ReferenceRow rows[] = {
      {1000, 10000, 0.21923142, 0.43846283, 0.21923142, 0.31189654, -0.18882221},
      {1000, 20000, 0.07189310, 0.14378619, 0.07189310, 1.11158618, -0.39915856},
      {600, 10000, 0.09718463, 0.19436925, 0.09718463, 0.94557401, -0.33431251},
      {180, 10000, 0.01179627, 0.02359254, 0.01179627, 1.67011746, -0.71730255},
      {60, 10000, 0.00145237, 0.00290473, 0.00145237, 1.88934322, -0.89515269},
  };
  for (const ReferenceRow& row : rows) {
    const FilterCoefficients c = CfcCoefficients(row.cfc, 1.0 / row.rate, FilterStandard::kSaeJ211);
    // The table has eight decimals.
    EXPECT_NEAR(c.a0, row.a0, 6e-9) << row.cfc << " at " << row.rate;
    EXPECT_NEAR(c.a1, row.a1, 6e-9) << row.cfc << " at " << row.rate;
    EXPECT_NEAR(c.a2, row.a2, 6e-9) << row.cfc << " at " << row.rate;
    EXPECT_NEAR(c.b1, row.b1, 6e-9) << row.cfc << " at " << row.rate;
    EXPECT_NEAR(c.b2, row.b2, 6e-9) << row.cfc << " at " << row.rate;
    // Unit gain at zero frequency.
    EXPECT_NEAR((c.a0 + c.a1 + c.a2) / (1 - c.b1 - c.b2), 1.0, 1e-12);
  }
}

// Amplitude and phase of `y` at frequency f over its middle half (least squares on sin, cos).
struct Tone {
  double amplitude, phase;
};
Tone FitTone(const std::vector<double>& y, double f, double dt) {
  double ss = 0, sc = 0, cc = 0, ys = 0, yc = 0;
  for (std::size_t k = y.size() / 4; k < 3 * y.size() / 4; ++k) {
    const double w = 2 * std::numbers::pi * f * static_cast<double>(k) * dt;
    const double s = std::sin(w), c = std::cos(w);
    ss += s * s, sc += s * c, cc += c * c, ys += y[k] * s, yc += y[k] * c;
  }
  const double det = ss * cc - sc * sc;
  const double a = (ys * cc - yc * sc) / det;  // coefficient of sin
  const double b = (yc * ss - ys * sc) / det;  // coefficient of cos
  return {std::hypot(a, b), std::atan2(b, a)};
}

// The gain of the filter at frequency f, measured on a unit sine through FilterCfc.
Tone MeasuredResponse(double cfc, double rate, double f, FilterStandard standard) {
  const double dt = 1.0 / rate;
  std::vector<double> x(static_cast<std::size_t>(0.4 * rate));
  for (std::size_t k = 0; k < x.size(); ++k) {
    x[k] = std::sin(2 * std::numbers::pi * f * static_cast<double>(k) * dt);
  }
  std::vector<double> y;
  std::string error;
  EXPECT_TRUE(FilterCfc(x, dt, cfc, standard, y, &error)) << error;
  return FitTone(y, f, dt);
}

double Decibels(double gain) { return 20 * std::log10(gain); }

TEST(J211Filter, GainFollowsTheTwoPassButterworthClosedForm) {
  // Each pass is a bilinear Butterworth with |H|^2 = 1 / (1 + (tan(pi f T) / wa)^4); forward and
  // backward multiply the magnitudes and cancel the phases.
  const double rate = 10000, cfc = 600;
  const double wa = std::tan(2 * std::numbers::pi * cfc * 2.0775 / rate / 2);
  for (const double f : {50.0, 300.0, 600.0, 1000.0, 1500.0, 2500.0}) {
    const double r = std::tan(std::numbers::pi * f / rate) / wa;
    const Tone tone = MeasuredResponse(cfc, rate, f, FilterStandard::kSaeJ211);
    EXPECT_NEAR(tone.amplitude, 1 / (1 + r * r * r * r), 1e-6) << f << " Hz";
    EXPECT_NEAR(tone.phase, 0.0, 1e-6) << f << " Hz: the forward-backward filter has no phase";
  }
}

TEST(J211Filter, ResponseAtTheClassFrequenciesIsInsideTheJ211Corridor) {
  // J211: flat within +0.5/-1 dB up to the class frequency, and the -3 dB point at 5/3 of the
  // class (F_H: 100, 300, 1000 and 1650 Hz), inside +0.5/-4 dB there.
  for (const double cfc : {60.0, 180.0, 600.0, 1000.0}) {
    const double rate = 10 * cfc * 2;  // twice the minimum rate
    const double at_class =
        Decibels(MeasuredResponse(cfc, rate, cfc, FilterStandard::kSaeJ211).amplitude);
    EXPECT_LE(at_class, 0.5) << "CFC " << cfc;
    EXPECT_GE(at_class, -1.0) << "CFC " << cfc;
    const double at_corner =
        Decibels(MeasuredResponse(cfc, rate, cfc * 5 / 3, FilterStandard::kSaeJ211).amplitude);
    EXPECT_GE(at_corner, -4.0) << "CFC " << cfc;
    const double half_class =
        Decibels(MeasuredResponse(cfc, rate, cfc / 2, FilterStandard::kSaeJ211).amplitude);
    EXPECT_NEAR(half_class, 0.0, 0.5) << "CFC " << cfc;
  }
}

// The frequency where the two-pass gain is 1/sqrt(2), as a multiple of the class, by bisection
// on the measured response.
double MinusThreeDecibelPoint(double cfc, double rate, FilterStandard standard) {
  double low = cfc, high = 3 * cfc;
  for (int i = 0; i < 40; ++i) {
    const double middle = 0.5 * (low + high);
    (MeasuredResponse(cfc, rate, middle, standard).amplitude > 1 / std::numbers::sqrt2 ? low
                                                                                       : high) =
        middle;
  }
  return 0.5 * (low + high) / cfc;
}

TEST(J211Filter, MinusThreeDecibelPointsOfTheTwoStandards) {
  // crash-conventions.md §2.5: 5/3 of the class for J211, 1.6713 for ISO 6487 (at a high rate,
  // where the bilinear warping is negligible).
  EXPECT_NEAR(MinusThreeDecibelPoint(60, 100000, FilterStandard::kSaeJ211), 5.0 / 3.0, 2e-4);
  EXPECT_NEAR(MinusThreeDecibelPoint(60, 100000, FilterStandard::kIso6487), 1.6713, 2e-4);
}

TEST(J211Filter, StartUpLeavesNoTransientAtTheEnds) {
  // A constant offset (1 g) plus a slow ramp: reflection padding and starting each pass from the
  // mean of its first samples pass it unchanged at both ends; a filter started from rest would
  // dip to zero at the start.
  const double dt = 1e-4;
  std::vector<double> x(2000);
  for (std::size_t k = 0; k < x.size(); ++k) x[k] = 9.80665 + 50.0 * static_cast<double>(k) * dt;
  for (const double cfc : {60.0, 180.0, 600.0, 1000.0}) {
    std::vector<double> y;
    ASSERT_TRUE(FilterCfc(x, dt, cfc, FilterStandard::kSaeJ211, y, nullptr));
    ASSERT_EQ(y.size(), x.size());
    double worst = 0;
    for (std::size_t k = 0; k < x.size(); ++k) worst = std::max(worst, std::abs(y[k] - x[k]));
    EXPECT_LT(worst, 1e-4) << "CFC " << cfc;
  }
}

TEST(J211Filter, ASymmetricPulseStaysSymmetricAndInPlace) {
  // Zero phase: a Gaussian pulse keeps its peak on the same sample and its symmetry.
  const double dt = 1e-4;
  std::vector<double> x(1001);
  for (std::size_t k = 0; k < x.size(); ++k) {
    const double t = (static_cast<double>(k) - 500) * dt;
    x[k] = std::exp(-t * t / (2 * 0.002 * 0.002));
  }
  std::vector<double> y;
  ASSERT_TRUE(FilterCfc(x, dt, 180, FilterStandard::kSaeJ211, y, nullptr));
  EXPECT_EQ(std::max_element(y.begin(), y.end()) - y.begin(), 500);
  for (std::size_t k = 0; k < 500; ++k) EXPECT_NEAR(y[500 - k], y[500 + k], 1e-9) << k;
}

TEST(J211Filter, RefusesASampleRateBelowTenTimesTheClass) {
  EXPECT_EQ(CheckSampleRate(1000, 1e-4), "");
  EXPECT_EQ(CheckSampleRate(60, 1.0 / 600), "");
  EXPECT_THAT(CheckSampleRate(1000, 2e-4), HasSubstr("at least 10000 Hz"));
  EXPECT_THAT(CheckSampleRate(180, 1e-3), HasSubstr("at most 0.555556 ms"));
  EXPECT_NE(CheckSampleRate(0, 1e-4), "");
  EXPECT_NE(CheckSampleRate(1000, 0), "");
  std::vector<double> y;
  std::string error;
  const std::vector<double> x(100, 1.0);
  EXPECT_FALSE(FilterCfc(x, 1e-3, 1000, FilterStandard::kSaeJ211, y, &error));
  EXPECT_THAT(error, HasSubstr("CFC 1000"));
}

TEST(J211Filter, ShortRecordsAreHandled) {
  std::vector<double> y;
  for (std::size_t n : {0u, 1u, 2u, 5u, 30u}) {
    const std::vector<double> x(n, 3.5);
    ASSERT_TRUE(FilterCfc(x, 1e-4, 1000, FilterStandard::kSaeJ211, y, nullptr)) << n;
    ASSERT_EQ(y.size(), n);
    for (const double v : y) EXPECT_NEAR(v, 3.5, 1e-12) << n;
  }
}

TEST(J211Filter, PaddingCoversTheClassPeriod) {
  EXPECT_EQ(PaddingLength(1000, 1e-4), 100u);
  EXPECT_EQ(PaddingLength(60, 1e-4), 167u);  // 1/60 s at 10 kHz
}

}  // namespace
}  // namespace sled::runtime::post
