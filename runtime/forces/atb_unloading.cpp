#include "runtime/forces/atb_unloading.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "runtime/forces/functions.h"

namespace sled::runtime {
namespace {

// The inertial spike still added to the loading force (-1: none, or dropped).
std::int32_t ActiveSpike(const FunctionTable& functions, std::int32_t id, const LoadingHistory& h) {
  const auto f = static_cast<std::size_t>(id);
  const bool given = f < functions.atb_spike.size() && f < functions.atb_spike_end.size();
  return h.spike_dropped || !given ? -1 : functions.atb_spike[f];
}

double Origin(const FunctionTable& functions, std::int32_t id) {
  const auto f = static_cast<std::size_t>(id);
  return f < functions.atb_origin.size() ? functions.atb_origin[f] : 0.0;
}

// ATB's loading curve: the function plus the inertial spike while it lasts.
double LoadingForce(const FunctionTable& functions, std::int32_t id, double x,
                    const LoadingHistory& h) {
  return EvaluateFunction(functions, id, x) +
         EvaluateFunction(functions, ActiveSpike(functions, id, h), x);
}

double LoadingSlope(const FunctionTable& functions, std::int32_t id, double x,
                    const LoadingHistory& h) {
  return FunctionSlope(functions, id, x) +
         FunctionSlope(functions, ActiveSpike(functions, id, h), x);
}

double Quadratic(const LoadingHistory& h, double u) {
  return u * (h.quadratic[0] + u * h.quadratic[1]);
}

double QuadraticSlope(const LoadingHistory& h, double u) {
  return h.quadratic[0] + 2 * u * h.quadratic[1];
}

// The area under the quadratic from x_g to x_g + u.
double QuadraticArea(const LoadingHistory& h, double u) {
  return u * u * (h.quadratic[0] / 2 + u * h.quadratic[1] / 3);
}

double Cubic(const double (&c)[4], double s) { return c[0] + s * (c[1] + s * (c[2] + s * c[3])); }

double CubicSlope(const double (&c)[4], double s) { return c[1] + s * (2 * c[2] + s * 3 * c[3]); }

double CubicArea(const double (&c)[4], double s) {
  return s * (c[0] + s * (c[1] / 2 + s * (c[2] / 3 + s * c[3] / 4)));
}

// The quadratic from zero force at x_g to (top, force) whose area is `returned`, with both end
// slopes at zero or above (ATB's clamps: A1 >= 0, else A2 >= 0 by the straight line).
void DefineQuadratic(LoadingHistory& h, double top, double force, double returned) {
  const double d = top - h.permanent;
  h.cubic_start = top;
  if (!(d > 0)) {  // x_g at the top (a G of 1 or more): the force drops at once
    h.quadratic[0] = h.quadratic[1] = 0.0;
    return;
  }
  double a1 = std::max(0.0, 2 / d * (3 * returned / d - force));
  double a2 = (force / d - a1) / d;
  if (a2 < 0) {
    a1 = force / d;
    a2 = 0.0;
  }
  h.quadratic[0] = a1;
  h.quadratic[1] = a2;
}

void NewLargestDeflection(const FunctionTable& functions, std::int32_t id, double x,
                          LoadingHistory& h) {
  const auto f = static_cast<std::size_t>(id);
  // ATB drops the spike for good at the first largest deflection past its end (DINER).
  if (ActiveSpike(functions, id, h) >= 0 && x >= functions.atb_spike_end[f]) {
    h.spike_dropped = true;
  }
  h.max_deflection = x;
  h.max_force = LoadingForce(functions, id, x, h);
  h.unloading = true;
  h.energy_return = EvaluateFunction(functions, functions.atb_return[f], x);
  // ATB compares R with 1 exactly: only then does it unload along f.
  h.elastic = h.energy_return == 1.0;
  h.permanent = 0.0;
  if (h.elastic) return;
  // The permanent set and the loading energy (of the function alone) count from the origin D0.
  const std::int32_t set = f < functions.atb_set.size() ? functions.atb_set[f] : -1;
  const double origin = Origin(functions, id);
  const double share = set >= 0 ? EvaluateFunction(functions, set, x) : 0.0;
  h.permanent = origin + share * (x - origin);
  const double energy =
      IntegrateFunction(functions, id, x) - IntegrateFunction(functions, id, origin);
  DefineQuadratic(h, x, h.max_force, h.energy_return * energy);
}

// A cubic (in s = x - x1) with a zero of its slope inside (0, dx) whose value there is below zero.
bool DipsBelowZero(const double (&c)[4], double dx) {
  auto below = [&](double s) { return s > 0 && s < dx && Cubic(c, s) < 0; };
  if (c[3] != 0) {
    const double a33 = 3 * c[3];
    const double disc = c[2] * c[2] - c[1] * a33;
    if (disc < 0) return false;
    const double root = std::sqrt(disc);
    return below((-c[2] + root) / a33) || below((-c[2] - root) / a33);
  }
  return c[2] != 0 && below(-0.5 * c[1] / c[2]);
}

void TurnToReload(const FunctionTable& functions, std::int32_t id, double x, LoadingHistory& h) {
  // Not below the top of the quadratic it unloads along: no turn (a belt's spans are all looked
  // at when one of them turns, one that has just turned among them).
  if (!(x < h.cubic_start)) return;
  const double x1 = std::max(x, h.permanent);
  const double dx = h.max_deflection - x1;
  if (!(dx > 0)) return;
  const double y1 = Quadratic(h, x1 - h.permanent);
  const double y1_slope = QuadraticSlope(h, x1 - h.permanent);
  const double y2 = h.max_force;
  const double y2_slope = LoadingSlope(functions, id, h.max_deflection, h);
  // Value and slope of the quadratic at x1, value and slope of f at x_max.
  const double r13 = (y2 - y1 - y1_slope * dx) / (dx * dx);
  const double r23 = (y2_slope - y1_slope) / dx;
  double(&c)[4] = h.cubic;
  c[0] = y1;
  c[1] = y1_slope;
  c[2] = 3 * r13 - r23;
  c[3] = (r23 - 2 * r13) / dx;
  if (DipsBelowZero(c, dx)) {
    c[1] = (y2 - y1) / dx;
    c[2] = c[3] = 0.0;
  }
  h.cubic_start = x1;
  h.unloading = false;
}

void TurnBackWhileReloading(double x, LoadingHistory& h) {
  const double start = h.cubic_start;
  const double area = QuadraticArea(h, start - h.permanent) + CubicArea(h.cubic, x - start);
  DefineQuadratic(h, x, Cubic(h.cubic, x - start), h.energy_return * area);
  h.unloading = true;
}

}  // namespace

std::int32_t AtbReturnFunction(const FunctionTable& functions, std::int32_t id) {
  if (id < 0) return -1;
  const auto f = static_cast<std::size_t>(id);
  return f < functions.atb_return.size() ? functions.atb_return[f] : -1;
}

double AtbForce(const FunctionTable& functions, std::int32_t id, double x,
                const LoadingHistory& h) {
  if (h.elastic || x >= h.max_deflection) return LoadingForce(functions, id, x, h);
  if (!h.unloading && x > h.cubic_start) return Cubic(h.cubic, x - h.cubic_start);
  return x > h.permanent ? Quadratic(h, x - h.permanent) : 0.0;
}

double AtbSlope(const FunctionTable& functions, std::int32_t id, double x,
                const LoadingHistory& h) {
  if (h.elastic || x >= h.max_deflection) return LoadingSlope(functions, id, x, h);
  if (!h.unloading && x > h.cubic_start) return CubicSlope(h.cubic, x - h.cubic_start);
  return x > h.permanent ? QuadraticSlope(h, x - h.permanent) : 0.0;
}

std::int32_t AtbSpikeFunction(const FunctionTable& functions, std::int32_t id) {
  const auto f = static_cast<std::size_t>(id);
  return id >= 0 && f < functions.atb_spike.size() ? functions.atb_spike[f] : -1;
}

double AtbSpikeEnd(const FunctionTable& functions, std::int32_t id, const LoadingHistory& h) {
  if (ActiveSpike(functions, id, h) < 0) return std::numeric_limits<double>::infinity();
  return functions.atb_spike_end[static_cast<std::size_t>(id)];
}

double AtbTurnFunction(double x, double rate, const LoadingHistory& h, double spike_end) {
  if (x > h.max_deflection) return std::min(rate, spike_end - x);
  if (h.elastic) return 1.0;
  if (h.unloading) return std::min(-rate, x - h.permanent);
  return x > h.cubic_start ? rate : 1.0;
}

void TurnAtbHistory(const FunctionTable& functions, std::int32_t id, double x, LoadingHistory& h) {
  x = std::max(x, 0.0);
  if (x > h.max_deflection) {
    NewLargestDeflection(functions, id, x, h);
  } else if (h.elastic) {
    return;
  } else if (h.unloading) {
    TurnToReload(functions, id, x, h);
  } else if (x > h.cubic_start) {
    TurnBackWhileReloading(x, h);
  }
}

}  // namespace sled::runtime
