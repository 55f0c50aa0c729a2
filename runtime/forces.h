// The force elements: gravity, joint characteristics (torque functions, viscous and Coulomb
// damping), spring–dampers / tension elements and contacts (runtime/contact/). They write
// data.external (wrenches at each centre of mass, segment frame) and data.generalized_force
// (joint torques).
#pragma once

#include "runtime/data.h"

namespace sled::runtime {

void ComputeForces(const Model& model, Data& data);

// The flexure and twist angles of a ball joint's quaternion about the joint's z axis (swing–twist
// decomposition), with the unit flexure axis in the parent joint frame.
struct SwingTwist {
  double flexure = 0.0;
  Vec3 flexure_axis = Vec3::UnitX();
  double twist = 0.0;
};
SwingTwist DecomposeSwingTwist(const Eigen::Quaterniond& rotation);

// Adds a force (world frame) acting at a world point of a segment to the segment's wrench in
// data.external (at its centre of mass, in its frame).
void AddPointForce(Data& data, std::size_t segment, const Vec3& point_world,
                   const Vec3& force_world);

// World position and velocity of a point fixed in a frame.
struct PointState {
  Vec3 position;
  Vec3 velocity;
};

// Adds a force (world) applied at a point (world) to a segment's wrench at its centre of mass.
void AddPointForce(Data& data, std::size_t segment, const Vec3& point_world,
                   const Vec3& force_world);

PointState PointInFrame(const Data& data, const FrameRef& frame, const Vec3& point);

}  // namespace sled::runtime
