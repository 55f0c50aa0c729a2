#include "runtime/forces/force_deflection.h"

#include <algorithm>
#include <cmath>

#include "runtime/forces/functions.h"

namespace sled::runtime {
namespace {

// Bounds on the unloading exponent: a curve steeper than x^1000 is a drop to zero, flatter than
// x^0.001 a step at x_p; parameters that ask for more are met as far as these allow.
constexpr double kMinExponent = 1e-3;
constexpr double kMaxExponent = 1e3;

}  // namespace

bool HasHysteresis(const FunctionTable& functions, std::int32_t id) {
  if (id < 0) return false;
  const auto f = static_cast<std::size_t>(id);
  return functions.energy_loss[f] > 0 || functions.permanent_set[f] > 0;
}

double LoadingUnloadingForce(const FunctionTable& functions, std::int32_t id, double x,
                             const LoadingHistory& history) {
  if (!HasHysteresis(functions, id) || x >= history.max_deflection)
    return EvaluateFunction(functions, id, x);
  const double range = history.max_deflection - history.permanent;
  if (x <= history.permanent || range <= 0) return 0.0;
  return history.max_force * std::pow((x - history.permanent) / range, history.exponent);
}

double LoadingUnloadingSlope(const FunctionTable& functions, std::int32_t id, double x,
                             const LoadingHistory& history) {
  if (!HasHysteresis(functions, id) || x >= history.max_deflection) {
    return FunctionSlope(functions, id, x);
  }
  const double range = history.max_deflection - history.permanent;
  if (x <= history.permanent || range <= 0) return 0.0;
  const double fraction = (x - history.permanent) / range;
  return history.max_force * history.exponent * std::pow(fraction, history.exponent - 1) / range;
}

void UpdateLoadingHistory(const FunctionTable& functions, std::int32_t id, double x,
                          LoadingHistory& history) {
  if (id < 0 || !(x > history.max_deflection)) return;
  const auto f = static_cast<std::size_t>(id);
  history.max_deflection = x;
  history.max_force = EvaluateFunction(functions, id, x);
  const double loss = std::clamp(functions.energy_loss[f], 0.0, 1.0);
  const double set = std::clamp(functions.permanent_set[f], 0.0, 1.0);
  history.permanent = 0.0;
  history.exponent = 1.0;
  if (loss <= 0 && set <= 0) return;
  const double energy = IntegrateFunction(functions, id, x);
  if (!(history.max_force > 0) || !(energy > 0)) {
    history.permanent = set * x;
    return;
  }
  history.permanent =
      set > 0 ? set * x : std::max(0.0, x - 2 * (1 - loss) * energy / history.max_force);
  if (loss > 0) {
    const double returned = (1 - loss) * energy;
    const double exponent =
        returned > 0 ? history.max_force * (x - history.permanent) / returned - 1 : kMaxExponent;
    history.exponent = std::clamp(exponent, kMinExponent, kMaxExponent);
  }
}

}  // namespace sled::runtime
