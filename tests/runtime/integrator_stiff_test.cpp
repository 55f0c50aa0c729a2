// The stiff methods on stiff problems: far fewer steps than dopri5 on coupled stiff modes, stiff
// vector groups and Van der Pol, and a Jacobian a projection does not spoil.
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

using testing::kMethods;
using testing::LinearSystem;
using testing::Make;
using testing::MaxAbsDifference;
using testing::Tolerance;
using testing::VanDerPol;

TEST(StiffTest, RosenbrockTakesFarFewerStepsThanDopri5OnCoupledStiffModes) {
  const double slow = -1.0;
  const double fast = -1e6;
  LinearSystem system(2,
                      {(slow + fast) / 2, (slow - fast) / 2, (slow - fast) / 2, (slow + fast) / 2});
  const double y0[] = {2.0, 0.0};  // both modes excited
  const double t_end = 1.0;
  const double exact[] = {std::exp(slow * t_end), std::exp(slow * t_end)};
  long steps[2] = {0, 0};
  const char* const methods[] = {"dopri5", "rosenbrock"};
  for (int m = 0; m < 2; ++m) {
    auto integrator = Make(methods[m]);
    integrator->Reset(system, 0.0, y0, Tolerance(1e-6));
    ASSERT_EQ(integrator->Advance(t_end).status, IntegratorStatus::kOk);
    EXPECT_LT(MaxAbsDifference(integrator->state(), exact), 1e-4) << methods[m];
    steps[m] = integrator->stats().steps + integrator->stats().rejected;
  }
  std::printf("  coupled stiff, tol 1e-6: dopri5 %ld steps, rosenbrock %ld\n", steps[0], steps[1]);
  EXPECT_GT(steps[0], 100 * steps[1]);
}

// The coupled stiff system whose Project scales its first component by (1 + shift), off the
// slow manifold, as renormalising a quaternion moves the state by the step's error.
class DriftingStiffSystem : public LinearSystem {
 public:
  DriftingStiffSystem(double shift, bool analytic)
      : LinearSystem(2, {-500000.5, 499999.5, 499999.5, -500000.5}, {}, analytic), shift_(shift) {}
  void Project(double, std::span<double> y) override { y[0] *= 1.0 + shift_; }

 private:
  double shift_;
};

// A projection below the re-evaluation threshold may leave the step's end derivative a little
// off the projected state; the Rosenbrock method's difference Jacobian and f_t are taken against
// it over sqrt(eps) increments, so it must re-evaluate after any projection, or a 1e-7 drift
// becomes an O(1) error in J and the steps multiply (707 instead of 41).
TEST(StiffTest, RosenbrockJacobianIsNotSpoiltByASmallProjection) {
  for (const bool analytic : {true, false}) {
    long steps[2] = {0, 0};
    for (int drift = 0; drift < 2; ++drift) {
      DriftingStiffSystem system(drift == 0 ? 0.0 : 1e-7, analytic);
      auto integrator = Make("rosenbrock");
      const double y0[] = {2.0, 0.0};
      integrator->Reset(system, 0.0, y0, Tolerance(1e-4));
      ASSERT_EQ(integrator->Advance(1.0).status, IntegratorStatus::kOk);
      steps[drift] = integrator->stats().steps + integrator->stats().rejected;
    }
    std::printf("  rosenbrock, %s Jacobian: %ld steps, %ld with the drift\n",
                analytic ? "analytic" : "difference", steps[0], steps[1]);
    EXPECT_LE(steps[1], steps[0] + steps[0] / 10) << (analytic ? "analytic" : "differences");
  }
}

