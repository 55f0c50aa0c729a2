// ATB's unloading and reloading law (runtime/forces/atb_unloading.h) against hand computations
// from ATB's equations (DEF_NEW_QUADRATIC, DEF_NEW_CUBIC). The loading function is the line
// f(x) = k x, k = 1e5 N/m, loaded to x_max = 0.1 m: f(x_max) = 1e4 N, loading energy E = 500 J.
// With R = 0.6 and G = 0.25: x_g = 0.025 m, d = 0.075 m, the quadratic returns R E = 300 J:
// A1 = 2/d (3 R E / d - f) = 160000/3 N/m, A2 = (f / d - A1) / d = 3200000/3 N/m^2.
#include <cmath>

#include <gtest/gtest.h>

#include "runtime/forces/atb_unloading.h"
#include "runtime/forces/force_deflection.h"
#include "tests/runtime/model_fixtures.h"

namespace sled::runtime {
namespace {

constexpr double kStiffness = 1e5;

std::int32_t AddConstant(FunctionTable& f, double value) {
  f.kind.push_back(FunctionTable::Kind::kConstant);
  f.constant.push_back(value);
  f.first.push_back(-1);
  f.count.push_back(0);
  f.energy_loss.push_back(0);
  f.permanent_set.push_back(0);
  f.atb_return.push_back(-1);
  f.atb_set.push_back(-1);
  return static_cast<std::int32_t>(f.size() - 1);
}

// The line k x with ATB's law; R and G are the given functions (G -1: none).
std::int32_t AddAtbLine(FunctionTable& f, std::int32_t r, std::int32_t g) {
  const std::int32_t id = testing::AddTableFunction(f, {{0, 0}, {1, kStiffness}});
  f.atb_return.push_back(r);
  f.atb_set.push_back(g);
  return id;
}

// The energy the law returns from x_max down to zero, by Simpson's rule on 20000 intervals.
double Returned(const FunctionTable& f, std::int32_t id, const LoadingHistory& h) {
  const int n = 20000;
  const double step = h.max_deflection / n;
  double sum = 0.0;
  for (int k = 0; k <= n; ++k) {
    const double w = (k == 0 || k == n) ? 1 : (k % 2 ? 4 : 2);
    sum += w * LoadingUnloadingForce(f, id, k * step, h);
  }
  return sum * step / 3;
}

TEST(AtbUnloading, QuadraticThroughTheLargestForceReturnsRAndEndsAtG) {
  FunctionTable f;
  const std::int32_t r = AddConstant(f, 0.6);
  const std::int32_t g = AddConstant(f, 0.25);
  const std::int32_t id = AddAtbLine(f, r, g);
  ASSERT_TRUE(HasHysteresis(f, id));
  LoadingHistory h;
  EXPECT_DOUBLE_EQ(LoadingUnloadingForce(f, id, 0.05, h), 5000.0);  // loading: f
  UpdateLoadingHistory(f, id, 0.1, h);
  EXPECT_NEAR(h.permanent, 0.025, 1e-15);
  EXPECT_NEAR(h.quadratic[0], 160000.0 / 3, 1e-8);
  EXPECT_NEAR(h.quadratic[1], 3200000.0 / 3, 1e-6);
  EXPECT_NEAR(LoadingUnloadingForce(f, id, 0.1 - 1e-12, h), 1e4, 1e-5);
  // u = 0.025: A1 u + A2 u^2 = 4000/3 + 2000/3.
  EXPECT_NEAR(LoadingUnloadingForce(f, id, 0.05, h), 2000.0, 1e-9);
  EXPECT_EQ(LoadingUnloadingForce(f, id, 0.02, h), 0.0);  // below x_g
  EXPECT_NEAR(Returned(f, id, h), 300.0, 1e-9);
  // Beyond x_max it loads along f again.
  EXPECT_DOUBLE_EQ(LoadingUnloadingForce(f, id, 0.12, h), 12000.0);
}

TEST(AtbUnloading, ReloadsAlongTheCubicAndUnloadsAgainFromATurnOnIt) {
  FunctionTable f;
  const std::int32_t id = AddAtbLine(f, AddConstant(f, 0.6), AddConstant(f, 0.25));
  LoadingHistory h;
  UpdateLoadingHistory(f, id, 0.1, h);
  // Turns to reload at 0.05 m: the cubic from (0.05, 2000 N) with the quadratic's slope
  // A1 + 2 A2 u = 320000/3 N/m to (0.1, 1e4 N) with f's slope 1e5 N/m, dx = 0.05:
  // r13 = (1e4 - 2000 - 320000/3 dx) / dx^2 = 3200000/3, r23 = (1e5 - 320000/3) / dx = -400000/3,
  // c2 = 3 r13 - r23 = 1e7/3, c3 = (r23 - 2 r13) / dx = -1.36e8/3 (its stationary points,
  // s = -0.0127 and 0.0617, are outside (0, dx): the cubic stands).
  UpdateLoadingHistory(f, id, 0.05, h);
  EXPECT_FALSE(h.unloading);
  EXPECT_NEAR(h.cubic[1], 320000.0 / 3, 1e-8);
  EXPECT_NEAR(h.cubic[2], 1e7 / 3, 1e-5);
  EXPECT_NEAR(h.cubic[3], -1.36e8 / 3, 1e-3);
  // s = 0.025: 2000 + 2666.67 + 2083.33 - 708.33 = 2000 + 12125/3.
  EXPECT_NEAR(LoadingUnloadingForce(f, id, 0.075, h), 2000 + 12125.0 / 3, 1e-8);
  EXPECT_NEAR(LoadingUnloadingForce(f, id, 0.1 - 1e-12, h), 1e4, 1e-5);
  EXPECT_NEAR(LoadingUnloadingSlope(f, id, 0.1 - 1e-12, h), 1e5, 1e-3);
  // Turning back at 0.075 m: the path came up the quadratic from 0.025 to 0.05 (A1 u^2/2 +
  // A2 u^3/3 = 200/9 J) and the cubic to 0.075 (50 + 33.333 + 17.361 - 4.427 = 96.267 J); R of
  // that, 71.09 J, asks for A1 = 2/d (3 * 71.09 / d - 6041.67) < 0, so A1 = 0 and
  // A2 = 6041.67 / d^2 (d = 0.05): the quadratic returns f d / 3 = 100.69 J.
  UpdateLoadingHistory(f, id, 0.075, h);
  EXPECT_TRUE(h.unloading);
  EXPECT_EQ(h.quadratic[0], 0.0);
  const double top = 2000 + 12125.0 / 3;
  EXPECT_NEAR(h.quadratic[1], top / 0.0025, 1e-6);
  EXPECT_NEAR(LoadingUnloadingForce(f, id, 0.05, h), top / 4, 1e-9);
  // A reload from here climbs a new cubic to the same x_max, whose force there is f's.
  UpdateLoadingHistory(f, id, 0.04, h);
  EXPECT_NEAR(LoadingUnloadingForce(f, id, 0.1 - 1e-12, h), 1e4, 1e-5);
  EXPECT_NEAR(LoadingUnloadingForce(f, id, 0.04, h), top * 0.015 * 0.015 / 0.0025, 1e-9);
}

TEST(AtbUnloading, ClampsOfTheQuadraticAndRWithoutG) {
  FunctionTable f;
  // R = 0.8 alone (G = 0): d = 0.1, R E = 400 J: A1 = 20 (12000 - 1e4) = 40000, A2 = 6e5.
  const std::int32_t alone = AddAtbLine(f, AddConstant(f, 0.8), -1);
  LoadingHistory h;
  UpdateLoadingHistory(f, alone, 0.1, h);
  EXPECT_EQ(h.permanent, 0.0);
  EXPECT_NEAR(h.quadratic[0], 40000.0, 1e-8);
  EXPECT_NEAR(h.quadratic[1], 6e5, 1e-6);
  EXPECT_NEAR(Returned(f, alone, h), 400.0, 1e-9);
  // R = 0.1, G = 0: A1 = 20 (1500 - 1e4) < 0, so A1 = 0: the parabola returns f d / 3.
  const std::int32_t low = AddAtbLine(f, AddConstant(f, 0.1), -1);
  LoadingHistory l;
  UpdateLoadingHistory(f, low, 0.1, l);
  EXPECT_NEAR(Returned(f, low, l), 1e4 * 0.1 / 3, 1e-9);
  // R = 0.9, G = 0.5: d = 0.05, A1 = 40 (27000 - 1e4) = 680000 gives A2 < 0: the straight line,
  // which returns f d / 2 = 250 J (not 450).
  const std::int32_t high = AddAtbLine(f, AddConstant(f, 0.9), AddConstant(f, 0.5));
  LoadingHistory s;
  UpdateLoadingHistory(f, high, 0.1, s);
  EXPECT_NEAR(s.quadratic[0], 2e5, 1e-8);
  EXPECT_EQ(s.quadratic[1], 0.0);
  EXPECT_NEAR(Returned(f, high, s), 250.0, 1e-9);
  // R = 1: it unloads along f.
  const std::int32_t elastic = AddAtbLine(f, AddConstant(f, 1.0), AddConstant(f, 0.5));
  LoadingHistory e;
  UpdateLoadingHistory(f, elastic, 0.1, e);
  EXPECT_DOUBLE_EQ(LoadingUnloadingForce(f, elastic, 0.03, e), 3000.0);
  EXPECT_EQ(TurnEventFunction(f, elastic, 0.03, -1.0, e), 1.0);
}

TEST(AtbUnloading, FactorsAreEvaluatedAtTheLargestDeflection) {
  FunctionTable f;
  // R(x) from 1 at 0 to 0.2 at 0.2 m: 0.6 at x_max = 0.1; G(x) = 2.5 x: 0.25 there.
  const std::int32_t r = testing::AddTableFunction(f, {{0, 1}, {0.2, 0.2}});
  f.atb_return.push_back(-1);
  f.atb_set.push_back(-1);
  const std::int32_t g = testing::AddTableFunction(f, {{0, 0}, {1, 2.5}});
  f.atb_return.push_back(-1);
  f.atb_set.push_back(-1);
  const std::int32_t id = AddAtbLine(f, r, g);
  LoadingHistory h;
  UpdateLoadingHistory(f, id, 0.1, h);
  EXPECT_NEAR(h.energy_return, 0.6, 1e-15);
  EXPECT_NEAR(h.permanent, 0.025, 1e-15);
  EXPECT_NEAR(Returned(f, id, h), 300.0, 1e-9);
  // At x_max = 0.05 m: R = 0.8, G = 0.125.
  LoadingHistory small;
  UpdateLoadingHistory(f, id, 0.05, small);
  EXPECT_NEAR(small.permanent, 0.125 * 0.05, 1e-15);
  EXPECT_NEAR(Returned(f, id, small), 0.8 * kStiffness * 0.05 * 0.05 / 2, 1e-9);
}

TEST(AtbUnloading, TurnEventsFallThroughZeroWhereTheHistoryMustChange) {
  FunctionTable f;
  const std::int32_t id = AddAtbLine(f, AddConstant(f, 0.6), AddConstant(f, 0.25));
  LoadingHistory h;
  EXPECT_EQ(TurnEventFunction(f, id, 0.05, 2.0, h), 2.0);  // loading: the rate
  UpdateLoadingHistory(f, id, 0.1, h);
  EXPECT_DOUBLE_EQ(TurnEventFunction(f, id, 0.06, -2.0, h),
                   0.035);  // unloading: min(-rate, x - x_g)
  EXPECT_EQ(TurnEventFunction(f, id, 0.08, -0.01, h), 0.01);
  EXPECT_LT(TurnEventFunction(f, id, 0.02, -2.0, h), 0.0);  // passed x_g
  UpdateLoadingHistory(f, id, 0.02, h);                     // reloads from x_g, not below
  EXPECT_EQ(h.cubic_start, 0.025);
  EXPECT_EQ(LoadingUnloadingForce(f, id, 0.02, h), 0.0);
  EXPECT_EQ(TurnEventFunction(f, id, -0.01, 0.0, h), 1.0);  // apart: nothing to turn
  EXPECT_EQ(TurnEventFunction(f, id, 0.05, 1.5, h), 1.5);   // reloading: the rate
}

// Gives function `id` ATB's inertial spike `spike` ending at `end` and the origin D0 (the other
// functions none: the arrays are per function).
void SetSpikeAndOrigin(FunctionTable& f, std::int32_t id, std::int32_t spike, double end,
                       double origin) {
  f.atb_spike.assign(f.size(), -1);
  f.atb_spike_end.assign(f.size(), 0.0);
  f.atb_origin.assign(f.size(), 0.0);
  const auto at = static_cast<std::size_t>(id);
  f.atb_spike[at] = spike;
  f.atb_spike_end[at] = end;
  f.atb_origin[at] = origin;
}

TEST(AtbUnloading, TheSpikeLoadsWithTheFunctionUntilALargestDeflectionPassesItsEnd) {
  // f = k x plus a spike of 500 N ending at 0.05 m, R = 0.6, G = 0.25. Loaded to x_max = 0.04 m
  // (before the end): F(x_max) = 4000 + 500 N, the energy of f alone 80 J, x_g = 0.01 m,
  // d = 0.03 m: A1 = 2/d (3 R E / d - F) = 20000 N/m, A2 = (F / d - A1) / d = 13e6/3 N/m^2,
  // whose area A1 d^2 / 2 + A2 d^3 / 3 = 9 + 39 J is R E = 48 J.
  FunctionTable f;
  const std::int32_t spike = AddConstant(f, 500.0);
  const std::int32_t id = AddAtbLine(f, AddConstant(f, 0.6), AddConstant(f, 0.25));
  SetSpikeAndOrigin(f, id, spike, 0.05, 0.0);
  LoadingHistory h;
  EXPECT_DOUBLE_EQ(LoadingUnloadingForce(f, id, 0.03, h), 3500.0);
  EXPECT_DOUBLE_EQ(LoadingUnloadingSlope(f, id, 0.03, h), kStiffness);
  UpdateLoadingHistory(f, id, 0.04, h);
  EXPECT_FALSE(h.spike_dropped);
  EXPECT_DOUBLE_EQ(h.max_force, 4500.0);
  EXPECT_NEAR(h.quadratic[0], 20000.0, 1e-8);
  EXPECT_NEAR(h.quadratic[1], 13e6 / 3, 1e-6);
  EXPECT_NEAR(Returned(f, id, h), 48.0, 1e-9);
  EXPECT_DOUBLE_EQ(LoadingUnloadingForce(f, id, 0.045, h), 5000.0);  // loading on, spike still
  // The turn event falls through zero where the deflection reaches the spike's end.
  EXPECT_DOUBLE_EQ(TurnEventFunction(f, id, 0.045, 1.0, h), 0.05 - 0.045);
  EXPECT_LT(TurnEventFunction(f, id, 0.051, 1.0, h), 0.0);
  UpdateLoadingHistory(f, id, 0.051, h);
  EXPECT_TRUE(h.spike_dropped);
  EXPECT_DOUBLE_EQ(h.max_force, 5100.0);  // f alone from here on
  EXPECT_DOUBLE_EQ(LoadingUnloadingForce(f, id, 0.06, h), 6000.0);
  EXPECT_EQ(TurnEventFunction(f, id, 0.06, 1.0, h), 1.0);  // the rate: no spike left to drop
}

TEST(AtbUnloading, AnElasticSpikeLoadsAndUnloadsAlongTheFunctionPlusTheSpike) {
  // R = 1: ATB unloads along its loading curve, which holds the spike until its end.
  FunctionTable f;
  const std::int32_t spike = testing::AddTableFunction(f, {{0, 800}, {0.1, 0}});
  f.atb_return.push_back(-1);
  f.atb_set.push_back(-1);
  const std::int32_t id = AddAtbLine(f, AddConstant(f, 1.0), -1);
  SetSpikeAndOrigin(f, id, spike, 0.05, 0.0);
  LoadingHistory h;
  UpdateLoadingHistory(f, id, 0.04, h);
  EXPECT_TRUE(h.elastic);
  // k x + 800 (1 - x / 0.1) at 0.02 m on the way down: 2000 + 640 N; slope k - 8000 N/m.
  EXPECT_DOUBLE_EQ(LoadingUnloadingForce(f, id, 0.02, h), 2640.0);
  EXPECT_DOUBLE_EQ(LoadingUnloadingSlope(f, id, 0.02, h), kStiffness - 8000.0);
  UpdateLoadingHistory(f, id, 0.05, h);  // reaches the end: dropped, k x alone both ways
  EXPECT_DOUBLE_EQ(LoadingUnloadingForce(f, id, 0.02, h), 2000.0);
}

TEST(AtbUnloading, TheOriginStartsTheLoadingEnergyAndThePermanentSet) {
  // D0 = 0.01 m, f = k x, R = 0.6, G = 0.25, x_max = 0.1 m: x_g = D0 + G (x_max - D0) =
  // 0.0325 m, E = k (x_max^2 - D0^2) / 2 = 495 J, so the quadratic returns R E = 297 J:
  // d = 0.0675 m, A1 = 2/d (3 R E / d - f(x_max)) = 2/d (13200 - 10000) N.
  FunctionTable f;
  const std::int32_t id = AddAtbLine(f, AddConstant(f, 0.6), AddConstant(f, 0.25));
  SetSpikeAndOrigin(f, id, -1, 0.0, 0.01);
  LoadingHistory h;
  UpdateLoadingHistory(f, id, 0.1, h);
  EXPECT_NEAR(h.permanent, 0.0325, 1e-15);
  EXPECT_NEAR(h.quadratic[0], 2 / 0.0675 * 3200, 1e-8);
  EXPECT_NEAR(Returned(f, id, h), 297.0, 1e-9);
  EXPECT_EQ(LoadingUnloadingForce(f, id, 0.03, h), 0.0);  // below x_g
  // Without G the force reaches zero at D0 itself; d = 0.09 m makes A1 negative, clamped to 0,
  // so the quadratic returns f(x_max) d / 3 = 300 J (more than R E, ATB's clamp).
  FunctionTable g;
  const std::int32_t no_set = AddAtbLine(g, AddConstant(g, 0.6), -1);
  SetSpikeAndOrigin(g, no_set, -1, 0.0, 0.01);
  LoadingHistory h0;
  UpdateLoadingHistory(g, no_set, 0.1, h0);
  EXPECT_NEAR(h0.permanent, 0.01, 1e-15);
  EXPECT_EQ(h0.quadratic[0], 0.0);
  EXPECT_NEAR(Returned(g, no_set, h0), 300.0, 1e-9);
}

}  // namespace
}  // namespace sled::runtime
