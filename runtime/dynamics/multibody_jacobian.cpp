#include "runtime/dynamics/multibody_jacobian.h"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>

#include "runtime/dynamics/constraints.h"
#include "runtime/dynamics/dynamics.h"
#include "runtime/dynamics/joint.h"
#include "runtime/dynamics/mass_matrix.h"
#include "runtime/forces/forces.h"

namespace sled::runtime {
namespace {

// Difference quotients: small against any length, angle or rate of a scene, large against the
// rounding of the poses (about 1e-16 m or rad) and of the forces.
constexpr double kAngleStep = 1e-8;   // rad
constexpr double kLengthStep = 1e-8;  // m
constexpr double kRateStep = 1e-8;    // rad/s, m/s
constexpr double kGasStep = 1e-8;     // relative to the gas state (a mass, kg)

// An eigenvalue of a segment's 6 x 6 load Gram matrix below this fraction of the largest is
// rounding: singular values 1e-6 of the largest.
constexpr double kLoadRank = 1e-12;

Vec6 ToWorld(const Mat3& rotation, const Vec6& wrench) {
  Vec6 out;
  out.head<3>() = rotation * wrench.head<3>();
  out.tail<3>() = rotation * wrench.tail<3>();
  return out;
}

Vec6 ToSegment(const Mat3& rotation, const Vec6& wrench) {
  Vec6 out;
  out.head<3>() = rotation.transpose() * wrench.head<3>();
  out.tail<3>() = rotation.transpose() * wrench.tail<3>();
  return out;
}

double StepOf(int direction) {
  return direction < 3 ? kAngleStep : direction < 6 ? kLengthStep : kRateStep;
}

// Moves segment s along direction d of its twist (0-2 rotation about its axes, 3-5 translation
// along them, 6-11 its velocity), by StepOf(d).
void Perturb(Data& data, std::size_t s, int d) {
  const double step = StepOf(d);
  if (d < 3) {
    data.rotation[s] = data.rotation[s] * Eigen::AngleAxisd(step, Vec3::Unit(d)).toRotationMatrix();
  } else if (d < 6) {
    data.position[s] += step * data.rotation[s].col(d - 3);
  } else {
    data.velocity[s][d - 6] += step;
  }
}

}  // namespace

MultibodyJacobian::MultibodyJacobian(const Model& model)
    : model_(model), coupling_(MakeForceCoupling(model)) {
  nq_ = static_cast<std::size_t>(model.nq);
  nv_ = static_cast<std::size_t>(model.nv);
  nw_ = static_cast<std::size_t>(model.nw);
  n_ = StateSize(model);
  const std::size_t segments = model.nsegment();
  std::size_t coupled = 0;
  std::size_t joint_axes = 0;
  for (std::size_t s = 0; s < segments; ++s) {
    if (coupling_.colour[s] >= 0) ++coupled;
    if (model.joint_kind[s] != JointKind::kFree && model.joint_kind[s] != JointKind::kPlanar) {
      joint_axes += static_cast<std::size_t>(model.v_count[s]);
    }
  }
  const std::size_t most = 6 * coupled + joint_axes + nw_;
  max_rank_ = std::min(most, kMaxRank);
  const auto rows = static_cast<Eigen::Index>(n_);
  candidate_u_.setZero(rows, static_cast<Eigen::Index>(most));
  candidate_v_.setZero(rows, static_cast<Eigen::Index>(most));
  load_coordinate_.assign(most, -1);
  load_segment_.assign(most, 0);
  load_wrench_.assign(most, Vec6::Zero());
  rate_.assign(most, 0.0);
  order_.assign(most, 0);

  g_.resize(segments);
  g_inverse_.resize(segments);
  rotation_.assign(segments, Mat3::Identity());
  position_.assign(segments, Vec3::Zero());
  velocity_.assign(segments, Vec6::Zero());
  wrench_world_.assign(segments, Vec6::Zero());
  blocks_.resize(segments);
  by_gas_.resize(segments);
  loaded_.assign(segments, 0);
  for (std::size_t s = 0; s < segments; ++s) {
    blocks_[s].assign(coupling_.neighbours[s].size(), Block::Zero());
    by_gas_[s].setZero(6, static_cast<Eigen::Index>(nw_));
  }
  gas_by_segment_.resize(model.airbags.size());
  for (std::size_t b = 0; b < model.airbags.size(); ++b) {
    const auto& element = coupling_.elements[static_cast<std::size_t>(coupling_.airbag_element[b])];
    gas_by_segment_[b].assign(element.size(), Eigen::Matrix<double, Eigen::Dynamic, 12>::Zero(
                                                  model.airbags.state_count(b), 12));
  }
  gas_by_gas_.setZero(static_cast<Eigen::Index>(nw_), static_cast<Eigen::Index>(nw_));
  wdot_.assign(nw_, 0.0);
  q_.assign(nq_, 0.0);
  v_.assign(nv_, 0.0);
  tau_.assign(nv_, 0.0);
  scratch_q_.assign(nq_, 0.0);
  scratch_v_.assign(nv_, 0.0);
  qdot_.assign(nq_, 0.0);
  response_base_.assign(nv_, 0.0);
  joint_dq_.setZero(static_cast<Eigen::Index>(nv_), 6);
  joint_dv_.setZero(static_cast<Eigen::Index>(nv_), 6);
  pose_covector_.setZero(static_cast<Eigen::Index>(nv_));
  nu_.assign(n_, 0.0);
  use_mass_matrix_ = model.nconstraint() == 0 && std::none_of(model.segment_mirror_twin.begin(),
                                                              model.segment_mirror_twin.end(),
                                                              [](auto twin) { return twin != 0; });
  if (use_mass_matrix_) {
    mass_.setZero(static_cast<Eigen::Index>(nv_), static_cast<Eigen::Index>(nv_));
    cholesky_ = Eigen::LLT<Eigen::MatrixXd>(static_cast<Eigen::Index>(nv_));
    composite_.assign(segments, Mat6::Zero());
    load_.setZero(static_cast<Eigen::Index>(nv_));
  }
}

Eigen::Index MultibodyJacobian::NewCandidate() {
  const Eigen::Index c = candidates_++;
  candidate_u_.col(c).setZero();
  candidate_v_.col(c).setZero();
  load_coordinate_[static_cast<std::size_t>(c)] = -1;
  return c;
}

void MultibodyJacobian::FormKinematics(Data& data, StructuredJacobian& jacobian) {
  const std::size_t segments = model_.nsegment();
  for (std::size_t s = 0; s < segments; ++s) {
    g_[s].setZero(model_.q_count[s], model_.v_count[s]);
  }
  // q' = G(q) v is linear in v and each joint's rates depend on its own velocities only: the
  // k-th velocity of every joint at once gives column k of every G.
  for (int k = 0; k < 6; ++k) {
    std::fill(scratch_v_.begin(), scratch_v_.end(), 0.0);
    bool any = false;
    for (std::size_t s = 0; s < segments; ++s) {
      if (model_.v_count[s] > k) {
        scratch_v_[static_cast<std::size_t>(model_.v_address[s] + k)] = 1.0;
        any = true;
      }
    }
    if (!any) break;
    PositionDerivative(model_, data.q, scratch_v_, data.locked, qdot_);
    for (std::size_t s = 0; s < segments; ++s) {
      if (model_.v_count[s] <= k) continue;
      const auto qa = static_cast<std::size_t>(model_.q_address[s]);
      const auto column = nq_ + static_cast<std::size_t>(model_.v_address[s] + k);
      for (int r = 0; r < model_.q_count[s]; ++r) {
        const double value = qdot_[qa + static_cast<std::size_t>(r)];
        g_[s](r, k) = value;
        if (value != 0.0)
          jacobian.nilpotent.push_back({qa + static_cast<std::size_t>(r), column, value});
      }
    }
  }
  for (std::size_t s = 0; s < segments; ++s) PseudoInverse(g_[s], g_inverse_[s]);
}

void MultibodyJacobian::PseudoInverse(const SmallBlock& g, SmallBlock& inverse) {
  // Every joint kind's G has orthogonal columns (quaternion rates, a rotated velocity, or the
  // rates themselves; a locked axis a zero column), so G^+ = diag(1 / |g_k|^2) G^T. Checked,
  // with an SVD for any G that is not so.
  const Eigen::Index cols = g.cols();
  inverse.setZero(cols, g.rows());
  bool orthogonal = true;
  for (Eigen::Index i = 0; i < cols && orthogonal; ++i) {
    for (Eigen::Index j = i + 1; j < cols; ++j) {
      const double product = g.col(i).dot(g.col(j));
      if (std::abs(product) > 1e-12 * g.col(i).norm() * g.col(j).norm()) {
        orthogonal = false;
        break;
      }
    }
  }
  if (orthogonal) {
    for (Eigen::Index k = 0; k < cols; ++k) {
      const double norm2 = g.col(k).squaredNorm();
      if (norm2 > 0.0) inverse.row(k) = g.col(k).transpose() / norm2;
    }
    return;
  }
  const Eigen::JacobiSVD<SmallBlock> svd(g, Eigen::ComputeFullU | Eigen::ComputeFullV);
  const auto& sigma = svd.singularValues();
  const double largest = sigma.size() > 0 ? sigma.maxCoeff() : 0.0;
  for (Eigen::Index i = 0; i < sigma.size(); ++i) {
    if (sigma[i] <= 1e-12 * largest || sigma[i] == 0.0) continue;
    inverse += (1.0 / sigma[i]) * svd.matrixV().col(i) * svd.matrixU().col(i).transpose();
  }
}

void MultibodyJacobian::JointTerms(Data& data) {
  const std::size_t segments = model_.nsegment();
  std::copy(data.q.begin(), data.q.end(), q_.begin());
  std::copy(data.v.begin(), data.v.end(), v_.begin());
  ComputeJointTorques(model_, data);
  std::copy(data.generalized_force.begin(), data.generalized_force.end(), tau_.begin());
  joint_dq_.setZero();
  joint_dv_.setZero();
  // Each joint's torque depends on its own coordinates only: the k-th direction of every joint
  // at once.
  for (int k = 0; k < 6; ++k) {
    bool any = false;
    for (std::size_t s = 0; s < segments; ++s) {
      if (model_.v_count[s] <= k || model_.joint_kind[s] == JointKind::kFree) continue;
      any = true;
      const auto qa = static_cast<std::size_t>(model_.q_address[s]);
      for (int r = 0; r < model_.q_count[s]; ++r) {
        data.q[qa + static_cast<std::size_t>(r)] += kAngleStep * g_[s](r, k);
      }
      data.v[static_cast<std::size_t>(model_.v_address[s] + k)] += kRateStep;
    }
    if (!any) break;
    // Positions first (velocities restored), then velocities.
    std::copy(v_.begin(), v_.end(), scratch_v_.begin());
    std::swap(data.v, scratch_v_);
    ComputeJointTorques(model_, data);
    for (std::size_t i = 0; i < nv_; ++i) {
      joint_dq_(static_cast<Eigen::Index>(i), k) =
          (data.generalized_force[i] - tau_[i]) / kAngleStep;
    }
    std::swap(data.v, scratch_v_);
    std::copy(q_.begin(), q_.end(), data.q.begin());
    ComputeJointTorques(model_, data);
    for (std::size_t i = 0; i < nv_; ++i) {
      joint_dv_(static_cast<Eigen::Index>(i), k) =
          (data.generalized_force[i] - tau_[i]) / kRateStep;
    }
    std::copy(v_.begin(), v_.end(), data.v.begin());
  }
  for (std::size_t s = 0; s < segments; ++s) {
    if (model_.joint_kind[s] == JointKind::kFree) continue;
    const int dof = model_.v_count[s];
    const auto va = static_cast<Eigen::Index>(model_.v_address[s]);
    const auto qa = static_cast<Eigen::Index>(model_.q_address[s]);
    int axes[6];
    const int active = ActiveAxes(model_, s, data.locked[s], axes);
    for (int a = 0; a < active; ++a) {
      // A locked axis does not move, whatever its characteristic says.
      const int r = axes[a];
      const Eigen::Index i = va + r;
      if (joint_dq_.row(i).head(dof).isZero(0.0) && joint_dv_.row(i).head(dof).isZero(0.0))
        continue;
      const Eigen::Index c = NewCandidate();
      load_coordinate_[static_cast<std::size_t>(c)] = i;
      auto v = candidate_v_.col(c);
      for (int k = 0; k < dof; ++k) {
        for (int j = 0; j < model_.q_count[s]; ++j) {
          v[qa + j] += g_inverse_[s](k, j) * joint_dq_(i, k);
        }
        v[static_cast<Eigen::Index>(nq_) + va + k] = joint_dv_(i, k);
      }
    }
  }
}

void MultibodyJacobian::SpaceDerivatives(Data& data) {
  const std::size_t segments = model_.nsegment();
  for (std::size_t s = 0; s < segments; ++s) {
    for (auto& block : blocks_[s]) block.setZero();
    by_gas_[s].setZero();
  }
  std::fill(loaded_.begin(), loaded_.end(), 0);
  if (coupling_.colours == 0 && nw_ == 0) return;
  std::copy(data.rotation.begin(), data.rotation.end(), rotation_.begin());
  std::copy(data.position.begin(), data.position.end(), position_.begin());
  std::copy(data.velocity.begin(), data.velocity.end(), velocity_.begin());
  auto restore = [&] {
    std::copy(rotation_.begin(), rotation_.end(), data.rotation.begin());
    std::copy(position_.begin(), position_.end(), data.position.begin());
    std::copy(velocity_.begin(), velocity_.end(), data.velocity.begin());
  };
  // Contacts, belts and airbags start their iterations (the ellipsoid-ellipsoid normal, the
  // belts' slip, the bags' scale) from the last evaluation: every evaluation here starts from
  // the same point, or the difference quotients see the iterations' own convergence.
  saved_contacts_ = data.contacts;
  saved_belts_ = data.belts;
  saved_airbags_ = data.airbags;
  auto evaluate = [&] {
    data.contacts = saved_contacts_;
    data.belts = saved_belts_;
    data.airbags = saved_airbags_;
    ComputeForces(model_, data);
  };
  evaluate();
  for (std::size_t s = 0; s < segments; ++s) {
    wrench_world_[s] = ToWorld(rotation_[s], data.external[s]);
  }
  std::copy(data.wdot.begin(), data.wdot.end(), wdot_.begin());
  // The change of a wrench, in world axes (so a segment's own turn does not count as a change
  // of the forces on it), back in the segment's base axes.
  auto change = [&](std::size_t s, double step) -> Vec6 {
    return ToSegment(rotation_[s], ToWorld(data.rotation[s], data.external[s]) - wrench_world_[s]) /
           step;
  };
  const AirbagTable& bags = model_.airbags;
  for (std::int32_t colour = 0; colour < coupling_.colours; ++colour) {
    const auto& owner = coupling_.owner[static_cast<std::size_t>(colour)];
    for (int d = 0; d < 12; ++d) {
      restore();
      for (std::size_t s = 0; s < segments; ++s) {
        if (coupling_.colour[s] == colour) Perturb(data, s, d);
      }
      evaluate();
      const double step = StepOf(d);
      for (std::size_t s = 0; s < segments; ++s) {
        const std::int32_t o = owner[s];
        if (o < 0) continue;
        const auto& neighbours = coupling_.neighbours[s];
        const auto m = static_cast<std::size_t>(
            std::lower_bound(neighbours.begin(), neighbours.end(), o) - neighbours.begin());
        const Vec6 delta = change(s, step);
        blocks_[s][m].col(d) = delta;
        if (!delta.isZero(0.0)) loaded_[s] = 1;
      }
      for (std::size_t b = 0; b < bags.size(); ++b) {
        const auto& element =
            coupling_.elements[static_cast<std::size_t>(coupling_.airbag_element[b])];
        const auto wa = static_cast<std::size_t>(bags.state_address[b]);
        for (std::size_t m = 0; m < element.size(); ++m) {
          if (coupling_.colour[static_cast<std::size_t>(element[m])] != colour) continue;
          for (std::size_t j = 0; j < static_cast<std::size_t>(bags.state_count(b)); ++j) {
            gas_by_segment_[b][m](static_cast<Eigen::Index>(j), d) =
                (data.wdot[wa + j] - wdot_[wa + j]) / step;
          }
        }
      }
    }
  }
  restore();
  for (std::size_t j = 0; j < nw_; ++j) {
    const double saved = data.w[j];
    const double step = kGasStep * std::max(std::abs(saved), 1e-6);
    data.w[j] = saved + step;
    const double actual = data.w[j] - saved;
    evaluate();
    data.w[j] = saved;
    for (std::size_t s = 0; s < segments; ++s) {
      if (coupling_.colour[s] < 0) continue;
      const Vec6 delta = change(s, actual);
      by_gas_[s].col(static_cast<Eigen::Index>(j)) = delta;
      if (!delta.isZero(0.0)) loaded_[s] = 1;
    }
    for (std::size_t i = 0; i < nw_; ++i) {
      gas_by_gas_(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) =
          (data.wdot[i] - wdot_[i]) / actual;
    }
  }
}

void MultibodyJacobian::AddTransposeJacobian(const Data& data, std::size_t segment, const Vec6& a,
                                             Eigen::Ref<Eigen::VectorXd> out) const {
  Vec6 f = a;
  for (auto k = static_cast<std::int32_t>(segment); k >= 0;) {
    const auto s = static_cast<std::size_t>(k);
    int axes[6];
    const int count = ActiveAxes(model_, s, data.locked[s], axes);
    const auto va = static_cast<Eigen::Index>(model_.v_address[s]);
    for (int c = 0; c < count; ++c) out[va + axes[c]] += data.subspace[s].col(c).dot(f);
    k = model_.segment_parent[s];
    if (k >= 0) f = data.parent_to_child[s].TransposeApplyForce(f);
  }
}

void MultibodyJacobian::AddSegmentRow(const Data& data, std::size_t segment,
                                      const Eigen::Matrix<double, 1, 12>& row,
                                      Eigen::Ref<Eigen::VectorXd> v) {
  AddTransposeJacobian(data, segment, row.head<6>().transpose(), pose_covector_);
  AddTransposeJacobian(data, segment, row.tail<6>().transpose(),
                       v.segment(static_cast<Eigen::Index>(nq_), static_cast<Eigen::Index>(nv_)));
}

void MultibodyJacobian::FlushPoseCovector(Eigen::Ref<Eigen::VectorXd> v) {
  // A covector over the joints' tangent coordinates, carried to q by G's pseudo-inverse.
  for (std::size_t s = 0; s < model_.nsegment(); ++s) {
    const auto va = static_cast<Eigen::Index>(model_.v_address[s]);
    const auto qa = static_cast<Eigen::Index>(model_.q_address[s]);
    for (int k = 0; k < model_.v_count[s]; ++k) {
      const double value = pose_covector_[va + k];
      if (value == 0.0) continue;
      for (int j = 0; j < model_.q_count[s]; ++j) v[qa + j] += g_inverse_[s](k, j) * value;
    }
  }
  pose_covector_.setZero();
}

void MultibodyJacobian::SpaceTerms(Data& data) {
  const std::size_t segments = model_.nsegment();
  const auto nq = static_cast<Eigen::Index>(nq_);
  const auto nv = static_cast<Eigen::Index>(nv_);
  for (std::size_t s = 0; s < segments; ++s) {
    if (!loaded_[s]) continue;
    Eigen::Matrix<double, 6, 6> gram = by_gas_[s] * by_gas_[s].transpose();
    for (const Block& block : blocks_[s]) gram.noalias() += block * block.transpose();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>> eigen(gram);
    const double largest = eigen.eigenvalues().maxCoeff();
    if (!(largest > 0.0)) continue;
    for (int i = 5; i >= 0; --i) {
      if (eigen.eigenvalues()[i] <= kLoadRank * largest) break;
      const Vec6 p = eigen.eigenvectors().col(i);
      const Eigen::Index c = NewCandidate();
      load_segment_[static_cast<std::size_t>(c)] = s;
      load_wrench_[static_cast<std::size_t>(c)] = p;
      auto v = candidate_v_.col(c);
      const auto& neighbours = coupling_.neighbours[s];
      for (std::size_t m = 0; m < neighbours.size(); ++m) {
        const Eigen::Matrix<double, 1, 12> row = p.transpose() * blocks_[s][m];
        if (row.isZero(0.0)) continue;
        AddSegmentRow(data, static_cast<std::size_t>(neighbours[m]), row, v);
      }
      FlushPoseCovector(v);
      if (nw_ > 0) {
        v.segment(nq + nv, static_cast<Eigen::Index>(nw_)) =
            (p.transpose() * by_gas_[s]).transpose();
      }
    }
  }
}

void MultibodyJacobian::AirbagTerms(Data& data) {
  const AirbagTable& bags = model_.airbags;
  const auto nq = static_cast<Eigen::Index>(nq_);
  const auto nv = static_cast<Eigen::Index>(nv_);
  for (std::size_t b = 0; b < bags.size(); ++b) {
    const auto& element = coupling_.elements[static_cast<std::size_t>(coupling_.airbag_element[b])];
    const auto wa = static_cast<Eigen::Index>(bags.state_address[b]);
    for (Eigen::Index j = 0; j < bags.state_count(b); ++j) {
      const Eigen::Index c = NewCandidate();
      load_coordinate_[static_cast<std::size_t>(c)] = -2;  // u is a unit vector, no response
      candidate_u_(nq + nv + wa + j, c) = 1.0;
      auto v = candidate_v_.col(c);
      for (std::size_t m = 0; m < element.size(); ++m) {
        const Eigen::Matrix<double, 1, 12> row = gas_by_segment_[b][m].row(j);
        if (row.isZero(0.0)) continue;
        AddSegmentRow(data, static_cast<std::size_t>(element[m]), row, v);
      }
      FlushPoseCovector(v);
      v.segment(nq + nv, static_cast<Eigen::Index>(nw_)) = gas_by_gas_.row(wa + j).transpose();
    }
  }
}

bool MultibodyJacobian::PrepareResponses(Data& data, Failure* failure) {
  if (use_mass_matrix_) {
    CompositeRigidBodyMassMatrix(model_, data, composite_, mass_);
    cholesky_.compute(mass_);
    if (cholesky_.info() == Eigen::Success) return true;
    if (failure != nullptr) failure->cause = "the mass matrix is not positive definite";
    return false;
  }
  // The response to a load at rest: no velocity terms; the base's acceleration and the
  // constraints' right-hand side give a response to no load, which is subtracted.
  std::fill(data.v.begin(), data.v.end(), 0.0);
  ComputeKinematics(model_, data);
  for (auto& wrench : data.external) wrench.setZero();
  std::fill(data.generalized_force.begin(), data.generalized_force.end(), 0.0);
  if (!ComputeAccelerations(model_, data, failure)) return false;
  if (model_.nconstraint() > 0 && !ApplyConstraints(model_, data, failure)) return false;
  std::copy(data.vdot.begin(), data.vdot.end(), response_base_.begin());
  return true;
}

bool MultibodyJacobian::Response(Data& data, std::ptrdiff_t coordinate, std::size_t segment,
                                 const Vec6& wrench, Eigen::Ref<Eigen::VectorXd> u,
                                 Failure* failure) {
  const auto nq = static_cast<Eigen::Index>(nq_);
  if (use_mass_matrix_) {
    load_.setZero();
    if (coordinate >= 0) {
      load_[coordinate] = 1.0;
    } else {
      AddTransposeJacobian(data, segment, wrench, load_);
    }
    cholesky_.solveInPlace(load_);
    u.segment(nq, static_cast<Eigen::Index>(nv_)) = load_;
    return true;
  }
  if (coordinate >= 0) {
    data.generalized_force[static_cast<std::size_t>(coordinate)] = 1.0;
  } else {
    data.external[segment] = wrench;
  }
  bool ok = ComputeAccelerations(model_, data, failure);
  if (ok && model_.nconstraint() > 0) ok = ApplyConstraints(model_, data, failure);
  if (coordinate >= 0) {
    data.generalized_force[static_cast<std::size_t>(coordinate)] = 0.0;
  } else {
    data.external[segment].setZero();
  }
  if (!ok) return false;
  for (std::size_t i = 0; i < nv_; ++i) {
    u[nq + static_cast<Eigen::Index>(i)] = data.vdot[i] - response_base_[i];
  }
  return true;
}

bool MultibodyJacobian::Form(Data& data, double t, std::span<const double> y, double step,
                             StructuredJacobian& jacobian, Failure* failure) {
  LoadState(data, t, y);
  ComputeKinematics(model_, data);
  candidates_ = 0;
  FormKinematics(data, jacobian);
  JointTerms(data);
  SpaceDerivatives(data);
  SpaceTerms(data);
  AirbagTerms(data);
  if (candidates_ == 0) return true;

  // Rates first from v alone is not possible (they need u): responses for every candidate.
  if (!PrepareResponses(data, failure)) return false;
  for (Eigen::Index c = 0; c < candidates_; ++c) {
    const auto k = static_cast<std::size_t>(c);
    if (load_coordinate_[k] == -2) continue;
    if (!Response(data, load_coordinate_[k], load_segment_[k], load_wrench_[k], candidate_u_.col(c),
                  failure)) {
      return false;
    }
  }
  // The rate of each term on its own: a damping |v . u| or a stiffness sqrt|v . N u|.
  for (Eigen::Index c = 0; c < candidates_; ++c) {
    const auto k = static_cast<std::size_t>(c);
    jacobian.ApplyNilpotent(std::span<const double>(candidate_u_.col(c).data(), n_), nu_);
    const double damping = std::abs(candidate_v_.col(c).dot(candidate_u_.col(c)));
    const double stiffness = std::abs(candidate_v_.col(c).dot(
        Eigen::Map<const Eigen::VectorXd>(nu_.data(), static_cast<Eigen::Index>(n_))));
    rate_[k] = std::max(damping, std::sqrt(stiffness));
    order_[k] = c;
    jacobian.stiff_rate = std::max(jacobian.stiff_rate, rate_[k]);
  }
  std::sort(order_.begin(), order_.begin() + candidates_, [&](Eigen::Index a, Eigen::Index b) {
    return rate_[static_cast<std::size_t>(a)] > rate_[static_cast<std::size_t>(b)];
  });
  for (Eigen::Index i = 0; i < candidates_; ++i) {
    const Eigen::Index c = order_[static_cast<std::size_t>(i)];
    if (!(step * rate_[static_cast<std::size_t>(c)] >= kStiffRate)) break;
    if (!jacobian.AddColumns(candidate_u_.col(c), candidate_v_.col(c))) break;
  }
  return true;
}

}  // namespace sled::runtime
