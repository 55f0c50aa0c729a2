#include "runtime/integrate/make_integrator.h"

#include "runtime/integrate/auto_integrator.h"
#include "runtime/integrate/dormand_prince.h"
#include "runtime/integrate/exponential.h"
#include "runtime/integrate/exponential_rk.h"
#include "runtime/integrate/rosenbrock.h"

namespace sled::runtime {

std::unique_ptr<Integrator> MakeIntegrator(std::string_view method) {
  if (method == "auto") return std::make_unique<AutoIntegrator>();
  if (method == "exponential") return std::make_unique<ExponentialRungeKutta>();
  if (method == "cvs") return std::make_unique<ExponentialIntegrator>();
  if (method == "dopri5") return std::make_unique<DormandPrince>();
  if (method == "rosenbrock") return std::make_unique<Rosenbrock>();
  return nullptr;
}

}  // namespace sled::runtime
