// One evaluation of a vehicle's prescribed motion (runtime::VehicleAt) on six-degree-of-freedom
// tables of 301, 3,003 and 6,003 rows (0.1 ms apart): the row before the time is found by a
// binary search, so the cost grows with log2 of the rows (docs/runtime.md, Vehicle motion).
//
//   sled_bench_vehicle_lookup_bench --benchmark_repetitions=5
//
// BM_SixDofVehicleAt: linear accelerations only (closed form from the rows' velocity and
// displacement). BM_TurningVehicleAt: with an angular acceleration (the tabulated path, one
// fourth-order step from the sample before t, four lookups of the table).
#include <cmath>
#include <cstdint>
#include <vector>

#include <benchmark/benchmark.h>

#include "runtime/dynamics/vehicle.h"

namespace sled::bench {
namespace {

using runtime::Mat3;
using runtime::Vec3;

runtime::Model SixDofModel(std::int64_t rows, bool turning) {
  runtime::VehicleMotion motion;
  motion.kind = runtime::VehicleMotion::Kind::kSixDof;
  for (std::int64_t k = 0; k < rows; ++k) {
    const double t = 1e-4 * static_cast<double>(k);
    const double a = -240.0 * std::sin(31.4 * t);
    motion.six_dof.push_back({t, a, 0.1 * a, 0, 0, turning ? 0.05 * a : 0.0, 0});
  }
  runtime::IntegrateMotionRows(motion);
  runtime::Model model;
  model.vehicle_name = {"sled"};
  model.vehicle_motion = {motion};
  model.vehicle_position = {Vec3::Zero()};
  model.vehicle_orientation = {Mat3::Identity()};
  model.vehicle_velocity = {Vec3::Zero()};
  model.vehicle_angular_velocity = {Vec3::Zero()};
  model.vehicle_path = {
      runtime::TabulateVehiclePath(model.vehicle_motion[0], Mat3::Identity(), Vec3::Zero())};
  return model;
}

void RunVehicleAt(benchmark::State& state, bool turning) {
  const runtime::Model model = SixDofModel(state.range(0), turning);
  // 97 times spread over the table, off the rows.
  const double span = 1e-4 * static_cast<double>(state.range(0) - 1);
  std::vector<double> times(97);
  for (std::size_t k = 0; k < times.size(); ++k) {
    times[k] = span * (static_cast<double>(k) + 0.37) / static_cast<double>(times.size());
  }
  std::size_t next = 0;
  for (auto _ : state) {
    const runtime::VehicleState vehicle = runtime::VehicleAt(model, 0, times[next]);
    benchmark::DoNotOptimize(vehicle.position.data());
    next = next + 1 == times.size() ? 0 : next + 1;
  }
}

void BM_SixDofVehicleAt(benchmark::State& state) { RunVehicleAt(state, false); }
void BM_TurningVehicleAt(benchmark::State& state) { RunVehicleAt(state, true); }

BENCHMARK(BM_SixDofVehicleAt)->Arg(301)->Arg(3003)->Arg(6003)->Unit(benchmark::kNanosecond);
BENCHMARK(BM_TurningVehicleAt)->Arg(301)->Arg(3003)->Arg(6003)->Unit(benchmark::kNanosecond);

}  // namespace
}  // namespace sled::bench

BENCHMARK_MAIN();
