// Tests of the integrators behind runtime/integrate/ode.h: the exactness of the exponential
// method on linear decay, tolerances, step limits and work counts, projections, reruns and
// restarts, and that Advance never allocates. Accuracy, stiff problems and events are in
// integrator_accuracy_test.cpp, integrator_stiff_test.cpp and integrator_events_test.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
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

// Counting allocations: glibc lets a program interpose malloc and still reach the real one,
// which sees every allocation (operator new and Eigen's aligned_malloc both end in malloc).
// Sanitizers interpose malloc themselves, so there the count is off and the test skips.
#if defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(memory_sanitizer) || \
    __has_feature(thread_sanitizer)
#define SLED_TEST_SANITIZED 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define SLED_TEST_SANITIZED 1
#endif
#if defined(__GLIBC__) && !defined(SLED_TEST_SANITIZED)
#define SLED_TEST_COUNTS_MALLOC 1
namespace {
// Atomics, so the compiler cannot keep them in registers across a malloc it thinks it knows.
std::atomic<bool> g_count_mallocs{false};
std::atomic<long> g_mallocs{0};
}  // namespace
// glibc's own allocator, under its reserved name: the one this malloc hands every call to.
extern "C" void* __libc_malloc(std::size_t size);  // NOLINT(bugprone-reserved-identifier)
extern "C" void* malloc(std::size_t size) {
  if (g_count_mallocs.load(std::memory_order_relaxed)) {
    g_mallocs.fetch_add(1, std::memory_order_relaxed);
  }
  return __libc_malloc(size);
}
#endif

