#include "runtime/forces/state_owner.h"

#include <fmt/format.h>

namespace sled::runtime {

void NameStateOwner(const Model& model, std::size_t component, Failure& failure) {
  if (!failure.where.empty()) return;
  const auto nq = static_cast<std::size_t>(model.nq);
  const auto nv = static_cast<std::size_t>(model.nv);
  const auto nw = static_cast<std::size_t>(model.nw);
  // A joint's coordinates are those of its child segment: [address, address + count).
  const auto in_joint = [&](std::size_t index, const std::vector<std::int32_t>& address,
                            const std::vector<std::int32_t>& count, const char* what) {
    for (std::size_t s = 0; s < model.nsegment(); ++s) {
      const auto first = static_cast<std::size_t>(address[s]);
      if (index >= first && index < first + static_cast<std::size_t>(count[s])) {
        failure.where = model.segment_name[s];
        failure.source = model.segment_source[s];
        failure.cause += fmt::format(", in its {}", what);
        return;
      }
    }
  };
  if (component < nq) {
    in_joint(component, model.q_address, model.q_count, "position");
  } else if (component < nq + nv) {
    in_joint(component - nq, model.v_address, model.v_count, "velocity");
  } else if (component < nq + nv + nw) {
    const auto w = static_cast<std::int32_t>(component - nq - nv);
    const AirbagTable& bags = model.airbags;
    for (std::size_t b = 0; b < bags.name.size(); ++b) {
      if (w >= bags.state_address[b] && w < bags.state_address[b] + bags.state_count(b)) {
        failure.where = bags.name[b];
        failure.source = bags.source[b];
        failure.cause += ", in its gas state";
        return;
      }
    }
    const ActuatorTable& actuators = model.actuators;
    for (std::size_t k = 0; k < actuators.size(); ++k) {
      if (w == actuators.state_address[k]) {
        failure.where = actuators.name[k];
        failure.source = actuators.source[k];
        failure.cause += ", in its integral of the angle error";
        return;
      }
    }
  }
}

}  // namespace sled::runtime
