// The world pose and motion of a frame (a segment, a vehicle or the ground) at data's current
// kinematics, for the force elements and constraints that act between frames.
#pragma once

#include "runtime/model/data.h"

namespace sled::runtime {

struct FrameMotion {
  Vec3 origin = Vec3::Zero();
  Mat3 rotation = Mat3::Identity();  // frame to world
  Vec3 velocity = Vec3::Zero();      // of the origin
  Vec3 angular_velocity = Vec3::Zero();
  // Classical acceleration of the origin, and angular acceleration: only from
  // MotionWithAcceleration.
  Vec3 acceleration = Vec3::Zero();
  Vec3 angular_acceleration = Vec3::Zero();
};

// Pose and velocities (vehicles from data.vehicle).
FrameMotion MotionOf(const Data& data, const FrameRef& frame);

// Also the accelerations, from data.acceleration (after the accelerations are computed).
FrameMotion MotionWithAcceleration(const Data& data, const FrameRef& frame);

// The velocity of the frame-fixed point at the world position `point`.
inline Vec3 VelocityAt(const FrameMotion& frame, const Vec3& point) {
  return frame.velocity + frame.angular_velocity.cross(point - frame.origin);
}

}  // namespace sled::runtime
