// Records the motion of a run for its animation (animation.glb): at each output row, the pose of
// every vehicle and segment, and the pieces of every belt's path. Sized for the run's rows when
// made, so recording allocates nothing.
//
// A belt's path is the polyline through its anchors and, for each body it wraps, the point where
// the webbing meets the body, the middle of the webbing on it and the point where it leaves
// (BeltState entry, middle, exit, world frame): a wrapped body gives three vertices, an anchor
// one. Each piece between two consecutive vertices is drawn as a unit line along z placed by a
// translation, rotation and scale, so the line's ends follow the path exactly.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "runtime/model/data.h"

namespace sled::runtime {

class AnimationRecorder {
 public:
  // Translation (3), rotation quaternion x, y, z, w (4) and scale (3) of one node in one frame.
  static constexpr std::size_t kFloatsPerNode = 10;

  AnimationRecorder(const Model& model, std::size_t frames);

  // One frame at data.time (after Forward). Frames whose time (single precision, from the
  // start of the run) would not increase are skipped. Beyond the frames it was made for, nothing.
  void Record(const Data& data);

  // Animated nodes, in this order: vehicles, segments, belt pieces.
  std::size_t nvehicle() const { return nvehicle_; }
  std::size_t nsegment() const { return nsegment_; }
  std::size_t nbelt_piece() const { return belt_piece_name_.size(); }
  std::size_t nnode() const { return nvehicle_ + nsegment_ + nbelt_piece(); }
  const std::string& belt_piece_name(std::size_t piece) const { return belt_piece_name_[piece]; }

  std::size_t frames() const { return times_.size(); }
  const std::vector<float>& times() const { return times_; }  // from the start, increasing
  // The pose of animated node `node` in frame `frame`: kFloatsPerNode floats.
  const float* pose(std::size_t frame, std::size_t node) const {
    return &poses_[(frame * nnode() + node) * kFloatsPerNode];
  }

 private:
  void Put(std::size_t node, const Vec3& translation, const Eigen::Quaterniond& rotation,
           const Vec3& scale);

  const Model& model_;
  std::size_t capacity_ = 0;
  std::size_t nvehicle_ = 0;
  std::size_t nsegment_ = 0;
  // Per belt piece: its belt, and the path vertex it starts at (an index into vertex_*).
  std::vector<std::string> belt_piece_name_;
  std::vector<std::size_t> piece_first_vertex_;
  // Per path vertex: the path point and which of entry (0), middle (1), exit (2) it is.
  std::vector<std::size_t> vertex_point_;
  std::vector<std::uint8_t> vertex_part_;
  std::vector<float> times_;
  std::vector<float> poses_;
};

}  // namespace sled::runtime
