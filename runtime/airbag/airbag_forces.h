// The airbags as force elements with state: each evaluation places every bag's envelope (while
// it unfolds, its size follows the gas it holds at the ambient pressure and the room the segments
// leave), finds how far the contact ellipsoids of its segments push into it, sets the uniform gas
// pressure from the ideal-gas law, applies the gauge pressure times the contact area to the
// segments (and the reaction to the bag's segment, when it is fixed in one), and writes the rates
// of the gas mass and internal energy (inflow, venting, the work of the pressure) into
// data.wdot. The model: docs/runtime.md, "Airbags".
#pragma once

#include "runtime/model/data.h"

namespace sled::runtime {

// Needs current kinematics and data.w. Records each bag's pressure, volume, temperature and
// flows and each contact's force in data.airbags; sets data.airbags.failed_bag when the segments
// inside a bag leave its gas no volume.
void ComputeAirbagForces(const Model& model, Data& data);

// The volume bag b's gas would take at the ambient pressure over the bag's full volume, from
// data.w: below 1 the envelope is still unfolding, at 1 it becomes full.
double AirbagUnfoldedFraction(const Model& model, const Data& data, std::size_t b);

// The event function of bag b's switch between unfolding and full, after ComputeAirbagForces:
// positive on the full side. Unfolding: the envelope's scale less one; full: the pressure over
// the ambient pressure less one (a full bag below the ambient pressure unfolds again), or, for
// ATB's free bag, which stays full, one.
double AirbagFullnessEvent(const Model& model, const Data& data, std::size_t b);

// Bag b's inflator phase at time t: 0 before deployment, 1 delivering, 2 spent (after the last
// row of a table function). The times it changes: deploy_time and AirbagInflowEnd.
std::uint8_t AirbagInflowPhase(const Model& model, std::size_t b, double t);
// When bag b's inflator is spent: after the last row of a table; infinity for other functions.
double AirbagInflowEnd(const Model& model, std::size_t b);

}  // namespace sled::runtime
