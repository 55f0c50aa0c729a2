// Joint kinematics: for each joint kind, the rotation its coordinates describe, its motion
// subspace S (the segment's spatial velocity per unit joint velocity, in the segment frame),
// the velocity-product term Sdot*qdot, and the position derivative qdot from the velocities.
#pragma once

#include <span>

#include "runtime/dynamics/spatial.h"
#include "runtime/model/model.h"

namespace sled::runtime {

// Precession about z, nutation about the new y, spin about the new x (z-y-x): the neutral
// posture (all zero) is far from the singular nutation of +-90 degrees.
Mat3 EulerRotation(double precession, double nutation, double spin);
// Columns: the joint-frame angular velocity per unit precession, nutation and spin rate.
Mat3 EulerRates(double nutation, double spin);

Eigen::Quaterniond QuaternionAt(std::span<const double> q, std::size_t address);

struct JointMotion {
  Mat3 rotation = Mat3::Identity();  // R_J: child joint frame to parent joint frame
  Vec3 translation = Vec3::Zero();   // slip: offset in the parent joint frame
  MotionSubspace subspace;           // S, active axes only
  Vec6 bias = Vec6::Zero();          // Sdot * qdot (active axes)
};

// The motion of the joint above segment `s` for the current q, v and lock mask.
void ComputeJointMotion(const Model& model, std::size_t s, std::span<const double> q,
                        std::span<const double> v, std::uint8_t locked, JointMotion& motion);

// ComputeJointMotion without the subspace: rotation, translation and bias (motion.subspace is
// left as it is). The kinematics pass keeps each subspace from call to call and rebuilds only
// those that change (see SubspaceDependsOnPosition).
void ComputeJointPose(const Model& model, std::size_t s, std::span<const double> q,
                      std::span<const double> v, std::uint8_t locked, JointMotion& motion);

// S of the joint above segment `s`: one column per active axis (ActiveAxes), in order.
void ComputeJointSubspace(const Model& model, std::size_t s, std::span<const double> q,
                          std::uint8_t locked, MotionSubspace& subspace);

// True when S changes with q (Euler joints, whose rate axes turn); otherwise S is constant in
// the segment frame for a given lock mask (free, ball, pin and slip joints).
bool SubspaceDependsOnPosition(JointKind kind);

// Indices (into the joint's velocity coordinates) of the active axes, in order; `count` is set.
int ActiveAxes(const Model& model, std::size_t s, std::uint8_t locked, int axes[6]);

// qdot for the whole state (quaternion rates for free and ball joints; locked axes stay put).
void PositionDerivative(const Model& model, std::span<const double> q, std::span<const double> v,
                        std::span<const std::uint8_t> locked, std::span<double> qdot);

}  // namespace sled::runtime
