// Belts and harnesses in the runtime (the model is described in docs/runtime.md, "Belts and
// harnesses"): each evaluation finds where the webbing lies on the wrapped ellipsoids
// (belt_wrap.h), the length of each span, the slip of webbing at the junctions (belt_slip.h), and
// the span tensions from the webbing function with loading and unloading (force_deflection.h),
// and applies each span's tension at its two ends. The history (the webbing in each span, the
// largest strain, the side of each body the webbing lies on and the body point it sticks to)
// changes only in CommitBelts, after an accepted step.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "runtime/data.h"

namespace sled::runtime {

// Sizes data.belts and fits the belts at the initial state: each span's webbing is its length at
// the start, less the stretch of the pretension, plus its share of the slack. Called by MakeData.
void SetUpBelts(const Model& model, Data& data);

// Adds the belt forces to data.external (after the kinematics of data's state).
void ComputeBeltForces(const Model& model, Data& data);

// After an accepted step at the state y = [q; v; w] and time t: commits the webbing distribution,
// the loading histories and the contact sides. For OdeSystem::Project; leaves y unchanged.
void CommitBelts(const Model& model, Data& data, double t, std::span<const double> y);

// The strain at which the belt's webbing function first reaches `tension`; -1 when it does not
// within a strain of 1.
double StrainAtTension(const FunctionTable& functions, std::int32_t function, double tension);

// Output channels of `belt_force`: the tension of each span, then the force on the first and
// the last anchor (x, y, z in the anchor's frame).
void AppendBeltChannelNames(const Model& model, std::size_t belt, const std::string& label,
                            std::vector<std::string>& names);
std::size_t WriteBeltChannels(const Model& model, const Data& data, std::size_t belt,
                              std::span<double> values);

}  // namespace sled::runtime
