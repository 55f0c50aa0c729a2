// Loading and unloading (runtime/forces/force_deflection.h): integrals of the function forms worked
// out by hand, and the energy an unloading returns, integrated by Simpson's rule, against the
// fraction 1 - energy_loss of the loading energy.
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "runtime/forces/force_deflection.h"
#include "runtime/forces/functions.h"
#include "tests/runtime/model_fixtures.h"

namespace sled::runtime {
namespace {

using testing::AddTableFunction;

// The energy returned when unloading from the largest deflection to zero.
double Returned(const FunctionTable& f, std::int32_t id, const LoadingHistory& history,
                double mirror = 1.0) {
  const int n = 20000;
  const double h = history.max_deflection / n;
  double sum = 0.0;
  for (int k = 0; k <= n; ++k) {
    const double w = (k == 0 || k == n) ? 1 : (k % 2 ? 4 : 2);
    sum += w * LoadingUnloadingForce(f, id, k * h, history, mirror);
  }
  return sum * h / 3;
}

TEST(ForceDeflection, IntegralsOfEachForm) {
  FunctionTable f;
  const auto table = AddTableFunction(f, {{0, 0}, {1, 2}, {3, 2}});
  EXPECT_NEAR(IntegrateFunction(f, table, 2.0), 1.0 + 2.0, 1e-15);
  EXPECT_NEAR(IntegrateFunction(f, table, 4.0), 1.0 + 2.0 * 3, 1e-15);  // flat beyond the end
  EXPECT_NEAR(IntegrateFunction(f, table, -1.0), 1.0, 1e-15);           // the first slope continues
  f.kind.push_back(FunctionTable::Kind::kPolynomial);
  f.constant.push_back(0);
  f.first.push_back(0);
  f.count.push_back(3);
  f.energy_loss.push_back(0);
  f.permanent_set.push_back(0);
  f.coefficients = {1, 2, 3};
  EXPECT_NEAR(IntegrateFunction(f, 1, 2.0), 2.0 + 4.0 + 8.0, 1e-14);
  f.kind.push_back(FunctionTable::Kind::kConstant);
  f.constant.push_back(5);
  f.first.push_back(-1);
  f.count.push_back(0);
  f.energy_loss.push_back(0);
  f.permanent_set.push_back(0);
  EXPECT_EQ(IntegrateFunction(f, 2, 0.3), 1.5);
}

TEST(ForceDeflection, UnloadingReturnsWhatTheEnergyLossLeaves) {
  FunctionTable f;
  struct Case {
    double loss, set;
  };
  for (const Case c : {Case{0.4, 0.0}, Case{0.4, 0.2}, Case{0.7, 0.5}, Case{0.1, 0.0}}) {
    const auto linear = AddTableFunction(f, {{0, 0}, {1, 1000}}, c.loss, c.set);
    // Softening: without a permanent set, a small loss would put x_p below zero.
    const auto softening = AddTableFunction(f, {{0, 0}, {0.02, 150}, {0.1, 200}}, c.loss, c.set);
    for (const auto id : {linear, softening}) {
      LoadingHistory history;
      UpdateLoadingHistory(f, id, 0.05, history);
      UpdateLoadingHistory(f, id, 0.1, history);
      UpdateLoadingHistory(f, id, 0.08, history);  // unloading leaves the history alone
      EXPECT_EQ(history.max_deflection, 0.1);
      const double energy = IntegrateFunction(f, id, 0.1);
      EXPECT_NEAR(Returned(f, id, history), (1 - c.loss) * energy, 1e-6 * energy)
          << "loss " << c.loss << " set " << c.set << " function " << id;
      if (c.set > 0) {
        EXPECT_DOUBLE_EQ(history.permanent, c.set * 0.1);
      }
      // Continuous at the largest deflection; nothing left below the permanent deflection.
      EXPECT_NEAR(LoadingUnloadingForce(f, id, 0.1 - 1e-12, history), history.max_force, 1e-6);
      EXPECT_EQ(LoadingUnloadingForce(f, id, history.permanent, history), 0.0);
    }
  }
}

TEST(ForceDeflection, PermanentSetAloneUnloadsAlongAStraightLine) {
  FunctionTable f;
  const auto id = AddTableFunction(f, {{0, 0}, {1, 1000}}, 0.0, 0.3);
  LoadingHistory history;
  UpdateLoadingHistory(f, id, 0.1, history);
  EXPECT_DOUBLE_EQ(history.exponent, 1.0);
  EXPECT_NEAR(LoadingUnloadingForce(f, id, 0.065, history), 100.0 * 0.5, 1e-12);
  // A linear spring keeps 1 - p of its energy: (1/2) F (x - p x) of (1/2) F x.
  EXPECT_NEAR(Returned(f, id, history), 0.7 * 5.0, 1e-9);
}

TEST(ForceDeflection, ElasticFunctionsUnloadAlongThemselves) {
  FunctionTable f;
  const auto id = AddTableFunction(f, {{0, 0}, {1, 1000}});
  LoadingHistory history;
  UpdateLoadingHistory(f, id, 0.1, history);
  EXPECT_EQ(LoadingUnloadingForce(f, id, 0.05, history), 50.0);
}

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

TEST(ForceDeflection, ATableIntegralIsExactBeyondTheEnds) {
  const FunctionTable f = Foam(0, 0);
  // 0.5 * 0.02 * 2000 + 0.5 * (2000 + 7000) * 0.015 = 20 + 67.5.
  EXPECT_NEAR(IntegrateFunction(f, 0, 0.035), 87.5, 1e-12);
  // Beyond the last row the end slope continues.
  const double f6 = 12000 + 10000 / 0.03 * 0.01;
  EXPECT_NEAR(IntegrateFunction(f, 0, 0.06), 20 + 0.5 * 14000 * 0.03 + 0.5 * (12000 + f6) * 0.01,
              1e-9);
}

TEST(ForceDeflection, UnloadingReturnsTheRestOfTheEnergy) {
  for (const double loss : {0.2, 0.5, 0.8}) {
    for (const double set : {0.0, 0.1, 0.3}) {
      const FunctionTable f = Foam(loss, set);
      const double peak = 0.04;
      LoadingHistory history;
      for (const double d : {0.01, 0.03, peak, 0.035}) UpdateLoadingHistory(f, 0, d, history);
      EXPECT_EQ(history.max_deflection, peak);
      const double loading = IntegrateFunction(f, 0, peak);
      EXPECT_NEAR(Returned(f, 0, history), (1 - loss) * loading, 1e-6 * loading)
          << loss << " " << set;
      // Zero at and below the permanent deflection, the loading force at the peak.
      EXPECT_EQ(LoadingUnloadingForce(f, 0, set * peak * 0.999, history), 0.0);
      EXPECT_DOUBLE_EQ(LoadingUnloadingForce(f, 0, peak, history), EvaluateFunction(f, 0, peak));
      // Beyond the peak: the loading function again.
      EXPECT_DOUBLE_EQ(LoadingUnloadingForce(f, 0, 0.045, history), EvaluateFunction(f, 0, 0.045));
    }
  }
}

TEST(ForceDeflection, AnUnloadSlopeEndsAtItsPermanentSet) {
  // A straight line of s times the secant f(x_max) / x_max from (x_max, f(x_max)): it reaches
  // zero at x_max (1 - 1/s), and returns the triangle it encloses, f(x_max) x_max / (2 s), unless
  // that is more than the loading work E: then the line ends where it returns E, at
  // x_max - 2 E / f(x_max) (the stiffening table at s = 1.5: E = 30 J of a 33.3 J triangle).
  for (const double s : {1.5, 3.0, 10.0}) {
    FunctionTable f;
    const auto linear = AddTableFunction(f, {{0, 0}, {1, 1000}});
    const auto stiffening = AddTableFunction(f, {{0, 0}, {0.05, 100}, {0.1, 1000}});
    f.unload_slope = {s, s};
    for (const auto id : {linear, stiffening}) {
      LoadingHistory history;
      UpdateLoadingHistory(f, id, 0.1, history);
      const double peak = EvaluateFunction(f, id, 0.1);
      const double energy = IntegrateFunction(f, id, 0.1);
      const double permanent = std::max(0.1 * (1 - 1 / s), 0.1 - 2 * energy / peak);
      EXPECT_NEAR(history.permanent, permanent, 1e-15) << s << " " << id;
      EXPECT_EQ(history.exponent, 1.0);
      const double halfway = 0.5 * (0.1 + permanent);
      EXPECT_NEAR(LoadingUnloadingForce(f, id, halfway, history), 0.5 * peak, 1e-9 * peak);
      EXPECT_NEAR(LoadingUnloadingSlope(f, id, halfway, history), peak / (0.1 - permanent),
                  1e-9 * peak / 0.1);
      EXPECT_NEAR(Returned(f, id, history), 0.5 * peak * (0.1 - permanent), 1e-6 * peak * 0.1);
      EXPECT_LE(Returned(f, id, history), energy * (1 + 1e-9));
    }
    // The linear function's line is the slope's: its set is 1 - 1/s (s = 1.5 included).
    LoadingHistory history;
    UpdateLoadingHistory(f, linear, 0.1, history);
    EXPECT_NEAR(history.permanent, 0.1 * (1 - 1 / s), 1e-15) << s;
  }
}

TEST(ForceDeflection, AnUnloadSlopeNeverReturnsMoreThanTheLoadingWork) {
  // s = 0.5 would end at -x_max: the line is bounded where it returns the loading work, the
  // linear function's own line back to zero.
  FunctionTable f;
  const auto id = AddTableFunction(f, {{0, 0}, {1, 1000}});
  f.unload_slope = {0.5};
  LoadingHistory history;
  UpdateLoadingHistory(f, id, 0.1, history);
  EXPECT_EQ(history.permanent, 0.0);
  EXPECT_NEAR(Returned(f, id, history), IntegrateFunction(f, id, 0.1), 1e-9);
}

TEST(ForceDeflection, AMirroredLawReadsTheFunctionOnItsNegativeSide) {
  // A table over negative and positive x, read for the deflection -x: F(d) = -f(-d), and the
  // loading energy is that of the negative side.
  FunctionTable f;
  const auto id = AddTableFunction(f, {{-1, -3000}, {0, 0}, {1, 1000}}, 0.5);
  LoadingHistory history;
  UpdateLoadingHistory(f, id, 0.1, history, -1.0);
  EXPECT_DOUBLE_EQ(history.max_force, 300.0);
  EXPECT_DOUBLE_EQ(LoadingUnloadingForce(f, id, 0.2, history, -1.0), 600.0);
  EXPECT_NEAR(Returned(f, id, history, -1.0), 0.5 * 0.5 * 300 * 0.1, 1e-6);
}

}  // namespace
}  // namespace sled::runtime
