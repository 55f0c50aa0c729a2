// The CVS force–deflection law (runtime/contact/contact_force_law.h): the unloading curve
// returns (1 - energy_loss) of the loading work, by quadrature of the force the law gives, and
// ends at the permanent deflection; reloading follows it back to the loading function.
#include <cmath>

#include <gtest/gtest.h>

#include "runtime/contact/contact_force_law.h"
#include "runtime/functions.h"
#include "runtime/model.h"

namespace sled::runtime {
namespace {

// One function: a table 0 -> 0, 0.02 -> 2 kN, 0.05 -> 12 kN, with the given unloading.
FunctionTable Foam(double energy_loss, double permanent_set) {
  FunctionTable f;
  f.kind = {FunctionTable::Kind::kTable};
  f.constant = {0};
  f.first = {0};
  f.count = {3};
  f.energy_loss = {energy_loss};
  f.permanent_set = {permanent_set};
  f.points_x = {0.0, 0.02, 0.05};
  f.points_y = {0.0, 2000.0, 12000.0};
  return f;
}

// Simpson's rule with many panels: the work of the law's force from a to b.
double Work(const FunctionTable& f, const LoadingHistory& history, double a, double b) {
  const int n = 20000;
  const double h = (b - a) / n;
  double sum = 0;
  for (int i = 0; i <= n; ++i) {
    const double w = i == 0 || i == n ? 1 : (i % 2 ? 4 : 2);
    sum += w * ElasticForce(f, 0, a + i * h, history);
  }
  return sum * h / 3;
}

TEST(ForceLaw, TableIntegralIsExact) {
  const FunctionTable f = Foam(0, 0);
  // 0.5 * 0.02 * 2000 + 0.5 * (2000 + 7000) * 0.015 = 20 + 67.5.
  EXPECT_NEAR(IntegrateFunction(f, 0, 0.035), 87.5, 1e-12);
  // Beyond the last row the end slope continues.
  const double f6 = 12000 + 10000 / 0.03 * 0.01;
  EXPECT_NEAR(IntegrateFunction(f, 0, 0.06), 20 + 0.5 * 14000 * 0.03 + 0.5 * (12000 + f6) * 0.01,
              1e-9);
}

TEST(ForceLaw, ElasticWithoutLossOrSet) {
  const FunctionTable f = Foam(0, 0);
  EXPECT_FALSE(HasHysteresis(f, 0));
  const LoadingHistory history = CommitDeflection(f, 0, 0.04, LoadingHistory{});
  EXPECT_EQ(history.max_deflection, 0.0);  // nothing to remember
  EXPECT_DOUBLE_EQ(ElasticForce(f, 0, 0.03, history), EvaluateFunction(f, 0, 0.03));
}

TEST(ForceLaw, UnloadingReturnsTheRestOfTheEnergy) {
  for (const double loss : {0.2, 0.5, 0.8}) {
    for (const double set : {0.0, 0.1, 0.3}) {
      const FunctionTable f = Foam(loss, set);
      const double peak = 0.04;
      LoadingHistory history;
      for (const double d : {0.01, 0.03, peak, 0.035}) history = CommitDeflection(f, 0, d, history);
      EXPECT_EQ(history.max_deflection, peak);
      const double loading = IntegrateFunction(f, 0, peak);
      EXPECT_NEAR(Work(f, history, 0, peak), (1 - loss) * loading, 1e-6 * loading)
          << loss << " " << set;
      // Zero at and below the permanent deflection, the loading force at the peak.
      EXPECT_EQ(ElasticForce(f, 0, set * peak * 0.999, history), 0.0);
      EXPECT_DOUBLE_EQ(ElasticForce(f, 0, peak, history), EvaluateFunction(f, 0, peak));
      // Beyond the peak: the loading function again.
      EXPECT_DOUBLE_EQ(ElasticForce(f, 0, 0.045, history), EvaluateFunction(f, 0, 0.045));
    }
  }
}

TEST(ForceLaw, LinearUnloadingWithoutLossIsTheLoadingLine) {
  // A linear function with permanent set s and no loss has no curve that returns all the energy
  // past a set above one half; with s = 0.25 the curve max_force x^k with k = 1 - 2 s does.
  FunctionTable f;
  f.kind = {FunctionTable::Kind::kPolynomial};
  f.constant = {0};
  f.first = {0};
  f.count = {2};
  f.energy_loss = {0};
  f.permanent_set = {0.25};
  f.coefficients = {0, 1e5};
  const LoadingHistory history = CommitDeflection(f, 0, 0.02, LoadingHistory{});
  EXPECT_NEAR(history.exponent, 0.5, 1e-12);
  EXPECT_NEAR(history.permanent, 0.005, 1e-15);
  EXPECT_NEAR(Work(f, history, 0, 0.02), 0.5 * 1e5 * 0.02 * 0.02, 1e-3);
}

}  // namespace
}  // namespace sled::runtime
