#include "runtime/run/relative_motion.h"

#include <algorithm>
#include <cmath>

namespace sled::runtime {

FrameMotion WorldMotion(const Model& model, const Data& data, const FrameRef& frame,
                        bool mirrored) {
  FrameMotion motion = MotionWithAcceleration(data, frame);
  if (!mirrored) return motion;
  // Reflection H = diag(1, -1, 1) in the plane y = mirror_plane_y: points and vectors turn by H,
  // angular velocities (pseudovectors) by -H, and the axes by R -> H R H.
  const Mat3 H = Vec3(1, -1, 1).asDiagonal();
  motion.origin.y() = 2 * model.mirror_plane_y - motion.origin.y();
  motion.rotation = H * motion.rotation * H;
  motion.velocity = H * motion.velocity;
  motion.acceleration = H * motion.acceleration;
  motion.angular_velocity = -(H * motion.angular_velocity);
  motion.angular_acceleration = -(H * motion.angular_acceleration);
  return motion;
}

RelativePoint PointRelativeTo(const FrameMotion& body, const Vec3& point,
                              const FrameMotion& frame) {
  const Vec3 arm = body.rotation * point;  // from the body's origin, world axes
  const Vec3 p = body.origin + arm;
  const Vec3 v = body.velocity + body.angular_velocity.cross(arm);
  const Vec3 a = body.acceleration + body.angular_acceleration.cross(arm) +
                 body.angular_velocity.cross(body.angular_velocity.cross(arm));
  const Vec3& w = frame.angular_velocity;
  const Vec3 d = p - frame.origin;
  const Vec3 u = v - frame.velocity - w.cross(d);
  const Vec3 a_rel = a - frame.acceleration - frame.angular_acceleration.cross(d) -
                     w.cross(w.cross(d)) - 2 * w.cross(u);
  const Mat3 to_frame = frame.rotation.transpose();
  return {to_frame * d, to_frame * u, to_frame * a_rel};
}

RelativeRotation RotationRelativeTo(const FrameMotion& body, const FrameMotion& frame) {
  const Mat3 to_frame = frame.rotation.transpose();
  return {to_frame * body.rotation, to_frame * (body.angular_velocity - frame.angular_velocity),
          to_frame * (body.angular_acceleration - frame.angular_acceleration -
                      frame.angular_velocity.cross(body.angular_velocity))};
}

Vec3 YawPitchRoll(const Mat3& R) {
  const double pitch = std::asin(std::clamp(-R(2, 0), -1.0, 1.0));
  return {std::atan2(R(1, 0), R(0, 0)), pitch, std::atan2(R(2, 1), R(2, 2))};
}

}  // namespace sled::runtime
