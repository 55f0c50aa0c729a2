// Which part of a scene a component of the integrated state y = [q; v; w; W] (data.h) belongs
// to, so that a numerical failure the integrator can only place in the state vector names the
// segment or airbag it happened in.
#pragma once

#include <cstddef>
#include <string>

#include "runtime/model/data.h"

namespace sled::runtime {

// Sets failure.where (and its source) to the owner of state component `component`, and adds
// which of its states it is (", in its velocity") to the cause. Leaves a failure that already
// names a place, or a component outside the state, as it is.
void NameStateOwner(const Model& model, std::size_t component, Failure& failure);

}  // namespace sled::runtime
