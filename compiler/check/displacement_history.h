// A prescribed displacement history (sled tests and reconstructions record the vehicle's travel,
// not its acceleration) as the acceleration table the runtime integrates: the natural cubic
// spline through the samples is twice continuously differentiable, its second derivative is
// linear between the samples (exactly a runtime acceleration table) and zero at both ends, so
// the runtime's closed-form integration of that table gives back the spline itself.
#pragma once

#include <array>
#include <vector>

namespace sled::compiler {

struct AccelerationHistory {
  std::vector<std::array<double, 2>> table;  // (t, acceleration), at the samples' times
  double position = 0.0;                     // displacement at the first sample
  double velocity = 0.0;                     // rate at the first sample
};

// `samples` are (t, displacement) with strictly increasing t, at least two.
AccelerationHistory AccelerationFromDisplacement(const std::vector<std::array<double, 2>>& samples);

}  // namespace sled::compiler
