// Motion relative to a frame: the `relative_to` outputs of the language (ATB's KREF on the H
// cards), and for anything else that measures one frame from another (load cases, criteria in a
// vehicle's axes). A frame is a segment, a vehicle or the ground (FrameRef); quantities relative
// to it are expressed in its axes and differentiated as an observer fixed in it sees them:
//
//   position      r = R_F^T (p - o_F)
//   velocity      dr/dt seen from F = R_F^T (v_p - v_F - w_F x (p - o_F))
//   acceleration  d2r/dt2 seen from F = R_F^T (a_p - a_F - al_F x d - w_F x (w_F x d) - 2 w_F x u)
//                 with d = p - o_F and u = v_p - v_F - w_F x d
//
// (p, v_p, a_p the world position, velocity and acceleration of the point; o_F, v_F, a_F, w_F,
// al_F those of the frame's origin and its angular velocity and acceleration). Accelerations are
// kinematic: gravity is a force in sled, so a point at rest in a frame at rest has none.
#pragma once

#include <cstdint>

#include "runtime/dynamics/frame_motion.h"

namespace sled::runtime {

// How a segment output is taken in its frame (Model::output_relative).
enum OutputFrame : std::uint8_t {
  kAbsolute = 0,     // as docs/runtime.md says
  kRelativeTo = 1,   // `relative_to`: seen from the frame, in its axes
  kExpressedIn = 2,  // `expressed_in`: relative to the ground, in the frame's axes
};

// The world pose, velocities and accelerations of a segment, a vehicle or the ground, after the
// accelerations are computed. `mirrored`: the frame is the right twin of segment frame.index,
// which mirror symmetry leaves out of the Model: its left twin's motion reflected in the plane
// y = model.mirror_plane_y (its axes the mirror image with y reversed, runtime/dynamics/mirror.h).
FrameMotion WorldMotion(const Model& model, const Data& data, const FrameRef& frame,
                        bool mirrored = false);

// A point fixed in `body` (at `point` in its axes) seen from `frame`, in the frame's axes.
struct RelativePoint {
  Vec3 position = Vec3::Zero();
  Vec3 velocity = Vec3::Zero();
  Vec3 acceleration = Vec3::Zero();
};
RelativePoint PointRelativeTo(const FrameMotion& body, const Vec3& point, const FrameMotion& frame);

// `body`'s orientation relative to `frame` (the rotation from body axes to frame axes, R_F^T R_B),
// its angular velocity relative to the frame (w_B - w_F in the frame's axes) and that vector's rate
// seen from the frame, R_F^T (al_B - al_F - w_F x w_B).
struct RelativeRotation {
  Mat3 rotation = Mat3::Identity();
  Vec3 angular_velocity = Vec3::Zero();
  Vec3 angular_acceleration = Vec3::Zero();
};
RelativeRotation RotationRelativeTo(const FrameMotion& body, const FrameMotion& frame);

// Yaw about z, then pitch about the new y, then roll about the new x (the input convention of
// orientations) of a rotation matrix.
Vec3 YawPitchRoll(const Mat3& rotation);

}  // namespace sled::runtime
