// Friction and slip of webbing between spans: at each junction (a wrapped segment, or a harness
// tie point) the tensions of the two spans may differ by at most the capstan ratio
// r = exp(mu theta), theta being the angle the webbing turns there:
//
//   T_first <= r T_second   and   T_second <= r T_first.
//
// While both hold, the webbing sticks: each span keeps its webbing (its unstretched length). When
// one fails, webbing slips from the slacker span into the tighter one until the ratio is exactly
// r. With mu = 0 (r = 1) the tensions on both sides are equal: the belt slides freely.
//
// Solved as a return mapping from the webbing distribution committed after the last accepted
// step: Gauss-Seidel sweeps over the junctions, each solving its one-dimensional slip (the
// tension difference is monotonic in the webbing moved) by the Illinois method, until no
// junction is off by more than 1e-10 of its tensions. The result depends only on the state and
// the committed history, so the forces are a function of the state within a step.
#pragma once

#include "runtime/data.h"

namespace sled::runtime {

// The tension of a span holding `rest_length` of webbing at its current length, from its belt's
// webbing function and the span's loading history (zero when slack).
double SpanTension(const Model& model, const BeltState& state, std::size_t span,
                   double rest_length);

// Moves webbing between spans so every junction obeys its ratio (state.junction_ratio), from the
// distribution in state.rest_length; then sets state.tension.
void ResolveSlip(const Model& model, BeltState& state);

}  // namespace sled::runtime
