#include "runtime/restraint/belt_slip.h"

#include <algorithm>
#include <cmath>

namespace sled::runtime {
namespace {

constexpr int kMaxSweeps = 200;
constexpr int kMaxIterations = 100;
constexpr double kRelativeTolerance = 1e-10;  // of the two tensions
constexpr double kAbsoluteTolerance = 1e-9;   // [N]

double Tolerance(double a, double b) { return kRelativeTolerance * (a + b) + kAbsoluteTolerance; }

// Webbing moved from span `giver` to span `taker` so that T_taker = ratio T_giver; the tension
// gap g(d) = T_taker(L_taker + d) - ratio T_giver(L_giver - d) falls as d grows and is positive
// at d = 0. Illinois (regula falsi that halves a stale end) on [0, d_high].
double SlipAmount(const Model& model, const BeltState& state, std::size_t taker, std::size_t giver,
                  double ratio) {
  const double taker_rest = state.rest_length[taker], giver_rest = state.rest_length[giver];
  auto gap = [&](double d) {
    return SpanTension(model, state, taker, taker_rest + d) -
           ratio * SpanTension(model, state, giver, giver_rest - d);
  };
  double low = 0.0, g_low = gap(0.0);
  // The giver's tension grows without bound as its webbing runs out: find where the gap turns.
  double high = 0.5 * giver_rest, g_high = gap(high);
  for (int k = 0; k < 60 && g_high > 0; ++k) {
    low = high;
    g_low = g_high;
    high = 0.5 * (high + giver_rest);
    g_high = gap(high);
  }
  if (g_high > 0) return high;  // a webbing function that never stiffens: give all but a sliver
  const double tolerance =
      0.1 * Tolerance(SpanTension(model, state, taker, taker_rest), 0.0) + 1e-12;
  int stale = 0;
  double d = low;
  for (int k = 0; k < kMaxIterations; ++k) {
    d = (low * g_high - high * g_low) / (g_high - g_low);
    const double g = gap(d);
    if (std::abs(g) <= tolerance || high - low <= 1e-15 * giver_rest) break;
    if (g > 0) {
      low = d;
      g_low = g;
      if (stale == 1) g_high *= 0.5;
      stale = 1;
    } else {
      high = d;
      g_high = g;
      if (stale == -1) g_low *= 0.5;
      stale = -1;
    }
  }
  return d;
}

}  // namespace

double SpanTension(const Model& model, const BeltState& state, std::size_t span,
                   double rest_length) {
  if (!(rest_length > 0)) return 0.0;
  const double strain = state.length[span] / rest_length - 1.0;
  if (!(strain > 0)) return 0.0;
  const std::int32_t function =
      model.belts.function[static_cast<std::size_t>(state.span_belt[span])];
  return std::max(0.0,
                  LoadingUnloadingForce(model.functions, function, strain, state.history[span]));
}

void ResolveSlip(const Model& model, BeltState& state) {
  const std::size_t junctions = state.junction_first.size();
  for (int sweep = 0; sweep < kMaxSweeps && junctions > 0; ++sweep) {
    ++state.slip_sweeps;
    bool moved = false;
    for (std::size_t j = 0; j < junctions; ++j) {
      const auto a = static_cast<std::size_t>(state.junction_first[j]);
      const auto b = static_cast<std::size_t>(state.junction_second[j]);
      const double ratio = state.junction_ratio[j];
      const double ta = SpanTension(model, state, a, state.rest_length[a]);
      const double tb = SpanTension(model, state, b, state.rest_length[b]);
      if (ta > ratio * tb + Tolerance(ta, tb)) {
        const double d = SlipAmount(model, state, a, b, ratio);
        state.rest_length[a] += d;
        state.rest_length[b] -= d;
        moved = true;
      } else if (tb > ratio * ta + Tolerance(ta, tb)) {
        const double d = SlipAmount(model, state, b, a, ratio);
        state.rest_length[b] += d;
        state.rest_length[a] -= d;
        moved = true;
      }
    }
    if (!moved) break;
  }
  for (std::size_t span = 0; span < state.tension.size(); ++span) {
    state.tension[span] = SpanTension(model, state, span, state.rest_length[span]);
  }
}

}  // namespace sled::runtime
