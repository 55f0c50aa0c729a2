// Checkpoint files (`sled run --checkpoint-every`, `--resume`): the format, reading and writing,
// and the sink that writes a run's checkpoints into a folder. What a checkpoint holds and how it
// is matched to a Model is the runtime's (runtime/run/checkpoint.h).
#pragma once

#include <string>

#include "runtime/run/checkpoint.h"

namespace sled::output {

// `checkpoint_<time>s.bin`, with the time to the microsecond.
std::string CheckpointFileName(double time);

// Both return false with `error` set when the file cannot be written or read, or is not a whole
// checkpoint of this format (its checksum says when it was damaged).
bool WriteCheckpoint(const std::string& path, const runtime::Checkpoint& checkpoint,
                     std::string* error);
bool ReadCheckpoint(const std::string& path, runtime::Checkpoint* checkpoint, std::string* error);

// Writes each checkpoint of a run into `directory`, named by CheckpointFileName.
class CheckpointFolder : public runtime::CheckpointSink {
 public:
  explicit CheckpointFolder(std::string directory) : directory_(std::move(directory)) {}
  bool Keep(const runtime::Checkpoint& checkpoint, std::string* where, std::string* error) override;

 private:
  std::string directory_;
};

}  // namespace sled::output
