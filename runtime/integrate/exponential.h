// The CVS/ATB "vector exponential" integrator (reference/numerics.md §1.2) rebuilt with a true
// local error estimate.
//
// Within a step from (t0, y0) each state component is modelled as
//   y' = lambda_g (y - y0) + N(tau),   N(tau) = b + c tau + d tau^2,
// with one decay rate lambda_g per 3-vector group (OdeSystem::VectorGroups; 0 outside groups)
// and the quadratic N fitted to samples of N = f - lambda_g (y - y0) at tau = 0, h/2 and h. The
// model is integrated exactly with phi-functions:
//   y1 = y0 + h [phi1 N0 + phi2 (-3 N0 + 4 Na - Nb) + 4 phi3 (N0 - 2 Na + Nb)],  z = h lambda.
// The samples come from a predictor (Cox & Matthews' ETD3RK stages, J. Comput. Phys. 176 (2002)
// 430-455):
//   a = y0 + h/2 phi1(z0/2) f0,   b = y0 + h phi1(z) (2 Na - N0),
// and the corrector is the exact integral above. With lambda = 0 the method is Kutta's
// third-order Runge-Kutta method (Simpson weights); with y' = -k y and lambda = -k it is exact.
//
// Decay rate: per group, the Rayleigh-quotient secant lambda = dy.df / |dy|^2 over the first
// stage difference of this step (a - y0, f(a) - f0), limited to lambda <= 0 (only decay is
// integrated exponentially). It is used only when the group moved along (nearly) an
// eigendirection of its own dynamics, |df - lambda dy| <= 0.5 |lambda dy|: a group driven by
// other groups or by time-dependent loads shows there the rate of its motion, not of its
// dynamics. Untrusted, positive, rounding-level or missing estimates use 0. There is no decay
// history (ATB's exp(-1600 H) weighting is not used); stage a is placed with the previous
// attempt's rate and, after a restart, with the rate from one probe evaluation at
// y0 + (h/1000) f0, so a linear decay is exact from the first step. Any rate <= 0 gives a
// consistent third-order method: the rate only decides how much of the dynamics is integrated
// exactly, and the error estimate checks the result.
//
// Error estimate, in the shared weighted norm and controller (k = 3), the larger of
//  - the difference to the embedded second-order exponential solution through the samples at 0
//    and h (ETD2):  y1 - y1_hat = h (4 phi3 - 2 phi2) (N0 - 2 Na + Nb), and
//  - ATB's derivative residual at the step end, f(t0 + h, y1) - lambda (y1 - y0) - Nb, times
//    h (1 - 5/6 phi1(z)): it sees a rate that is wrong for part of a group (a slow axis frozen
//    by a fast rate), which the two solutions above, sharing the model, cannot.
// A step that fails the test at min_step is reported, never accepted. The end derivative is
// evaluated inside the step (it is the next step's f0), so a step costs three evaluations.
//
// Dense output: the exact solution of the step's own model at tau = theta h,
//   y(tau) = y0 + tau [phi1(theta z) N0 + theta phi2(theta z) (-3 N0 + 4 Na - Nb)
//                      + 4 theta^2 phi3(theta z) (N0 - 2 Na + Nb)],
// which is y1 at theta = 1, follows a stiff decay within the step as the step does (a cubic
// Hermite interpolant would overshoot it by h |lambda| times), and with lambda = 0 is the
// integral of the quadratic through the stage derivatives (local error O(h^3)).
//
// Like ATB's, the method captures decay along each 3-vector only: a stiff mode that couples
// groups, or a stiff group held quasi-static by slow forcing (where the secant along the motion
// sees the slow rate), falls back to rate 0 and limits the step as it would for RK3.
#pragma once

#include <cstddef>
#include <span>
#include <string_view>
#include <vector>

#include "runtime/integrate/adaptive_integrator.h"

namespace sled::runtime {

struct PhiValues {
  double phi1 = 1.0;
  double phi2 = 0.5;
  double phi3 = 1.0 / 6.0;
};

// phi_k(z) = sum_j z^j / (j + k)!: phi1 = (e^z - 1)/z, phi2 = (e^z - 1 - z)/z^2,
// phi3 = (e^z - 1 - z - z^2/2)/z^3, by series for |z| < 2 (no cancellation) and by the
// recurrence phi_{k+1} = (phi_k - 1/k!)/z from expm1 beyond.
PhiValues ComputePhi(double z);

class ExponentialIntegrator final : public AdaptiveIntegrator {
 public:
  std::string_view name() const override { return "cvs"; }
  int order() const override { return 3; }

  // The decay rate of each group used by the last step attempted (for tests and reports).
  std::span<const double> decay_rates() const { return lambda_step_; }

 protected:
  int ErrorPower() const override { return 3; }  // ETD3 - ETD2 is O(h^3)
  void ResizeWorkspace(std::size_t size) override;
  void RestartHistory() override { rates_known_ = false; }
  bool TryStep(double h, double* error) override;
  bool HasEndDerivative() const override { return true; }  // the residual test needs it
  void StepAccepted() override;
  void StepRejected() override;
  void SerializeHistory(Archive& archive) override;
  void PrepareDenseOutput() override;
  void DenseOutput(double theta, std::span<double> y) const override;

 private:
  // The secant decay rate of every group from state and derivative differences, and whether
  // each is trusted (see the header comment); untrusted rates are set to 0.
  void EstimateRates(std::span<const double> y_base, std::span<const double> y_moved,
                     std::span<const double> f_base, std::span<const double> f_moved,
                     std::span<double> rates) const;

  std::vector<std::size_t> group_start_;
  std::vector<std::size_t> group_of_;  // per component; group count for "no group"
  std::vector<double> lambda_place_;   // per group + 1: rate used to place stage a
  std::vector<double> lambda_step_;    // per group + 1: rate of this step's model
  std::vector<PhiValues> phi_half_;    // per group + 1, at z/2 with lambda_place_
  std::vector<PhiValues> phi_;         // per group + 1, at z with lambda_step_
  bool rates_known_ = false;
  bool step_rates_valid_ = false;  // lambda_step_ was measured by the last attempt
  std::vector<double> a_, fa_, na_, b_, fb_, nb_, error_;
  // The dense output of the last accepted step: its start, N0 (= f0), Na and Nb, the rates,
  // and per-call scratch for the phi values of each group.
  std::vector<double> dense_start_, dense_n0_, dense_na_, dense_nb_, dense_lambda_;
  mutable std::vector<PhiValues> dense_phi_;
};

}  // namespace sled::runtime
