// ATB's unloading and reloading law (ATB V.3's DEF_NEW_QUADRATIC and DEF_NEW_CUBIC, read from
// their description), for a force function f with `unloading = atb(energy_return = R,
// permanent_set = G)`. R and G are functions of the largest deflection x_max, evaluated where a
// new x_max is set (a constant is the usual case).
//
// - Loading beyond x_max follows f, plus the inertial spike s (ATB's NF(2)) until the first
//   x_max at or past the spike's end, where ATB drops it for good (DEF_NEW_QUADRATIC).
// - At a new x_max with R(x_max) = 1 the function unloads along its loading curve (elastic).
// - Otherwise it unloads along the quadratic Q(u) = A1 u + A2 u^2, u = x - x_g, from zero force
//   at x_g = D0 + G (x_max - D0) to (x_max, F(x_max)), F the loading curve (f plus the spike
//   while it lasts), whose area is R times the loading energy E = integral of f (without the
//   spike) from D0 to x_max, D0 the function's origin (0 unless given): A1 = 2 / d (3 R E / d -
//   f(x_max)), d = x_max - x_g. A negative A1 is taken as 0 (then Q returns f d / 3, more than R
//   E); a negative A2 makes Q the straight line to (x_max, f(x_max)) (then f d / 2, less). Below
//   x_g the force is zero.
// - Where it turns to reload, at x_t (no lower than x_g), it reloads along the cubic C from
//   (x_t, Q(x_t)) with Q's slope to (x_max, f(x_max)) with f's slope there; a cubic whose lowest
//   point between the two is below zero force becomes the straight line between them.
// - Where it turns back while reloading, at x_r below x_max, it unloads along a new quadratic
//   from x_g to (x_r, C(x_r)) returning R (the last x_max's) of the area under the path it came
//   up: Q from x_g to x_t, then C to x_r.
//
// The history (what was last set, the branch, the curves) changes only at these turns, which are
// events (AtbTurnFunction); every force between events is a function of the state. ATB redefines
// its curves after every integration step instead, which gives the same curves where the turns
// fall on step ends, except the turn while reloading: ATB makes a new quadratic at every step of
// the reload, each from the area under the last, so R compounds once per step (docs/legacy.md).
#pragma once

#include <cstdint>
#include <limits>

#include "runtime/forces/force_deflection.h"
#include "runtime/model/model.h"

namespace sled::runtime {

// The function of R at x_max when the force function `id` unloads by ATB's law, -1 otherwise.
std::int32_t AtbReturnFunction(const FunctionTable& functions, std::int32_t id);

// F(x) and dF/dx under ATB's law with the committed history (x >= 0).
double AtbForce(const FunctionTable& functions, std::int32_t id, double x,
                const LoadingHistory& history);
double AtbSlope(const FunctionTable& functions, std::int32_t id, double x,
                const LoadingHistory& history);

// The inertial spike of the force function `id` under ATB's law, -1 without one.
std::int32_t AtbSpikeFunction(const FunctionTable& functions, std::int32_t id);

// Where the inertial spike still on the loading curve drops (infinity: none, or dropped).
double AtbSpikeEnd(const FunctionTable& functions, std::int32_t id, const LoadingHistory& history);

// The event function of a turn: the deflection rate while loading beyond x_max or reloading, so
// it falls through zero where the deflection turns (loading, also where it reaches
// `spike_end`, the end of an inertial spike); while unloading the smaller of minus the rate and
// x - x_g (falls through zero where the deflection turns to reload, or passes x_g); 1 where no
// turn changes the history. `x` is the signed deflection (below zero: apart).
double AtbTurnFunction(double x, double rate, const LoadingHistory& history,
                       double spike_end = std::numeric_limits<double>::infinity());

// At a turn at deflection x (clamped to zero and above, as ATB does): a new x_max, the turn to
// reload, or the turn back while reloading, by the branch the history is on.
void TurnAtbHistory(const FunctionTable& functions, std::int32_t id, double x,
                    LoadingHistory& history);

}  // namespace sled::runtime
