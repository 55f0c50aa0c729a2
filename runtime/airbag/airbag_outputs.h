// Output channels of `airbag_force`: for each segment the bag may touch, the force the bag
// applies to it (x, y, z in the ground frame, then its magnitude), summed over the segment's
// contact ellipsoids.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "runtime/model/data.h"

namespace sled::runtime {

void AppendAirbagForceChannelNames(const Model& model, std::size_t bag, const std::string& label,
                                   std::vector<std::string>& names);
std::size_t WriteAirbagForceChannels(const Model& model, const Data& data, std::size_t bag,
                                     std::span<double> values);

}  // namespace sled::runtime
