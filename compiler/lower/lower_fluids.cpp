// Wind and water: one row of the Model's fluid table for each contact ellipsoid of each segment a
// `wind` or `water` block names (runtime/forces/fluid_forces.h). Water's `direction` is up,
// against gravity, which the checker requires for water.
#include "compiler/lower/lowering.h"

namespace sled::compiler::lowering {

void LowerFluids(Lowering& lowering) {
  runtime::Model& model = lowering.model();
  const CheckedScenario& scenario = lowering.scenario();
  runtime::FluidTable& fluids = model.fluids;
  for (const Fluid& fluid : scenario.fluids) {
    const bool wind = fluid.medium == Fluid::Medium::kWind;
    const runtime::Vec3 direction = wind ? runtime::Vec3(ToEigen(fluid.direction).normalized())
                                         : runtime::Vec3(-model.gravity.normalized());
    const std::int32_t speed = wind ? lowering.Function(fluid.speed) : -1;
    const std::int32_t pressure = wind ? lowering.Function(fluid.pressure) : -1;
    for (const int old : fluid.segments) {
      const std::int32_t segment = lowering.new_index[static_cast<std::size_t>(old)];
      if (segment < 0) continue;  // symmetry is refused with fluids, so every segment is kept
      for (const int e : lowering.segment(old).ellipsoids) {
        const Ellipsoid& ellipsoid = scenario.ellipsoids[static_cast<std::size_t>(e)];
        fluids.medium.push_back(wind ? runtime::FluidTable::Medium::kWind
                                     : runtime::FluidTable::Medium::kWater);
        fluids.segment.push_back(segment);
        fluids.center.push_back(ToEigen(ellipsoid.center));
        fluids.axes.push_back(RotationMatrix(ellipsoid.orientation));
        fluids.semi_axes.push_back(ToEigen(ellipsoid.semi_axes));
        fluids.drag.push_back(fluid.drag);
        fluids.density.push_back(fluid.density);
        fluids.speed.push_back(speed);
        fluids.pressure.push_back(pressure);
        fluids.direction.push_back(direction);
        fluids.carrier.push_back(wind ? lowering.Frame(fluid.carrier) : runtime::FrameRef{});
        fluids.level.push_back(wind ? 0.0 : fluid.level);
      }
    }
  }
}

}  // namespace sled::compiler::lowering
