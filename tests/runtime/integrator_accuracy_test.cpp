// The integrators behind runtime/integrate/ode.h against exact solutions: the methods there are,
// the phi functions, linear problems at several tolerances and the observed convergence orders.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <memory>
#include <numbers>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "runtime/integrate/adaptive_integrator.h"
#include "runtime/integrate/dormand_prince.h"
#include "runtime/integrate/exponential.h"
#include "runtime/integrate/make_integrator.h"
#include "runtime/integrate/ode.h"
#include "runtime/integrate/rosenbrock.h"
#include "tests/runtime/integrator_test_systems.h"
#include "tests/runtime/ode_test_helpers.h"

namespace sled::runtime {
namespace {

using testing::EveryMethod;
using testing::Fixed;
using testing::Kepler;
using testing::kMethods;
using testing::LinearSystem;
using testing::Make;
using testing::MaxAbsDifference;
using testing::Tolerance;

constexpr double kPi = std::numbers::pi;

TEST(MakeIntegratorTest, KnowsItsMethodsAndNothingElse) {
  for (const char* method : kMethods) {
    auto integrator = MakeIntegrator(method);
    ASSERT_NE(integrator, nullptr) << method;
    EXPECT_EQ(integrator->name(), method);
  }
  EXPECT_EQ(MakeIntegrator("euler"), nullptr);
  EXPECT_EQ(MakeIntegrator(""), nullptr);
  EXPECT_EQ(MakeIntegrator("Dopri5"), nullptr);
}

TEST(PhiFunctionsTest, MatchLongDoubleReferences) {
  for (const double z : {-1e-12, -1e-3, -0.5, -1.999, -2.0, -5.0, -50.0, -1e6, 0.7}) {
    const PhiValues p = ComputePhi(z);
    // References in long double: the series near 0, the closed forms elsewhere.
    const long double zl = z;
    long double phi[4];
    if (std::abs(z) <= 2.0) {
      for (int k = 1; k <= 3; ++k) {
        long double sum = 0.0L;
        long double term = 1.0L;
        for (int j = 1; j <= k; ++j) term /= j;  // 1/k!
        for (int j = 0; j < 40; ++j) {
          sum += term;
          term *= zl / (j + k + 1);
        }
        phi[k] = sum;
      }
    } else {
      const long double e = std::expm1(zl);
      phi[1] = e / zl;
      phi[2] = (e - zl) / (zl * zl);
      phi[3] = (e - zl - zl * zl / 2) / (zl * zl * zl);
    }
    EXPECT_NEAR(p.phi1, static_cast<double>(phi[1]), 4e-16 * std::abs(p.phi1)) << z;
    EXPECT_NEAR(p.phi2, static_cast<double>(phi[2]), 4e-16 * std::abs(p.phi2)) << z;
    EXPECT_NEAR(p.phi3, static_cast<double>(phi[3]), 2e-15 * std::abs(p.phi3)) << z;
  }
  const PhiValues zero = ComputePhi(0.0);
  EXPECT_EQ(zero.phi1, 1.0);
  EXPECT_EQ(zero.phi2, 0.5);
  EXPECT_DOUBLE_EQ(zero.phi3, 1.0 / 6.0);
}

// (a) Exact linear problems at several tolerances: the error follows the tolerance down.
TEST_P(EveryMethod, DecayMatchesExactSolutionAndErrorFollowsTolerance) {
  LinearSystem decay(1, {-1.0});
  double previous = 1.0;
  for (const double tol : {1e-3, 1e-5, 1e-7, 1e-9}) {
    auto integrator = Make(GetParam());
    const double y0[] = {1.0};
    integrator->Reset(decay, 0.0, y0, Tolerance(tol));
    const AdvanceResult result = integrator->Advance(5.0);
    ASSERT_EQ(result.status, IntegratorStatus::kOk);
    EXPECT_EQ(integrator->time(), 5.0);  // lands exactly
    const double error = std::abs(integrator->state()[0] - std::exp(-5.0));
    EXPECT_LT(error, 20.0 * tol) << GetParam() << " tol " << tol;
    // The exponential method is exact on a linear problem: its error is rounding at every
    // tolerance.
    if (std::string(GetParam()) == "exponential") {
      EXPECT_LT(error, 1e-14) << "tol " << tol;
    } else {
      EXPECT_LT(error, previous) << GetParam() << " tol " << tol;
    }
    previous = error;
  }
}

TEST_P(EveryMethod, ComplexEigenvalueMatchesExactSolutionAndErrorFollowsTolerance) {
  // lambda = -0.1 +- 2i as a real 2x2 system; exact: a damped rotation.
  const double a = -0.1;
  const double b = 2.0;
  LinearSystem oscillator(2, {a, -b, b, a});
  const double t_end = 10.0;
  const double decay = std::exp(a * t_end);
  const double exact[] = {decay * std::cos(b * t_end), decay * std::sin(b * t_end)};
  double previous = 1.0;
  for (const double tol : {1e-3, 1e-5, 1e-7, 1e-9}) {
    auto integrator = Make(GetParam());
    const double y0[] = {1.0, 0.0};
    integrator->Reset(oscillator, 0.0, y0, Tolerance(tol));
    // Output at fixed times continues the same solution.
    for (int k = 1; k <= 10; ++k) {
      ASSERT_EQ(integrator->Advance(t_end * k / 10.0).status, IntegratorStatus::kOk);
    }
    EXPECT_EQ(integrator->time(), t_end);
    const double error = MaxAbsDifference(integrator->state(), exact);
    EXPECT_LT(error, 100.0 * tol) << GetParam() << " tol " << tol;
    if (std::string(GetParam()) == "exponential") {
      EXPECT_LT(error, 1e-14) << "tol " << tol;  // exact on a linear problem
    } else {
      EXPECT_LT(error, previous) << GetParam() << " tol " << tol;
    }
    previous = error;
  }
}

// (b) Observed order with fixed steps, on one period of a Kepler orbit (e = 0.5: exact answer
// the initial state) and on a decaying spiral of one 3-vector, y' = -20 (1 + |y|^2) y + w x y,
// where h lambda is of order 1 and the exponential method integrates with its decay rate.
class DecayingSpiral : public OdeSystem {
 public:
  static constexpr double kRate = 20.0;
  std::size_t size() const override { return 3; }
  bool Derivative(double, std::span<const double> y, std::span<double> dy) override {
    const double rate = kRate * (1.0 + y[0] * y[0] + y[1] * y[1] + y[2] * y[2]);
    const double w = 5.0;
    dy[0] = -rate * y[0] - w * y[1];
    dy[1] = -rate * y[1] + w * y[0];
    dy[2] = -rate * y[2];
    return true;
  }
  std::vector<std::size_t> VectorGroups() const override { return {0}; }
};

struct OrderCase {
  const char* method;
  int order;
  bool kepler;            // else DecayingSpiral
  double jacobian_scale;  // Kepler only
  long first_steps;
  bool stiff_mode = false;  // Kepler with a stiff decay beside it (KeplerWithStiffMode)
};

// The Kepler orbit and, decoupled from it, z' = -1e4 z from z = 0: the solution is the orbit's,
// but the Jacobian's rate makes every step of an order study stiff (h * 1e4 >= 1).
class KeplerWithStiffMode : public OdeSystem {
 public:
  static constexpr double kRate = 1e4;
  std::size_t size() const override { return 7; }
  bool Derivative(double t, std::span<const double> y, std::span<double> dy) override {
    dy[6] = -kRate * y[6];
    return kepler_.Derivative(t, y.first(6), dy.first(6));
  }

