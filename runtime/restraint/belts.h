// Belts and harnesses in the runtime (the model is described in docs/runtime.md, "Belts and
// harnesses"): each evaluation finds where the webbing lies on the wrapped ellipsoids
// (belt_wrap.h), the length of each span, the slip of webbing at the junctions (belt_slip.h), and
// the span tensions from the webbing function with loading and unloading (force_deflection.h),
// and applies each span's tension at its two ends. What a belt carries beyond the state (each
// junction's stick or slip, the webbing it holds and the body point it sticks to, each span's
// largest strain) changes only at the events of belt_events.h, so every evaluation is a function
// of the state and the events so far.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "runtime/model/data.h"

namespace sled::runtime {

// Sizes data.belts and fits the belts at the initial state: each span's webbing is its length at
// the start, less the stretch of the pretension, plus its share of the slack. Called by MakeData.
void SetUpBelts(const Model& model, Data& data);

// Adds the belt forces to data.external (after the kinematics of data's state).
void ComputeBeltForces(const Model& model, Data& data);

// Where the webbing lies, the junctions' ratios and transfers, the slip and the tensions, at
// data's kinematics: ComputeBeltForces without the forces.
void EvaluateBelts(const Model& model, Data& data);

// EvaluateBelts without the slip solve: where the webbing lies (the spans' lengths), the
// junctions' capstan ratios and the arcs their bodies carried.
void EvaluateBeltGeometry(const Model& model, Data& data);

// After EvaluateBelts at an accepted step's end: records each taut span's strain past its
// webbing table's rows (runtime/forces/table_range.h). A report only; nothing feeds back.
void WatchBeltTables(const Model& model, Data& data);

// The length along the surface of junction j's wrap from the webbing's middle to the body point
// `anchor` (segment frame), positive toward the second span (0 at a tie point or a webbing that
// runs straight), from the last EvaluateBelts.
double CarriedLength(const Model& model, const Data& data, std::size_t j,
                     const Eigen::Vector3d& anchor);

// Junction j sticks to the body point under the webbing's middle now (a wrap; nothing at a tie
// point), with the webbing's present stretch, carrying it if the webbing touches the body.
void AnchorJunction(const Model& model, Data& data, std::size_t j);

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
