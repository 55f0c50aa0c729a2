// The unit a plot shows a channel in: crash engineers read accelerations in g, forces in kN,
// lengths in mm, angles in degrees and time in ms, while the files hold SI units.
#pragma once

#include <string>

namespace sled::report {

struct DisplayUnit {
  std::string unit;    // as shown on the axis, e.g. "g"
  double scale = 1.0;  // shown value = file value * scale
};

// The display unit of a channel whose file unit is `si_unit` (the text between the brackets of
// its name, like "m/s^2"); a unit without a friendlier one is shown as it is.
DisplayUnit DisplayUnitFor(const std::string& si_unit);

}  // namespace sled::report
