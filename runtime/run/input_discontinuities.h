// The times at which the scene's inputs, functions of time the state does not enter, have kinks
// or jumps: a vehicle pulse's start, corners and end, the rows of a tabulated pulse or
// six-degree-of-freedom table, an airbag inflator's start and the rows of its flow table. A step
// across one would see a right-hand side that is not smooth, which the error control can only
// answer with rejections and small steps; the run stops the integrator on each instead
// (Integrator::Step's t_stop), so every step sees one smooth piece.
#pragma once

#include <vector>

#include "runtime/model/model.h"

namespace sled::runtime {

// Sorted, without repeats, strictly inside (model.start_time, model.end_time).
std::vector<double> InputDiscontinuities(const Model& model);

}  // namespace sled::runtime
