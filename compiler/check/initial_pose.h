// The pose of every frame at the start of the run, from the joint tree with its initial joint
// angles, the initial conditions, the vehicles' positions and the fixed-point constraints that
// hold roots at a point of the ground or a vehicle: what the lints need to find buried
// ellipsoids, and what the lowering places the scene by.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "compiler/check/checked_scenario.h"
#include "runtime/model/model_types.h"

namespace sled::compiler {

using Mat3 = std::array<Vec3, 3>;  // rows

struct Pose {
  Vec3 position{};
  Mat3 rotation{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};  // frame to world
};

struct InitialPoses {
  std::vector<Pose> segments;
  std::vector<Pose> vehicles;
  // Each vehicle's velocity and angular velocity at the start, in the ground frame.
  std::vector<Vec3> vehicle_velocities;
  std::vector<Vec3> vehicle_angular_velocities;
  Pose Of(const FrameRef& frame) const;
};

// The weld or fixed-point constraint that holds root segment `segment` at a point of the ground
// or a vehicle (its joint to that base, locked for a weld; the lowering solves it in the tree),
// or -1. A weld comes first.
int HoldingConstraintOf(const CheckedScenario& scenario, int segment);

// Yaw about z, then pitch about y, then roll about x (the ATB order).
Mat3 RotationFromYawPitchRoll(const Vec3& yaw_pitch_roll);

// The checker's arrays as the runtime's Eigen types.
inline runtime::Vec3 ToEigen(const Vec3& v) { return {v[0], v[1], v[2]}; }
inline runtime::Mat3 ToEigen(const Mat3& rows) {
  runtime::Mat3 m;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) m(i, j) = rows[i][j];
  }
  return m;
}
inline runtime::Mat3 RotationMatrix(const Vec3& yaw_pitch_roll) {
  return ToEigen(RotationFromYawPitchRoll(yaw_pitch_roll));
}

InitialPoses ComputeInitialPoses(const CheckedScenario& scenario);

// Where a root held by a fixed-point constraint (HoldingConstraintOf) is at the start: its
// centre of mass as the held point and its orientation in `poses` put it; none for other
// segments.
std::optional<Vec3> HeldRootPosition(const CheckedScenario& scenario, const InitialPoses& poses,
                                     int root);
// The held point itself, in the ground frame at the start.
std::optional<Vec3> HeldPoint(const CheckedScenario& scenario, const InitialPoses& poses, int root);
// The velocity of that centre of mass when the root turns at `angular_velocity` (ground frame)
// about the held point, which moves with its vehicle.
std::optional<Vec3> HeldRootVelocity(const CheckedScenario& scenario, const InitialPoses& poses,
                                     int root, const Vec3& angular_velocity);

// How far the contact's first ellipsoid reaches into its second surface at the start [m], by the
// runtime's own contact geometry (runtime/contact/contact_geometry.h): its deflection where the
// force law applies (an ellipsoid beside a finite plane, whose footprint misses the
// parallelogram, is not in contact); zero or negative when it does not touch.
double InitialPenetration(const CheckedScenario& scenario, const InitialPoses& poses,
                          const Contact& contact);

}  // namespace sled::compiler
