#include "runtime/run/checkpoint.h"

#include <fmt/format.h>

#include "runtime/dynamics/constraints.h"
#include "runtime/model/model_fields.h"
#include "runtime/run/outputs.h"

namespace sled::runtime {
ModelFingerprint FingerprintOf(const Model& model) {
  ModelFingerprint fingerprint;
  fingerprint.physics = HashModelFields(model, FieldRole::kPhysics);
  fingerprint.settings = DumpModelFields(model, FieldRole::kSettings);
  if (!fingerprint.settings.empty() && fingerprint.settings.back() == '\n') {
    fingerprint.settings.pop_back();  // one line, quoted in CheckpointMismatch's message
  }
  fingerprint.outputs = DumpModelFields(model, FieldRole::kRecords);
  for (const std::string& name : ChannelNames(model)) fingerprint.outputs += name + "\n";
  return fingerprint;
}

std::string CheckpointMismatch(const Checkpoint& checkpoint, const ModelFingerprint& model) {
  if (checkpoint.model.physics != model.physics) {
    return "the scene's model is not the one the checkpoint was made from (a segment, joint, "
           "force element, function, vehicle motion or initial condition changed); only the "
           "end time and the output requests may change";
  }
  if (checkpoint.model.settings != model.settings) {
    return fmt::format(
        "the integrator settings changed: the checkpoint was made with `{}`, the scene has `{}`",
        checkpoint.model.settings, model.settings);
  }
  return {};
}

void SerializeData(Archive& archive, Data& data) {
  archive.Field(data.time);
  archive.Field(data.q);
  archive.Field(data.v);
  archive.Field(data.w);
  archive.Field(data.locked);
  data.joint_histories.Serialize(archive);
  data.contacts.Serialize(archive);
  data.belts.Serialize(archive);
  data.airbags.Serialize(archive);
  data.table_watch.Serialize(archive);
  archive.Field(data.energy);
  archive.Field(data.vehicle_power);
  archive.Field(data.evaluations);
  bool constraints = data.constraints != nullptr;
  archive.Field(constraints);
  if (archive.reading() && constraints != (data.constraints != nullptr)) {
    archive.Fail();  // another model's checkpoint (the fingerprint catches it first)
    return;
  }
  if (data.constraints) SerializeConstraints(archive, *data.constraints);
}

}  // namespace sled::runtime
