// The belts and harnesses of a Model (runtime/model/model.h holds one BeltTable). Flat arrays in SI
// units, filled by compiler::Lower and never resized.
//
// A belt is a path of points: an anchor fixed in a frame (ground, vehicle or segment), then one
// or more segments whose ellipsoid the webbing wraps, then an anchor. Between two consecutive
// points runs a span; a belt of n points has n - 1 spans. Spans are numbered across all belts in
// order: belt b's spans are first_span(b) .. first_span(b) + span_count(b) - 1.
//
// Webbing can pass from one span to the next: over a wrapped segment (friction: the belt's
// `friction`) and, in a harness, through a tie point where two of its belts share an anchor
// (friction: the harness's `friction`). Both are junctions of two spans; see belts.h.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace sled::runtime {

struct FrameRef;  // runtime/model/model.h; complete before a BeltTable is made or used

struct BeltTable {
  // --- Per belt.
  std::vector<std::string> name;
  std::vector<std::int32_t> function;  // strain -> force (with its unloading parameters)
  std::vector<double> slack;           // [m] added to the fitted length
  std::vector<double> pretension;      // [N] initial tension
  std::vector<double> friction;        // over the wrapped segments
  std::vector<std::int32_t> harness;   // -1: none
  std::vector<std::int32_t> first_point;
  std::vector<std::int32_t> point_count;

  // --- Per path point.
  std::vector<FrameRef> point_frame;      // anchor: its frame; wrap: the segment (kSegment)
  std::vector<std::uint8_t> point_wraps;  // 1: wraps the segment's ellipsoid; 0: an anchor
  // Anchor: the point in its frame. Wrap: the ellipsoid's centre in the segment frame.
  std::vector<Eigen::Vector3d> point_position;
  std::vector<Eigen::Matrix3d> point_axes;  // wrap: ellipsoid axes (columns) in the segment frame
  std::vector<Eigen::Vector3d> point_semi_axes;  // wrap: zero for a segment without an ellipsoid

  // --- Harnesses, and their tie points: two anchors (path points) of different belts of one
  // harness at the same place, through which webbing passes from one belt to the other.
  std::vector<std::string> harness_name;
  std::vector<double> harness_friction;
  std::vector<std::array<std::int32_t, 2>> tie_points;  // path points; the first is a belt end
  std::vector<std::int32_t> tie_harness;

  std::size_t size() const { return name.size(); }
  std::size_t npoint() const { return point_wraps.size(); }
  // Spans before belt b (each belt's points less one).
  std::int32_t first_span(std::size_t b) const {
    return first_point[b] - static_cast<std::int32_t>(b);
  }
  std::int32_t span_count(std::size_t b) const { return point_count[b] - 1; }
  std::size_t nspan() const { return npoint() - size(); }
};

}  // namespace sled::runtime