 private:
  Kepler kepler_;
};

class ConvergenceOrder : public ::testing::TestWithParam<OrderCase> {};
INSTANTIATE_TEST_SUITE_P(
    Integrators, ConvergenceOrder,
    ::testing::Values(
        OrderCase{"dopri5", 5, true, 1.0, 200},
        // A W-method keeps its order with the exact Jacobian, a wrong one (half of it) or
        // differences: the order-4 method of the steps that are not stiff.
        OrderCase{"rosenbrock", 4, true, 1.0, 400}, OrderCase{"rosenbrock", 4, true, 0.5, 400},
        OrderCase{"rosenbrock", 4, true, 0.0, 400},
        // With a stiff mode beside the orbit every step is stiff: ROS34PW2 takes them (its
        // error with the exact Jacobian changes sign near 1000 steps, so its asymptotic slope
        // shows only from 3200 on).
        OrderCase{"rosenbrock", 3, true, 0.0, 3200, true}, OrderCase{"cvs", 3, true, 1.0, 400},
        // The exponential method with half the Jacobian (its error changes sign
        // near 1000 steps, so the slope shows from 3200 on): the order of its
        // stiff order conditions, which hold for any A (an exponential Rosenbrock
        // method would be first order here). With the exact Jacobian it
        // converges faster (4.4 to 4.6 over 400 to 6400 steps).
        OrderCase{"exponential", 3, true, 0.5, 3200}, OrderCase{"rosenbrock", 4, false, 0.0, 200},
        OrderCase{"cvs", 3, false, 0.0, 400}));

TEST_P(ConvergenceOrder, ObservedOrderIsWithinHalfOfTheTheoreticalOrder) {
  const OrderCase c = GetParam();
  const double t_end = c.kepler ? 2.0 * kPi : 0.25;
  std::vector<double> y0 = c.kepler ? Kepler::Initial(0.5) : std::vector<double>{1, 0, 0.5};
  if (c.stiff_mode) y0.push_back(0.0);
  std::vector<double> exact = y0;
  if (!c.kepler) {
    // Reference: DOPRI5 with 40000 steps (its error is at rounding level from 400 on).
    DecayingSpiral system;
    DormandPrince reference;
    reference.Reset(system, 0.0, y0, Tolerance(1e-8));
    ASSERT_EQ(reference.AdvanceFixed(t_end, 40000).status, IntegratorStatus::kOk);
    exact.assign(reference.state().begin(), reference.state().end());
  }
  std::vector<double> errors;
  for (long steps = c.first_steps; steps <= 8 * c.first_steps; steps *= 2) {
    Kepler kepler(c.jacobian_scale);
    KeplerWithStiffMode stiff_kepler;
    DecayingSpiral spiral;
    OdeSystem& system = c.stiff_mode ? static_cast<OdeSystem&>(stiff_kepler)
                        : c.kepler   ? static_cast<OdeSystem&>(kepler)
                                     : spiral;
    auto integrator = Make(c.method);
    integrator->Reset(system, 0.0, y0, Tolerance(1e-8));
    const AdvanceResult result = Fixed(*integrator).AdvanceFixed(t_end, steps);
    ASSERT_EQ(result.status, IntegratorStatus::kOk);
    EXPECT_EQ(integrator->stats().steps, steps);
    EXPECT_EQ(integrator->stats().rejected, 0);
    errors.push_back(MaxAbsDifference(integrator->state(), exact));
    if (!c.kepler && std::string(c.method) == "cvs") {
      // The spiral is integrated with its decay rate, not as plain RK3.
      const auto& exponential = dynamic_cast<const ExponentialIntegrator&>(*integrator);
      EXPECT_LT(exponential.decay_rates()[0], -0.9 * DecayingSpiral::kRate);
      EXPECT_EQ(integrator->stats().decaying_steps, steps);  // and the stats say so
    }
    if (std::string(c.method) != "cvs") {
      EXPECT_EQ(integrator->stats().decaying_steps, 0);
    }
  }
  for (std::size_t i = 1; i < errors.size(); ++i) {
    const double observed = std::log2(errors[i - 1] / errors[i]);
    std::printf("  %s on %s (J x %.1f): %ld steps, error %.3e, observed order %.2f\n", c.method,
                c.stiff_mode ? "Kepler + stiff mode"
                : c.kepler   ? "Kepler"
                             : "spiral",
                c.jacobian_scale, c.first_steps << i, errors[i], observed);
    EXPECT_NEAR(observed, c.order, 0.5) << c.method << " at " << (c.first_steps << i);
  }
}

// (c) Stiff problems. Two-way coupled: eigenvalues -1 (vector (1,1)) and -1e6 (vector (1,-1)).

}  // namespace
}  // namespace sled::runtime
