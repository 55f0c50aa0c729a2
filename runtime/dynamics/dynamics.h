// The forward dynamics of a Model: kinematics down the trees, forces, then the articulated-body
// recursion for the accelerations (O(n) in the number of segments) and the joint wrenches.
#pragma once

#include <cstdint>
#include <span>

#include "runtime/model/data.h"

namespace sled::runtime {

// Poses, velocities and motion subspaces from data.q, data.v and data.locked.
void ComputeKinematics(const Model& model, Data& data);
// The same for the segments marked in `segments` (one flag per segment; each marked segment's
// ancestors must be marked too), and every vehicle: for a caller that reads only those. The
// others keep what they held.
void ComputeKinematics(const Model& model, Data& data, std::span<const std::uint8_t> segments);

// Accelerations (data.vdot, data.acceleration) and joint wrenches from the forces in
// data.external and data.generalized_force. False when an articulated inertia is singular or
// not finite; `failure` then says which segment.
bool ComputeAccelerations(const Model& model, Data& data, Failure* failure);

// Kinematics, forces and accelerations at data.time: ForwardElements, then ForwardAccelerations.
bool Forward(const Model& model, Data& data, Failure* failure);
// The first part of Forward (counted as an evaluation): kinematics and the force elements'
// loads (ComputeElementForces), all that the event functions read but a lock level's.
void ForwardElements(const Model& model, Data& data);
// The rest of Forward, after ForwardElements at the same state: the joints' torques, the
// accelerations, and the loop constraints' forces.
bool ForwardAccelerations(const Model& model, Data& data, Failure* failure);

// The spatial inertia of a segment about its centre of mass, in its frame.
Mat6 SpatialInertia(const Model& model, std::size_t segment);

}  // namespace sled::runtime
