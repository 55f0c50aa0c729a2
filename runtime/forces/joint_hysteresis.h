// Joint torque functions that unload otherwise than they load: a joint's `energy_loss` (the
// compiler gives each of its torque functions that energy loss) or a torque function's own
// unloading attributes. Each such joint axis follows the force-deflection model of
// runtime/forces/force_deflection.h, the angle's size as the deflection, with one loading history
// for each side of the angle (a ball joint's flexure angle is a size: one side), so a joint bent
// forward and released unloads along a curve that returns 1 - energy_loss of its spring energy,
// and bending it the other way loads afresh.
//
// The histories change only at events (MultibodySystem's kJointTurn): while an axis loads beyond
// its largest angle on that side, the event function is the angle's rate away from zero, and
// where it falls through zero the angle there becomes the largest. Checkpoints carry them.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "runtime/forces/force_deflection.h"

namespace sled::runtime {

struct Model;
struct Data;

struct JointHistories {
  // Fixed by SizeJointHistories: per segment, the history of each of its joint's three torque
  // functions (Model::joint_function), -1 for one that is elastic or absent; per history, its
  // segment and axis.
  std::vector<std::array<std::int32_t, 3>> of_axis;
  std::vector<std::uint32_t> segment;
  std::vector<std::uint8_t> axis;
  // Changed only at events: the loading history of each side of the angle (positive, negative).
  std::vector<LoadingHistory> positive;
  std::vector<LoadingHistory> negative;

  std::size_t size() const { return segment.size(); }

  template <class Archive>
  void Serialize(Archive& a) {
    a.Field(positive);
    a.Field(negative);
  }
};

// Sizes the histories for the Model's hysteretic joint axes, all unloaded.
void SizeJointHistories(const Model& model, JointHistories& histories);

// The start: each hysteretic axis has loaded to its initial angle.
void SetUpJointHistories(const Model& model, Data& data);

// The torque the joint above segment `s` applies about its axis `k` (0..2, as
// Model::joint_function) at `angle`, against it: RestoringTorque (runtime/forces/functions.h), or
// along the axis's loading history when it has one.
double JointSpringTorque(const Model& model, const Data& data, std::size_t s, std::size_t k,
                         double angle);

// The angles of the axes of the joint above segment `s` (as Model::joint_function, 0 for an
// axis it does not have) as their torque functions read them (a ball joint's flexure: its size;
// a slip joint's travel).
std::array<double, 3> JointAxisAngles(const Model& model, const Data& data, std::size_t s);

// The event function of history h: the rate of the angle's size while it loads beyond its
// largest so far on its side, 1 otherwise (a locked axis cannot turn).
double JointTurnFunction(const Model& model, const Data& data, std::size_t h);

// At history h's event: the angle's size there becomes the largest on its side.
void TurnJointHistory(const Model& model, Data& data, std::size_t h);

}  // namespace sled::runtime
