// How far a contact pair can go in one step, and where it went past its force law.
//
// Free flight has no error for the error test to see, so the step of a body flying at a surface
// grows past the contact zone, and a step could carry it from in front of the surface to wholly
// behind it, where the force law gives nothing (the contact tunnels). ContactStepLimit bounds
// every step by the time an approaching pair could close its gap and a share of the thinner
// ellipsoid's depth, at its closing speed and acceleration bound, so the step that reaches a
// surface ends inside the contact zone, where the force (and the error test) sees it.
//
// The force law describes deflections up to about the ellipsoid's smallest semi-axis; past it
// (or with an ellipsoid wholly behind its plane) the answer is not physical. WatchContactReach
// records when that happens; ContactReachWarnings words it for the run (W0010).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "runtime/model/data.h"
#include "runtime/model/model.h"

namespace sled::runtime {

// The share of the thinner ellipsoid's smallest semi-axis a step may carry an approaching pair
// past its gap.
inline constexpr double kContactReachShare = 0.25;

// The longest step from data's state (after Forward: positions, velocities and accelerations)
// over which no pair can pass more than kContactReachShare of its thinner ellipsoid's smallest
// semi-axis into contact, past its gap when apart, past where it is when touching; infinity
// when no pair approaches.
double ContactStepLimit(const Model& model, const Data& data);

// At the start (data's surfaces placed): which ellipsoids start wholly behind their plane.
void StartContactReach(const Model& model, Data& data);

// After an accepted step (data at its end, after Forward): records each pair's deflection past
// its ellipsoid's smallest semi-axis, and an ellipsoid that went from in front of its plane to
// wholly behind it over the plane's parallelogram.
void WatchContactReach(const Model& model, Data& data);

// One line per pair that went past its force law ("warning[W0010]: ...").
std::vector<std::string> ContactReachWarnings(const Model& model, const Data& data);

// "contact `occupant.head` with `panel`": pair k in messages.
std::string ContactPairName(const ContactTable& table, std::size_t k);

}  // namespace sled::runtime
