// Evaluating the Model's functions (constant, table, polynomial) and their slopes.
#pragma once

#include "runtime/model/model.h"

namespace sled::runtime {

// f(x). Tables interpolate linearly and extend their end slopes beyond the last rows.
double EvaluateFunction(const FunctionTable& functions, std::int32_t id, double x);

// df/dx (a table's slope on the piece that holds x, the right one at a row).
double FunctionSlope(const FunctionTable& functions, std::int32_t id, double x);

// The integral of f from 0 to x (a work or an energy when f is a force of a deflection); exact
// for every form.
double IntegrateFunction(const FunctionTable& functions, std::int32_t id, double x);

// A restoring characteristic: a function given for x >= 0 (a table starting at zero or above,
// or any polynomial or constant) is extended as an odd function, so -f(|x|) sign(x) resists
// the motion both ways; a table that covers negative x is used as written.
double RestoringTorque(const FunctionTable& functions, std::int32_t id, double x);

// True for a table whose first row is at a negative argument: RestoringTorque reads it as
// written on both sides of zero.
bool CoversNegative(const FunctionTable& functions, std::int32_t id);

}  // namespace sled::runtime
