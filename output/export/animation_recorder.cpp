#include "output/export/animation_recorder.h"

#include <algorithm>

#include <fmt/format.h>

namespace sled::runtime {

AnimationRecorder::AnimationRecorder(const Model& model, std::size_t frames)
    : model_(model), capacity_(frames), nvehicle_(model.nvehicle()), nsegment_(model.nsegment()) {
  const BeltTable& belts = model.belts;
  for (std::size_t b = 0; b < belts.size(); ++b) {
    const std::size_t first_vertex = vertex_point_.size();
    for (std::int32_t i = 0; i < belts.point_count[b]; ++i) {
      const auto k = static_cast<std::size_t>(belts.first_point[b] + i);
      const int parts = belts.point_wraps[k] != 0 ? 3 : 1;
      for (int part = 0; part < parts; ++part) {
        vertex_point_.push_back(k);
        vertex_part_.push_back(static_cast<std::uint8_t>(parts == 3 ? part : 1));
      }
    }
    for (std::size_t v = first_vertex; v + 1 < vertex_point_.size(); ++v) {
      piece_first_vertex_.push_back(v);
      belt_piece_name_.push_back(fmt::format("{}.piece{}", belts.name[b], v - first_vertex + 1));
    }
  }
  times_.reserve(frames);
  poses_.reserve(frames * nnode() * kFloatsPerNode);
}

void AnimationRecorder::Put(std::size_t node, const Vec3& translation,
                            const Eigen::Quaterniond& rotation, const Vec3& scale) {
  Eigen::Quaterniond q = rotation.normalized();
  // The same rotation as +q and -q: keep the sign of the previous frame, so interpolation between
  // frames takes the short way.
  if (times_.size() > 1) {
    const float* previous = pose(times_.size() - 2, node) + 3;
    const double dot =
        previous[0] * q.x() + previous[1] * q.y() + previous[2] * q.z() + previous[3] * q.w();
    if (dot < 0) q.coeffs() = -q.coeffs();
  }
  const double values[kFloatsPerNode] = {
      translation.x(), translation.y(), translation.z(), q.x(),     q.y(),
      q.z(),           q.w(),           scale.x(),       scale.y(), scale.z()};
  for (const double value : values) poses_.push_back(static_cast<float>(value));
}

void AnimationRecorder::Record(const Data& data) {
  if (times_.size() >= capacity_) return;
  const auto t = static_cast<float>(data.time - model_.start_time);
  if (!times_.empty() && !(t > times_.back())) return;
  times_.push_back(t);
  const Vec3 unit = Vec3::Ones();
  for (std::size_t v = 0; v < nvehicle_; ++v) {
    Put(v, data.vehicle[v].position, Eigen::Quaterniond(data.vehicle[v].rotation), unit);
  }
  for (std::size_t s = 0; s < nsegment_; ++s) {
    Put(nvehicle_ + s, data.position[s], Eigen::Quaterniond(data.rotation[s]), unit);
  }
  const BeltState& belts = data.belts;
  auto vertex = [&](std::size_t v) -> const Vec3& {
    const std::size_t k = vertex_point_[v];
    switch (vertex_part_[v]) {
      case 0:
        return belts.entry[k];
      case 2:
        return belts.exit[k];
      default:
        return belts.middle[k];
    }
  };
  for (std::size_t piece = 0; piece < nbelt_piece(); ++piece) {
    const Vec3& from = vertex(piece_first_vertex_[piece]);
    const Vec3 along = vertex(piece_first_vertex_[piece] + 1) - from;
    const double length = along.norm();
    // A piece of no length (webbing not touching a body) keeps a tiny scale: a zero scale would
    // make the node's matrix singular.
    const Eigen::Quaterniond rotation =
        length > 1e-9 ? Eigen::Quaterniond::FromTwoVectors(Vec3::UnitZ(), along)
                      : Eigen::Quaterniond::Identity();
    Put(nvehicle_ + nsegment_ + piece, from, rotation, Vec3(1, 1, std::max(length, 1e-6)));
  }
}

}  // namespace sled::runtime
