#include "runtime/dynamics/frame_motion.h"

namespace sled::runtime {

FrameMotion MotionOf(const Data& data, const FrameRef& frame) {
  FrameMotion motion;
  const auto i = static_cast<std::size_t>(frame.index);
  switch (frame.kind) {
    case FrameRef::Kind::kSegment:
      motion.origin = data.position[i];
      motion.rotation = data.rotation[i];
      motion.velocity = motion.rotation * data.velocity[i].tail<3>();
      motion.angular_velocity = motion.rotation * data.velocity[i].head<3>();
      break;
    case FrameRef::Kind::kVehicle: {
      const VehicleState& vehicle = data.vehicle[i];
      motion.origin = vehicle.position;
      motion.rotation = vehicle.rotation;
      motion.velocity = vehicle.velocity;
      motion.angular_velocity = vehicle.angular_velocity;
      break;
    }
    case FrameRef::Kind::kGround:
      break;
  }
  return motion;
}

FrameMotion MotionWithAcceleration(const Data& data, const FrameRef& frame) {
  FrameMotion motion = MotionOf(data, frame);
  const auto i = static_cast<std::size_t>(frame.index);
  switch (frame.kind) {
    case FrameRef::Kind::kSegment: {
      // Spatial to classical: the origin's acceleration is a + w x v (segment coordinates).
      const Vec3 w = data.velocity[i].head<3>();
      const Vec3 v = data.velocity[i].tail<3>();
      motion.acceleration = motion.rotation * (data.acceleration[i].tail<3>() + w.cross(v));
      motion.angular_acceleration = motion.rotation * data.acceleration[i].head<3>();
      break;
    }
    case FrameRef::Kind::kVehicle:
      motion.acceleration = data.vehicle[i].acceleration;
      motion.angular_acceleration = data.vehicle[i].angular_acceleration;
      break;
    case FrameRef::Kind::kGround:
      break;
  }
  return motion;
}

}  // namespace sled::runtime
