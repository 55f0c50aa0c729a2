// Prescribed vehicle motion: pose, velocity and acceleration of a vehicle frame at time t, from
// its pulse (half-sine, trapezoid, tabulated single-axis or six-degree-of-freedom), integrated
// in closed form so the vehicle's path has no integration error.
#pragma once

#include "runtime/model.h"

namespace sled::runtime {

struct VehicleState {
  Vec3 position = Vec3::Zero();
  Mat3 rotation = Mat3::Identity();
  Vec3 velocity = Vec3::Zero();
  Vec3 acceleration = Vec3::Zero();
  Vec3 angular_velocity = Vec3::Zero();  // world frame
};

VehicleState VehicleAt(const Model& model, std::size_t vehicle, double t);

// The acceleration of a pulse alone (along its axis, before the vehicle's orientation).
double PulseAcceleration(const VehicleMotion& motion, double t);

}  // namespace sled::runtime
