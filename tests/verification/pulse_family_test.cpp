// Pulse families and prescribed displacement against closed forms, through the language: a
// trapezoid given by delta-v and duration changes the vehicle's velocity by exactly delta-v over
// exactly the duration, at the peak delta_v / (T - (rise + fall) / 2); a displacement history
// puts the vehicle on every recorded sample, and between them on the natural cubic spline
// (computed here independently, by its closed-form piece on each interval).
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "runtime/dynamics/vehicle.h"
#include "tests/verification/compile.h"

namespace sled::verification {
namespace {

Compiled Scene(const std::string& motion) {
  return CompileText(R"(scenario "pulse" {
  time { end = 200 ms  output_every = 1 ms }
  vehicle sled {
    position = (1, 0, 0) m
    motion = )" + motion +
                     R"(
  }
}
)");
}

TEST(PulseFamily, ATrapezoidByDeltaVAndDurationGivesBoth) {
  const Compiled compiled =
      Scene("trapezoid(delta_v = 16 km/h, duration = 90 ms, rise = 20 ms, fall = 40 ms, axis = x)");
  ASSERT_TRUE(compiled.errors.empty()) << compiled.errors;
  const runtime::Model& model = compiled.model();
  const double delta_v = 16.0 / 3.6;
  const double peak = delta_v / (0.090 - 0.5 * (0.020 + 0.040));
  EXPECT_NEAR(model.vehicle_motion[0].peak, peak, 1e-12 * peak);
  // Velocity before, at and after the pulse.
  EXPECT_NEAR(runtime::VehicleAt(model, 0, 0.0).velocity.x(), 0.0, 1e-15);
  EXPECT_NEAR(runtime::VehicleAt(model, 0, 0.090).velocity.x(), delta_v, 1e-12);
  EXPECT_NEAR(runtime::VehicleAt(model, 0, 0.150).velocity.x(), delta_v, 1e-12);
  // On the plateau, the peak; after the end, nothing.
  EXPECT_NEAR(runtime::VehicleAt(model, 0, 0.040).acceleration.x(), peak, 1e-9 * peak);
  EXPECT_NEAR(runtime::VehicleAt(model, 0, 0.095).acceleration.x(), 0.0, 1e-12);
}

TEST(PulseFamily, ATrapezoidShorterThanItsRampsIsRefused) {
  const Compiled compiled =
      Scene("trapezoid(delta_v = 16 km/h, duration = 50 ms, rise = 30 ms, fall = 30 ms)");
  EXPECT_NE(compiled.errors.find("E0409"), std::string::npos) << compiled.errors;
}

// The natural cubic spline through (t_i, x_i) at t, solved here by Gaussian elimination of the
// full system (independent of the checker's tridiagonal sweep).
double Spline(const std::vector<std::array<double, 2>>& rows, double t) {
  const std::size_t n = rows.size();
  std::vector<std::vector<double>> a(n, std::vector<double>(n + 1, 0.0));
  a[0][0] = 1.0;
  a[n - 1][n - 1] = 1.0;
  for (std::size_t i = 1; i + 1 < n; ++i) {
    const double h0 = rows[i][0] - rows[i - 1][0], h1 = rows[i + 1][0] - rows[i][0];
    a[i][i - 1] = h0;
    a[i][i] = 2.0 * (h0 + h1);
    a[i][i + 1] = h1;
    a[i][n] = 6.0 * ((rows[i + 1][1] - rows[i][1]) / h1 - (rows[i][1] - rows[i - 1][1]) / h0);
  }
  for (std::size_t c = 0; c < n; ++c) {
    for (std::size_t r = c + 1; r < n; ++r) {
      const double f = a[r][c] / a[c][c];
      for (std::size_t k = c; k <= n; ++k) a[r][k] -= f * a[c][k];
    }
  }
  std::vector<double> m(n, 0.0);
  for (std::size_t c = n; c-- > 0;) {
    double sum = a[c][n];
    for (std::size_t k = c + 1; k < n; ++k) sum -= a[c][k] * m[k];
    m[c] = sum / a[c][c];
  }
  std::size_t i = 0;
  while (i + 2 < n && t > rows[i + 1][0]) ++i;
  const double h = rows[i + 1][0] - rows[i][0];
  const double u = rows[i + 1][0] - t, w = t - rows[i][0];
  return m[i] * u * u * u / (6 * h) + m[i + 1] * w * w * w / (6 * h) +
         (rows[i][1] / h - m[i] * h / 6) * u + (rows[i + 1][1] / h - m[i + 1] * h / 6) * w;
}

TEST(PulseFamily, ADisplacementHistoryIsFollowedThroughItsSamples) {
  const std::vector<std::array<double, 2>> rows = {
      {0.000, 0.000}, {0.020, 0.290}, {0.035, 0.480}, {0.060, 0.700}, {0.100, 0.880}};
  const Compiled compiled = Scene(R"(table(time -> displacement, axis = -x) {
      0 ms -> 0 mm
      20 ms -> 290 mm
      35 ms -> 480 mm
      60 ms -> 700 mm
      100 ms -> 880 mm
    })");
  ASSERT_TRUE(compiled.errors.empty()) << compiled.errors;
  const runtime::Model& model = compiled.model();
  for (const auto& row : rows) {
    EXPECT_NEAR(runtime::VehicleAt(model, 0, row[0]).position.x(), 1.0 - row[1], 1e-12)
        << "at " << row[0] << " s";
  }
  for (double t = 0.0; t <= 0.100; t += 0.0025) {
    EXPECT_NEAR(runtime::VehicleAt(model, 0, t).position.x(), 1.0 - Spline(rows, t), 1e-12)
        << "at " << t << " s";
  }
  // Natural ends: no acceleration at the first and the last sample; after the last, a steady
  // motion at the spline's end rate.
  EXPECT_NEAR(runtime::VehicleAt(model, 0, 0.0).acceleration.x(), 0.0, 1e-12);
  const double end_rate = (Spline(rows, 0.100) - Spline(rows, 0.100 - 1e-6)) / 1e-6;
  EXPECT_NEAR(runtime::VehicleAt(model, 0, 0.150).velocity.x(), -end_rate, 1e-4);
  EXPECT_NEAR(runtime::VehicleAt(model, 0, 0.150).position.x(),
              1.0 - rows.back()[1] - end_rate * 0.050, 1e-6);
}

TEST(PulseFamily, ADisplacementHistoryStartsAtZero) {
  const Compiled compiled = Scene(R"(table(time -> displacement) {
      5 ms -> 0 mm
      20 ms -> 290 mm
    })");
  EXPECT_NE(compiled.errors.find("starts at 0 ms"), std::string::npos) << compiled.errors;
}

}  // namespace
}  // namespace sled::verification
