// What FinalizeModel derives from a valid Model once, so that every Data made from it only
// allocates and copies: which joint frames are exactly the identity, and the constraint system's
// rows and KKT sparsity pattern (the KLU symbolic analysis of that pattern is still made per
// Data: it belongs to the Data's KLU objects, which the checkpoints save with the factors).
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "runtime/dynamics/constraints.h"
#include "runtime/model/model.h"

namespace sled::runtime {

struct ModelStructure {
  // HashModelFields(model, kPhysics) when it was built: a Model changed since is rebuilt.
  std::uint64_t physics = 0;
  // Per segment: bit 0 when its joint frame in the parent is exactly the identity, bit 1 when the
  // one in the child is, so the kinematics skips those products.
  std::vector<std::uint8_t> joint_frame_identity;
  ConstraintPattern constraints;
};

// Derives the structure of a Model that ValidateModel accepts.
std::shared_ptr<const ModelStructure> BuildModelStructure(const Model& model);

// The Model's structure: model.structure when FinalizeModel made it for the Model as it is now,
// else one built now (a Model built by hand, or changed after FinalizeModel).
std::shared_ptr<const ModelStructure> StructureOf(const Model& model);

}  // namespace sled::runtime
