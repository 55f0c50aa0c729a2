// Welds: `constraint NAME : welded(BASE -> body.segment)` makes a reference segment move rigidly
// with the ground or a vehicle (a segment whose motion is prescribed, ATB's MSEG). The lowering
// solves it in the tree as the root's locked joint to its base, so a weld must hold a reference
// segment (not one that hangs from a joint, nor two segments), at most once, and the segment
// turns with its base: E0426 otherwise.
#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "compiler/check/checkers.h"
#include "compiler/check/initial_pose.h"

namespace sled::compiler::internal {
namespace {

// An angular velocity agrees with the base's to within 1e-6 rad/s or 1e-6 of its size.
bool SameAngularVelocity(const Vec3& a, const Vec3& b) {
  const double difference = std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
  return difference <= 1e-6 * std::max(1.0, std::hypot(b[0], b[1], b[2]));
}

}  // namespace

void InitialChecker::CheckWelds() {
  std::vector<int> welded_by(scenario_.segments.size(), -1);
  for (std::size_t c = 0; c < scenario_.constraints.size(); ++c) {
    const Constraint& weld = scenario_.constraints[c];
    if (weld.kind != Constraint::Kind::kWelded) continue;
    const bool first = weld.first.kind == FrameRef::Kind::kSegment;
    const bool second = weld.second.kind == FrameRef::Kind::kSegment;
    if (first == second) {
      Report(DiagnosticKind::kWeldNotOnRoot, weld.range,
             fmt::format("constraint `{}` welds {}", weld.name,
                         first ? "two segments" : "two frames that no segment is part of"),
             "a weld holds one segment to a base",
             "write `welded(VEHICLE -> body.segment)` (or `ground ->`): the segment moves with "
             "the vehicle; two segments are joined by a joint, locked with `locked = true`");
      continue;
    }
    const int segment = first ? weld.first.index : weld.second.index;
    if (segment < 0) continue;  // reported where the name was resolved
    if (scenario_.segments[static_cast<std::size_t>(segment)].body < 0) continue;
    const Segment& held = scenario_.segments[static_cast<std::size_t>(segment)];
    const Body& body = scenario_.bodies[static_cast<std::size_t>(held.body)];
    const auto& roots = body.reference_segments;
    if (std::find(roots.begin(), roots.end(), segment) == roots.end()) {
      Report(
          DiagnosticKind::kWeldNotOnRoot, weld.range,
          fmt::format("constraint `{}` welds `{}`, which hangs from a joint", weld.name, held.name),
          "not a reference segment",
          "weld the body's reference segment (the one no joint hangs from); the joints place "
          "the others from it");
      continue;
    }
    if (welded_by[static_cast<std::size_t>(segment)] >= 0 ||
        HoldingConstraintOf(scenario_, segment) != static_cast<int>(c)) {
      Report(DiagnosticKind::kWeldNotOnRoot, weld.range,
             fmt::format("`{}` is already held by another constraint; constraint `{}` would hold "
                         "it twice",
                         held.name, weld.name),
             "held twice", "keep one weld (it fixes the segment's position and orientation)");
      continue;
    }
    welded_by[static_cast<std::size_t>(segment)] = static_cast<int>(c);
    // Any other constraint between the segment and a frame of prescribed motion would hold it
    // twice (both of its ends move as they are told).
    for (const Constraint& other : scenario_.constraints) {
      if (&other == &weld) continue;
      const bool ties = (other.first == FrameRef{FrameRef::Kind::kSegment, segment} &&
                         other.second.kind != FrameRef::Kind::kSegment) ||
                        (other.second == FrameRef{FrameRef::Kind::kSegment, segment} &&
                         other.first.kind != FrameRef::Kind::kSegment);
      if (!ties || other.kind == Constraint::Kind::kWelded) continue;  // welds: reported above
      Report(DiagnosticKind::kWeldNotOnRoot, other.range,
             fmt::format("constraint `{}` ties `{}`, which constraint `{}` welds, to a frame "
                         "whose motion is prescribed",
                         other.name, held.name, weld.name),
             "held twice", "leave it out: the weld already moves the segment with its base");
    }
    // The segment turns with its base: an angular velocity of its own contradicts the weld.
    const FrameRef base = first ? weld.second : weld.first;
    const InitialPoses poses = ComputeInitialPoses(scenario_);
    const Vec3 base_rate =
        base.kind == FrameRef::Kind::kVehicle
            ? poses.vehicle_angular_velocities[static_cast<std::size_t>(base.index)]
            : Vec3{};
    for (const InitialCondition& initial : scenario_.initial_conditions) {
      const bool of_segment =
          (initial.kind == InitialCondition::Kind::kSegment && initial.index == segment) ||
          (initial.kind == InitialCondition::Kind::kBody && initial.index == held.body &&
           roots.front() == segment);
      if (!of_segment || !initial.angular_velocity) continue;
      if (SameAngularVelocity(*initial.angular_velocity, base_rate)) continue;
      Report(DiagnosticKind::kWeldNotOnRoot, initial.range,
             fmt::format("the initial angular velocity of `{}` is not its base's, and constraint "
                         "`{}` welds it to that base",
                         held.name, weld.name),
             "contradicts the weld",
             fmt::format("leave `angular_velocity` out: the segment turns with its base, at "
                         "({:.6g}, {:.6g}, {:.6g}) rad/s",
                         base_rate[0], base_rate[1], base_rate[2]));
    }
  }
}

}  // namespace sled::compiler::internal
