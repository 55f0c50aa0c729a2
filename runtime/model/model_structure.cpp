#include "runtime/model/model_structure.h"

#include "runtime/model/model_fields.h"

namespace sled::runtime {

std::shared_ptr<const ModelStructure> BuildModelStructure(const Model& model) {
  auto structure = std::make_shared<ModelStructure>();
  structure->physics = HashModelFields(model, FieldRole::kPhysics);
  const std::size_t n = model.nsegment();
  structure->joint_frame_identity.assign(n, 0);
  for (std::size_t s = 0; s < n; ++s) {
    const bool parent_identity = model.joint_frame_in_parent[s] == Mat3::Identity();
    const bool child_identity = model.joint_frame_in_child[s] == Mat3::Identity();
    structure->joint_frame_identity[s] =
        static_cast<std::uint8_t>((parent_identity ? 1 : 0) | (child_identity ? 2 : 0));
  }
  structure->constraints = BuildConstraintPattern(model);
  return structure;
}

std::shared_ptr<const ModelStructure> StructureOf(const Model& model) {
  if (model.structure && model.structure->physics == HashModelFields(model, FieldRole::kPhysics)) {
    return model.structure;
  }
  return BuildModelStructure(model);
}

std::string FinalizeModel(Model& model) {
  model.structure.reset();
  std::string errors = ValidateModel(model);
  if (errors.empty()) model.structure = BuildModelStructure(model);
  return errors;
}

}  // namespace sled::runtime
