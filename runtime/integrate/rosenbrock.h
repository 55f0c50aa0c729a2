// Linearly implicit (Rosenbrock-W) steps for stiff problems, by two W-methods
// (rosenbrock_tableaus.h), chosen at each step by whether the step is stiff, h times the
// Jacobian's stiff rate (StructuredJacobian::stiff_rate: its fastest term) at least kStiffStep:
//   - stiff: ROS34PW2 (Rang & Angermann, BIT 45 (2005) 761-787), four stages, order 3 with an
//     embedded order-2 solution, L-stable and stiffly accurate;
//   - not stiff: the six-stage W-method of order 4 of Rahunanthan & Stanescu (J. Comput. Appl.
//     Math. 233 (2010) 1798-1811), L-stable, with an embedded order-3 solution of our own on
//     the same stages (rosenbrock_tableaus.h).
// Being W-methods, both keep their order with any approximation W of the Jacobian, which is what
// makes the structured Jacobian (which leaves out the soft terms) and reusing one across steps
// sound. Measured, why two: ROS34PW2 alone took 308 steps on the 60-link chain at 1e-6, where W
// is the kinematics alone, against dopri5's 49 (the order-4 method: 110); the order-4 method
// alone took 1,290 steps on viscous_damping at 1e-6 with an energy balance of 1.4e-4, where
// ROS34PW2 takes 467 and closes it to 2e-6 (it is not stiffly accurate).
//
// Dense output: the cubic Hermite interpolant of the step's ends (AdaptiveIntegrator's
// default, third order), which needs f(t + h, y1), the next step's f0, and nothing else.
//
// Jacobian: W is the structured approximation A = N + U V^T of jacobian_source.h: the system's
// own (for a multibody system, the kinematics and the force elements' stiffness and damping
// through the tree, with no derivative evaluations), or the dense Jacobian as U = J, V = I
// (OdeSystem::Jacobian, or forward differences of Derivative column by column). f_t by a forward
// difference in t. The stage systems (1/(h gamma) I - W) u = r are solved by the
// Sherman-Morrison-Woodbury formula (StructuredShiftedSolver): one factorization of an R x R
// matrix per step size, O(n R) per solve, so a 60-segment chain no longer pays a dense n x n
// Jacobian and LU.
//
// Reuse rule. The Jacobian (with f_t) is formed afresh at the start of a step when
//   - there is none (after Reset, an event or an external change of the state),
//   - the previous attempt was rejected and the Jacobian was formed at an earlier point,
//   - it has served kMaxJacobianAge accepted steps, or
//   - the step has grown by more than kJacobianGrowth since it was formed (the system leaves out
//     terms too soft for ten times that step);
// otherwise the stale one serves as W. The factorization is redone whenever the step size or
// the Jacobian changes; to save refactorizations the step is kept when the controller proposes
// a growth of less than kKeepStepRatio (Hairer's RADAU5 rule).
#pragma once

#include <Eigen/Dense>
#include <cstddef>
#include <span>
#include <string_view>
#include <vector>

#include "runtime/integrate/adaptive_integrator.h"
#include "runtime/integrate/jacobian_source.h"
#include "runtime/integrate/rosenbrock_tableaus.h"
#include "runtime/integrate/structured_jacobian.h"

namespace sled::runtime {

class Rosenbrock final : public AdaptiveIntegrator {
 public:
  static constexpr int kStages = RosenbrockTableau::kMaxStages;
  // A step is stiff when h times the Jacobian's stiff rate reaches this.
  static constexpr double kStiffStep = 1.0;
  static constexpr long kMaxJacobianAge = 20;
  static constexpr double kJacobianGrowth = 5.0;
  static constexpr double kKeepStepRatio = 1.2;

  std::string_view name() const override { return "rosenbrock"; }
  int order() const override { return 4; }

 protected:
  // The order-4 method's (its embedded order 3, plus one), for the steps where order pays; on
  // ROS34PW2's steps (embedded order 2) the controller only changes the step a little faster.
  int ErrorPower() const override { return 4; }
  void ResizeWorkspace(std::size_t size) override;
  bool ControlsQuadratures() const override { return true; }
  void RestartHistory() override;
  bool TryStep(double h, double* error) override;
  void StepAccepted() override;
  void StepRejected() override;
  void SerializeHistory(Archive& archive) override;
  double AdjustStep(double proposed, double current) const override;
  // A difference Jacobian is taken against f0_ over sqrt(eps) increments: a start derivative off
  // by a projection spoils it (free_body: 691 steps instead of 170 at 1e-3). The system's own
  // structured Jacobian does not use f0_, and f_t is then taken against a fresh f(t, y).
  bool ToleratesProjectedStart() const override { return system().StructuredRank() > 0; }
  // With quadratures, TryStep evaluates the end derivative for them.
  bool HasEndDerivative() const override { return quadratures_ < y_.size(); }

 private:
  // Forms the Jacobian and f_t at (t_, y_) (f0_ is f there). False if Derivative failed.
  JacobianSource::Status FormJacobian(double h);
  // The method for a step of size h with the Jacobian in hand.
  const RosenbrockTableau& MethodFor(double h) const;
  // 1/(h gamma) I - W for the method of a step of size h, factored; false when it is singular.
  bool Factor(double h);
  // The quadratures (from quadratures_ on: the work integrals) by Simpson's rule on the step's
  // ends and the midpoint of its dense output, their error Simpson's against the stages' own
  // quadrature (both of order 4 on a smooth problem; against the trapezoidal rule, of order 2,
  // the work took 4.7 times the motion's steps). The stages' own quadrature is not kept: of
  // stage order 1 on a stiff problem, it let a stiff element's work drift by hundreds of
  // tolerances. Leaves f(t + h, y1) in f1_. False if Derivative failed.
  bool IntegrateQuadratures(double h);

  JacobianSource source_;
  StructuredShiftedSolver solver_;
  Eigen::VectorXd time_derivative_;  // f_t
  long time_derivative_age_ = 0;     // accepted steps since f_t was formed
  Eigen::VectorXd u_[kStages];
  Eigen::VectorXd rhs_, stage_, f_stage_, error_;

  double factored_step_ = 0.0;   // the step of the current factorization
  double factored_gamma_ = 0.0;  // and its method's gamma
  std::size_t quadratures_ = 0;  // where the quadratures begin (system().ControlledSize())
};

}  // namespace sled::runtime
