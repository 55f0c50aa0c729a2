#include "runtime/contact/contact_outputs.h"

#include <algorithm>

namespace sled::runtime {

ContactGroupValues EvaluateContactGroup(const Model& model, const Data& data, std::size_t group) {
  const ContactTable& table = model.contacts;
  const ContactState& state = data.contacts;
  ContactGroupValues out;
  const auto first = static_cast<std::size_t>(table.group_first[group]);
  const auto count = static_cast<std::size_t>(table.group_count[group]);
  for (std::size_t i = first; i < first + count; ++i) {
    const auto k = static_cast<std::size_t>(table.group_pairs[i]);
    out.force += state.force[k];
    out.normal_force += state.normal_force[k];
    out.point += state.normal_force[k] * state.point[k];
    out.deflection = std::max(out.deflection, state.deflection[k]);
  }
  if (out.normal_force > 0) {
    out.point /= out.normal_force;
  } else {
    out.point.setZero();
  }
  return out;
}

}  // namespace sled::runtime
