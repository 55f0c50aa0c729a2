#include "runtime/checkpoint.h"

#include <sstream>

#include <fmt/format.h>

#include "runtime/constraints.h"
#include "runtime/fnv1a.h"
#include "runtime/outputs.h"

namespace sled::runtime {
namespace {

// The Model's dump in two parts: what the run's physics is (without the title, the run settings,
// compared separately, and where things were declared), and what it records (the output
// requests and criteria: kinds, targets, points, filters), which may change between the saved
// and the resumed run.
struct DumpParts {
  std::string physics;
  std::string outputs;
};
DumpParts SplitDump(const Model& model) {
  std::istringstream lines(DumpModel(model));
  DumpParts parts;
  std::string line;
  while (std::getline(lines, line)) {
    if (line.starts_with("title ") || line.starts_with("run ") || line.starts_with("sizes ")) {
      continue;
    }
    if (const auto source = line.find(" source "); source != std::string::npos) {
      line.erase(source);
    }
    const bool output =
        line.starts_with("output ") || line.starts_with("criterion ") || line.starts_with("shape ");
    (output ? parts.outputs : parts.physics) += line + '\n';
  }
  return parts;
}

}  // namespace

ModelFingerprint FingerprintOf(const Model& model) {
  ModelFingerprint fingerprint;
  const DumpParts parts = SplitDump(model);
  fingerprint.physics = Fnv1a(parts.physics);
  fingerprint.outputs = parts.outputs;
  fingerprint.settings = fmt::format(
      "integrator {} relative_tolerance {} absolute_tolerance {} min_step {} max_step {} "
      "initial_step {} start {} output_every {}",
      model.integrator, model.relative_tolerance, model.absolute_tolerance, model.min_step,
      model.max_step, model.initial_step, model.start_time, model.output_every);
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
