// The belts' event rates (runtime/restraint/belt_events.h): UpdateBeltRates takes each junction's
// transfer rate from the slip equations' derivative (implicit differentiation, no slip solve).
// Here they are checked against central differences of the whole belt evaluation, slip solve
// included, along the motion, at the states of a flagship run where its junctions slip or stick
// and its spans load and unload.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "runtime/dynamics/dynamics.h"
#include "runtime/dynamics/joint.h"
#include "runtime/forces/forces.h"
#include "runtime/restraint/belt_events.h"
#include "runtime/restraint/belts.h"
#include "tests/verification/compile.h"
#include "tests/verification/verification.h"

namespace sled::verification {
namespace {

using runtime::Data;
using runtime::Model;

struct BeltRates {
  std::vector<double> slip;    // per junction [m/s]
  std::vector<double> strain;  // per span [1/s]
};

// The rates by central differences over `step` seconds along q' of EvaluateBelts (the geometry
// and the slip solve): each junction's transfer less the webbing its body carries past the
// body point under the webbing's middle now, and each span's strain. Leaves data as Forward does.
BeltRates CentralDifferences(const Model& model, Data& data, double step) {
  const runtime::BeltState& state = data.belts;
  const std::size_t junctions = state.transfer.size(), spans = state.length.size();
  std::vector<runtime::Vec3> anchor(junctions, runtime::Vec3::Zero());
  for (std::size_t j = 0; j < junctions; ++j) {
    const std::int32_t point = state.junction_point[j];
    if (point < 0) continue;
    const auto k = static_cast<std::size_t>(point);
    const auto s = static_cast<std::size_t>(model.belts.point_frame[k].index);
    anchor[j] = data.rotation[s].transpose() * (state.middle[k] - data.position[s]);
  }
  const std::vector<double> q = data.q;
  std::vector<double> dq(q.size());
  runtime::PositionDerivative(model, data.q, data.v, data.locked, dq);
  const double t = data.time;
  BeltRates rates{std::vector<double>(junctions, 0.0), std::vector<double>(spans, 0.0)};
  for (const double sign : {-1.0, 1.0}) {
    for (std::size_t i = 0; i < q.size(); ++i) data.q[i] = q[i] + sign * 0.5 * step * dq[i];
    data.time = t + sign * 0.5 * step;
    runtime::ComputeKinematics(model, data);
    runtime::EvaluateBelts(model, data);
    for (std::size_t j = 0; j < junctions; ++j) {
      double slip = state.transfer[j];
      const std::int32_t point = state.junction_point[j];
      if (point >= 0 && state.contact[static_cast<std::size_t>(point)]) {
        const auto a = static_cast<std::size_t>(state.junction_first[j]);
        const auto c = static_cast<std::size_t>(state.junction_second[j]);
        const double stretch =
            0.5 * (state.length[a] / state.rest_length[a] + state.length[c] / state.rest_length[c]);
        slip -= runtime::CarriedLength(model, data, j, anchor[j]) / std::max(stretch, 1e-3);
      }
      rates.slip[j] += sign * slip / step;
    }
    for (std::size_t span = 0; span < spans; ++span) {
      rates.strain[span] += sign * (state.length[span] / state.rest_length[span] - 1.0) / step;
    }
  }
  data.q = q;
  data.time = t;
  EXPECT_TRUE(runtime::Forward(model, data, nullptr));
  return rates;
}

TEST(BeltRates, TheSlipEquationsDerivativeMatchesCentralDifferencesOnTheFlagship) {
  const Compiled compiled =
      CompileFile(std::filesystem::path(SLED_SOURCE_ROOT) / "examples" / "frontal_sled.sled");
  ASSERT_EQ(compiled.errors, "");
  const Model& model = compiled.model();
  Data data = runtime::MakeData(model);
  ASSERT_TRUE(runtime::Forward(model, data, nullptr));
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  int compared = 0, slipping = 0, carried = 0;
  double worst_slip = 0.0, worst_strain = 0.0, largest_slip = 0.0, largest_strain = 0.0;
  ASSERT_TRUE(Simulate(model, data, "dopri5", 1e-6, Linspace(0, 0.2, 400), [&](const Data&) {
    runtime::BeltState& state = data.belts;
    // (UpdateBeltRates writes the rates only when an event function needs them.)
    std::fill(state.slip_rate.begin(), state.slip_rate.end(), kNaN);
    std::fill(state.strain_rate.begin(), state.strain_rate.end(), kNaN);
    runtime::UpdateBeltRates(model, data);
    if (std::isnan(state.strain_rate[0])) return;
    const std::vector<double> slip = state.slip_rate, strain = state.strain_rate;
    const BeltRates reference = CentralDifferences(model, data, 1e-6);
    ++compared;
    for (std::size_t j = 0; j < slip.size(); ++j) {
      const runtime::JunctionMode mode = state.mode[j];
      slipping += mode == runtime::JunctionMode::kSlipIntoFirst ||
                  mode == runtime::JunctionMode::kSlipIntoSecond;
      carried += mode == runtime::JunctionMode::kStick && state.carried_arc[j] != 0.0;
      worst_slip = std::max(worst_slip, std::abs(slip[j] - reference.slip[j]));
      largest_slip = std::max(largest_slip, std::abs(reference.slip[j]));
    }
    for (std::size_t span = 0; span < strain.size(); ++span) {
      worst_strain = std::max(worst_strain, std::abs(strain[span] - reference.strain[span]));
      largest_strain = std::max(largest_strain, std::abs(reference.strain[span]));
    }
  }));
  std::printf(
      "  %d states (%d slipping and %d carried junctions): slip rates within %.3g m/s of "
      "the differences (largest %.3g), strain rates within %.3g 1/s (largest %.3g)\n",
      compared, slipping, carried, worst_slip, largest_slip, worst_strain, largest_strain);
  // The run must have had junctions that slip and junctions their bodies carry, or the test
  // says nothing about the slip equations' derivative.
  EXPECT_GT(compared, 50);
  EXPECT_GT(slipping, 20);
  EXPECT_GT(carried, 20);
  // The differences' own error: rounding of lengths near 1 m over 1e-6 s, some 1e-9.
  EXPECT_LT(worst_slip, 1e-6 * largest_slip + 1e-7);
  EXPECT_LT(worst_strain, 1e-6 * largest_strain + 1e-7);
}

}  // namespace
}  // namespace sled::verification
