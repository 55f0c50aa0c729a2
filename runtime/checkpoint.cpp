#include "runtime/checkpoint.h"

#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "runtime/constraints.h"
#include "runtime/fnv1a.h"
#include "runtime/outputs.h"

namespace sled::runtime {
namespace {

// Format 2 ends with a 16-hex-digit FNV-1a checksum of everything between the magic line and
// it, so that a damaged file (a flipped byte, a torn write) is refused rather than resumed from.
constexpr char kMagic[] = "sled checkpoint 2\n";
constexpr char kMagicPrefix[] = "sled checkpoint ";
constexpr std::size_t kChecksumDigits = 16;

// The checksum that ends a format-2 file: FNV-1a of the payload in kChecksumDigits hex digits.
std::string ChecksumText(const std::string& payload) {
  return fmt::format("{:0{}x}", Fnv1a(payload), kChecksumDigits);
}

// The Model's dump without what may change between the saved and the resumed run: the title,
// the run settings (compared separately), the output requests and where things were declared.
std::string PhysicsText(const Model& model) {
  std::istringstream lines(DumpModel(model));
  std::string text, line;
  while (std::getline(lines, line)) {
    if (line.starts_with("title ") || line.starts_with("run ") || line.starts_with("sizes ") ||
        line.starts_with("output ")) {
      continue;
    }
    if (const auto source = line.find(" source "); source != std::string::npos) {
      line.erase(source);
    }
    text += line;
    text += '\n';
  }
  return text;
}

void SerializeFingerprint(Archive& archive, ModelFingerprint& model) {
  archive.Field(model.physics);
  archive.Resizable(model.settings);
  archive.Resizable(model.outputs);
}

}  // namespace

ModelFingerprint FingerprintOf(const Model& model) {
  ModelFingerprint fingerprint;
  fingerprint.physics = Fnv1a(PhysicsText(model));
  fingerprint.settings = fmt::format(
      "integrator {} relative_tolerance {} absolute_tolerance {} min_step {} max_step {} "
      "initial_step {} start {} output_every {}",
      model.integrator, model.relative_tolerance, model.absolute_tolerance, model.min_step,
      model.max_step, model.initial_step, model.start_time, model.output_every);
  for (const std::string& name : ChannelNames(model)) fingerprint.outputs += name + "\n";
  return fingerprint;
}

bool WriteCheckpoint(const std::string& path, const Checkpoint& checkpoint, std::string* error) {
  Archive archive = Archive::ForWriting();
  Checkpoint copy = checkpoint;  // Serialize takes references; the writer does not change them
  SerializeFingerprint(archive, copy.model);
  archive.Field(copy.time);
  archive.Field(copy.next_row);
  std::string names;
  for (const std::string& name : copy.series.names) names += name + "\n";
  archive.Resizable(names);
  std::int64_t columns = static_cast<std::int64_t>(copy.series.columns);
  archive.Field(columns);
  archive.Resizable(copy.series.values);
  archive.Resizable(copy.state);
  std::ofstream out(path, std::ios::binary);
  out << kMagic << archive.bytes() << ChecksumText(archive.bytes());
  if (!out) {
    *error = fmt::format("cannot write the checkpoint `{}`", path);
    return false;
  }
  return true;
}

bool ReadCheckpoint(const std::string& path, Checkpoint* checkpoint, std::string* error) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    *error = fmt::format("cannot read the checkpoint `{}`", path);
    return false;
  }
  std::stringstream content;
  content << in.rdbuf();
  std::string bytes = content.str();
  const std::string magic = kMagic;
  if (!bytes.starts_with(magic)) {
    const std::string version = bytes.substr(0, bytes.find('\n'));
    *error = version.starts_with(kMagicPrefix) && version.size() < 40
                 ? fmt::format(
                       "`{}` is a checkpoint of another format (`{}`); this sled reads "
                       "`{}`: run the scene again to write it",
                       path, version, magic.substr(0, magic.size() - 1))
                 : fmt::format("`{}` is not a sled checkpoint (it does not start with `{}`)", path,
                               magic.substr(0, magic.size() - 1));
    return false;
  }
  const std::string_view rest = std::string_view(bytes).substr(magic.size());
  const std::string payload(rest.substr(0, rest.size() - std::min(rest.size(), kChecksumDigits)));
  if (rest.size() < kChecksumDigits || rest.substr(payload.size()) != ChecksumText(payload)) {
    *error = fmt::format(
        "the checkpoint `{}` is truncated or damaged: its checksum does not match its contents",
        path);
    return false;
  }
  Archive archive = Archive::ForReading(payload);
  SerializeFingerprint(archive, checkpoint->model);
  archive.Field(checkpoint->time);
  archive.Field(checkpoint->next_row);
  std::string names;
  archive.Resizable(names);
  std::int64_t columns = 0;
  archive.Field(columns);
  archive.Resizable(checkpoint->series.values);
  archive.Resizable(checkpoint->state);
  if (!archive.ok() || !archive.at_end() || columns < 1 ||
      checkpoint->series.values.size() % static_cast<std::size_t>(columns) != 0) {
    *error = fmt::format("the checkpoint `{}` is truncated or damaged", path);
    return false;
  }
  checkpoint->series.columns = static_cast<std::size_t>(columns);
  checkpoint->series.names.clear();
  std::istringstream lines(names);
  for (std::string name; std::getline(lines, name);) checkpoint->series.names.push_back(name);
  return true;
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
  data.contacts.Serialize(archive);
  data.belts.Serialize(archive);
  data.airbags.Serialize(archive);
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
