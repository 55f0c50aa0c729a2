// Wind and water: `wind { speed  direction  density  drag  segments }` and
// `water { level  density  drag  segments }` (FluidChecker, checkers.h). They act on the contact
// ellipsoids of the segments they name; what the runtime cannot take is E0425, never ignored:
// a segment without an ellipsoid or with a hyper-ellipsoid (its volume and projected area are
// not the ellipsoid's), water without gravity (nothing to float against), either under symmetry
// (the mirrored or planar half would feel a flow that is not symmetric).
#include <map>

#include <fmt/format.h>

#include "compiler/check/checkers.h"

namespace sled::compiler::internal {

void FluidChecker::CheckFluids(Scope& scope) {
  // The wind each segment is in: two airs' drags do not add (the drag is quadratic in the
  // velocity relative to the air), so a segment is in one wind.
  std::map<int, const ast::Expr*> in_wind;
  for (const ast::Statement* statement : run_blocks_) {
    const bool wind = statement->keyword == "wind";
    if (!wind && statement->keyword != "water") continue;
    const BlockKind kind = wind ? BlockKind::kWind : BlockKind::kWater;
    const BoundBlock bound = Bind(kind, statement->block.get(), statement->range);
    Fluid fluid;
    fluid.medium = wind ? Fluid::Medium::kWind : Fluid::Medium::kWater;
    fluid.range = statement->range;
    fluid.density = ReadQuantity(scope, bound, kind, "density").value_or(wind ? 1.225 : 1000.0);
    fluid.drag = ReadQuantity(scope, bound, kind, "drag").value_or(1.0);
    if (wind) {
      const auto speed = ReadFunction(scope, bound, kind, "speed");
      const auto pressure = ReadFunction(scope, bound, kind, "pressure");
      RefuseUnloading(speed, bound, "speed", "the wind");
      RefuseUnloading(pressure, bound, "pressure", "the wind");
      fluid.speed = speed.value_or(-1);
      fluid.pressure = pressure.value_or(-1);
      if ((One(bound, "speed") != nullptr) == (One(bound, "pressure") != nullptr)) {
        Report(DiagnosticKind::kMissingAttribute, statement->range,
               "a wind has a `speed` or a `pressure`, one of them", "not one of the two",
               "give the air's `speed` (its drag then depends on the body's motion through it), "
               "or a blast's `pressure` against time (whatever the body's motion)");
      }
      if (const ast::Expr* carrier = ValueOf(bound, "carried_by")) {
        fluid.carrier = ResolveFrame(scope, *carrier).value_or(FrameRef{});
      }
      if (const ast::Expr* direction = ValueOf(bound, "direction")) {
        fluid.direction = ExpectDirection(scope, *direction, "direction").value_or(fluid.direction);
      }
    } else {
      fluid.level = ReadQuantity(scope, bound, kind, "level").value_or(0.0);
      const Vec3& g = scenario_.run.gravity;
      if (g[0] == 0.0 && g[1] == 0.0 && g[2] == 0.0) {
        Report(DiagnosticKind::kFluidNotModelled, statement->keyword_range,
               "water without gravity: nothing floats or sinks", "gravity is zero",
               "give the scenario a `gravity`, or leave the water out");
      }
    }
    if (scenario_.run.symmetry != Symmetry::kNone) {
      Report(DiagnosticKind::kFluidNotModelled, statement->keyword_range,
             fmt::format("{} under symmetry: sled computes one half of the scene, and the flow "
                         "on it is not the mirror of the other's",
                         statement->keyword),
             "with symmetry", "remove the `symmetry` block to simulate the whole scene");
    }
    if (const ast::Statement* segments = One(bound, "segments")) {
      for (const ast::Expr& value : segments->values) {
        Entity* entity = Resolve(scope, value, {EntityKind::kSegment});
        if (!entity) continue;
        const Segment& segment = scenario_.segments[static_cast<std::size_t>(entity->index)];
        std::string why;
        if (segment.ellipsoids.empty()) why = "it has no contact ellipsoid";
        for (int e : segment.ellipsoids) {
          const double degree = scenario_.ellipsoids[static_cast<std::size_t>(e)].degree;
          if (degree != 2.0) {
            why = fmt::format("its ellipsoid is a hyper-ellipsoid of degree {:g}", degree);
          }
        }
        if (!why.empty()) {
          Report(DiagnosticKind::kFluidNotModelled, value.range,
                 fmt::format("segment `{}` cannot be in the {}: {}", segment.name,
                             statement->keyword, why),
                 "no plain ellipsoid",
                 "the flow acts on a segment's contact ellipsoids: give it an `ellipsoid { "
                 "semi_axes = ... }` of degree 2");
          continue;
        }
        if (wind) {
          const auto [earlier, first] = in_wind.emplace(entity->index, &value);
          if (!first) {
            auto diagnostic = lang::MakeDiagnostic(
                DiagnosticKind::kFluidNotModelled, value.range,
                fmt::format("segment `{}` is in two winds", segment.name), "in a second wind");
            diagnostic.labels.push_back({earlier->second->range, "first here", false});
            diagnostic.help =
                "a drag is quadratic in the velocity relative to the air, so two winds' do not "
                "add: give the segment one wind";
            diagnostics_.Consume(std::move(diagnostic));
            continue;
          }
        }
        fluid.segments.push_back(entity->index);
      }
    }
    scenario_.fluids.push_back(std::move(fluid));
  }
}

}  // namespace sled::compiler::internal
