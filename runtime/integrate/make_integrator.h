// Chooses an integrator by the name a scene or the command line gives.
#pragma once

#include <memory>
#include <string_view>

#include "runtime/integrate/ode.h"

namespace sled::runtime {

// "exponential" (the CVS/ATB vector exponential method), "dopri5" (Dormand-Prince 5(4)) or
// "rosenbrock" (ROS34PW2, for stiff problems); nullptr for any other name.
std::unique_ptr<Integrator> MakeIntegrator(std::string_view method);

}  // namespace sled::runtime