TEST(StiffTest, StiffMethodsTakeFarFewerStepsThanDopri5OnAStiffVectorGroup) {
  // Group A (components 0..2) decays at -1e6 and drives group B (3..5), which decays at -1:
  // coupled modes -1e6 and -1, with the stiff one along a 3-vector as the exponential method
  // needs it.
  const double k = 1e6;
  std::vector<double> a(36, 0.0);
  for (std::size_t i = 0; i < 3; ++i) {
    a[i * 6 + i] = -k;
    a[(i + 3) * 6 + (i + 3)] = -1.0;
    a[(i + 3) * 6 + i] = 1.0;
  }
  LinearSystem system(6, a, {0, 3});
  const double y0[] = {1.0, -2.0, 0.5, 1.0, 1.0, -1.0};
  const double t_end = 1.0;
  std::vector<double> exact(6);
  for (std::size_t i = 0; i < 3; ++i) {
    exact[i] = std::exp(-k * t_end) * y0[i];
    exact[i + 3] = std::exp(-t_end) * y0[i + 3] +
                   y0[i] * (std::exp(-t_end) - std::exp(-k * t_end)) / (k - 1.0);
  }
  long steps[4] = {0, 0, 0, 0};
  for (int m = 0; m < 4; ++m) {
    auto integrator = Make(kMethods[m]);
    integrator->Reset(system, 0.0, y0, Tolerance(1e-6));
    ASSERT_EQ(integrator->Advance(t_end).status, IntegratorStatus::kOk);
    EXPECT_LT(MaxAbsDifference(integrator->state(), exact), 1e-4) << kMethods[m];
    steps[m] = integrator->stats().steps + integrator->stats().rejected;
  }
  std::printf(
      "  stiff group, tol 1e-6: dopri5 %ld, rosenbrock %ld, exponential %ld, cvs %ld steps\n",
      steps[0], steps[1], steps[2], steps[3]);
  for (int m = 1; m < 4; ++m) EXPECT_GT(steps[0], 100 * steps[m]) << kMethods[m];
}

TEST(StiffTest, ExponentialStaysAccurateWhenStiffnessCouplesGroups) {
  // The two-way coupled pair above split over two groups (x in group 0, y in group 1; the other
  // components decay at -1). No single rate per group fits, the secants are not trusted after
  // the transient, and the method must fall back to explicit steps rather than integrate a slow
  // mode with a fast rate: slower than on a decoupled group, but accurate.
  const double slow = -1.0;
  const double fast = -1e6;
  std::vector<double> a(36, 0.0);
  for (std::size_t i = 0; i < 6; ++i) a[i * 6 + i] = -1.0;
  a[0 * 6 + 0] = (slow + fast) / 2;
  a[0 * 6 + 3] = (slow - fast) / 2;
  a[3 * 6 + 0] = (slow - fast) / 2;
  a[3 * 6 + 3] = (slow + fast) / 2;
  LinearSystem system(6, a, {0, 3});
  const double y0[] = {2.0, 1.0, 1.0, 0.0, 1.0, 1.0};
  const double t_end = 0.05;
  ExponentialIntegrator integrator;
  integrator.Reset(system, 0.0, y0, Tolerance(1e-6));
  ASSERT_EQ(integrator.Advance(t_end).status, IntegratorStatus::kOk);
  const double e = std::exp(-t_end);
  const double exact[] = {e, e, e, e, e, e};
  EXPECT_LT(MaxAbsDifference(integrator.state(), exact), 1e-5);
}

TEST(StiffTest, RosenbrockSolvesVanDerPolWithMu1000) {
  // Van der Pol with mu = 1000 in Lienard time, y2' = ((1 - y1^2) y2 - y1) / eps with
  // eps = 1/mu^2 = 1e-6, y(0) = (2, 0), over [0, 2] (two fast transitions). Reference at t = 2
  // from Hairer's stiff test set (VDPOL, computed with RADAU5 at tight tolerances).
  const double reference[] = {1.706167732170483, -0.8928097010247975};
  const double y0[] = {2.0, 0.0};
  double previous = 1.0;
  for (const double tol : {1e-4, 1e-6, 1e-8}) {
    VanDerPol system(1000.0);
    Rosenbrock rosenbrock;
    rosenbrock.Reset(system, 0.0, y0, Tolerance(tol));
    ASSERT_EQ(rosenbrock.Advance(2.0).status, IntegratorStatus::kOk);
    const double error = MaxAbsDifference(rosenbrock.state(), reference);
    const IntegratorStats& s = rosenbrock.stats();
    std::printf(
        "  van der Pol mu 1000, tol %.0e: rosenbrock error %.2e, %ld steps, %ld rejected, %ld "
        "evaluations, %ld jacobians, %ld factorizations\n",
        tol, error, s.steps, s.rejected, s.evaluations, s.jacobians, s.factorizations);
    EXPECT_LT(error, 10.0 * tol);
    EXPECT_LT(error, 0.5 * previous);
    previous = error;
    EXPECT_LT(3 * s.jacobians, s.steps);  // reused across steps
  }
}

}  // namespace
}  // namespace sled::runtime
