// Prescribed vehicle motion: pose, velocity and acceleration of a vehicle frame at time t, from
// its pulse (half-sine, trapezoid, tabulated single-axis or six-degree-of-freedom). A vehicle
// that only translates is integrated in closed form, so its path has no integration error; one
// that turns has its path tabulated once (TabulateVehiclePath) and continued from the sample
// before t by one fourth-order step.
#pragma once

#include <vector>

#include "runtime/model/model.h"

namespace sled::runtime {

struct VehicleState {
  Vec3 position = Vec3::Zero();
  Mat3 rotation = Mat3::Identity();
  Vec3 velocity = Vec3::Zero();
  Vec3 acceleration = Vec3::Zero();
  Vec3 angular_velocity = Vec3::Zero();      // world frame
  Vec3 angular_acceleration = Vec3::Zero();  // world frame
};

VehicleState VehicleAt(const Model& model, std::size_t vehicle, double t);

// The path of a vehicle that turns (a six-degree-of-freedom table, or an initial angular
// velocity in world axes), tabulated by fourth-order steps of at most 0.1 ms that land on every
// kink of the accelerations; empty for a vehicle that only translates (closed form, exact).
std::vector<VehiclePathSample> TabulateVehiclePath(const VehicleMotion& motion,
                                                   const Mat3& orientation,
                                                   const Vec3& angular_velocity);

// Fills motion.row_gain: the velocity and displacement a tabulated pulse's or six-degree-of-
// freedom table's linear accelerations have given by each row (empty for the other kinds). Once,
// when the Model is made, in one pass over the rows; VehicleAt then finds the row before a time
// by binary search. VehicleAt refuses (std::logic_error) a table whose rows were not integrated.
void IntegrateMotionRows(VehicleMotion& motion);

// Times (from the motion's start) where the accelerations have kinks or jumps: the pulse's
// start and corners, a table's rows. The turning path is tabulated on each of them, and the
// integrators stop on them (runtime/run/input_discontinuities.h).
std::vector<double> MotionBreakpoints(const VehicleMotion& motion);

// The acceleration of a pulse alone (along its axis, before the vehicle's orientation).
double PulseAcceleration(const VehicleMotion& motion, double t);

}  // namespace sled::runtime
