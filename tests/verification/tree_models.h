// Body trees described once and built twice: as a sled runtime::Model and as MuJoCo MJCF text,
// so the MuJoCo comparison test (mujoco_test.cpp) and the dynamics benchmark
// (tests/bench/dynamics_bench.cpp) run the same bodies. Also the state and result maps between
// the two programs' coordinates.
//
// Conventions that differ between sled and MuJoCo (2.2.2) and are mapped here:
// - Free root. sled: q = (position, quaternion w-first), v = (angular velocity in the segment
//   frame, velocity of the centre of mass in the segment frame), vdot = the spatial acceleration
//   in segment coordinates. MuJoCo: qpos the same, qvel = (linear velocity in the world frame,
//   angular velocity in the body frame), qacc = time derivatives of those.
// - Ball joint. Both: a quaternion (w-first) and the relative angular velocity in the child
//   frame. sled's quaternion turns the child joint frame into the parent joint frame; MuJoCo's
//   acts in the child body frame after the body's fixed quat, so the two differ by a conjugation
//   with the child joint frame.
// - Pin joint. sled: an angle about `axis` of the joint frame; MuJoCo: a hinge about the same
//   axis in the child body frame. The same angle.
// The MuJoCo body frame is placed at the sled segment frame (the centre of mass): every
// <inertial> has pos="0 0 0".
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <mujoco/mujoco.h>

#include "runtime/model/data.h"

namespace sled::verification {

struct TreeSegment {
  std::string name;
  int parent = -1;  // index of the parent in BodyTree::segments; -1 only for the free root
  runtime::JointKind joint = runtime::JointKind::kFree;  // kFree, kBall or kPin
  double mass = 1.0;
  runtime::Mat3 inertia = runtime::Mat3::Identity();      // about the centre of mass, segment frame
  runtime::Vec3 point_in_parent = runtime::Vec3::Zero();  // joint point, parent segment frame
  runtime::Vec3 point_in_child = runtime::Vec3::Zero();   // joint point, this segment's frame
  runtime::Mat3 frame_in_parent = runtime::Mat3::Identity();  // joint frame axes (columns)
  runtime::Mat3 frame_in_child = runtime::Mat3::Identity();
  runtime::Vec3 axis = runtime::Vec3::UnitY();  // pin: unit axis in the joint frame
};

struct BodyTree {
  std::string name;
  std::vector<TreeSegment> segments;  // a parent before its children; segment 0 is a free root
  runtime::Vec3 root_position = runtime::Vec3::Zero();  // initial pose of the root
  runtime::Vec3 gravity{0, 0, -9.80665};
};

// The CVS/ATB occupant of the issue: 15 segments, 40 degrees of freedom (a free pelvis; ball
// joints at the lumbar, thoracic, lower and upper neck, shoulders, hips and ankles; pins at the
// elbows and knees), a 78 kg man standing, segment frames at the centres of mass (x forward,
// y left, z up). The left elbow and the shoulders have turned joint frames.
BodyTree CvsBody();

// A chain of `n` >= 1 segments: a free root, then ball, ball, pin, ball, ball, pin, ...; turned
// joint frames, products of inertia and uneven masses, all from a fixed seed.
BodyTree Chain(int n);

runtime::Model BuildModel(const BodyTree& tree);
std::string BuildMjcf(const BodyTree& tree);

// A random state from a fixed seed: the root anywhere within 1 m, any unit quaternion; ball
// joints turned up to 1 rad about a random axis; pins within +-1 rad; every velocity within
// +-2 (rad/s or m/s).
void SetRandomState(const runtime::Model& model, std::uint64_t seed, runtime::Data& data);

struct MujocoDeleter {
  void operator()(mjModel* m) const { mj_deleteModel(m); }
  void operator()(mjData* d) const { mj_deleteData(d); }
};
using MujocoModelPtr = std::unique_ptr<mjModel, MujocoDeleter>;
using MujocoDataPtr = std::unique_ptr<mjData, MujocoDeleter>;

// Compiles MJCF text (from memory); null with `error` set when MuJoCo rejects it.
MujocoModelPtr LoadMjcf(const std::string& xml, std::string* error);

// Where each sled segment lives in the MuJoCo model (found by name).
struct MujocoMap {
  std::vector<int> body;
  std::vector<int> qpos_address;
  std::vector<int> dof_address;
};
MujocoMap MapToMujoco(const BodyTree& tree, const mjModel* m);

// Writes sled's q and v (data.q, data.v) into d->qpos and d->qvel.
void CopyStateToMujoco(const BodyTree& tree, const runtime::Model& model, const runtime::Data& data,
                       const MujocoMap& map, const mjModel* m, mjData* d);

// sled's generalized accelerations (after Forward) in MuJoCo's qacc coordinates (m->nv values).
std::vector<double> AccelerationsAsMujocoQacc(const runtime::Model& model,
                                              const runtime::Data& data, const MujocoMap& map,
                                              const mjModel* m);

// sled's joint wrench on `segment` (after Forward) as MuJoCo's cfrc_int: [moment; force] in world
// axes, the moment about the centre of mass of the whole body (subtree_com of the root).
runtime::Vec6 JointWrenchAsMujocoCfrcInt(const runtime::Data& data, const MujocoMap& map,
                                         const mjModel* m, const mjData* d, std::size_t segment);

}  // namespace sled::verification
