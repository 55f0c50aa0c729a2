// The envelope of an airbag and what the contact ellipsoids of its segments take from it: the
// geometry both of sled's energy-balance bag and of ATB's free bag use (docs/runtime.md,
// "Airbags", "Contact"). The envelope is the bag's ellipsoid scaled by s about its back pole,
// carried by a body whose pose places the pole: the bag's frame, or for a free bag that is full,
// a body moving with the bag.
#pragma once

#include <cstddef>

#include "runtime/dynamics/frame_motion.h"
#include "runtime/model/data.h"

namespace sled::runtime {

// Below this fraction of its full volume the gas of a full bag is taken to have no room left:
// the run fails there (the pressure would be unbounded), and the volume is held at it meanwhile.
inline constexpr double kMinimumAirbagVolumeFraction = 1e-3;

// The volume of bag b's fully deployed envelope.
double FullAirbagVolume(const AirbagTable& table, std::size_t b);

// What the segments' ellipsoids take from bag b's envelope at `scale`: the volume, its rate
// from their motion, and its derivative with respect to the scale. Records each contact's area,
// volume, point and direction (the unit normal from the bag to the segment, in `force`).
struct Penetration {
  double volume = 0.0;
  double motion_rate = 0.0;  // d(volume)/dt from the motion of the segments and the carrier
  double per_scale = 0.0;    // d(volume)/d(scale)
};
Penetration Penetrate(const Model& model, Data& data, std::size_t b, const FrameMotion& carrier,
                      double scale);

// The scale at which an unfolding bag's envelope, less what the segments take, holds
// `gas_volume`: the root of s^3 V_full - V_pen(s) = gas_volume, above the free bag's scale.
// Leaves the contacts recorded at the scale returned.
double UnfoldedScale(const Model& model, Data& data, std::size_t b, const FrameMotion& carrier,
                     double gas_volume, Penetration& penetration);

}  // namespace sled::runtime
