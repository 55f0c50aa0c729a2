// Shared helpers of the verification tests: run a hand-built Model with one integrator and
// sample it, so each test compares the samples with an independent answer.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "runtime/dynamics/dynamics.h"
#include "runtime/integrate/make_integrator.h"
#include "runtime/run/system.h"

namespace sled::verification {

inline const std::vector<std::string>& AllIntegrators() {
  static const std::vector<std::string> kMethods = {"auto", "exponential", "dopri5", "rosenbrock",
                                                    "cvs"};
  return kMethods;
}

// Integrates from data's state to each time in `times`, calling `sample` there (after Forward,
// so accelerations and joint wrenches are current). Returns false on an integrator failure.
inline bool Simulate(const runtime::Model& model, runtime::Data& data, const std::string& method,
                     double tolerance, const std::vector<double>& times,
                     const std::function<void(const runtime::Data&)>& sample,
                     runtime::IntegratorStats* stats = nullptr) {
  auto integrator = runtime::MakeIntegrator(method);
  if (!integrator) return false;
  runtime::MultibodySystem system(model, data);
  std::vector<double> y(system.size());
  system.Store(y);
  runtime::IntegratorOptions options;
  options.relative_tolerance = tolerance;
  options.absolute_tolerance = tolerance * 1e-3;
  options.min_step = 1e-14;
  integrator->Reset(system, data.time, y, options);
  for (double t : times) {
    const runtime::AdvanceResult result = integrator->Advance(t);
    if (result.status != runtime::IntegratorStatus::kOk) return false;
    system.Load(integrator->time(), integrator->state());
    if (!runtime::Forward(model, data, nullptr)) return false;
    sample(data);
  }
  if (stats) *stats = integrator->stats();
  return true;
}

inline std::vector<double> Linspace(double from, double to, int count) {
  std::vector<double> out;
  for (int k = 1; k <= count; ++k) out.push_back(from + (to - from) * k / count);
  return out;
}

}  // namespace sled::verification
