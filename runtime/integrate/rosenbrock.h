// A linearly implicit (Rosenbrock-W) method for stiff problems: ROS34PW2 of Rang & Angermann,
// "New Rosenbrock W-methods of order 3 for partial differential algebraic equations of index 1",
// BIT Numer. Math. 45 (2005) 761-787. Four stages, order 3 with an embedded order-2 solution,
// L-stable (R(inf) = 0) and stiffly accurate; being a W-method it keeps order 3 with any
// approximation W of the Jacobian, which is what makes reusing a Jacobian across steps sound.
//
// In Hairer & Wanner's notation (Solving ODEs II, §IV.7), with W the Jacobian approximation:
//   (I - h gamma W) k_i = h f(t + alpha_i h, y0 + sum_j alpha_ij k_j)
//                         + h W sum_j gamma_ij k_j + gamma_i h^2 f_t,
//   y1 = y0 + sum_i b_i k_i,  y1_hat = y0 + sum_i bhat_i k_i,
// gamma = 0.435866521508459 and (rows i = 2..4, entries j < i; from the paper, as tabulated in
// PETSc's TSROSWRA34PW2):
//   alpha_21 =  0.87173304301691801
//   alpha_31 =  0.84457060015369423, alpha_32 = -0.11299064236484185
//   alpha_41 =  0,                   alpha_42 =  0,                   alpha_43 = 1
//   gamma_21 = -0.87173304301691801
//   gamma_31 = -0.90338057013044082, gamma_32 =  0.054180672388095326
//   gamma_41 =  0.24212380706095346, gamma_42 = -1.2232505839045147,
//   gamma_43 =  0.54526025533510214
//   b    = ( 0.24212380706095346, -1.2232505839045147,   1.5452602553351020, gamma)
//   bhat = ( 0.37810903145819369, -0.096042292212423178, 0.5,  0.2179332607542295)
// The code uses the equivalent form without products by W (Hairer's u_i = sum_j gamma_ij k_j),
// whose coefficients are computed from these at compile time.
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
#include "runtime/integrate/structured_jacobian.h"

namespace sled::runtime {

class Rosenbrock final : public AdaptiveIntegrator {
 public:
  static constexpr int kStages = 4;
  static constexpr long kMaxJacobianAge = 20;
  static constexpr double kJacobianGrowth = 5.0;
  static constexpr double kKeepStepRatio = 1.2;

  std::string_view name() const override { return "rosenbrock"; }
  int order() const override { return 3; }

 protected:
  int ErrorPower() const override { return 3; }  // order 3 with an order-2 embedded solution
  void ResizeWorkspace(std::size_t size) override;
  bool ControlsQuadratures() const override { return true; }
  void RestartHistory() override;
  bool TryStep(double h, double* error) override;
  void StepAccepted() override;
  void StepRejected() override;
  void SerializeHistory(Archive& archive) override;
  double AdjustStep(double proposed, double current) const override;
  // The difference Jacobian and f_t are taken against f0_ over sqrt(eps) increments: a start
  // derivative off by a projection spoils them (free_body: 691 steps instead of 170 at 1e-3).
  bool ToleratesProjectedStart() const override { return false; }
  // With quadratures, TryStep evaluates the end derivative for them.
  bool HasEndDerivative() const override { return quadratures_ < y_.size(); }

 private:
  // Forms the Jacobian and f_t at (t_, y_) (f0_ is f there). False if Derivative failed.
  JacobianSource::Status FormJacobian(double h);
  // 1/(h gamma) I - W, factored; false when it is singular.
  bool Factor(double h);
  // The quadratures (from quadratures_ on: the work integrals) by Simpson's rule on the step's
  // ends and the midpoint of its dense output, their error against the trapezoidal rule; the
  // stages' own quadrature (stage order 1 on a stiff problem) let a stiff element's work drift
  // by hundreds of tolerances. Leaves f(t + h, y1) in f1_. False if Derivative failed.
  bool IntegrateQuadratures(double h);

  JacobianSource source_;
  StructuredShiftedSolver solver_;
  Eigen::VectorXd time_derivative_;  // f_t
  long time_derivative_age_ = 0;     // accepted steps since f_t was formed
  Eigen::VectorXd u_[kStages];
  Eigen::VectorXd rhs_, stage_, f_stage_, error_;

  double factored_step_ = 0.0;   // the step of the current factorization
  std::size_t quadratures_ = 0;  // where the quadratures begin (system().ControlledSize())
};

}  // namespace sled::runtime
