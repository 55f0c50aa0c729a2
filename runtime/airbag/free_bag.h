// ATB's free airbag (`model = atb_free`; docs/runtime.md, "ATB's free airbag"): a bag whose gas
// is polytropic, p V^gamma constant from the volume its mass takes at the ambient pressure and
// the reference temperature, that vents as the square root of its gauge pressure, unfolds with
// its frame until full, and from then on moves as a free body (translation; it keeps its frame's
// axes) pushed by the pressure on the segments it touches and held by a spring from its back
// pole to its deployment point. Its states in data.w, from state_address: the gas mass, the
// mass vented, the centre (world) and its velocity; the motion states start when the bag is full.
#pragma once

#include <cstddef>

#include "runtime/dynamics/frame_motion.h"
#include "runtime/model/data.h"

namespace sled::runtime {

// The volume bag b's gas of `mass` takes at the ambient pressure and the reference temperature.
double FreeBagAmbientVolume(const AirbagTable& table, std::size_t b, double mass);

// Pressure, volume, vent flow and contact forces of free bag b, and the rates of its states,
// for the inflator's current `inflow`; `frame` is the motion of the bag's frame.
void ComputeFreeBagForces(const Model& model, Data& data, std::size_t b, const FrameMotion& frame,
                          double inflow);

// Starts free bag b's motion where the full envelope sits in its frame, with the frame's velocity
// there: writes its centre and velocity into data.w (needs current kinematics).
void StartFreeBag(const Model& model, Data& data, std::size_t b);

}  // namespace sled::runtime
