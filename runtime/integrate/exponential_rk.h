// The exponential method: an explicit exponential Runge-Kutta method of stiff order 3 with an
// embedded solution of stiff order 2 and a continuous extension of stiff order 3, applied in
// each step to
//
//   y' = A y + g(t, y),   g = f - A y,
//
// where A = N + U V^T is the step's structured Jacobian approximation (structured_jacobian.h):
// the kinematics and the force elements' stiffness and damping, formed by the system
// (OdeSystem::StructuredJacobianAt) and reused over steps while it serves.
//
// Why not an exponential Rosenbrock method (Hochbruck, Ostermann & Schweitzer's exprb32/exprb43,
// SIAM J. Numer. Anal. 47 (2009) 786-803)? Their order conditions assume A = f'(y_n) exactly at
// every step (g_n'(y_n) = 0): with any other A, exprb32 is first order. The exact Jacobian of a
// multibody system is dense and costs one evaluation per state; its stiff part is low rank and
// comes from the force elements almost for free. An exponential Runge-Kutta method whose stiff
// order conditions hold for any A whose remainder g is non-stiff (Hochbruck & Ostermann,
// "Explicit exponential Runge-Kutta methods for semilinear parabolic problems", SIAM J. Numer.
// Anal. 43 (2005) 1069-1090, Table 4.1 / Acta Numerica 19 (2010) Table 2.2) takes that A as it
// is, keeps its order when A is a step or two old, and is exact when the problem is linear
// in the stiff part (a linear contact spring, a viscous damper). This makes it an exponential
// Rosenbrock-type W-method in all but name.
//
// The scheme (c = 0, 1/2, 1/2, 1; phi_k = phi_k(hA), phi_k,i = phi_k(c_i hA);
// D_i = g(t + c_i h, Y_i) - g(t, y) = f(t + c_i h, Y_i) - f(t, y) - A (Y_i - y)):
//
//   Y_2 = y + h/2 phi_1,2 f
//   Y_3 = Y_2 + h/2 phi_2,3 D_2
//   Y_4 = y + h phi_1 f + 2h phi_2 D_3
//   y_1 = y + h phi_1 f + h phi_2 (4 D_3 - D_4) + h phi_3 (4 D_4 - 8 D_3)
//   y^_1 = y_1 - h kappa (2 D_3 - D_4) - 2h phi_2 (D_3 - D_2)  (embedded, stiff order 2)
//
// i.e. b_2 = 0, b_3 = 4 phi_2 - 8 phi_3, b_4 = 4 phi_3 - phi_2, a_32 = phi_2,3 / 2,
// a_42 = 0, a_43 = 2 phi_2. Its stiff order conditions, all in the strong form (for any A):
//   sum b_i = phi_1,  sum b_i c_i = phi_2,  sum b_i c_i^2 / 2 = phi_3  (b_3/8 + b_4/2 = phi_3),
//   sum b_i J psi_2,i = 0  (b_2 = 0; psi_2,i = sum_j a_ij c_j - c_i^2 phi_2,i vanishes for
//   i = 3, 4 by the choice of a_32 and a_43).
// The embedded solution: b^_2 = 2 phi_2, b^_3 = 2 phi_2 - 8 phi_3 - 2 kappa,
// b^_4 = 4 phi_3 - phi_2 + kappa with kappa = (phi_1 - 2 phi_2 + 2 phi_3) / 2, of stiff order 2
// (sum b^_i c_i = phi_2; sum b^_i c_i^2 / 2 = phi_3 + kappa / 4). The error estimate
//   y_1 - y^_1 = h kappa (2 D_3 - D_4) + 2h phi_2 (D_3 - D_2)
// goes to the shared controller (k = 3). At hA = 0 kappa is 1/6, and where D_2 = D_3 the estimate
// is then as large as that of the exponential midpoint rule (2h phi_2 D_2, Cox & Matthews'
// ETD2RK, J. Comput. Phys. 176 (2002) 430-455), the earlier embedded solution; on a stiff decay
// kappa falls as 1/|z|^3.
// Why: on a stiff mode slaved to a forcing g(t) the midpoint rule's error is h^2 g'' / (4
// lambda), y_1's only h^2 g''' / (12 lambda^2), and the controller held `viscous_damping` (a
// damper at c/m = 1e4 1/s under a moving anchor) to 588 steps at 1e-5 for an error of 1.8e-7
// of the ranges; now 167 steps for 1.1e-6. The second term, the difference of the two midpoint
// stages, watches the exponential Euler stage Y_2 where the remainder is nonlinear.
//
// Dense output on the step, theta = (t - t0)/h, tau = theta h, the same stiff order 3 (its
// weights satisfy the three conditions above with phi_k(tau A) and theta^k):
//   y(t) = y + tau phi_1(tau A) f + h theta^2 phi_2(tau A) (4 D_3 - D_4)
//            + h theta^3 phi_3(tau A) (4 D_4 - 8 D_3).
//
// A costs no derivative evaluations when the system forms it; the phi-functions are exact on the
// invariant subspace of A (structured_jacobian.h). Reuse: A is formed afresh after a restart or
// event, after a rejection when it was formed at an earlier point, after kMaxJacobianAge
// accepted steps, and when the step has grown by more than kJacobianGrowth since it was formed
// (the system leaves out terms too soft for ten times that step). The phi-functions are
// recomputed when A or the step changes, and to save that, the step is kept when the controller
// proposes a growth of less than kKeepStepRatio.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <span>
#include <string_view>
#include <vector>

