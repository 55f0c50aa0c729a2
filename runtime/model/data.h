// runtime::Data: everything that changes during a run of one Model: time, state, lock states,
// the kinematic and dynamic caches and the solver workspace. Sized by MakeData; nothing in a
// step allocates. A Data is only valid with the Model that made it.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "runtime/airbag/airbag_state.h"
#include "runtime/contact/contact_state.h"
#include "runtime/dynamics/spatial.h"
#include "runtime/dynamics/vehicle.h"
#include "runtime/forces/joint_hysteresis.h"
#include "runtime/forces/table_range.h"
#include "runtime/model/model.h"
#include "runtime/restraint/belt_state.h"
#include "runtime/run/energy_balance.h"

namespace sled::runtime {

// A numerical failure: when, where and why. The run keeps its outputs up to `time`.
struct Failure {
  double time = 0.0;
  std::string where;  // a segment or joint name
  std::string cause;
  SourcePosition source;
};

struct ConstraintWorkspace;  // runtime/dynamics/constraints.h
struct ConstraintWorkspaceDeleter {
  void operator()(ConstraintWorkspace* workspace) const;
};

struct Data {
  const Model* model = nullptr;  // the Model this Data belongs to (CheckDataOf)
  double time = 0.0;
  std::vector<double> q;             // generalized positions (nq)
  std::vector<double> v;             // generalized velocities (nv)
  std::vector<double> w;             // auxiliary states of force elements (nw)
  std::vector<std::uint8_t> locked;  // per segment: bit k locks axis k of its joint

  // Prescribed motion: each vehicle's pose and motion at `time`, set by ComputeKinematics, so
  // every force element and constraint on a vehicle reads it instead of evaluating the pulse.
  std::vector<VehicleState> vehicle;

  // Kinematics, per segment.
  std::vector<Mat3> rotation;              // R_WS: segment to world
  std::vector<Vec3> position;              // centre of mass in the world frame
  std::vector<Transform> parent_to_child;  // X from the parent (or world) frame
  std::vector<MotionSubspace> subspace;    // S: active joint axes as motion vectors
  // The lock mask each subspace was built for (-1: not built yet); a subspace constant in the
  // segment frame is rebuilt only when its joint locks or unlocks.
  std::vector<std::int16_t> subspace_locked;
  // Per segment, from the Model: bit 0 when the joint frame in the parent is exactly the
  // identity, bit 1 when the one in the child is, so the kinematics skips those products.
  std::vector<std::uint8_t> joint_frame_identity;
  std::vector<Vec6> velocity;           // spatial velocity in the segment frame
  std::vector<Vec6> bias_acceleration;  // c = v x S qdot + Sdot qdot
  std::vector<Vec6> acceleration;       // spatial acceleration in the segment frame

  // Forces.
  std::vector<Vec6> external;             // applied wrench at the centre of mass, segment frame
  std::vector<double> generalized_force;  // joint torques and forces (nv)
  std::vector<Vec6> joint_wrench;  // force the parent transmits to the segment, segment frame
  std::vector<double> vdot;        // generalized accelerations (nv)
  std::vector<double> wdot;        // rates of the auxiliary states (nw), set by their owners

  // Articulated-body workspace. With N active axes, only the first N columns of U, the top-left
  // N x N of D^-1 and the first N entries of u are used: fixed-size storage, so the recursion
  // works on fixed-size blocks.
  std::vector<Mat6> articulated_inertia;
  std::vector<Vec6> articulated_bias;
  std::vector<Mat6> u_matrix;   // U = I^A S
  std::vector<Mat6> d_inverse;  // D^-1 = (S^T U)^-1
  std::vector<Vec6> u_vector;   // u = tau - S^T p^A

  // Spring–dampers: current length and force (positive in tension).
  std::vector<double> spring_length;
  std::vector<double> spring_force;
  // Elements whose argument left their table's rows: when and how far
  // (runtime/forces/table_range.h).
  TableWatch table_watch;

  // Joint axes whose torque functions unload otherwise than they load: their loading histories.
  JointHistories joint_histories;
  // Contacts: per pair deflection, force and point, the loading history and work arrays.
  ContactState contacts;
  // Belts and harnesses (restraint/belts.h).
  BeltState belts;
  // What UpdateBeltRates (restraint/belt_events.h) moves for its central differences and puts
  // back: the kinematics and the belts' last evaluation, copied into storage sized once by
  // SetUpBelts rather than evaluated a third time.
  struct BeltRatesCopy {
    std::vector<VehicleState> vehicle;
    std::vector<Mat3> rotation;
    std::vector<Vec3> position;
    std::vector<Transform> parent_to_child;
    std::vector<MotionSubspace> subspace;
    std::vector<std::int16_t> subspace_locked;
    std::vector<Vec6> velocity;
    std::vector<Vec6> bias_acceleration;
    BeltState belts;
  } belt_rates_copy;
  // Airbags: pressure, volume, flows and contact forces of the last evaluation.
  AirbagState airbags;

  // Loop-closing constraints (constraints.h): multipliers, forces and the KLU factorization;
  // null when the Model has none.
  std::unique_ptr<ConstraintWorkspace, ConstraintWorkspaceDeleter> constraints;

  // The energy balance (runtime/run/energy.h): the power the force elements delivered to vehicles
  // at the last evaluation, and the accumulated terms.
  double vehicle_power = 0.0;
  double applied_power = 0.0;  // of the applied loads into the segments (AddAppliedLoads)
  EnergyBalance energy;

  // A mass-proportional damping rate [1/s] (generalized force -c M v), applied only while the
  // run settles (runtime/run/settle.h); 0 otherwise.
  double settling_damping = 0.0;

  std::int64_t evaluations = 0;
};

// A Data for `model`: sized from it, with the structure FinalizeModel derived (or derived now for
// a Model that was not finalized), at the Model's initial state.
Data MakeData(const Model& model);

// std::logic_error unless `data` was made for `model` (data.model) and the Model's sizes are
// still those it was made with. Run, Settle and the integrators' system check it on entry.
void CheckDataOf(const Model& model, const Data& data);

// The integrated state y = [q; v; w; W] of a Model: the positions, velocities and auxiliary
// states (an airbag's gas), then the kEnergyStates work integrals of the energy balance
// (data.energy: elements, constraints, vehicles), which the error control leaves out. Its size,
// and copying it into a Data (with the time) and back.
inline constexpr std::size_t kEnergyStates = 4;
std::size_t StateSize(const Model& model);
void LoadState(Data& data, double t, std::span<const double> y);
void StoreState(const Data& data, std::span<double> y);

}  // namespace sled::runtime
