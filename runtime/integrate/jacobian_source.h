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

  // Forms A at (t, y), where f(t, y) = f0, for steps up to about kReach times `step` (the system
  // may leave out terms too soft for those: a step that grows by the controller's factor 10 still
  // finds every term it needs). Counts the Jacobian and any evaluations in `stats`.
  static constexpr double kReach = 10.0;
  enum class Status { kOk, kEvaluationFailed, kNotFinite };
  Status Form(OdeSystem& system, double t, std::span<const double> y, std::span<const double> f0,
              double step, const IntegratorOptions& options, IntegratorStats& stats);

  // Reuse. Whether a Jacobian must be formed before a step of size h: none in hand, it has served
  // `max_age` accepted steps, or h exceeds `growth` times the step it was formed for (a shorter
  // step is served: the terms left out are softer still for it); with `same_point_serves`, one
  // formed at the point the step starts from serves any h.
  bool MustForm(double h, long max_age, double growth, bool same_point_serves);
  bool valid() const { return valid_; }
  void Forget() { valid_ = at_current_point_ = false, age_ = 0, step_ = 0.0; }
  // The state moved on: the Jacobian ages.
  void StepAccepted() { ++age_, at_current_point_ = false; }
  // A stale Jacobian may be why the step failed: forget it unless it was formed at this point.
  void StepRejected() { valid_ = valid_ && at_current_point_; }
  // Writes or reads the Jacobian and its reuse state (a checkpoint).
  template <class Archive>
  void Serialize(Archive& archive) {
    jacobian_.Serialize(archive);
    archive.Field(valid_);
    archive.Field(at_current_point_);
    archive.Field(age_);
    archive.Field(step_);
  }

  StructuredJacobian& jacobian() { return jacobian_; }
  const StructuredJacobian& jacobian() const { return jacobian_; }
  // Whether the last Form had the system's structured Jacobian (else the dense one).
  bool structured() const { return structured_; }

 private:
  Status FormDense(OdeSystem& system, double t, std::span<const double> y,
                   std::span<const double> f0, const IntegratorOptions& options,
                   IntegratorStats& stats);

  StructuredJacobian jacobian_;
  bool valid_ = false;
  bool at_current_point_ = false;   // formed at the point the step in progress starts from
  long age_ = 0;                    // accepted steps since it was formed
  double step_ = 0.0;               // the step it was formed (or last taken) for
  bool system_structured_ = false;  // the system said it has one (StructuredRank > 0)
  bool structured_ = false;
  std::vector<double> row_major_;  // OdeSystem::Jacobian's output
  std::vector<double> perturbed_, f_perturbed_;
};

}  // namespace sled::runtime
