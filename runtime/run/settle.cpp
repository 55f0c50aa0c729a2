#include "runtime/run/settle.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <fmt/format.h>

#include "runtime/dynamics/joint.h"
#include "runtime/dynamics/vehicle.h"
#include "runtime/integrate/make_integrator.h"
#include "runtime/run/run.h"
#include "runtime/run/system.h"

namespace sled::runtime {
namespace {

// The Model the pre-simulation runs: every vehicle held still at its pose at the start of the
// run (no pulse, no velocity, no turn), the scene starting at rest.
Model HeldStill(const Model& model) {
  Model held = model;
  for (std::size_t k = 0; k < model.nvehicle(); ++k) {
    const VehicleState start = VehicleAt(model, k, model.start_time);
    held.vehicle_motion[k] = VehicleMotion{};
    held.vehicle_position[k] = start.position;
    held.vehicle_orientation[k] = start.rotation;
    held.vehicle_velocity[k] = Vec3::Zero();
    held.vehicle_angular_velocity[k] = Vec3::Zero();
    if (k < held.vehicle_path.size()) held.vehicle_path[k].clear();
  }
  std::fill(held.v0.begin(), held.v0.end(), 0.0);
  return held;
}

// Every force the convergence test watches: contact pairs, belt spans and springs.
void CollectForces(const Data& data, std::vector<double>& forces) {
  forces.clear();
  for (const Vec3& force : data.contacts.force) forces.push_back(force.norm());
  for (double tension : data.belts.tension) forces.push_back(tension);
  for (double force : data.spring_force) forces.push_back(std::abs(force));
}

// The convergence measures of data's state (after Forward) into summary.
void Measure(const Model& model, const Data& data, const std::vector<double>& forces,
             const std::vector<double>& previous, SettleSummary& summary) {
  summary.largest_velocity = 0.0;
  summary.largest_angular_velocity = 0.0;
  summary.largest_acceleration = 0.0;
  summary.largest_angular_acceleration = 0.0;
  for (std::size_t s = 0; s < model.nsegment(); ++s) {
    // data.velocity and data.acceleration are spatial (angular; linear, of the centre of mass)
    // in the segment frame; the norms do not depend on the frame. The centre of mass's own
    // acceleration is the spatial one plus w x v. Forward leaves the settling damping out.
    const Vec6& velocity = data.velocity[s];
    const Vec6& acceleration = data.acceleration[s];
    const double speed = velocity.tail<3>().norm();
    if (speed > summary.largest_velocity) {
      summary.largest_velocity = speed;
      summary.fastest_segment = model.segment_name[s];
    }
    summary.largest_angular_velocity =
        std::max(summary.largest_angular_velocity, velocity.head<3>().norm());
    const Vec3 linear = acceleration.tail<3>() + velocity.head<3>().cross(velocity.tail<3>());
    summary.largest_acceleration = std::max(summary.largest_acceleration, linear.norm());
    summary.largest_angular_acceleration =
        std::max(summary.largest_angular_acceleration, acceleration.head<3>().norm());
  }
  summary.largest_force = 0.0;
  double change = 0.0;
  for (std::size_t k = 0; k < forces.size(); ++k) {
    summary.largest_force = std::max(summary.largest_force, forces[k]);
    change = std::max(change, std::abs(forces[k] - (k < previous.size() ? previous[k] : 0.0)));
  }
  // A force below 1 N is no scale: a scene with nothing but gravity settles on velocities alone.
  summary.largest_force_change = change / std::max(summary.largest_force, 1.0);
}

// The run's initial velocities on the settled positions: a floating reference segment keeps the
// world-frame velocity and angular velocity the scene gave it (its coordinates are in its own
// frame, which settling turned); every other coordinate keeps its value.
void RestoreInitialVelocities(const Model& model, Data& data) {
  data.v = model.v0;
  data.v.resize(static_cast<std::size_t>(model.nv), 0.0);
  for (std::size_t s = 0; s < model.nsegment(); ++s) {
    if (model.joint_kind[s] != JointKind::kFree) continue;
    const auto qa = static_cast<std::size_t>(model.q_address[s]);
    const auto va = static_cast<std::size_t>(model.v_address[s]);
    const Mat3 given = QuaternionAt(model.q0, qa + 3).normalized().toRotationMatrix();
    const Mat3 settled = QuaternionAt(data.q, qa + 3).normalized().toRotationMatrix();
    const Mat3 turn = settled.transpose() * given;
    const Vec3 w = turn * Vec3(model.v0[va], model.v0[va + 1], model.v0[va + 2]);
    const Vec3 v = turn * Vec3(model.v0[va + 3], model.v0[va + 4], model.v0[va + 5]);
    for (std::size_t k = 0; k < 3; ++k) {
      data.v[va + k] = w[static_cast<Eigen::Index>(k)];
      data.v[va + 3 + k] = v[static_cast<Eigen::Index>(k)];
    }
  }
}

}  // namespace

SettleSummary Settle(const Model& model, Data& data) {
  CheckDataOf(model, data);
  SettleSummary summary;
  const Model::Settle& settle = model.settle;
  if (settle.duration <= 0.0) return summary;
  summary.settled = true;

  const Model held = HeldStill(model);
  Data settling = MakeData(held);
  settling.q = data.q;
  settling.w = data.w;
  settling.locked = data.locked;
  settling.settling_damping = settle.damping;
  // The pre-simulation ends where the run starts, so nothing the scene times (an inflator, a
  // pretensioner, a pulse) happens while it settles.
  const double t0 = model.start_time - settle.duration;
  settling.time = t0;

  auto integrator = MakeIntegrator(model.integrator);
  if (!integrator) {
    summary.failure = fmt::format("unknown integrator `{}`", model.integrator);
    return summary;
  }
  MultibodySystem system(held, settling);
  std::vector<double> y(system.size());
  system.Store(y);
  IntegratorOptions options = IntegratorOptionsOf(model);
  options.end_time = model.start_time;  // the pre-simulation's end
  integrator->Reset(system, t0, y, options);

  std::vector<double> forces;
  std::vector<double> previous;
  if (!system.Evaluate(t0, y)) {
    summary.failure = system.failure().cause;
    return summary;
  }
  CollectForces(settling, previous);
  const double every = std::min(settle.check_every, settle.duration);
  for (long check = 1; !summary.converged; ++check) {
    const double t_check = std::min(t0 + static_cast<double>(check) * every, model.start_time);
    const AdvanceResult result = integrator->Advance(t_check);
    if (result.status != IntegratorStatus::kOk) {
      system.Load(integrator->time(), integrator->state());
      summary.failure = system.failure().cause.empty() ? result.reason : system.failure().cause;
      break;
    }
    std::copy(integrator->state().begin(), integrator->state().end(), y.begin());
    if (!system.Evaluate(t_check, y)) {
      summary.failure = system.failure().cause;
      break;
    }
    CollectForces(settling, forces);
    Measure(held, settling, forces, previous, summary);
    summary.time = t_check - t0;
    summary.converged =
        summary.largest_velocity <= settle.velocity &&
        summary.largest_angular_velocity <= settle.angular_velocity &&
        summary.largest_acceleration <= settle.velocity / settle.check_every &&
        summary.largest_angular_acceleration <= settle.angular_velocity / settle.check_every &&
        summary.largest_force_change <= settle.force_change;
    std::swap(forces, previous);
    if (t_check >= model.start_time) break;
  }
  summary.steps = integrator->stats().steps;
  summary.evaluations = integrator->stats().evaluations;
  if (!summary.converged) return summary;

  // The last step's load histories, then the settled state into the run's data.
  system.CommitStep(integrator->time(), integrator->state());
  data.q = settling.q;
  data.locked = settling.locked;
  data.joint_histories = settling.joint_histories;
  data.contacts = settling.contacts;
  data.belts = settling.belts;
  RestoreInitialVelocities(model, data);
  return summary;
}

}  // namespace sled::runtime
