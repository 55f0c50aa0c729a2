#include "runtime/dynamics/tree_bias.h"

#include <algorithm>

#include "runtime/dynamics/dynamics.h"
#include "runtime/dynamics/joint.h"

namespace sled::runtime {

void TreeBiasForces(const Model& model, Data& data, std::span<double> residual) {
  const std::size_t n = model.nsegment();
  std::fill(data.vdot.begin(), data.vdot.end(), 0.0);
  // Roots to leaves: accelerations at zero joint acceleration, and the wrench each segment
  // needs for them (in joint_wrench, as scratch until the backward pass is done).
  for (std::size_t i = 0; i < n; ++i) {
    const std::int32_t parent = model.segment_parent[i];
    Vec6 a = data.bias_acceleration[i];
    if (parent >= 0) {
      a += data.parent_to_child[i].ApplyMotion(data.acceleration[static_cast<std::size_t>(parent)]);
    }
    data.acceleration[i] = a;
    const Mat6 inertia = SpatialInertia(model, i);
    data.joint_wrench[i] =
        inertia * a + CrossForce(data.velocity[i], inertia * data.velocity[i]) - data.external[i];
  }
  // Leaves to roots: each joint carries its subtree's wrench; C is its projection on the axes.
  std::fill(residual.begin(), residual.end(), 0.0);
  for (std::size_t i = n; i-- > 0;) {
    int axes[6];
    const int count = ActiveAxes(model, i, data.locked[i], axes);
    const auto va = static_cast<std::size_t>(model.v_address[i]);
    for (int c = 0; c < count; ++c) {
      const auto k = va + static_cast<std::size_t>(axes[c]);
      residual[k] = data.generalized_force[k] - data.subspace[i].col(c).dot(data.joint_wrench[i]);
    }
    const std::int32_t parent = model.segment_parent[i];
    if (parent < 0) continue;
    data.joint_wrench[static_cast<std::size_t>(parent)] +=
        data.parent_to_child[i].TransposeApplyForce(data.joint_wrench[i]);
  }
}

}  // namespace sled::runtime
