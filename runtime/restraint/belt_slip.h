// Friction and slip of webbing between spans: at each junction (a wrapped segment, or a harness
// tie point) the tensions of the two spans may differ by at most the capstan ratio
// r = exp(mu theta), theta being the angle the webbing turns there:
//
//   T_first <= r T_second   and   T_second <= r T_first.
//
// A junction that sticks holds its webbing, or lets the body it lies on carry it (its transfer
// is set before the solve); one that slips passes webbing until the tighter side's tension is
// exactly r times the slacker side's; one without friction passes webbing until both sides carry
// one tension. Which a junction does is its mode, changed only at events
// (runtime/restraint/belt_events.h); for a given mode the webbing distribution is a function of
// the geometry alone, found here by Newton's method on the slipping junctions' transfers from the
// transfer they held at their last event (a fixed start: the result does not depend on earlier
// evaluations), to 1e-12 of the tensions.
//
// Below the strain where a span's tension is zero the solver extends the tension linearly with
// the belt's slack stiffness (T~ < 0: how slack the span is), and the capstan bound r (T~) on the
// tighter side is r T~ while the slacker side pulls and T~ / r while it is slack. So the slack
// of two slack spans has the same friction cone as the tension of two taut ones: a junction
// between slack spans sticks unless one is r times slacker than the other, a slipping junction
// whose other side is slack keeps its tighter side slack too (no tension moves webbing), and a
// frictionless junction between two slack spans shares the slack in proportion. Every equation
// keeps a slope in every unknown, so the webbing distribution is a unique, continuous function of
// the geometry even where all tensions vanish (two junctions feeding one span can no longer share
// its webbing arbitrarily), and the tensions themselves are never negative.
#pragma once

#include <span>

#include "runtime/model/data.h"

namespace sled::runtime {

// A span's tension at `rest_length` of webbing (zero when slack), the extension of it below zero
// tension described above, and the derivatives of both with respect to the rest length.
struct SpanForce {
  double tension = 0.0;
  double extended = 0.0;
  double tension_slope = 0.0;
  double extended_slope = 0.0;
  double extended_strain_slope = 0.0;  // d extended / d strain
};
SpanForce SpanForceAt(const Model& model, const BeltState& state, std::size_t span,
                      double rest_length);

// The capstan bound on the tighter side's extended tension given the slacker side's, r (T~)
// above, and its slope d r(T~) / d T~.
double CapstanBound(double ratio, double extended);
double CapstanSlope(double ratio, double extended);

// The tension of a span holding `rest_length` of webbing at its current length, from its belt's
// webbing function and the span's loading history (zero when slack).
double SpanTension(const Model& model, const BeltState& state, std::size_t span,
                   double rest_length);

// Solves the transfers of the junctions that slip or have no friction (a sticking junction's
// transfer is set by the caller), then sets every span's rest length and tension.
void ResolveSlip(const Model& model, BeltState& state);

// After ResolveSlip: the rate of each junction's transfer [m/s] (0 for one that holds its
// webbing) along a motion that changes the spans' lengths, the junctions' capstan ratios and the
// arcs their bodies carried at the given rates. The derivative of the solved equations: the
// solver's Jacobian in the transfers times their rates balances the equations' derivative in
// those quantities (implicit differentiation), so the rates are exact where the equations are
// smooth, with no second solve.
void TransferRates(const Model& model, BeltState& state, std::span<const double> length_rate,
                   std::span<const double> ratio_rate, std::span<const double> carried_rate,
                   std::span<double> transfer_rate);

// Sizes the solver's workspace in `state` (SetUpBelts).
void SizeSlipSolver(BeltState& state);

}  // namespace sled::runtime