namespace sled::runtime {

using testing::EveryMethod;
INSTANTIATE_TEST_SUITE_P(Integrators, EveryMethod, ::testing::ValuesIn(testing::kMethods));

namespace {

using testing::BouncingBall;
using testing::Kepler;
using testing::LinearSystem;
using testing::Make;
using testing::ProjectedCircle;
using testing::Tolerance;
using testing::VanDerPol;

TEST(ExponentialTest, ExactForLinearDecayInOneStepOfAnySize) {
  for (const double k : {1.0, 10.0, 1e3, 1e6}) {
    for (const double h : {1e-3, 0.1, 1.0, 10.0, 1000.0}) {
      LinearSystem decay(3, {-k, 0, 0, 0, -k, 0, 0, 0, -k}, {0});
      const double y0[] = {1.0, -2.0, 0.25};
      ExponentialIntegrator integrator;
      integrator.Reset(decay, 0.0, y0, Tolerance(1e-6));
      ASSERT_EQ(integrator.AdvanceFixed(h, 1).status, IntegratorStatus::kOk);
      ASSERT_EQ(integrator.stats().steps, 1);
      for (std::size_t i = 0; i < 3; ++i) {
        const double exact = y0[i] * std::exp(-k * h);
        EXPECT_NEAR(integrator.state()[i], exact, 4e-16 * std::abs(y0[i]))
            << "k " << k << " h " << h;
      }
      EXPECT_NEAR(integrator.decay_rates()[0], -k, 1e-12 * k);
      // Its error estimate knows it: an adaptive run takes that one step and no other.
      ExponentialIntegrator adaptive;
      IntegratorOptions options = Tolerance(1e-10);
      options.initial_step = h;
      adaptive.Reset(decay, 0.0, y0, options);
      ASSERT_EQ(adaptive.Advance(h).status, IntegratorStatus::kOk);
      EXPECT_EQ(adaptive.stats().steps, 1) << "k " << k << " h " << h;
      EXPECT_EQ(adaptive.stats().rejected, 0);
    }
  }
}

TEST(ExponentialTest, ErrorEstimateSeesASlowAxisFrozenByAFastRate) {
  // One group with a fast axis (-1e4) that dominates the secant and two slow ones (-1): the
  // step integrates the whole group with rate -1e4, which all but freezes the slow axes. The
  // ETD3 - ETD2 difference cannot see that (both share the rate); the derivative residual
  // must, so the estimate stays within a factor 2 of the true local error.
  LinearSystem system(3, {-1e4, 0, 0, 0, -1, 0, 0, 0, -1}, {0});
  const double y0[] = {1.0, 0.01, 0.01};
  const double tol = 1e-6;
  for (const double h : {1e-3, 1e-2, 1e-1}) {
    ExponentialIntegrator integrator;
    integrator.Reset(system, 0.0, y0, Tolerance(tol));
    ASSERT_EQ(integrator.AdvanceFixed(h, 1).status, IntegratorStatus::kOk);
    ASSERT_LT(integrator.decay_rates()[0], -0.9e4);  // the fast rate was used
    const double exact[] = {std::exp(-1e4 * h), 0.01 * std::exp(-h), 0.01 * std::exp(-h)};
    double sum = 0.0;
    for (std::size_t i = 0; i < 3; ++i) {
      const double weight = tol + tol * std::max(std::abs(y0[i]), std::abs(exact[i]));
      sum += std::pow((integrator.state()[i] - exact[i]) / weight, 2);
    }
    const double true_error = std::sqrt(sum / 3.0);
    const double estimate = integrator.stats().max_local_error;
    EXPECT_GT(true_error, 1.0) << h;  // a step the controller must reject
    EXPECT_GT(estimate, 0.5 * true_error) << h;
    EXPECT_LT(estimate, 2.0 * true_error) << h;
  }
}

TEST(ExponentialTest, OutsideGroupsItIsKuttasThirdOrderMethod) {
  // Without groups every rate is 0: one step of y' = -y gives Kutta's RK3 polynomial.
  LinearSystem decay(1, {-1.0});
  const double h = 0.1;
  const double y0[] = {1.0};
  ExponentialIntegrator integrator;
  integrator.Reset(decay, 0.0, y0, Tolerance(1e-6));
  ASSERT_EQ(integrator.AdvanceFixed(h, 1).status, IntegratorStatus::kOk);
  EXPECT_NEAR(integrator.state()[0], 1.0 - h + h * h / 2.0 - h * h * h / 6.0, 1e-16);
}

// General behaviour of the shared step loop.
TEST_P(EveryMethod, PureRelativeToleranceCopesWithZeroComponents) {
  // atol = 0 and a component that stays exactly 0: its tolerance weight is 0.
  LinearSystem decay(3, {-1, 0, 0, 0, -2, 0, 0, 0, -3}, {0});
  auto integrator = Make(GetParam());
  IntegratorOptions options;
  options.relative_tolerance = 1e-8;
  options.absolute_tolerance = 0.0;
  const double y0[] = {1.0, -2.0, 0.0};
  integrator->Reset(decay, 0.0, y0, options);
  ASSERT_EQ(integrator->Advance(3.0).status, IntegratorStatus::kOk);
  EXPECT_NEAR(integrator->state()[0], std::exp(-3.0), 1e-8);
  EXPECT_NEAR(integrator->state()[1], -2.0 * std::exp(-6.0), 1e-8);
  EXPECT_EQ(integrator->state()[2], 0.0);
}

TEST_P(EveryMethod, HonoursMaxStepAndCountsWork) {
  Kepler kepler;
  auto integrator = Make(GetParam());
  IntegratorOptions options = Tolerance(1e-6);
  options.max_step = 0.01;
  integrator->Reset(kepler, 0.0, Kepler::Initial(0.5), options);
  ASSERT_EQ(integrator->Advance(1.0).status, IntegratorStatus::kOk);
  const IntegratorStats& s = integrator->stats();
  EXPECT_GE(s.steps, 100);
  EXPECT_GT(s.evaluations, 2 * s.steps);
  EXPECT_GT(s.max_local_error, 0.0);
  EXPECT_LE(s.max_local_error, 1.0);
  if (std::string(GetParam()) == "rosenbrock") {
    EXPECT_GT(s.jacobians, 0);
    EXPECT_GE(s.factorizations, s.jacobians);
  } else if (std::string(GetParam()) == "exponential") {
    EXPECT_GT(s.jacobians, 0);
    EXPECT_LT(s.jacobians, s.steps);  // reused over steps
    EXPECT_EQ(s.factorizations, 0);
  } else {
    EXPECT_EQ(s.jacobians, 0);
    EXPECT_EQ(s.factorizations, 0);
  }
}

TEST_P(EveryMethod, ProjectsAfterEveryAcceptedStep) {
  ProjectedCircle circle;
  auto integrator = Make(GetParam());
  const double y0[] = {1.0, 0.0};
  integrator->Reset(circle, 0.0, y0, Tolerance(1e-5));
  ASSERT_EQ(integrator->Advance(20.0).status, IntegratorStatus::kOk);
  EXPECT_EQ(circle.projections, integrator->stats().steps);
  EXPECT_NEAR(std::hypot(integrator->state()[0], integrator->state()[1]), 1.0, 1e-15);
}

// The circle again, whose Project scales the state by (1 + shift) and which counts the
// evaluations made exactly at a projected state.
class ShiftedCircle : public OdeSystem {
 public:
  explicit ShiftedCircle(double shift) : shift_(shift) {}
  std::size_t size() const override { return 2; }
  bool Derivative(double, std::span<const double> y, std::span<double> dy) override {
    if (y[0] == projected_[0] && y[1] == projected_[1]) ++evaluations_at_projected;
    dy[0] = -y[1];
    dy[1] = y[0];
    return true;
  }
  void Project(double, std::span<double> y) override {
    for (std::size_t i = 0; i < 2; ++i) projected_[i] = y[i] *= 1.0 + shift_;
  }
  long evaluations_at_projected = 0;

