// The small types the Model and its parts share: vectors, frames and source positions.
#pragma once

#include <cstdint>
#include <string>

#include <Eigen/Core>

namespace sled::runtime {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;

// Where a point or frame is attached: the ground (inertial), a vehicle (prescribed motion) or a
// segment (integrated).
struct FrameRef {
  enum class Kind : std::uint8_t { kGround, kVehicle, kSegment };
  Kind kind = Kind::kGround;
  std::int32_t index = -1;
};

// A line back to the scenario, so runtime messages can name it.
struct SourcePosition {
  std::string file;
  std::uint32_t line = 0;
  std::uint32_t column = 0;
};

}  // namespace sled::runtime
