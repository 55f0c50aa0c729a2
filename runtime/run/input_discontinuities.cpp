#include "runtime/run/input_discontinuities.h"

#include <algorithm>

#include "runtime/dynamics/vehicle.h"

namespace sled::runtime {

std::vector<double> InputDiscontinuities(const Model& model) {
  std::vector<double> times;
  for (const VehicleMotion& motion : model.vehicle_motion) {
    if (motion.kind == VehicleMotion::Kind::kNone) continue;
    for (const double t : MotionBreakpoints(motion)) times.push_back(motion.start + t);
  }
  const AirbagTable& bags = model.airbags;
  const FunctionTable& functions = model.functions;
  for (std::size_t b = 0; b < bags.size(); ++b) {
    times.push_back(bags.deploy_time[b]);
    const std::int32_t id = bags.inflow[b];
    if (id < 0 || functions.kind[static_cast<std::size_t>(id)] != FunctionTable::Kind::kTable) {
      continue;
    }
    const auto first = static_cast<std::size_t>(functions.first[static_cast<std::size_t>(id)]);
    const auto count = static_cast<std::size_t>(functions.count[static_cast<std::size_t>(id)]);
    for (std::size_t k = 0; k < count; ++k) {
      times.push_back(bags.deploy_time[b] + functions.points_x[first + k]);
    }
  }
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end()), times.end());
  std::erase_if(times, [&](double t) { return !(t > model.start_time) || !(t < model.end_time); });
  return times;
}

}  // namespace sled::runtime
