// The force elements: gravity, joint characteristics (torque functions, viscous and Coulomb
// damping), spring–dampers / tension elements and contacts (runtime/contact/). They write
// data.external (wrenches at each centre of mass, segment frame) and data.generalized_force
// (joint torques).
#pragma once

#include "runtime/model/data.h"

namespace sled::runtime {

// Every load at data's kinematics: ComputeJointTorques, then ComputeElementForces.
void ComputeForces(const Model& model, Data& data);

// The loads of everything but the joints' characteristics (gravity, contacts, springs, belts,
// airbags, applied loads, fluids) into data.external (and the elements' own state: contact
// deflections, belt tensions); none of them reads data.generalized_force.
void ComputeElementForces(const Model& model, Data& data);

// The joint characteristics alone (torque functions, viscous and Coulomb damping) into
// data.generalized_force, which it zeroes first: functions of each joint's own q and v only.
void ComputeJointTorques(const Model& model, Data& data);

// The flexure and twist angles of a ball joint's quaternion about the joint's z axis (swing–twist
// decomposition), with the unit flexure axis in the parent joint frame.
struct SwingTwist {
  double flexure = 0.0;
  Vec3 flexure_axis = Vec3::UnitX();
  double twist = 0.0;
};
SwingTwist DecomposeSwingTwist(const Eigen::Quaterniond& rotation);

// World position and velocity of a point fixed in a frame.
struct PointState {
  Vec3 position;
  Vec3 velocity;
};

// Adds a force (world) applied at a point (world) to a segment's wrench at its centre of mass
// (data.external, segment frame).
void AddPointForce(Data& data, std::size_t segment, const Vec3& point_world,
                   const Vec3& force_world);

// A force element's force on one of the frames it connects: on a segment, AddPointForce; on a
// vehicle, its power (force . velocity of the vehicle point) goes into data.vehicle_power, times
// `weight` (the MirrorWeight of the segment the element acts on: 2 when it stands for its
// mirror image too), for the energy balance; the ground does no work.
void AddFrameForce(Data& data, const FrameRef& frame, const Vec3& point_world,
                   const Vec3& force_world, double weight = 1.0);

PointState PointInFrame(const Data& data, const FrameRef& frame, const Vec3& point);

}  // namespace sled::runtime
