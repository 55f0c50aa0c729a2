// The pose of every frame at the start of the run, from the joint tree with joint angles at
// zero, the initial conditions and the vehicles' positions: what the lints need to find buried
// ellipsoids. (The runtime computes its own, exact initial state.)
#pragma once

#include <array>
#include <vector>

#include "compiler/check/checked_scenario.h"
#include "runtime/model_types.h"

namespace sled::compiler {

using Mat3 = std::array<Vec3, 3>;  // rows

struct Pose {
  Vec3 position{};
  Mat3 rotation{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};  // frame to world
};

struct InitialPoses {
  std::vector<Pose> segments;
  std::vector<Pose> vehicles;
  Pose Of(const FrameRef& frame) const;
};

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

// How far the contact's first ellipsoid reaches into its second surface at the start [m], by the
// runtime's own contact geometry (runtime/contact/contact_geometry.h): its deflection where the
// force law applies (an ellipsoid beside a finite plane, whose footprint misses the
// parallelogram, is not in contact); zero or negative when it does not touch.
double InitialPenetration(const CheckedScenario& scenario, const InitialPoses& poses,
                          const Contact& contact);

}  // namespace sled::compiler
