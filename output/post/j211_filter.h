// The SAE J211-1 (Appendix C) channel filter: a two-pole Butterworth low-pass run forward and
// then backward over the record, which makes a four-pole filter without phase shift. The class
// (CFC 60, 180, 600, 1000) sets the corner; ISO 6487 computes the coefficients with a slightly
// different factor. Filtering comes before resultants and injury criteria (J211).
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace sled::runtime::post {

enum class FilterStandard : std::uint8_t { kSaeJ211, kIso6487 };

// Y[t] = a0 X[t] + a1 X[t-1] + a2 X[t-2] + b1 Y[t-1] + b2 Y[t-2]
struct FilterCoefficients {
  double a0 = 0, a1 = 0, a2 = 0, b1 = 0, b2 = 0;
};

// The coefficients of one pass for channel frequency class `cfc` [Hz] at `sample_period` [s].
FilterCoefficients CfcCoefficients(double cfc, double sample_period, FilterStandard standard);

// Empty when `sample_period` samples at least ten times the class (J211's rule for the
// digital filter); otherwise why not, in words a caller can show.
std::string CheckSampleRate(double cfc, double sample_period);

// Points added by reflection at each end before filtering: at least 100 and at least one period
// of the class frequency, so the start-up transient dies out before the record begins.
std::size_t PaddingLength(double cfc, double sample_period);

// `signal` filtered at class `cfc`, forward and backward, into `out` (resized to the signal's
// length). Each end is extended by point reflection about its end sample (2 x0 - x_i), and each
// pass starts from the mean of its first ten samples. False with `error` set when the class is
// not positive or the sample rate is below ten times the class.
bool FilterCfc(std::span<const double> signal, double sample_period, double cfc,
               FilterStandard standard, std::vector<double>& out, std::string* error);

}  // namespace sled::runtime::post
