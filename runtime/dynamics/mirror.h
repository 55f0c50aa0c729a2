// Reflection in a plane through the origin with unit normal n, for spatial quantities in the
// (motion: angular, linear; force: moment, force) layout: a vector turns by H = I - 2 n n^T, an
// angular velocity or a moment (a pseudovector) by -H. Mirror symmetry adds the mirror image of
// a left subtree's articulated inertia and bias to its parent, standing for the right twin the
// Model leaves out.
#pragma once

#include "runtime/dynamics/spatial.h"

namespace sled::runtime {

// inertia += M inertia M and bias += M bias, with M = diag(-H, H).
inline void AddMirrorImage(const Vec3& normal, Mat6& inertia, Vec6& bias) {
  const Mat3 H = Mat3::Identity() - 2.0 * normal * normal.transpose();
  const Mat3 A = inertia.topLeftCorner<3, 3>(), B = inertia.topRightCorner<3, 3>(),
             D = inertia.bottomRightCorner<3, 3>();
  inertia.topLeftCorner<3, 3>() += H * A * H;
  inertia.topRightCorner<3, 3>() -= H * B * H;
  inertia.bottomLeftCorner<3, 3>() -= H * B.transpose() * H;
  inertia.bottomRightCorner<3, 3>() += H * D * H;
  const Vec3 moment = bias.head<3>(), force = bias.tail<3>();
  bias.head<3>() -= H * moment;
  bias.tail<3>() += H * force;
}

// The signs that turn a left segment's output into its right twin's: world vectors flip y;
// in the segment's own frame (the twin's frame is the mirror image with y reversed to stay
// right-handed) vectors flip y and pseudovectors flip x and z; yaw and roll change sign.
inline Vec3 MirrorWorldVector(const Vec3& v) { return {v.x(), -v.y(), v.z()}; }
inline Vec3 MirrorFrameVector(const Vec3& v) { return {v.x(), -v.y(), v.z()}; }
inline Vec3 MirrorFramePseudovector(const Vec3& v) { return {-v.x(), v.y(), -v.z()}; }
inline Vec3 MirrorYawPitchRoll(const Vec3& v) { return {-v.x(), v.y(), -v.z()}; }

}  // namespace sled::runtime
