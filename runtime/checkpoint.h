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

#include "runtime/archive.h"
#include "runtime/data.h"
#include "runtime/run.h"

namespace sled::runtime {

// What must match for a checkpoint to continue a Model.
struct ModelFingerprint {
  std::uint64_t physics = 0;  // the Model without run settings, outputs and source positions
  std::string settings;       // integrator, tolerances, step limits, start time, output step
  std::string outputs;        // the channel names, one per line
};
ModelFingerprint FingerprintOf(const Model& model);

struct Checkpoint {
  ModelFingerprint model;
  double time = 0.0;
  std::int64_t next_row = 0;  // index of the next output row
  TimeSeries series;          // the rows up to `time`
  std::string state;          // the integrator's and the Data's archive (SerializeRunState)
};

bool WriteCheckpoint(const std::string& path, const Checkpoint& checkpoint, std::string* error);
bool ReadCheckpoint(const std::string& path, Checkpoint* checkpoint, std::string* error);

// Why the checkpoint cannot continue the Model with this fingerprint; empty when it can.
std::string CheckpointMismatch(const Checkpoint& checkpoint, const ModelFingerprint& model);

// Writes or reads what a Data carries between output rows.
void SerializeData(Archive& archive, Data& data);

}  // namespace sled::runtime
