// Small Models built by hand for the runtime's tests: the runtime is tested without the compiler.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "runtime/model/data.h"

namespace sled::runtime::testing {

// Appends a segment whose joint attaches it to `parent` (-1: to the ground or `base`).
inline std::size_t AddSegment(Model& model, std::string name, int parent, JointKind kind,
                              double mass, const Vec3& principal_inertia,
                              const Vec3& point_in_parent = Vec3::Zero(),
                              const Vec3& point_in_child = Vec3::Zero(),
                              const Vec3& axis = Vec3::UnitY(), FrameRef base = {}) {
  const std::size_t s = model.segment_name.size();
  model.segment_name.push_back(std::move(name));
  model.segment_parent.push_back(parent);
  model.segment_base.push_back(base);
  model.segment_mass.push_back(mass);
  model.segment_inertia.push_back(principal_inertia.asDiagonal());
  model.joint_kind.push_back(kind);
  model.joint_name.push_back(parent >= 0 || kind != JointKind::kFree ? "j" + std::to_string(s)
                                                                     : std::string());
  const int nq = PositionCount(kind);
  const int nv = VelocityCount(kind);
  model.q_address.push_back(model.nq);
  model.v_address.push_back(model.nv);
  model.q_count.push_back(nq);
  model.v_count.push_back(nv);
  model.q0.resize(static_cast<std::size_t>(model.nq) + static_cast<std::size_t>(nq), 0.0);
  model.v0.resize(static_cast<std::size_t>(model.nv) + static_cast<std::size_t>(nv), 0.0);
  if (kind == JointKind::kFree || kind == JointKind::kBall) {
    // Identity quaternion (w first), after the position for a free joint.
    model.q0[static_cast<std::size_t>(model.nq) + (kind == JointKind::kFree ? 3U : 0U)] = 1.0;
  }
  model.nq += nq;
  model.nv += nv;
  model.joint_point_in_parent.push_back(point_in_parent);
  model.joint_frame_in_parent.push_back(Mat3::Identity());
  model.joint_point_in_child.push_back(point_in_child);
  model.joint_frame_in_child.push_back(Mat3::Identity());
  model.joint_axis.push_back(axis.normalized());
  AppendPlainJointCharacteristics(model);
  model.segment_source.push_back({});
  model.joint_source.push_back({});
  return s;
}

// Appends a loop-closing constraint between two frames.
inline void AddConstraint(Model& model, std::string name, Model::ConstraintKind kind,
                          FrameRef first, const Vec3& point_first, FrameRef second,
                          const Vec3& point_second, double distance = 0.0,
                          const Vec3& axis = Vec3::UnitX()) {
  model.constraint_name.push_back(std::move(name));
  model.constraint_kind.push_back(kind);
  model.constraint_first.push_back(first);
  model.constraint_second.push_back(second);
  model.constraint_point_first.push_back(point_first);
  model.constraint_point_second.push_back(point_second);
  model.constraint_distance.push_back(distance);
  model.constraint_axis.push_back(axis);
}

// Appends a table function (x, f(x)) with unloading parameters; returns its id.
inline std::int32_t AddTableFunction(FunctionTable& f,
                                     const std::vector<std::array<double, 2>>& points,
                                     double energy_loss = 0.0, double permanent_set = 0.0) {
  f.kind.push_back(FunctionTable::Kind::kTable);
  f.constant.push_back(0.0);
  f.first.push_back(static_cast<std::int32_t>(f.points_x.size()));
  f.count.push_back(static_cast<std::int32_t>(points.size()));
  f.energy_loss.push_back(energy_loss);
  f.permanent_set.push_back(permanent_set);
  for (const auto& [x, y] : points) {
    f.points_x.push_back(x);
    f.points_y.push_back(y);
  }
  return static_cast<std::int32_t>(f.size() - 1);
}

}  // namespace sled::runtime::testing
