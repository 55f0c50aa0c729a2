#include "runtime/dynamics/mass_matrix.h"

#include "runtime/dynamics/dynamics.h"
#include "runtime/dynamics/joint.h"

namespace sled::runtime {

bool IsAncestorOrSelf(const Model& model, std::size_t ancestor, std::size_t segment) {
  for (std::int32_t s = static_cast<std::int32_t>(segment); s >= 0;
       s = model.segment_parent[static_cast<std::size_t>(s)]) {
    if (static_cast<std::size_t>(s) == ancestor) return true;
  }
  return false;
}

void CompositeRigidBodyMassMatrix(const Model& model, const Data& data, std::span<Mat6> composite,
                                  Eigen::Ref<Eigen::MatrixXd> mass) {
  const std::size_t n = model.nsegment();
  for (std::size_t s = 0; s < n; ++s) composite[s] = SpatialInertia(model, s);
  // Leaves to roots: the composite inertia of each subtree, in the subtree root's frame.
  for (std::size_t i = n; i-- > 0;) {
    const std::int32_t parent = model.segment_parent[i];
    if (parent < 0) continue;
    data.parent_to_child[i].AddTransposeApplyInertia(composite[i],
                                                     composite[static_cast<std::size_t>(parent)]);
  }
  for (std::size_t i = 0; i < n; ++i) {
    int axes_i[6];
    const int count_i = ActiveAxes(model, i, data.locked[i], axes_i);
    const auto va_i = static_cast<Eigen::Index>(model.v_address[i]);
    // Locked axes: identity rows, so their (zero) correction is well defined.
    for (int k = 0; k < model.v_count[i]; ++k) {
      for (int l = 0; l < model.v_count[i]; ++l) mass(va_i + k, va_i + l) = k == l ? 1.0 : 0.0;
    }
    if (count_i == 0) continue;
    // F = I^c_i S_i, carried up the tree: M_ij = F^T S_j for each ancestor j.
    // Column by column, so each product is a fixed-size 6x6 times a 6-vector.
    const MotionSubspace& S_i = data.subspace[i];
    MotionSubspace F(6, count_i);
    for (int a = 0; a < count_i; ++a) F.col(a).noalias() = composite[i] * S_i.col(a);
    for (int a = 0; a < count_i; ++a) {
      for (int b = 0; b < count_i; ++b) {
        mass(va_i + axes_i[a], va_i + axes_i[b]) = S_i.col(a).dot(F.col(b));
      }
    }
    std::size_t j = i;
    while (model.segment_parent[j] >= 0) {
      for (Eigen::Index c = 0; c < F.cols(); ++c) {
        F.col(c) = data.parent_to_child[j].TransposeApplyForce(F.col(c));
      }
      j = static_cast<std::size_t>(model.segment_parent[j]);
      int axes_j[6];
      const int count_j = ActiveAxes(model, j, data.locked[j], axes_j);
      const auto va_j = static_cast<Eigen::Index>(model.v_address[j]);
      // Locked axes of an ancestor couple to nothing.
      for (int a = 0; a < model.v_count[i]; ++a) {
        for (int b = 0; b < model.v_count[j]; ++b) {
          mass(va_i + a, va_j + b) = 0.0;
          mass(va_j + b, va_i + a) = 0.0;
        }
      }
      if (count_j == 0) continue;
      for (int a = 0; a < count_i; ++a) {
        for (int b = 0; b < count_j; ++b) {
          const double value = F.col(a).dot(data.subspace[j].col(b));
          mass(va_i + axes_i[a], va_j + axes_j[b]) = value;
          mass(va_j + axes_j[b], va_i + axes_i[a]) = value;
        }
      }
    }
  }
}

}  // namespace sled::runtime
