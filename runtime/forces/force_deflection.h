// The CVS force-deflection model with loading and unloading, for any function of the Model
// that has unloading parameters (energy_loss G, permanent_set p, unload_slope s): contact force
// against deflection (runtime/contact/), webbing force against strain (runtime/restraint/) and a
// joint's torque against its angle (runtime/forces/joint_hysteresis.h).
//
// Loading (the deflection beyond the largest so far, x_max) follows the function f. Below x_max
// the force follows an unloading curve from (x_max, f(x_max)) down to zero force at the
// permanent deflection x_p, and reloading climbs the same curve back to x_max:
//
//   F(x) = F_max ((x - x_p) / (x_max - x_p))^n   for x_p < x < x_max,   0 for x <= x_p.
//
// With s given, the curve is the straight line (n = 1) of slope s times the loading slope, the
// secant F_max / x_max: x_p = x_max (1 - 1 / s). Otherwise x_p = p x_max when p is given, or
// the x_p at which a straight unloading line returns the fraction 1 - G of the loading energy
// E = integral of f from 0 to x_max: x_max - x_p = 2 (1 - G) E / F_max; and the exponent n makes
// the returned energy, F_max (x_max - x_p) / (n + 1), exactly (1 - G) E, so a full unloading
// dissipates G E (with only p given, n = 1). G = p = 0 and no s: elastic, unloading along f.
// No curve returns more than E or ends below zero deflection (x_p >= 0).
//
// A law on the negative side of a function (a joint angle below zero, when the function's table
// covers negative angles) reads it mirrored, F(x) = -f(-x) for the deflection x = -angle: the
// `mirror` argument (-1) does that; 1 reads f as written.
//
// The history (x_max and the curve) changes only at events, where the deflection turns while it
// loads (runtime/run/system.h, runtime/restraint/belt_events.h), so every evaluation is a function
// of the state and the events so far.
#pragma once

#include <cstdint>

#include "runtime/model/model.h"

namespace sled::runtime {

struct LoadingHistory {
  double max_deflection = 0.0;  // x_max
  double max_force = 0.0;       // f(x_max)
  double permanent = 0.0;       // x_p (ATB's law: x_g, where the force reaches zero)
  double exponent = 1.0;        // n
  // ATB's law only (runtime/forces/atb_unloading.h): the branch (unloading along the quadratic,
  // or reloading along the cubic), R = 1 at x_max (unloads along f), R at x_max, the quadratic's
  // A1 and A2 in x - x_g, and the cubic's start and coefficients in x - start.
  bool unloading = false;
  bool elastic = false;
  double energy_return = 1.0;
  double quadratic[2] = {0.0, 0.0};
  double cubic_start = 0.0;
  double cubic[4] = {0.0, 0.0, 0.0, 0.0};
  // ATB's inertial spike has been dropped: a largest deflection reached its end.
  bool spike_dropped = false;
};

// F(x) under the committed history.
double LoadingUnloadingForce(const FunctionTable& functions, std::int32_t id, double x,
                             const LoadingHistory& history, double mirror = 1.0);

// dF/dx under the history.
double LoadingUnloadingSlope(const FunctionTable& functions, std::int32_t id, double x,
                             const LoadingHistory& history, double mirror = 1.0);

// At a deflection x that turns (an event, or the start): a new largest deflection loads further
// and moves the unloading curve; under ATB's law also the turns below x_max (atb_unloading.h).
void UpdateLoadingHistory(const FunctionTable& functions, std::int32_t id, double x,
                          LoadingHistory& history, double mirror = 1.0);

// The event function of a turn of the history at the signed deflection x (below zero: apart)
// moving at `rate`: it falls through zero where the history must change (runtime/run/system.cpp,
// runtime/restraint/belt_events.cpp); 1 where nothing can change it.
double TurnEventFunction(const FunctionTable& functions, std::int32_t id, double x, double rate,
                         const LoadingHistory& history);

// True when the function's unloading differs from its loading (an energy loss, a permanent set,
// an unloading slope or ATB's law): only such force elements keep a history.
bool HasHysteresis(const FunctionTable& functions, std::int32_t id);

// The function's unloading slope relative to its loading slope; 0 when it has none (a Model
// built by hand may leave FunctionTable::unload_slope empty).
double UnloadSlope(const FunctionTable& functions, std::int32_t id);

}  // namespace sled::runtime
