#include "runtime/airbag/airbag_state.h"

#include "runtime/airbag/airbag_forces.h"
#include "runtime/model/data.h"

namespace sled::runtime {

void SizeAirbagState(const Model& model, Data& data) {
  AirbagState& state = data.airbags;
  const std::size_t bags = model.airbags.size();
  state.full.assign(bags, 0);
  state.inflow_phase.assign(bags, 0);
  for (std::size_t b = 0; b < bags; ++b) {
    state.full[b] = AirbagUnfoldedFraction(model, data, b) >= 1.0 ? 1 : 0;
    state.inflow_phase[b] = AirbagInflowPhase(model, b, data.time);
  }
  const std::size_t contacts = model.airbags.ncontact();
  state.pressure.assign(bags, 0.0);
  for (std::size_t b = 0; b < bags; ++b) state.pressure[b] = model.airbags.ambient_pressure[b];
  state.volume.assign(bags, 0.0);
  state.temperature.assign(model.airbags.inflow_temperature.begin(),
                           model.airbags.inflow_temperature.end());
  state.vent_flow.assign(bags, 0.0);
  state.inflow.assign(bags, 0.0);
  state.scale.assign(bags, 0.0);
  state.force.assign(contacts, Vec3::Zero());
  state.point.assign(contacts, Vec3::Zero());
  state.area.assign(contacts, 0.0);
  state.penetrated_volume.assign(contacts, 0.0);
  state.search_direction.assign(contacts, Vec3::UnitX());
  state.failed_bag = -1;
}

}  // namespace sled::runtime
