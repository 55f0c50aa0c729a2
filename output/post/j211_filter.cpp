#include "output/post/j211_filter.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

namespace sled::runtime::post {
namespace {

// The design frequency of one pass as a multiple of the class: J211 Appendix C uses 2.0775,
// ISO 6487 1.25 * 5/3; both put the cascade's -3 dB point near 5/3 of the class.
double DesignFactor(FilterStandard standard) {
  return standard == FilterStandard::kSaeJ211 ? 2.0775 : 1.25 * 5.0 / 3.0;
}

// One pass of the two-pole section over `x` in place, started as if the signal had stood at
// the mean of its first ten samples forever (then a constant passes through unchanged).
void FilterPass(const FilterCoefficients& c, std::vector<double>& x) {
  const std::size_t head = std::min<std::size_t>(10, x.size());
  double start = 0.0;
  for (std::size_t i = 0; i < head; ++i) start += x[i];
  start /= static_cast<double>(head);
  double x1 = start, x2 = start, y1 = start, y2 = start;
  for (double& value : x) {
    const double y = c.a0 * value + c.a1 * x1 + c.a2 * x2 + c.b1 * y1 + c.b2 * y2;
    x2 = x1;
    x1 = value;
    y2 = y1;
    y1 = y;
    value = y;
  }
}

}  // namespace

FilterCoefficients CfcCoefficients(double cfc, double sample_period, FilterStandard standard) {
  const double wd = 2.0 * std::numbers::pi * cfc * DesignFactor(standard);
  const double wa = std::sin(wd * sample_period / 2.0) / std::cos(wd * sample_period / 2.0);
  const double norm = 1.0 + std::numbers::sqrt2 * wa + wa * wa;
  FilterCoefficients c;
  c.a0 = wa * wa / norm;
  c.a1 = 2.0 * c.a0;
  c.a2 = c.a0;
  c.b1 = -2.0 * (wa * wa - 1.0) / norm;
  c.b2 = (-1.0 + std::numbers::sqrt2 * wa - wa * wa) / norm;
  return c;
}

std::string CheckSampleRate(double cfc, double sample_period) {
  if (!(cfc > 0.0) || !std::isfinite(cfc)) {
    return fmt::format("the filter class must be a positive frequency, not {}", cfc);
  }
  if (!(sample_period > 0.0) || !std::isfinite(sample_period)) {
    return fmt::format("the sample period must be positive, not {} s", sample_period);
  }
  const double rate = 1.0 / sample_period;
  // A relative slack of 1e-9 lets 0.1 ms pass for CFC 1000 despite rounding.
  if (rate < 10.0 * cfc * (1.0 - 1e-9)) {
    return fmt::format(
        "CFC {:g} needs a sample rate of at least {:g} Hz (ten times the class), but the "
        "outputs come every {:g} ms ({:g} Hz); set output_every to at most {:g} ms",
        cfc, 10.0 * cfc, sample_period * 1e3, rate, 1e3 / (10.0 * cfc));
  }
  return {};
}

std::size_t PaddingLength(double cfc, double sample_period) {
  const double period_samples = std::ceil(1.0 / (cfc * sample_period));
  return std::max<std::size_t>(100, static_cast<std::size_t>(period_samples));
}

bool FilterCfc(std::span<const double> signal, double sample_period, double cfc,
               FilterStandard standard, std::vector<double>& out, std::string* error) {
  if (std::string reason = CheckSampleRate(cfc, sample_period); !reason.empty()) {
    if (error) *error = std::move(reason);
    return false;
  }
  const std::size_t n = signal.size();
  out.assign(signal.begin(), signal.end());
  if (n < 2) return true;  // nothing to smooth
  // Point reflection about each end sample keeps the value and the slope continuous there;
  // beyond the record's length the reflection holds its last value.
  const std::size_t pad = PaddingLength(cfc, sample_period);
  std::vector<double> padded(n + 2 * pad);
  for (std::size_t i = 1; i <= pad; ++i) {
    padded[pad - i] = 2.0 * signal[0] - signal[std::min(i, n - 1)];
    padded[pad + n - 1 + i] = 2.0 * signal[n - 1] - signal[n - 1 - std::min(i, n - 1)];
  }
  std::copy(signal.begin(), signal.end(), padded.begin() + static_cast<std::ptrdiff_t>(pad));
  const FilterCoefficients c = CfcCoefficients(cfc, sample_period, standard);
  FilterPass(c, padded);
  std::reverse(padded.begin(), padded.end());
  FilterPass(c, padded);
  std::reverse(padded.begin(), padded.end());
  std::copy_n(padded.begin() + static_cast<std::ptrdiff_t>(pad), n, out.begin());
  return true;
}

}  // namespace sled::runtime::post
