// Applied loads: forces and torques that are functions of time (ATB's applied forces and
// torques), on a segment, or across a joint, where the joint's child gets the load and its
// parent (or the frame a root hangs from) the opposite one. A segment's force acts at a point of
// the segment along a direction fixed in the ground or turning with the segment, its torque
// about an axis fixed either way; a joint's torque acts about its pin axis (pin joints) or an
// axis fixed in the parent segment (ball and Euler joints), a slip joint's force along its
// axis at the joint point. The work the loads do on the segments is a term of its own in the
// energy balance.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "runtime/model/model_types.h"

namespace sled::runtime {

struct Model;
struct Data;

struct LoadTable {
  enum class Kind : std::uint8_t { kSegment, kJointTorque, kJointForce };
  std::vector<std::string> name;
  std::vector<SourcePosition> source;
  std::vector<Kind> kind;
  std::vector<std::int32_t> segment;     // the segment loaded: for a joint, its child
  std::vector<std::int32_t> force;       // time -> force, into Model::functions; -1: none
  std::vector<std::int32_t> torque;      // time -> torque; -1: none
  std::vector<Vec3> direction;           // segment loads: unit, in the ground or the segment
  std::vector<Vec3> axis;                // unit; joint loads: in the parent's frame
  std::vector<Vec3> point;               // segment loads: where the force acts, segment frame
  std::vector<std::uint8_t> in_segment;  // segment loads: direction and axis turn with it
  std::size_t size() const { return name.size(); }
};

// Adds a force at a world point and a torque (world frame) to segment s's data.external, and
// their power into the segment to data.applied_power.
void AddAppliedForce(Data& data, std::size_t s, const Vec3& point_world, const Vec3& force_world,
                     const Vec3& torque_world);

// Adds every load's force and torque at data.time to data.external (segments only: a parent
// frame that is the ground or a vehicle takes the reaction without effect on the run), and their
// power into the segments to data.applied_power (which ComputeForces zeroes). After the
// kinematics.
void AddAppliedLoads(const Model& model, Data& data);

}  // namespace sled::runtime
