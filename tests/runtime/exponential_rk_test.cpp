// The exponential method (runtime/integrate/exponential_rk.h) on analytic stiff problems: exact
// on linear problems in one step of any size, third order on a nonlinear problem both with the
// exact Jacobian and with only the stiff part of it as A (the stiff order conditions hold for any
// A), with the step much longer than the stiff time scale, checked against Dormand-Prince at a
// far tighter tolerance; and its dense output, through event location.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <cstdio>
#include <span>
#include <vector>

#include "runtime/integrate/dormand_prince.h"
#include "runtime/integrate/exponential_rk.h"
#include "runtime/integrate/ode.h"
#include "runtime/integrate/structured_jacobian.h"
#include "tests/runtime/ode_test_helpers.h"

namespace sled::runtime {
namespace {

using testing::MaxAbsDifference;
using testing::Tolerance;

// y' = A y with a stiff, non-normal 3 x 3 A (oscillatory and decaying modes), analytic Jacobian.
class StiffLinear : public OdeSystem {
 public:
  StiffLinear() { a_ << -2e5, 1e5, 0, -3e3, -1.0, 400.0, 0, -400.0, -0.5; }
  std::size_t size() const override { return 3; }
  bool Derivative(double, std::span<const double> y, std::span<double> dy) override {
    Eigen::Map<Eigen::Vector3d>(dy.data()) = a_ * Eigen::Map<const Eigen::Vector3d>(y.data());
    return true;
  }
  bool Jacobian(double, std::span<const double>, std::span<double> jacobian) override {
    Eigen::Map<Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(jacobian.data()) = a_;
    return true;
  }
  Eigen::Matrix3d a_;
};

TEST(ExponentialMethod, ExactOnALinearProblemInOneStepOfAnySize) {
  StiffLinear system;
  const Eigen::Vector3d y0(1.0, -2.0, 0.5);
  for (const double h : {1e-6, 1e-3, 0.1, 2.0}) {
    ExponentialRungeKutta integrator;
    integrator.Reset(system, 0.0, std::span<const double>(y0.data(), 3), Tolerance(1e-8));
    ASSERT_EQ(integrator.AdvanceFixed(h, 1).status, IntegratorStatus::kOk);
    // The exact solution from the augmented-matrix exponential of structured_jacobian's tests
    // would do; here e^{hA} y0 by a fine Dormand-Prince run is independent of the phi code.
    DormandPrince reference;
    reference.Reset(system, 0.0, std::span<const double>(y0.data(), 3), Tolerance(1e-13));
    ASSERT_EQ(reference.Advance(h).status, IntegratorStatus::kOk);
    EXPECT_LT(MaxAbsDifference(integrator.state(), reference.state()), 1e-10) << h;
    // And the error estimate knows the step is exact: an adaptive run takes that one step.
    ExponentialRungeKutta adaptive;
    IntegratorOptions options = Tolerance(1e-10);
    options.initial_step = h;
    adaptive.Reset(system, 0.0, std::span<const double>(y0.data(), 3), options);
    ASSERT_EQ(adaptive.Advance(h).status, IntegratorStatus::kOk);
    EXPECT_EQ(adaptive.stats().steps, 1) << h;
    EXPECT_EQ(adaptive.stats().rejected, 0) << h;
  }
}

// A mass on a stiff spring (k, with damping c) to an anchor moving as sin(5t), with a soft
// nonlinear restoring force x^3 and a nonlinear drag: x'' = -k (x - a(t)) - c x' - x^3 - x'|x'|.
// Its structured Jacobian holds the spring and damper only (N: x' = v; U = [0; 1],
// V = [-k; -c]), or, with `exact`, the whole Jacobian at the point (the x^3 and drag terms
// too, as a second rank-one term).
class AnchoredMass : public OdeSystem {
 public:
  AnchoredMass(double k, double c, bool exact) : k_(k), c_(c), exact_(exact) {}
  std::size_t size() const override { return 2; }
  bool Derivative(double t, std::span<const double> y, std::span<double> dy) override {
    dy[0] = y[1];
    dy[1] =
        -k_ * (y[0] - std::sin(5.0 * t)) - c_ * y[1] - y[0] * y[0] * y[0] - y[1] * std::abs(y[1]);
    return true;
  }
  std::size_t StructuredRank() const override { return 2; }
  bool StructuredJacobianAt(double, std::span<const double> y, std::span<const double>, double,
                            StructuredJacobian& jacobian) override {
    jacobian.nilpotent.push_back({0, 1, 1.0});
    jacobian.AddColumns(Eigen::Vector2d(0, 1), Eigen::Vector2d(-k_, -c_));
    if (exact_) {
      jacobian.AddColumns(Eigen::Vector2d(0, 1),
                          Eigen::Vector2d(-3.0 * y[0] * y[0], -2.0 * std::abs(y[1])));
    }
    return true;
  }

