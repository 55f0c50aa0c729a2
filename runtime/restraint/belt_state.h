// What the belts of a Model carry in a Data (runtime/data.h holds one BeltState): the junctions
// where webbing passes between spans, the webbing each span holds, the history committed after
// accepted steps, and the results of the last evaluation. Sized once by SetUpBelts.
#pragma once

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "runtime/force_deflection.h"

namespace sled::runtime {

struct BeltState {
  // --- Junctions, fixed when the Data is made: two spans that exchange webbing, over a wrapped
  // segment (point: the path point) or through a harness tie point (point: -1).
  std::vector<std::int32_t> junction_first;   // the span on the `from` side
  std::vector<std::int32_t> junction_second;  // the span on the `to` side
  std::vector<std::int32_t> junction_point;   // wrapped path point, or -1
  std::vector<std::int32_t> junction_tie;     // tie point, or -1
  std::vector<double> junction_friction;
  std::vector<double> junction_ratio;  // last evaluation: largest tension ratio, exp(mu theta)

  // --- Per span.
  std::vector<std::int32_t> span_belt;        // fixed: the belt the span belongs to
  std::vector<double> rest_length;            // webbing in the span, unstretched [m]
  std::vector<double> committed_rest_length;  // after the last accepted step
  std::vector<LoadingHistory> history;        // of its strain, after the last accepted step
  std::vector<double> length;                 // last evaluation: geometric length [m]
  std::vector<double> tension;                // last evaluation [N]
  std::vector<Eigen::Vector3d> start;         // last evaluation: world ends of the straight part
  std::vector<Eigen::Vector3d> end;

  // --- Per path point. Wraps: the last evaluation's geometry, and the side of the body and the
  // body-fixed point under the webbing's middle after the last accepted step (the webbing sticks
  // to that point unless it slips).
  std::vector<Eigen::Vector3d> entry;
  std::vector<Eigen::Vector3d> exit;
  std::vector<double> arc;
  std::vector<double> turning;
  std::vector<std::uint8_t> contact;
  std::vector<Eigen::Vector3d> middle;
  std::vector<Eigen::Vector3d> tangent;
  std::vector<Eigen::Vector3d> side;
  std::vector<Eigen::Vector3d> committed_side;
  std::vector<Eigen::Vector3d> committed_middle;  // in the segment frame
  std::vector<std::uint8_t> committed_contact;

  // --- Per belt, last evaluation: the force on its first and last anchor, in the anchor's frame.
  std::vector<Eigen::Vector3d> start_anchor_force;
  std::vector<Eigen::Vector3d> end_anchor_force;

  std::int64_t slip_sweeps = 0;  // Gauss-Seidel sweeps of the slip solver, for tests

  // Every field, for checkpoints (runtime/archive.h): the committed histories matter, and the
  // last evaluation's values are warm starts.
  template <class Archive>
  void Serialize(Archive& a) {
    a.Field(junction_ratio);
    a.Field(rest_length);
    a.Field(committed_rest_length);
    a.Field(history);
    a.Field(length);
    a.Field(tension);
    a.Field(start);
    a.Field(end);
    a.Field(entry);
    a.Field(exit);
    a.Field(arc);
    a.Field(turning);
    a.Field(contact);
    a.Field(middle);
    a.Field(tangent);
    a.Field(side);
    a.Field(committed_side);
    a.Field(committed_middle);
    a.Field(committed_contact);
    a.Field(start_anchor_force);
    a.Field(end_anchor_force);
    a.Field(slip_sweeps);
  }
};

}  // namespace sled::runtime
