#include "output/report/channel_groups.h"

#include <array>
#include <map>
#include <string_view>
#include <utility>

namespace sled::report {
namespace {

// The quantity words of the output requests (docs/runtime.md#outputs), longest first where one
// ends another (`angular_acceleration` before `acceleration`).
constexpr std::array<std::string_view, 15> kQuantities = {
    "angular_acceleration", "angular_velocity", "contact_deflection", "joint_displacement",
    "contact_force",        "contact_point",    "spring_force",       "joint_torque",
    "joint_angle",          "joint_force",      "belt_force",         "acceleration",
    "orientation",          "velocity",         "position",
};

}  // namespace

RequestPart SplitRequest(const std::string& base) {
  // The last dotted word of the base that is a quantity word.
  std::size_t best = std::string::npos;
  for (const std::string_view quantity : kQuantities) {
    for (std::size_t at = base.rfind(quantity); at != std::string::npos;
         at = at == 0 ? std::string::npos : base.rfind(quantity, at - 1)) {
      const std::size_t end = at + quantity.size();
      const bool word_start = at == 0 || base[at - 1] == '.';
      const bool word_end = end == base.size() || base[end] == '.';
      if (word_start && word_end) {
        if (best == std::string::npos || at > best) best = at;
        break;
      }
    }
  }
  if (best == std::string::npos || best == 0) return {base, ""};
  return {base.substr(0, best - 1), base.substr(best)};
}

ChannelName SplitChannelName(const std::string& name) {
  ChannelName out;
  std::string path = name;
  const std::size_t open = name.rfind(" [");
  if (open != std::string::npos && name.back() == ']') {
    out.unit = name.substr(open + 2, name.size() - open - 3);
    path = name.substr(0, open);
  }
  const std::size_t dot = path.rfind('.');
  if (dot == std::string::npos) {
    out.base = path;
  } else {
    out.base = path.substr(0, dot);
    out.component = path.substr(dot + 1);
  }
  return out;
}

std::vector<ChannelGroup> GroupChannels(const std::vector<std::string>& names) {
  std::vector<ChannelGroup> groups;
  // Each group's place by base and unit: a search through the groups for every name took time
  // quadratic in the channels (200,000 columns ran past 20 s).
  std::map<std::pair<std::string, std::string>, std::size_t> found;
  for (const std::string& name : names) {
    ChannelName parts = SplitChannelName(name);
    ChannelGroup* group = nullptr;
    const auto [at, added] = found.emplace(std::make_pair(parts.base, parts.unit), groups.size());
    if (!added) group = &groups[at->second];
    if (group == nullptr) {
      RequestPart request = SplitRequest(parts.base);
      groups.push_back({parts.base,
                        parts.unit,
                        std::move(request.request),
                        std::move(request.quantity),
                        {},
                        {}});
      group = &groups.back();
    }
    group->components.push_back(std::move(parts.component));
    group->names.push_back(name);
  }
  return groups;
}

}  // namespace sled::report