 private:
  double shift_;
  double projected_[2] = {0.0, 0.0};
};

// A projection that moves the state by far less than the tolerance keeps the step's end
// derivative (one evaluation per step saved on every scene with a quaternion); one that moves
// it by more re-evaluates there, so the next step starts from a consistent pair.
TEST(Projection, OnlyAProjectionBeyondATinyFractionOfTheToleranceReevaluates) {
  for (const char* method : {"dopri5", "exponential"}) {
    for (const double shift : {1e-12, 1e-4}) {
      ShiftedCircle circle(shift);
      auto integrator = Make(method);
      const double y0[] = {1.0, 0.0};
      integrator->Reset(circle, 0.0, y0, Tolerance(1e-5));
      ASSERT_EQ(integrator->Advance(1.0).status, IntegratorStatus::kOk) << method;
      if (shift < 1e-5) {
        EXPECT_EQ(circle.evaluations_at_projected, 0) << method;
      } else {
        EXPECT_EQ(circle.evaluations_at_projected, integrator->stats().steps) << method;
      }
    }
  }
}

TEST_P(EveryMethod, RerunsAreBitIdentical) {
  std::vector<double> first;
  IntegratorStats first_stats;
  for (int run = 0; run < 2; ++run) {
    VanDerPol system(2.0);
    auto integrator = Make(GetParam());
    const double y0[] = {2.0, 0.0};
    integrator->Reset(system, 0.0, y0, Tolerance(1e-7));
    ASSERT_EQ(integrator->Advance(10.0).status, IntegratorStatus::kOk);
    if (run == 0) {
      first.assign(integrator->state().begin(), integrator->state().end());
      first_stats = integrator->stats();
    } else {
      EXPECT_EQ(first[0], integrator->state()[0]);
      EXPECT_EQ(first[1], integrator->state()[1]);
      EXPECT_EQ(first_stats.steps, integrator->stats().steps);
      EXPECT_EQ(first_stats.evaluations, integrator->stats().evaluations);
    }
  }
}

TEST_P(EveryMethod, ChangingTheStateRestartsFromIt) {
  LinearSystem decay(1, {-1.0});
  auto integrator = Make(GetParam());
  const double y0[] = {1.0};
  integrator->Reset(decay, 0.0, y0, Tolerance(1e-9));
  ASSERT_EQ(integrator->Advance(1.0).status, IntegratorStatus::kOk);
  integrator->mutable_state()[0] = 3.0;  // an external impulse
  ASSERT_EQ(integrator->Advance(2.0).status, IntegratorStatus::kOk);
  EXPECT_NEAR(integrator->state()[0], 3.0 * std::exp(-1.0), 1e-7);
}

#if defined(SLED_TEST_COUNTS_MALLOC)
long CountAllocations(Integrator& integrator, double t_end) {
  g_mallocs = 0;
  g_count_mallocs = true;
  const AdvanceResult result = integrator.Advance(t_end);
  g_count_mallocs = false;
  EXPECT_EQ(result.status, IntegratorStatus::kOk);
  return g_mallocs;
}

// Through a volatile pointer, so the compiler can neither elide the allocation nor see it is
// malloc.
void* (*volatile g_allocate)(std::size_t) = std::malloc;
#endif

TEST_P(EveryMethod, AdvanceNeverAllocates) {
#if !defined(SLED_TEST_COUNTS_MALLOC)
  GTEST_SKIP() << "allocation counting needs glibc without a sanitizer";
#else
  {
    // The counter itself sees an allocation.
    g_mallocs = 0;
    g_count_mallocs = true;
    void* probe = g_allocate(64);
    g_count_mallocs = false;
    std::free(probe);
    ASSERT_EQ(g_mallocs.load(), 1);
  }
  {
    // Events, event location and restarts.
    BouncingBall ball;
    ball.Reserve();
    auto integrator = Make(GetParam());
    const double y0[] = {1.0, 0.0};
    integrator->Reset(ball, 0.0, y0, Tolerance(1e-8));
    EXPECT_EQ(CountAllocations(*integrator, 2.0), 0);
    EXPECT_GT(integrator->stats().events, 2);
  }
  {
    // A larger stiff system without an analytic Jacobian: finite differences and Eigen's
    // blocked LU (n > 16).
    const std::size_t n = 48;
    std::vector<double> a(n * n, 0.0);
    for (std::size_t i = 0; i < n; ++i) {
      a[i * n + i] = -1.0 - 1e3 * static_cast<double>(i % 3);
      if (i + 1 < n) a[i * n + i + 1] = 0.5;
      if (i > 0) a[(i)*n + i - 1] = 0.25;
    }
    std::vector<std::size_t> groups;
    for (std::size_t g = 0; g + 3 <= n; g += 3) groups.push_back(g);
    LinearSystem system(n, a, groups, /*analytic_jacobian=*/false);
    std::vector<double> y0(n, 1.0);
    auto integrator = Make(GetParam());
    integrator->Reset(system, 0.0, y0, Tolerance(1e-6));
    for (int k = 1; k <= 5; ++k) EXPECT_EQ(CountAllocations(*integrator, 0.01 * k), 0);
  }
#endif
}

}  // namespace
}  // namespace sled::runtime
