#include "runtime/airbag/airbag_outputs.h"

#include <fmt/format.h>

namespace sled::runtime {
namespace {

// Calls visit(segment, first, last) for each run of consecutive contacts of one segment.
template <typename Visit>
void ForEachContactSegment(const AirbagTable& table, std::size_t bag, Visit visit) {
  const auto first = static_cast<std::size_t>(table.first_contact[bag]);
  const auto end = first + static_cast<std::size_t>(table.contact_count[bag]);
  for (std::size_t c = first; c < end;) {
    std::size_t next = c + 1;
    while (next < end && table.contact_segment[next] == table.contact_segment[c]) ++next;
    visit(static_cast<std::size_t>(table.contact_segment[c]), c, next);
    c = next;
  }
}

}  // namespace

void AppendAirbagForceChannelNames(const Model& model, std::size_t bag, const std::string& label,
                                   std::vector<std::string>& names) {
  ForEachContactSegment(model.airbags, bag, [&](std::size_t segment, std::size_t, std::size_t) {
    for (const char* component : {"x", "y", "z", "resultant"}) {
      names.push_back(
          fmt::format("{}.airbag_force.{}.{} [N]", label, model.segment_name[segment], component));
    }
  });
}

std::size_t WriteAirbagForceChannels(const Model& model, const Data& data, std::size_t bag,
                                     std::span<double> values) {
  std::size_t column = 0;
  ForEachContactSegment(model.airbags, bag, [&](std::size_t, std::size_t first, std::size_t end) {
    Vec3 force = Vec3::Zero();
    for (std::size_t c = first; c < end; ++c) force += data.airbags.force[c];
    for (int i = 0; i < 3; ++i) values[column++] = force[i];
    values[column++] = force.norm();
  });
  return column;
}

}  // namespace sled::runtime
