// The joint-space mass matrix M(q) of the segment trees by the composite-rigid-body algorithm
// (Featherstone, Rigid Body Dynamics Algorithms, §6.2). M is symmetric positive definite; its
// nonzeros are the (i, j) whose segments lie on a common root-to-leaf path, so it is sparse by
// tree. The articulated-body recursion (dynamics.h) never forms M; the loop-closing constraints
// (constraints.h) need it for their KKT system.
#pragma once

#include <span>

#include <Eigen/Core>

#include "runtime/model/data.h"

namespace sled::runtime {

// Fills `mass` (nv x nv) from the kinematics in data (ComputeKinematics first). Only entries of
// the tree pattern are written; the caller zeroes the rest once. A locked axis (a coordinate the
// articulated-body recursion holds still) gets a row and column of zeros and a one on the
// diagonal, so M stays regular and the pattern fixed. `composite` is workspace of nsegment
// entries. No allocation.
void CompositeRigidBodyMassMatrix(const Model& model, const Data& data, std::span<Mat6> composite,
                                  Eigen::Ref<Eigen::MatrixXd> mass);

// True when segment `ancestor` is `segment` or lies on its path to the root.
bool IsAncestorOrSelf(const Model& model, std::size_t ancestor, std::size_t segment);

}  // namespace sled::runtime