 private:
  double k_, c_;
  bool exact_;
};

// The slow-manifold start (to O(1/k^2)): x = a - (a'' + c x' + x^3 + x'|x'|)/k at t = 0, so
// the fast mode starts unexcited, as in a scene that starts at rest. (An excited undamped fast
// mode makes g(t, y(t)) oscillate at sqrt(k), which no step longer than its period follows.)
std::vector<double> SlowStart(double k, double c) {
  return {-(25.0 + 5.0 * c) / k, 5.0 + 125.0 / k};
}

double PositionError(double k, double c, bool exact, long steps) {
  const double t_end = 1.0;
  const std::vector<double> y0 = SlowStart(k, c);
  AnchoredMass system(k, c, exact);
  DormandPrince reference;
  reference.Reset(system, 0.0, y0, Tolerance(1e-13));
  EXPECT_EQ(reference.Advance(t_end).status, IntegratorStatus::kOk);
  ExponentialRungeKutta integrator;
  integrator.Reset(system, 0.0, y0, Tolerance(1e-8));
  EXPECT_EQ(integrator.AdvanceFixed(t_end, steps).status, IntegratorStatus::kOk);
  return std::abs(integrator.state()[0] - reference.state()[0]);
}

TEST(ExponentialMethod, ThirdOrderWithOnlyPartOfTheJacobian) {
  // Not stiff (h sqrt(k) < 1): A holds the spring but not the cubic and drag terms, so this is
  // the classical order of the scheme with an inexact A (an exponential Rosenbrock method
  // would be first order here).
  for (const double c : {0.0, 5.0}) {
    std::vector<double> errors;
    for (long steps = 16; steps <= 128; steps *= 2) {
      errors.push_back(PositionError(100.0, c, false, steps));
    }
    for (std::size_t i = 1; i < errors.size(); ++i) {
      const double observed = std::log2(errors[i - 1] / errors[i]);
      std::printf("  k 100, c %.0f, A without the nonlinear terms: error %.3e, order %.2f\n", c,
                  errors[i], observed);
      EXPECT_NEAR(observed, 3.0, 0.5);
    }
  }
}

TEST(ExponentialMethod, ErrorAtAFixedStepDoesNotGrowWithTheStiffness) {
  // h sqrt(k) from 50 to 1600: steps far beyond the stiff time scale (dopri5 is unstable for
  // h sqrt(k) > 3.3). Stiff order: the error is bounded by C h^3 with C independent of k, so at
  // each step size the error may not grow as k does, and it falls as h does.
  for (const double damping_ratio : {0.0, 1.5}) {
    std::vector<double> coarse, fine;
    for (const double k : {1e7, 1e8, 1e9}) {
      const double c = 2.0 * damping_ratio * std::sqrt(k);
      coarse.push_back(PositionError(k, c, false, 64));
      fine.push_back(PositionError(k, c, false, 128));
      std::printf("  k %.0e, damping ratio %.1f: error %.3e at h = 1/64, %.3e at 1/128\n", k,
                  damping_ratio, coarse.back(), fine.back());
      EXPECT_LT(fine.back(), coarse.back());
      EXPECT_LT(coarse.back(), 1e-6);
    }
    EXPECT_LT(coarse[2], 2.0 * coarse[0]);
    EXPECT_LT(fine[2], 2.0 * fine[0]);
  }
}

// Event location runs on the dense output: a decay y' = -1000 (y - 1) + ... crossing a level
// between steps, with steps far longer than 1/1000.
class RelaxingWithEvent : public OdeSystem {
 public:
  std::size_t size() const override { return 2; }
  bool Derivative(double, std::span<const double> y, std::span<double> dy) override {
    dy[0] = -1e3 * (y[0] - y[1]);  // y0 relaxes onto y1 fast
    dy[1] = -y[1] * y[1];          // y1 = 1 / (1 + t)
    return true;
  }
  std::size_t StructuredRank() const override { return 1; }
  bool StructuredJacobianAt(double, std::span<const double>, std::span<const double>, double,
                            StructuredJacobian& jacobian) override {
    jacobian.AddColumns(Eigen::Vector2d(1, 0), Eigen::Vector2d(-1e3, 1e3));
    return true;
  }
  std::size_t EventCount() const override { return 1; }
  void Events(double, std::span<const double> y, std::span<double> g) override {
    g[0] = y[0] - 0.5;  // y0 ~ 1/(1+t) crosses 1/2 near t = 1
  }
  EventEffect HandleEvent(std::size_t, int, double t, std::span<double>) override {
    event_time = t;
    return EventEffect::kModeChanged;
  }
  double event_time = -1.0;
};

TEST(ExponentialMethod, DenseOutputLocatesEventsToTheTolerance) {
  for (const double tol : {1e-4, 1e-6, 1e-8}) {
    RelaxingWithEvent explicit_system;
    DormandPrince dopri5;
    RelaxingWithEvent system;
    ExponentialRungeKutta integrator;
    const double y0[] = {1.0, 1.0};
    integrator.Reset(system, 0.0, y0, Tolerance(tol));
    ASSERT_EQ(integrator.Advance(3.0).status, IntegratorStatus::kOk);
    // y1 = 1/(1+t), and y0 follows it with lag ~ y1'/1000: y0 = y1 + y1^2/1000 + O(1e-6).
    RelaxingWithEvent fine;
    DormandPrince reference;
    reference.Reset(fine, 0.0, y0, Tolerance(1e-12));
    ASSERT_EQ(reference.Advance(3.0).status, IntegratorStatus::kOk);
    dopri5.Reset(explicit_system, 0.0, y0, Tolerance(tol));
    ASSERT_EQ(dopri5.Advance(3.0).status, IntegratorStatus::kOk);
    std::printf("  tol %.0e: event at %.10f (dopri5 1e-12: %.10f), %ld steps (dopri5 %ld)\n", tol,
                system.event_time, fine.event_time, integrator.stats().steps, dopri5.stats().steps);
    EXPECT_NEAR(system.event_time, fine.event_time, 30 * tol);
    // Not limited by the fast decay, as dopri5 is (h < 3.3e-3) where the tolerance allows.
    if (tol >= 1e-6) {
      EXPECT_LT(3 * integrator.stats().steps, dopri5.stats().steps);
    }
  }
}

}  // namespace
}  // namespace sled::runtime
