// The pose of every frame at the start of the run, from the joint tree with joint angles at
// zero, the initial conditions and the vehicles' positions: what the lints need to find buried
// ellipsoids. (The runtime computes its own, exact initial state.)
#pragma once

#include <array>
#include <vector>

#include "compiler/check/checked_scenario.h"

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

InitialPoses ComputeInitialPoses(const CheckedScenario& scenario);

// How far the contact's first ellipsoid reaches into its second surface at the start [m]; zero
// or negative when it does not (for ellipsoid pairs: positive when a centre lies in the other).
double InitialPenetration(const CheckedScenario& scenario, const InitialPoses& poses,
                          const Contact& contact);

}  // namespace sled::compiler
