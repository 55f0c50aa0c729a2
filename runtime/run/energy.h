// The energy balance of a run: kinetic + potential energy of the segments, the work the force
// elements absorb (stored elastically or dissipated), the work the prescribed vehicle motion does
// on the occupant, and the kinetic energy impulses change. With every term computed
// independently, KE + PE + absorbed - prescribed - impulses stays at its initial value up to the
// integration error; the residual measures it.
#pragma once

#include <cstddef>

#include "runtime/model/data.h"
#include "runtime/run/energy_balance.h"

namespace sled::runtime {

// 2 for a left segment of a mirror-symmetric scene and every segment below it (each stands for
// its right twin too), else 1 (Model::segment_mirror_count).
double MirrorWeight(const Model& model, std::size_t segment);

// Kinetic energy (absolute velocities) and gravitational potential energy (zero at the ground
// origin) of every segment, each times its MirrorWeight.
double KineticEnergy(const Model& model, const Data& data);
double PotentialEnergy(const Model& model, const Data& data);

// The power the non-gravity forces deliver to the segments at data's last evaluation: applied
// wrenches (data.external less gravity), joint torques (data.generalized_force), constraint
// wrenches and the reactions of joints to moving vehicles. Its integral is the change of KE + PE.
struct SegmentPower {
  double elements = 0.0;     // force elements and joint characteristics
  double constraints = 0.0;  // constraints, and root joints on vehicles (ideal: they absorb none)
  std::ptrdiff_t not_finite = -1;  // the first segment whose power is not finite, for a failure
};
SegmentPower PowerIntoSegments(const Model& model, const Data& data);

}  // namespace sled::runtime