#include "runtime/integrate/adaptive_integrator.h"
#include "runtime/integrate/jacobian_source.h"
#include "runtime/integrate/structured_jacobian.h"

namespace sled::runtime {

class ExponentialRungeKutta final : public AdaptiveIntegrator {
 public:
  static constexpr long kMaxJacobianAge = 8;
  static constexpr double kJacobianGrowth = 5.0;
  static constexpr double kKeepStepRatio = 1.2;

  // Defined out of line, so it is user-provided: std::make_unique's value-initialization then
  // does not zero the whole object first (the phi-functions' fixed-capacity eigen-decomposition
  // storage is some 350 KB: 0.35 million instructions of memset per run, callgrind).
  ExponentialRungeKutta();

  std::string_view name() const override { return "exponential"; }
  int order() const override { return 3; }

  // The stiff rank of the Jacobian in use (the columns of U), for statistics and auto.
  Eigen::Index stiff_rank() const { return source_.jacobian().rank(); }
  // The largest rate [1/s] of the stiff part of the Jacobian in use (StructuredJacobian::
  // stiff_rate), 0 before one is formed: an explicit method's step is bound by about 3 / rate.
  double stiff_rate() const { return source_.valid() ? source_.jacobian().stiff_rate : 0.0; }

 protected:
  int ErrorPower() const override { return 3; }
  void ResizeWorkspace(std::size_t size) override;
  bool ControlsQuadratures() const override { return true; }
  void RestartHistory() override;
  bool TryStep(double h, double* error) override;
  void StepAccepted() override;
  void StepRejected() override;
  bool HasEndDerivative() const override { return true; }
  double AdjustStep(double proposed, double current) const override;
  void SerializeHistory(Archive& archive) override;
  void PrepareDenseOutput() override;
  void DenseOutput(double theta, std::span<double> y) const override;

 private:
  JacobianSource::Status EnsureJacobian(double h);
  // D = f_stage - f0 - A increment.
  void Remainder(std::span<const double> f_stage, std::span<const double> increment,
                 std::span<double> d);

  JacobianSource source_;
  StructuredPhi phi_;
  double prepared_step_ = 0.0;   // the step of the current phi-functions (0: none)
  std::size_t quadratures_ = 0;  // where the quadratures begin (system().ControlledSize())

  std::vector<double> half_;   // h/2 phi_1(hA/2) f
  std::vector<double> whole_;  // h phi_1(hA) f
  std::vector<double> stage_, increment_, f_stage_;
  std::vector<double> d2_, d3_, d4_;
  std::vector<double> c2_, c3_;  // 4 D_3 - D_4 and 4 D_4 - 8 D_3, kept for the dense output
  std::vector<double> error_, product_;
  // The dense output's data of the last accepted step: y0, f0 and its c2, c3.
  std::vector<double> dense_y0_, dense_f0_, dense_c2_, dense_c3_;
  Eigen::VectorXd scratch_;
};

}  // namespace sled::runtime
