#include "runtime/forces/force_deflection.h"

#include <algorithm>
#include <cmath>

#include "runtime/forces/atb_unloading.h"
#include "runtime/forces/functions.h"

namespace sled::runtime {
namespace {

// Bounds on the unloading exponent: a curve steeper than x^1000 is a drop to zero, flatter than
// x^0.001 a step at x_p; parameters that ask for more are met as far as these allow.
constexpr double kMinExponent = 1e-3;
constexpr double kMaxExponent = 1e3;

// The loading law read on the side `mirror` says: f(x), or -f(-x) on a negative side.
double Loading(const FunctionTable& functions, std::int32_t id, double x, double mirror) {
  return mirror * EvaluateFunction(functions, id, mirror * x);
}

// The permanent deflection of a straight unloading line of slope s times the secant
// F_max / x_max from (x_max, F_max): it returns no more than the loading energy.
double PermanentOfSlope(double slope, double x, double force, double energy) {
  const double permanent = x * (1 - 1 / slope);
  return std::max({permanent, x - 2 * energy / force, 0.0});
}

}  // namespace

double UnloadSlope(const FunctionTable& functions, std::int32_t id) {
  const auto f = static_cast<std::size_t>(id);
  return id >= 0 && f < functions.unload_slope.size() ? functions.unload_slope[f] : 0.0;
}

bool HasHysteresis(const FunctionTable& functions, std::int32_t id) {
  if (id < 0) return false;
  const auto f = static_cast<std::size_t>(id);
  return functions.energy_loss[f] > 0 || functions.permanent_set[f] > 0 ||
         UnloadSlope(functions, id) > 0 || AtbReturnFunction(functions, id) >= 0;
}

double TurnEventFunction(const FunctionTable& functions, std::int32_t id, double x, double rate,
                         const LoadingHistory& history) {
  if (AtbReturnFunction(functions, id) >= 0) {
    return AtbTurnFunction(x, rate, history, AtbSpikeEnd(functions, id, history));
  }
  return x > history.max_deflection ? rate : 1.0;
}

double LoadingUnloadingForce(const FunctionTable& functions, std::int32_t id, double x,
                             const LoadingHistory& history, double mirror) {
  if (AtbReturnFunction(functions, id) >= 0) return AtbForce(functions, id, x, history);
  if (!HasHysteresis(functions, id) || x >= history.max_deflection)
    return Loading(functions, id, x, mirror);
  const double range = history.max_deflection - history.permanent;
  if (x <= history.permanent || range <= 0) return 0.0;
  return history.max_force * std::pow((x - history.permanent) / range, history.exponent);
}

double LoadingUnloadingSlope(const FunctionTable& functions, std::int32_t id, double x,
                             const LoadingHistory& history, double mirror) {
  if (AtbReturnFunction(functions, id) >= 0) return AtbSlope(functions, id, x, history);
  if (!HasHysteresis(functions, id) || x >= history.max_deflection) {
    return FunctionSlope(functions, id, mirror * x);  // d/dx of m f(m x) is f'(m x)
  }
  const double range = history.max_deflection - history.permanent;
  if (x <= history.permanent || range <= 0) return 0.0;
  const double fraction = (x - history.permanent) / range;
  return history.max_force * history.exponent * std::pow(fraction, history.exponent - 1) / range;
}

void UpdateLoadingHistory(const FunctionTable& functions, std::int32_t id, double x,
                          LoadingHistory& history, double mirror) {
  if (AtbReturnFunction(functions, id) >= 0) {
    TurnAtbHistory(functions, id, x, history);
    return;
  }
  if (id < 0 || !(x > history.max_deflection)) return;
  const auto f = static_cast<std::size_t>(id);
  history.max_deflection = x;
  history.max_force = Loading(functions, id, x, mirror);
  const double loss = std::clamp(functions.energy_loss[f], 0.0, 1.0);
  const double set = std::clamp(functions.permanent_set[f], 0.0, 1.0);
  const double slope = UnloadSlope(functions, id);
  history.permanent = 0.0;
  history.exponent = 1.0;
  if (loss <= 0 && set <= 0 && slope <= 0) return;
  // The integral of m f(m u) for u from 0 to x is the integral of f from 0 to m x.
  const double energy = IntegrateFunction(functions, id, mirror * x);
  if (!(history.max_force > 0) || !(energy > 0)) {
    history.permanent = set * x;
    return;
  }
  if (slope > 0) {
    history.permanent = PermanentOfSlope(slope, x, history.max_force, energy);
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
