// BuildConstraintPattern: the rows of the constraint system and the sparsity pattern of its KKT
// matrix, which depend only on the Model (FinalizeModel builds them once; constraints.h).
#include <cstdint>
#include <vector>

#include "runtime/dynamics/constraints.h"
#include "runtime/dynamics/mass_matrix.h"

namespace sled::runtime {
namespace {

int RowCount(Model::ConstraintKind kind) {
  switch (kind) {
    case Model::ConstraintKind::kFixedPoint:
      return 3;
    case Model::ConstraintKind::kFixedDistance:
      return 1;
    case Model::ConstraintKind::kSliding:
      return 2;
    case Model::ConstraintKind::kRolling:
      return 0;
  }
  return 0;
}

}  // namespace

ConstraintPattern BuildConstraintPattern(const Model& model) {
  ConstraintPattern w;
  const std::size_t nc = model.nconstraint();
  if (nc == 0) return w;
  const std::size_t n = model.nsegment();
  const auto nv = static_cast<std::size_t>(model.nv);
  w.nv = model.nv;
  w.first_row.resize(nc);
  w.row_count.resize(nc);
  w.sliding_normal.assign(2 * nc, Vec3::Zero());
  std::int32_t rows = 0;
  for (std::size_t c = 0; c < nc; ++c) {
    w.first_row[c] = rows;
    w.row_count[c] = RowCount(model.constraint_kind[c]);
    rows += w.row_count[c];
    if (model.constraint_kind[c] == Model::ConstraintKind::kSliding) {
      const double norm = model.constraint_axis[c].norm();
      const Vec3 axis = norm > 0.0 ? Vec3(model.constraint_axis[c] / norm) : Vec3::UnitX();
      w.sliding_normal[2 * c] = axis.unitOrthogonal();
      w.sliding_normal[2 * c + 1] = axis.cross(w.sliding_normal[2 * c]);
    }
  }
  w.rows = rows;
  const auto m = static_cast<std::size_t>(rows);

  // The segment of each velocity coordinate, and the coordinates each row can involve.
  std::vector<std::size_t> dof_segment(nv);
  for (std::size_t s = 0; s < n; ++s) {
    const auto first = static_cast<std::size_t>(model.v_address[s]);
    for (std::size_t k = 0; k < static_cast<std::size_t>(model.v_count[s]); ++k) {
      dof_segment[first + k] = s;
    }
  }
  auto on_path = [&](const FrameRef& frame, std::size_t j) {
    return frame.kind == FrameRef::Kind::kSegment &&
           IsAncestorOrSelf(model, dof_segment[j], static_cast<std::size_t>(frame.index));
  };
  // The KKT pattern, column-major and dense while it is built.
  const std::size_t size = nv + m;
  std::vector<std::uint8_t> pattern(size * size, 0);
  for (std::size_t j = 0; j < nv; ++j) {
    for (std::size_t i = 0; i < nv; ++i) {
      if (IsAncestorOrSelf(model, dof_segment[i], dof_segment[j]) ||
          IsAncestorOrSelf(model, dof_segment[j], dof_segment[i])) {
        pattern[i + j * size] = 1;
      }
    }
  }
  for (std::size_t c = 0; c < nc; ++c) {
    for (std::int32_t k = 0; k < w.row_count[c]; ++k) {
      const std::size_t r = nv + static_cast<std::size_t>(w.first_row[c] + k);
      pattern[r + r * size] = 1;
      for (std::size_t j = 0; j < nv; ++j) {
        if (on_path(model.constraint_first[c], j) || on_path(model.constraint_second[c], j)) {
          pattern[r + j * size] = 1;
          pattern[j + r * size] = 1;
        }
      }
    }
  }
  w.kkt_pointer.assign(size + 1, 0);
  w.mass_position.assign(nv * nv, -1);
  w.jacobian_position.assign(m * nv, -1);
  w.transpose_position.assign(m * nv, -1);
  w.diagonal_position.assign(m, -1);
  for (std::size_t j = 0; j < size; ++j) {
    for (std::size_t i = 0; i < size; ++i) {
      if (pattern[i + j * size] == 0) continue;
      const auto position = static_cast<std::int32_t>(w.kkt_index.size());
      w.kkt_index.push_back(static_cast<std::int32_t>(i));
      if (i < nv && j < nv) {
        w.mass_position[i + j * nv] = position;
      } else if (i >= nv && j < nv) {
        w.jacobian_position[(i - nv) + j * m] = position;
      } else if (i < nv && j >= nv) {
        w.transpose_position[(j - nv) + i * m] = position;
      } else {
        w.diagonal_position[i - nv] = position;
      }
    }
    w.kkt_pointer[j + 1] = static_cast<std::int32_t>(w.kkt_index.size());
  }
  return w;
}

}  // namespace sled::runtime
