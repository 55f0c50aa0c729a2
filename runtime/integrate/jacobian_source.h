// Where the exponential and Rosenbrock methods get their Jacobian approximation A = N + U V^T
// (structured_jacobian.h): the system's own structured Jacobian (OdeSystem::StructuredJacobianAt:
// for a multibody system, the force elements' stiffness and damping through the tree) when it
// gives one; otherwise the dense Jacobian J as U = J, V = I and N = 0, analytic
// (OdeSystem::Jacobian) or by forward differences of Derivative, one column per evaluation, with
// increment sqrt(eps) max(|y_j|, atol/rtol).
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "runtime/integrate/ode.h"
#include "runtime/integrate/structured_jacobian.h"

namespace sled::runtime {

class JacobianSource {
 public:
  // Sizes the Jacobian for `system` (the only allocation): the system's StructuredRank, or n
  // columns when it has none.
  void Reserve(OdeSystem& system);

  // Forms A at (t, y), where f(t, y) = f0, for a step of about `step`. Counts the Jacobian and
  // any evaluations in `stats`.
  enum class Status { kOk, kEvaluationFailed, kNotFinite };
  Status Form(OdeSystem& system, double t, std::span<const double> y, std::span<const double> f0,
              double step, const IntegratorOptions& options, IntegratorStats& stats);

  StructuredJacobian& jacobian() { return jacobian_; }
  const StructuredJacobian& jacobian() const { return jacobian_; }
  // Whether the last Form had the system's structured Jacobian (else the dense one).
  bool structured() const { return structured_; }

 private:
  Status FormDense(OdeSystem& system, double t, std::span<const double> y,
                   std::span<const double> f0, const IntegratorOptions& options,
                   IntegratorStats& stats);

  StructuredJacobian jacobian_;
  bool system_structured_ = false;  // the system said it has one (StructuredRank > 0)
  bool structured_ = false;
  std::vector<double> row_major_;  // OdeSystem::Jacobian's output
  std::vector<double> perturbed_, f_perturbed_;
};

}  // namespace sled::runtime
