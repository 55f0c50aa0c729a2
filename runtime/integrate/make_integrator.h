// Chooses an integrator by the name a scene or the command line gives.
#pragma once

#include <memory>
#include <string_view>

#include "runtime/integrate/ode.h"

namespace sled::runtime {

// "auto" (dopri5, and the exponential method while the problem is stiff), "exponential" (an
// exponential Runge-Kutta method on the force elements' Jacobian), "dopri5" (Dormand-Prince
// 5(4)), "rosenbrock" (ROS34PW2, for stiff problems) or "cvs" (the CVS/ATB vector exponential
// method); nullptr for any other name.
std::unique_ptr<Integrator> MakeIntegrator(std::string_view method);

}  // namespace sled::runtime
