#include "runtime/contact/contact_state.h"

#include "runtime/forces/force_deflection.h"
#include "runtime/model/model.h"

namespace sled::runtime {

void SizeContactState(const Model& model, ContactState& state) {
  const ContactTable& table = model.contacts;
  const std::size_t n = table.npair();
  state.deflection.assign(n, 0.0);
  state.gap.assign(n, 0.0);
  state.normal_force.assign(n, 0.0);
  state.force.assign(n, Vec3::Zero());
  state.point.assign(n, Vec3::Zero());
  state.normal.assign(n, Vec3::UnitZ());
  state.search_direction.assign(n, Vec3::Zero());
  state.rate.assign(n, 0.0);
  state.history.assign(n, LoadingHistory{});
  state.hysteresis.assign(n, 0);
  for (std::size_t k = 0; k < n; ++k) {
    state.hysteresis[k] = HasHysteresis(model.functions, table.pair_function[k]) ? 1 : 0;
  }
  state.engaged.assign(n, 1);  // SetUpContacts says which start apart
  state.behind.assign(n, 0);   // and which start behind their plane
  state.overrun.assign(n, ContactLawOverrun{});
  state.ellipsoid_center.assign(table.nellipsoid(), Vec3::Zero());
  state.ellipsoid_rotation.assign(table.nellipsoid(), Mat3::Identity());
  state.plane_origin.assign(table.nplane(), Vec3::Zero());
  state.plane_edge_u.assign(table.nplane(), Vec3::Zero());
  state.plane_edge_v.assign(table.nplane(), Vec3::Zero());
  state.plane_normal.assign(table.nplane(), Vec3::UnitZ());
  state.response.assign(n > 0 ? static_cast<std::size_t>(model.nv) : 0, 0.0);
  state.saved_v.assign(n > 0 ? static_cast<std::size_t>(model.nv) : 0, 0.0);
}

}  // namespace sled::runtime
