#include "runtime/contact/contact_force_law.h"

#include <algorithm>
#include <cmath>

#include "runtime/functions.h"
#include "runtime/model.h"

namespace sled::runtime {
namespace {

// Bounds of the unloading exponent: below the lower one the curve is nearly a step at the
// permanent deflection (it cannot return more energy than that), above the upper one it hugs
// zero until the largest deflection (nearly all the energy is lost).
constexpr double kMinExponent = 0.05;
constexpr double kMaxExponent = 50.0;

}  // namespace

bool HasHysteresis(const FunctionTable& functions, std::int32_t function) {
  if (function < 0) return false;
  const auto f = static_cast<std::size_t>(function);
  return functions.energy_loss[f] > 0 || functions.permanent_set[f] > 0;
}

double ElasticForce(const FunctionTable& functions, std::int32_t function, double deflection,
                    const LoadingHistory& history) {
  if (deflection >= history.max_deflection) {
    return EvaluateFunction(functions, function, deflection);
  }
  const double span = history.max_deflection - history.permanent;
  const double x = (deflection - history.permanent) / span;
  if (!(x > 0)) return 0.0;
  return history.max_force * std::pow(x, history.exponent);
}

LoadingHistory CommitDeflection(const FunctionTable& functions, std::int32_t function,
                                double deflection, const LoadingHistory& history) {
  if (!(deflection > history.max_deflection) || !HasHysteresis(functions, function)) {
    return history;
  }
  const auto f = static_cast<std::size_t>(function);
  LoadingHistory next;
  next.max_deflection = deflection;
  next.max_force = std::max(EvaluateFunction(functions, function, deflection), 0.0);
  next.permanent = std::clamp(functions.permanent_set[f], 0.0, 1.0) * deflection;
  const double returned = (1.0 - std::clamp(functions.energy_loss[f], 0.0, 1.0)) *
                          IntegrateFunction(functions, function, deflection);
  // Area under max_force x^k over the span is max_force span / (k + 1).
  const double box = next.max_force * (deflection - next.permanent);
  next.exponent = returned > 0 && box > 0
                      ? std::clamp(box / returned - 1.0, kMinExponent, kMaxExponent)
                      : kMaxExponent;
  return next;
}

}  // namespace sled::runtime
