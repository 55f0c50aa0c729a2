// The generalized forces of a joint tree that do not come from acceleration: tau - C(q, v), with
// C the gyroscopic, Coriolis and base-acceleration terms less the applied wrenches, by the
// recursive Newton–Euler algorithm at zero joint acceleration. With the mass matrix it states
// the tree's equations M vdot = tau - C directly, for a tree whose articulated-body recursion
// breaks down (a singular, massless segment) but whose constraints determine the motion.
#pragma once

#include <span>

#include "runtime/model/data.h"

namespace sled::runtime {

// Writes tau - C into `residual` (nv; zero for locked axes), and leaves data.vdot = 0 and
// data.acceleration at the accelerations of zero joint acceleration. Needs the kinematics and
// the forces of data (ComputeKinematics, ComputeForces). No allocation.
void TreeBiasForces(const Model& model, Data& data, std::span<double> residual);

}  // namespace sled::runtime
