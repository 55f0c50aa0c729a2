#include "runtime/integrate/error_norm.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sled::runtime {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

}  // namespace

double WeightedRmsNorm(std::span<const double> error, std::span<const double> y0,
                       std::span<const double> y1, double relative_tolerance,
                       double absolute_tolerance, LargestComponent* largest,
                       QuadratureWeight quadratures) {
  const std::size_t n = error.size();
  if (n == 0) return 0.0;
  double sum = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double floor = i >= quadratures.scaled_from ? quadratures.scale : 0.0;
    const double weight = absolute_tolerance +
                          relative_tolerance * std::max({std::abs(y0[i]), std::abs(y1[i]), floor});
    // With atol = 0 a component that is exactly zero has weight 0: no error there is no error,
    // any other is infinitely too large (and NaN stays NaN).
    const double scaled =
        weight > 0.0 ? error[i] / weight : (error[i] == 0.0 ? 0.0 : error[i] * kInfinity);
    sum += scaled * scaled;
    if (largest != nullptr && !std::isnan(largest->weighted) &&
        (std::isnan(scaled) || std::abs(scaled) > largest->weighted)) {
      *largest = {i, std::abs(scaled)};
    }
  }
  return std::sqrt(sum / static_cast<double>(n));
}

void StepSizeController::Configure(int error_power) {
  const double k = static_cast<double>(std::max(error_power, 1));
  beta_ = 0.2 / k;
  alpha_ = 1.0 / k - 0.75 * beta_;
  Restart();
}

void StepSizeController::Restart() {
  previous_error_ = 1e-4;  // dopri5.f's starting value: no memory of a previous step
  last_rejected_ = false;
}

double StepSizeController::Accepted(double h, double error) {
  // err^alpha / err_old^beta is the factor by which h was too large; zero error means "grow".
  const double error_now = std::max(error, 0.0);
  const double too_large = std::pow(error_now, alpha_) / std::pow(previous_error_, beta_);
  double factor = too_large > 0.0 ? kSafety / too_large : kMaxFactor;
  factor = std::clamp(factor, kMinFactor, kMaxFactor);
  if (last_rejected_) factor = std::min(factor, 1.0);
  previous_error_ = std::max(error_now, 1e-4);
  last_rejected_ = false;
  return h * factor;
}

double StepSizeController::Rejected(double h, double error) {
  last_rejected_ = true;
  // A NaN or infinite error says nothing about the right step: shrink as much as allowed.
  if (!std::isfinite(error)) return h * kMinFactor;
  // Only the current error counts here, as in dopri5.f: the previous one belonged to a
  // step that passed.
  const double factor = kSafety / std::pow(error, alpha_);
  return h * std::clamp(factor, kMinFactor, 1.0);
}

}  // namespace sled::runtime
