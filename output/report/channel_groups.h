// Channels that belong in one plot. A request writes its channels as `BASE.COMPONENT [UNIT]`
// (`occupant.head.acceleration.x [m/s^2]`, `three_point.lap.belt_force.start.z [N]`): the
// components of one base and unit share a plot, in the order the file lists them.
#pragma once

#include <string>
#include <vector>

namespace sled::report {

struct ChannelName {
  std::string base;       // "occupant.head.acceleration"
  std::string component;  // "x"; empty for a name without a dot
  std::string unit;       // "m/s^2"; empty for a name without brackets
};

// Splits a column name into its parts.
ChannelName SplitChannelName(const std::string& name);

// The request a base belongs to and what it measures: the base split before its quantity word
// (`acceleration`, `joint_torque`, `contact_force`, `belt_force`, ...), so that
// `three_point.lap.belt_force.start` is `three_point.lap` and `belt_force.start`. A base without
// a known quantity word is a request of its own with an empty quantity.
struct RequestPart {
  std::string request;
  std::string quantity;
};
RequestPart SplitRequest(const std::string& base);

struct ChannelGroup {
  std::string base;
  std::string unit;
  std::string request;                  // SplitRequest(base), the part before the quantity
  std::string quantity;                 // SplitRequest(base)
  std::vector<std::string> components;  // in file order
  std::vector<std::string> names;       // the full column names, one per component
};

// The groups of some column names, in the order their first channel appears.
std::vector<ChannelGroup> GroupChannels(const std::vector<std::string>& names);

}  // namespace sled::report
