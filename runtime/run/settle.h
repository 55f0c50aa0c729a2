// Settling: before the run, the scene comes to rest under gravity in its seat and belts. A damped
// pre-simulation (the ATB/CVS-IV equilibrium positioning done dynamically): the vehicles are held
// at their pose at the start of the run, every velocity is damped at a mass-proportional rate
// (generalized force -c M v, which only takes energy out), and the convergence test is checked
// every check interval: every centre of mass slower than the velocity tolerance and accelerating
// (undamped, from the forces alone) by less than that tolerance per check interval, every segment
// turning slower than the angular tolerance and gaining less than it per check interval, and no
// contact, belt or spring force changed by more than the force tolerance (a fraction of the
// largest of them) since the last check. The accelerations are what make it an equilibrium: a
// body can pass a turning point of an oscillation slowly, never with its forces balanced. The run
// then starts from the settled positions, lock states and load histories, with the initial
// velocities the scene gives (a body's rigid motion, re-expressed in its settled orientation).
#pragma once

#include <string>

#include "runtime/model/data.h"

namespace sled::runtime {

struct SettleSummary {
  bool settled = false;    // a settling pre-simulation ran
  bool converged = false;  // and its convergence test held
  double time = 0.0;       // simulated time it took [s]
  long steps = 0;
  long evaluations = 0;
  // The convergence test's measures at its last check.
  double largest_velocity = 0.0;              // [m/s], of a centre of mass
  std::string fastest_segment;                // the segment that moves fastest
  double largest_angular_velocity = 0.0;      // [rad/s]
  double largest_acceleration = 0.0;          // [m/s^2], of a centre of mass, without damping
  double largest_angular_acceleration = 0.0;  // [rad/s^2], without damping
  double largest_force_change = 0.0;          // over the last check interval, of largest_force
  double largest_force = 0.0;                 // [N], the largest contact, belt or spring force
  std::string failure;                        // why the pre-simulation stopped early, if it did
};

// Settles data (made from model, at its initial state) when model.settle.duration > 0: on
// return data holds the state the run starts from. A summary with converged == false leaves
// data as the pre-simulation ended; the caller fails the run.
SettleSummary Settle(const Model& model, Data& data);

}  // namespace sled::runtime
