// Output channels: what the Model's output requests compile to, their names and units, and
// their values at the current state. Accelerations are in the segment's own frame, as a
// body-mounted accelerometer reads them; positions and velocities of points are in the ground
// frame; angular rates and accelerations in the segment frame; joint torques and forces in the
// child segment's frame, about the joint point; contact forces (on the first surface) and
// points in the ground frame.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "runtime/model/data.h"

namespace sled::runtime {

// Column names, like `occupant.head.acceleration.x [m/s^2]`, in the order EvaluateChannels
// writes them.
std::vector<std::string> ChannelNames(const Model& model);

// The number of channels output group `group` produces (its columns in ChannelNames).
std::size_t ChannelCount(const Model& model, std::size_t group);

// Values after Forward (accelerations and joint wrenches must be current).
void EvaluateChannels(const Model& model, const Data& data, std::span<double> values);

}  // namespace sled::runtime
