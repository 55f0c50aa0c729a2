// Belts and harnesses: each belt's path (anchors in their frame, wrapped segments with their
// ellipsoid), its webbing function, slack, pretension and friction; and each harness's tie
// points, where two of its belts end at the same anchor and webbing passes between them.
#include <cmath>

#include <fmt/format.h>

#include "compiler/lower/lowering.h"
#include "runtime/restraint/belts.h"

namespace sled::compiler::lowering {
namespace {

// Two anchors of one harness closer than this are one tie point [m].
constexpr double kTieDistance = 1e-6;

void LowerPathPoint(Lowering& lowering, const Belt& belt, const BeltPoint& point) {
  runtime::BeltTable& table = lowering.model().belts;
  if (point.kind == BeltPoint::Kind::kAnchor) {
    table.point_frame.push_back(lowering.Frame(point.frame));
    table.point_wraps.push_back(0);
    table.point_position.push_back(ToEigen(point.point));
    table.point_axes.push_back(runtime::Mat3::Identity());
    table.point_semi_axes.push_back(runtime::Vec3::Zero());
    return;
  }
  const Segment& segment = lowering.segment(point.segment);
  table.point_frame.push_back({runtime::FrameRef::Kind::kSegment,
                               lowering.new_index[static_cast<std::size_t>(point.segment)]});
  table.point_wraps.push_back(1);
  if (segment.ellipsoids.empty()) {
    lowering.AddNote(lang::DiagnosticKind::kSimulatedApproximately, belt.range,
                     fmt::format("segment `{}` has no ellipsoid: belt `{}` passes "
                                 "through its centre of mass",
                                 segment.name, belt.name));
    table.point_position.push_back(runtime::Vec3::Zero());
    table.point_axes.push_back(runtime::Mat3::Identity());
    table.point_semi_axes.push_back(runtime::Vec3::Zero());
    return;
  }
  const Ellipsoid& ellipsoid =
      lowering.scenario().ellipsoids.at(static_cast<std::size_t>(segment.ellipsoids.front()));
  if (segment.ellipsoids.size() > 1) {
    lowering.AddNote(lang::DiagnosticKind::kSimulatedApproximately, belt.range,
                     fmt::format("belt `{}` wraps the first ellipsoid of `{}`, `{}`", belt.name,
                                 segment.name, ellipsoid.name));
  }
  if (ellipsoid.degree != 2.0) {
    lowering.AddNote(lang::DiagnosticKind::kSimulatedApproximately, belt.range,
                     fmt::format("belt `{}` wraps `{}` as an ellipsoid of degree 2 "
                                 "with its semi-axes",
                                 belt.name, ellipsoid.name));
  }
  table.point_position.push_back(ToEigen(ellipsoid.center));
  table.point_axes.push_back(RotationMatrix(ellipsoid.orientation));
  table.point_semi_axes.push_back(ToEigen(ellipsoid.semi_axes));
}

// Anchors of different belts of a harness at one place (the belts share the harness's frame).
void LowerTiePoints(Lowering& lowering, const Harness& harness, int harness_index) {
  runtime::BeltTable& table = lowering.model().belts;
  auto ends = [&](int belt) {
    const auto b = static_cast<std::size_t>(belt);
    const std::int32_t first = table.first_point[b];
    return std::array<std::int32_t, 2>{first, first + table.point_count[b] - 1};
  };
  for (std::size_t i = 0; i < harness.belts.size(); ++i) {
    for (std::size_t j = i + 1; j < harness.belts.size(); ++j) {
      for (std::int32_t a : ends(harness.belts[i])) {
        for (std::int32_t b : ends(harness.belts[j])) {
          const auto pa = static_cast<std::size_t>(a), pb = static_cast<std::size_t>(b);
          if ((table.point_position[pa] - table.point_position[pb]).norm() > kTieDistance) {
            continue;
          }
          table.tie_points.push_back({a, b});
          table.tie_harness.push_back(harness_index);
        }
      }
    }
  }
}

}  // namespace

void LowerBelts(Lowering& lowering) {
  const CheckedScenario& scenario = lowering.scenario();
  runtime::Model& model = lowering.model();
  runtime::BeltTable& table = model.belts;
  for (const Harness& harness : scenario.harnesses) {
    table.harness_name.push_back(harness.name);
    table.harness_friction.push_back(harness.friction);
  }
  for (const Belt& belt : scenario.belts) {
    table.name.push_back(belt.name);
    table.function.push_back(lowering.Function(belt.force));
    table.slack.push_back(belt.slack);
    table.pretension.push_back(belt.pretension);
    table.friction.push_back(belt.friction);
    table.harness.push_back(belt.harness);
    table.first_point.push_back(static_cast<std::int32_t>(table.npoint()));
    table.point_count.push_back(static_cast<std::int32_t>(belt.path.size()));
    for (const BeltPoint& point : belt.path) LowerPathPoint(lowering, belt, point);
    if (belt.pretension > 0 &&
        runtime::StrainAtTension(model.functions, table.function.back(), belt.pretension) < 0) {
      lowering.AddNote(lang::DiagnosticKind::kSimulatedApproximately, belt.range,
                       fmt::format("the force of belt `{}` does not reach its pretension of {:g} "
                                   "N within a strain of 1; it starts without pretension",
                                   belt.name, belt.pretension));
    }
  }
  for (std::size_t h = 0; h < scenario.harnesses.size(); ++h) {
    LowerTiePoints(lowering, scenario.harnesses[h], static_cast<int>(h));
  }
}

}  // namespace sled::compiler::lowering
