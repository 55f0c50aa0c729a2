#include "runtime/model/data.h"

#include <algorithm>
#include <stdexcept>

#include "runtime/contact/contact_forces.h"
#include "runtime/dynamics/constraints.h"
#include "runtime/forces/joint_hysteresis.h"
#include "runtime/model/model_structure.h"
#include "runtime/restraint/belts.h"

namespace sled::runtime {

Data MakeData(const Model& model) {
  const std::shared_ptr<const ModelStructure> structure = StructureOf(model);
  const std::size_t n = model.nsegment();
  Data data;
  data.model = &model;
  data.time = model.start_time;
  data.q = model.q0;
  data.v = model.v0;
  data.q.resize(static_cast<std::size_t>(model.nq), 0.0);
  data.v.resize(static_cast<std::size_t>(model.nv), 0.0);
  data.w = model.w0;
  data.w.resize(static_cast<std::size_t>(model.nw), 0.0);
  data.wdot.assign(static_cast<std::size_t>(model.nw), 0.0);
  data.locked.assign(model.joint_locked.begin(), model.joint_locked.end());
  data.locked.resize(n, 0);
  data.rotation.assign(n, Mat3::Identity());
  data.vehicle.assign(model.nvehicle(), VehicleState{});
  data.position.assign(n, Vec3::Zero());
  data.parent_to_child.assign(n, Transform{});
  data.subspace.assign(n, MotionSubspace(6, 0));
  data.subspace_locked.assign(n, -1);
  data.joint_frame_identity = structure->joint_frame_identity;
  data.velocity.assign(n, Vec6::Zero());
  data.bias_acceleration.assign(n, Vec6::Zero());
  data.acceleration.assign(n, Vec6::Zero());
  data.external.assign(n, Vec6::Zero());
  data.generalized_force.assign(static_cast<std::size_t>(model.nv), 0.0);
  data.joint_wrench.assign(n, Vec6::Zero());
  data.vdot.assign(static_cast<std::size_t>(model.nv), 0.0);
  data.articulated_inertia.assign(n, Mat6::Zero());
  data.articulated_bias.assign(n, Vec6::Zero());
  data.u_matrix.assign(n, Mat6::Zero());
  data.d_inverse.assign(n, Mat6::Zero());
  data.u_vector.assign(n, Vec6::Zero());
  data.spring_length.assign(model.nspring(), 0.0);
  data.spring_force.assign(model.nspring(), 0.0);
  SizeTableWatch(model, data.table_watch);
  SizeContactState(model, data.contacts);
  SizeJointHistories(model, data.joint_histories);
  SetUpJointHistories(model, data);
  SizeAirbagState(model, data);
  SetUpConstraints(model, structure->constraints, data);
  SetUpBelts(model, data);
  SetUpContacts(model, data);
  return data;
}

void CheckDataOf(const Model& model, const Data& data) {
  if (data.model != &model) {
    throw std::logic_error(
        "runtime: a Data used with a Model other than the one MakeData made it for");
  }
  if (data.q.size() != static_cast<std::size_t>(model.nq) ||
      data.v.size() != static_cast<std::size_t>(model.nv) ||
      data.w.size() != static_cast<std::size_t>(model.nw) ||
      data.rotation.size() != model.nsegment()) {
    throw std::logic_error("runtime: the Model's sizes changed after its Data was made");
  }
}

std::size_t StateSize(const Model& model) {
  return static_cast<std::size_t>(model.nq + model.nv + model.nw) + kEnergyStates;
}

void LoadState(Data& data, double t, std::span<const double> y) {
  data.time = t;
  auto next = y.begin();
  for (std::vector<double>* part : {&data.q, &data.v, &data.w}) {
    std::copy(next, next + static_cast<std::ptrdiff_t>(part->size()), part->begin());
    next += static_cast<std::ptrdiff_t>(part->size());
  }
  data.energy.element_work = next[0];
  data.energy.constraint_work = next[1];
  data.energy.vehicle_work = next[2];
  data.energy.applied_work = next[3];
}

void StoreState(const Data& data, std::span<double> y) {
  auto next = y.begin();
  for (const std::vector<double>* part : {&data.q, &data.v, &data.w}) {
    next = std::copy(part->begin(), part->end(), next);
  }
  next[0] = data.energy.element_work;
  next[1] = data.energy.constraint_work;
  next[2] = data.energy.vehicle_work;
  next[3] = data.energy.applied_work;
}

}  // namespace sled::runtime
