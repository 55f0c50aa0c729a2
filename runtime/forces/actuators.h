// Joint actuators: PID torques about a pin joint's axis that drive its angle towards a target
// angle that is a function of time (ATB's F.10 actuators, INPUT_ROBOTICS and ACTUATOR_TORQUE).
// With theta the pin's angle, theta0(t) the target and e = theta - theta0, the child segment
// gets the torque
//   tau = -kp(theta0) e - kd(theta0) (theta' - theta0') - ki(theta0) E,   E' = e,
// about the pin's axis and its parent the opposite one: positive gains drive the angle towards
// the target. The gains are functions of the target angle; E, the integral of the error, is an
// auxiliary state (Model::nw) integrated with the motion under the error control. The work the
// torques do is counted with the applied loads' (data.applied_power).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "runtime/model/model_types.h"

namespace sled::runtime {

struct Model;
struct Data;

struct ActuatorTable {
  std::vector<std::string> name;
  std::vector<SourcePosition> source;
  std::vector<std::int32_t> segment;        // the pin joint's child segment
  std::vector<Vec3> axis;                   // the pin's axis in the parent's frame, unit
  std::vector<std::int32_t> target;         // time -> angle (rad), into Model::functions
  std::vector<std::int32_t> proportional;   // target angle -> torque per rad
  std::vector<std::int32_t> derivative;     // target angle -> torque per rad/s; -1: none
  std::vector<std::int32_t> integral;       // target angle -> torque per rad*s; -1: none
  std::vector<std::int32_t> state_address;  // E in w; -1 without an integral gain
  std::size_t size() const { return name.size(); }
};

// The torque of actuator k at the state in data (after the kinematics); sets its integral
// state's rate in data.wdot.
double ActuatorTorque(const Model& model, Data& data, std::size_t k);

// Adds every actuator's torque to its pin's child and, opposite, to its parent (data.external,
// data.applied_power), and the rates of their integral states.
void AddActuatorTorques(const Model& model, Data& data);

}  // namespace sled::runtime
