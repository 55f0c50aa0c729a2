// Checkpoints, the CVS-III "restart tape": everything a run carries from one output row to the
// next (the integrator's state and memory, the Data's histories, warm starts and lock states,
// the energy account and the rows so far), so `sled run --resume FILE` continues bit for bit as
// the uninterrupted run. A checkpoint names the model it belongs to by fingerprints: a scene
// whose physics or integrator settings changed is refused; one whose end time or output
// requests changed may resume.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "runtime/model/data.h"
#include "runtime/run/archive.h"
#include "runtime/run/time_series.h"

namespace sled::runtime {

// What must match for a checkpoint to continue a Model.
// Each part is made by walking model_fields.h's list, by the fields' roles.
struct ModelFingerprint {
  std::uint64_t physics = 0;  // the fields of role Physics (HashModelFields)
  std::string settings;       // those of role Settings: integrator, tolerances, steps, start
  // Those of role Records (the output requests, criteria and drawn shapes, as DumpModel prints
  // them), then the channel names, one per line: rows before a checkpoint are kept only when
  // all of it is the same.
  std::string outputs;
};
ModelFingerprint FingerprintOf(const Model& model);

struct Checkpoint {
  ModelFingerprint model;
  double time = 0.0;
  std::int64_t next_row = 0;  // index of the next output row
  TimeSeries series;          // the rows up to `time`
  std::string state;          // the integrator's and the Data's archive (SerializeRunState)
};

// Keeps the checkpoints a run takes (runtime::Run calls it at each checkpoint row): a file per
// checkpoint in a folder (output/checkpoint_file.h), memory, a test's counter.
class CheckpointSink {
 public:
  virtual ~CheckpointSink() = default;
  // Keeps `checkpoint`: true with `where` (a file's path) set, or false with `error` set, which
  // stops the run as failed.
  virtual bool Keep(const Checkpoint& checkpoint, std::string* where, std::string* error) = 0;
};

// Why the checkpoint cannot continue the Model with this fingerprint; empty when it can.
std::string CheckpointMismatch(const Checkpoint& checkpoint, const ModelFingerprint& model);

// Writes or reads what a Data carries between output rows.
void SerializeData(Archive& archive, Data& data);

}  // namespace sled::runtime
