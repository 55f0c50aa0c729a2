#include "runtime/dynamics/dynamics.h"

#include <cmath>
#include <type_traits>

#include <Eigen/LU>

#include <fmt/format.h>

#include "runtime/dynamics/constraints.h"
#include "runtime/dynamics/joint.h"
#include "runtime/dynamics/mirror.h"
#include "runtime/dynamics/vehicle.h"
#include "runtime/forces/forces.h"

namespace sled::runtime {
namespace {

// Calls step(std::integral_constant<int, N>{}) for N = count (1 to 6 active joint axes), so the
// articulated-body steps run on fixed-size matrices.
template <typename Step>
bool WithAxisCount(int count, Step&& step) {
  switch (count) {
    case 1:
      return step(std::integral_constant<int, 1>{});
    case 2:
      return step(std::integral_constant<int, 2>{});
    case 3:
      return step(std::integral_constant<int, 3>{});
    case 4:
      return step(std::integral_constant<int, 4>{});
    case 5:
      return step(std::integral_constant<int, 5>{});
    case 6:
      return step(std::integral_constant<int, 6>{});
    default:
      return true;  // no active axes: nothing to do
  }
}

// The active entries of a joint-space vector (velocities, forces) for the joint above segment
// `s`: all its coordinates unless some are locked (then ActiveAxes picks).
template <int N>
Eigen::Matrix<double, N, 1> GatherActive(const Model& model, const Data& data, std::size_t s,
                                         const std::vector<double>& x) {
  Eigen::Matrix<double, N, 1> out;
  const auto va = static_cast<std::size_t>(model.v_address[s]);
  if (N == model.v_count[s]) {
    for (int c = 0; c < N; ++c) out[c] = x[va + static_cast<std::size_t>(c)];
    return out;
  }
  int axes[6];
  ActiveAxes(model, s, data.locked[s], axes);
  for (int c = 0; c < N; ++c) out[c] = x[va + static_cast<std::size_t>(axes[c])];
  return out;
}

// Writes the active entries of the joint above `s` into x and zeroes its locked ones.
template <int N>
void ScatterActive(const Model& model, const Data& data, std::size_t s,
                   const Eigen::Matrix<double, N, 1>& values, std::vector<double>& x) {
  const auto va = static_cast<std::size_t>(model.v_address[s]);
  if (N == model.v_count[s]) {
    for (int c = 0; c < N; ++c) x[va + static_cast<std::size_t>(c)] = values[c];
    return;
  }
  int axes[6];
  ActiveAxes(model, s, data.locked[s], axes);
  for (int k = 0; k < model.v_count[s]; ++k) x[va + static_cast<std::size_t>(k)] = 0.0;
  for (int c = 0; c < N; ++c) x[va + static_cast<std::size_t>(axes[c])] = values[c];
}

// S of segment `s` as a fixed-size 6 x N matrix (a MotionSubspace is stored column by column).
template <int N>
Eigen::Map<const Eigen::Matrix<double, 6, N>> Subspace(const Data& data, std::size_t s) {
  return Eigen::Map<const Eigen::Matrix<double, 6, N>>(data.subspace[s].data());
}

// The inverse of a symmetric positive definite matrix by its Cholesky factor L (D = L L^T,
// D^-1 = L^-T L^-1), in plain loops the compiler unrolls for a fixed size. False when D is not
// positive definite.
template <int N>
bool InvertByCholesky(const Eigen::Matrix<double, N, N>& D, Eigen::Matrix<double, N, N>& out) {
  Eigen::Matrix<double, N, N> L = Eigen::Matrix<double, N, N>::Zero();
  for (int j = 0; j < N; ++j) {
    double diagonal = D(j, j);
    for (int k = 0; k < j; ++k) diagonal -= L(j, k) * L(j, k);
    if (!(diagonal > 0.0)) return false;
    L(j, j) = std::sqrt(diagonal);
    for (int i = j + 1; i < N; ++i) {
      double value = D(i, j);
      for (int k = 0; k < j; ++k) value -= L(i, k) * L(j, k);
      L(i, j) = value / L(j, j);
    }
  }
  // L^-1, lower triangular, by forward substitution.
  Eigen::Matrix<double, N, N> L_inverse = Eigen::Matrix<double, N, N>::Zero();
  for (int j = 0; j < N; ++j) {
    L_inverse(j, j) = 1.0 / L(j, j);
    for (int i = j + 1; i < N; ++i) {
      double value = 0.0;
      for (int k = j; k < i; ++k) value -= L(i, k) * L_inverse(k, j);
      L_inverse(i, j) = value / L(i, i);
    }
  }
  for (int j = 0; j < N; ++j) {
    for (int i = j; i < N; ++i) {
      double value = 0.0;
      for (int k = i; k < N; ++k) value += L_inverse(k, i) * L_inverse(k, j);
      out(i, j) = value;
      out(j, i) = value;
    }
  }
  return true;
}

// D^-1 for the symmetric positive definite D = S^T I^A S: closed form up to three axes,
// Cholesky for more. False when D is singular or not finite.
template <int N>
bool InvertJointInertia(const Eigen::Matrix<double, N, N>& D, Eigen::Matrix<double, N, N>& out) {
  if constexpr (N == 3) {
    // The cofactors of a symmetric matrix (six distinct) over the determinant, which is
    // positive for a positive definite D.
    const double c00 = D(1, 1) * D(2, 2) - D(1, 2) * D(1, 2);
    const double c01 = D(0, 2) * D(1, 2) - D(0, 1) * D(2, 2);
    const double c02 = D(0, 1) * D(1, 2) - D(0, 2) * D(1, 1);
    const double determinant = D(0, 0) * c00 + D(0, 1) * c01 + D(0, 2) * c02;
    const double scale = 1.0 / determinant;
    if (!(determinant > 0.0) || !std::isfinite(scale)) return false;
    const double c11 = D(0, 0) * D(2, 2) - D(0, 2) * D(0, 2);
    const double c12 = D(0, 1) * D(0, 2) - D(0, 0) * D(1, 2);
    const double c22 = D(0, 0) * D(1, 1) - D(0, 1) * D(0, 1);
    out << c00, c01, c02, c01, c11, c12, c02, c12, c22;
    out *= scale;
  } else if constexpr (N <= 2) {
    out = D.inverse();
  } else if (!InvertByCholesky<N>(D, out)) {
    return false;
  }
  return out.allFinite();
}

// U = I^A S, D = S^T U and S^T p^A for the joint above segment i with N active axes.
template <int N, typename UBlock>
void JointProducts(const Model& model, const Data& data, std::size_t i, UBlock& U,
                   Eigen::Matrix<double, N, N>& D, Eigen::Matrix<double, N, 1>& S_bias) {
  const Mat6& IA = data.articulated_inertia[i];
  const Vec6& pA = data.articulated_bias[i];
  if constexpr (N == 6) {
    // The only six-axis joint is the free joint, whose S is the identity.
    U = IA;
    D = IA;
    S_bias = pA;
    return;
  }
  if constexpr (N == 3) {
    if (model.joint_kind[i] == JointKind::kBall) {
      // S = [1; p~] (p: the joint point in the segment frame, p~ its cross-product matrix).
      // With I^A = [A B; B^T C]: U = [A + B p~; B^T + C p~], D = U_top - p~ U_bottom and
      // S^T p^A = p_top - p x p_bottom; each product with p~ is a cross product per row or
      // column, a third of the work of the general products.
      const Vec3& p = model.joint_point_in_child[i];
      for (int k = 0; k < 3; ++k) {
        // Row k of B p~ is (row k of B) x p; likewise for C.
        const Vec3 b_row = IA.block<1, 3>(k, 3).transpose();
        const Vec3 c_row = IA.block<1, 3>(k + 3, 3).transpose();
        U.template block<1, 3>(k, 0) = IA.block<1, 3>(k, 0) + b_row.cross(p).transpose();
        U.template block<1, 3>(k + 3, 0) = IA.block<1, 3>(k + 3, 0) + c_row.cross(p).transpose();
      }
      for (int k = 0; k < 3; ++k) {
        const Vec3 bottom = U.template block<3, 1>(3, k);
        D.col(k) = U.template block<3, 1>(0, k) - p.cross(bottom);
      }
      S_bias = pA.head<3>() - p.cross(Vec3(pA.tail<3>()));
      return;
    }
  }
  const auto S = Subspace<N>(data, i);
  U.noalias() = IA * S;
  D.noalias() = S.transpose() * U;
  S_bias.noalias() = S.transpose() * pA;
}

// True when segment i stands also for its right twin (mirror symmetry, runtime/dynamics/mirror.h).
bool IsMirrorTwin(const Model& model, std::size_t i) {
  return i < model.segment_mirror_twin.size() && model.segment_mirror_twin[i] != 0;
}

// Hands segment i's articulated inertia Ia and bias pa to its parent p (both in i's frame); a
// mirror twin hands them over together with their mirror image.
void HandToParent(const Model& model, Data& data, std::size_t i, std::size_t p, const Mat6& Ia,
                  const Vec6& pa) {
  const Transform& X = data.parent_to_child[i];
  if (IsMirrorTwin(model, i)) {
    Mat6 inertia = X.TransposeApplyInertia(Ia);
    Vec6 bias = X.TransposeApplyForce(pa);
    AddMirrorImage(model.mirror_normal[i], inertia, bias);
    data.articulated_inertia[p] += inertia;
    data.articulated_bias[p] += bias;
    return;
  }
  X.AddTransposeApplyInertia(Ia, data.articulated_inertia[p]);
  data.articulated_bias[p] += X.TransposeApplyForce(pa);
}

// The backward step at the joint above segment i with N active axes: U, D^-1 and u, then the
// articulated inertia Ia = I^A - U D^-1 U^T and bias pa = p^A + Ia c + U D^-1 u that the
// segment hands to its parent (when it has one). False when D is singular.
template <int N>
bool ArticulatedStep(const Model& model, Data& data, std::size_t i) {
  using MatN = Eigen::Matrix<double, N, N>;
  using VecN = Eigen::Matrix<double, N, 1>;
  const Mat6& IA = data.articulated_inertia[i];
  const Vec6& pA = data.articulated_bias[i];
  auto U = data.u_matrix[i].leftCols<N>();
  auto u = data.u_vector[i].head<N>();
  const VecN tau = GatherActive<N>(model, data, i, data.generalized_force);
  MatN D;
  VecN S_bias;
  JointProducts<N>(model, data, i, U, D, S_bias);
  u = tau - S_bias;
  MatN D_inverse;
  if (!InvertJointInertia<N>(D, D_inverse)) return false;
  data.d_inverse[i].topLeftCorner<N, N>() = D_inverse;
  const std::int32_t parent = model.segment_parent[i];
  if (parent < 0) return true;
  const auto p = static_cast<std::size_t>(parent);
  const Transform& X = data.parent_to_child[i];
  const Vec6& c = data.bias_acceleration[i];
  if constexpr (N == 6) {
    // A free joint passes no inertia to its parent (Ia = 0), only its generalized force.
    data.articulated_bias[p] += X.TransposeApplyForce(tau);
    return true;
  }
  if constexpr (N == 3) {
    if (model.joint_kind[i] == JointKind::kBall && !IsMirrorTwin(model, i)) {
      // Ia S = 0 with S = [1; p~]: through a ball joint at p only a translational inertia K at
      // p passes, Ia = [-p~ K p~, p~ K; -K p~, K] with K = C - U_bottom D^-1 U_bottom^T; then
      // Ia c = [p x g; g] with g = K (c_linear - p x c_angular).
      const Vec3& point = model.joint_point_in_child[i];
      Mat3 K = IA.bottomRightCorner<3, 3>();
      K.noalias() -=
          (U.template bottomRows<3>() * D_inverse) * U.template bottomRows<3>().transpose();
      const Vec3 g = K * (c.tail<3>() - point.cross(c.head<3>()));
      Vec6 pa = pA;
      pa.head<3>() += point.cross(g);
      pa.tail<3>() += g;
      pa.noalias() += U * (D_inverse * u);
      X.AddTransposeApplyPointInertia(K, point, data.articulated_inertia[p]);
      data.articulated_bias[p] += X.TransposeApplyForce(pa);
      return true;
    }
  }
  const Eigen::Matrix<double, 6, N> UD = U * D_inverse;
  Mat6 Ia = IA;
  Ia.noalias() -= UD * U.transpose();
  Vec6 pa = pA;
  pa.noalias() += Ia * c;
  pa.noalias() += UD * u;
  HandToParent(model, data, i, p, Ia, pa);
  return true;
}

// The forward step at the joint above segment i: the joint accelerations (into data.vdot) and
// the segment's acceleration a from a_prime, its parent's acceleration seen in its frame plus
// its bias acceleration.
template <int N>
bool AccelerationStep(const Model& model, Data& data, std::size_t i, Vec6& a) {
  using VecN = Eigen::Matrix<double, N, 1>;
  const auto U = data.u_matrix[i].leftCols<N>();
  const auto D_inverse = data.d_inverse[i].topLeftCorner<N, N>();
  VecN rhs = data.u_vector[i].head<N>();
  rhs.noalias() -= U.transpose() * a;
  const VecN qdd = D_inverse * rhs;
  if constexpr (N == 6) {
    a += qdd;  // S = I
  } else {
    a.noalias() += Subspace<N>(data, i) * qdd;
  }
  ScatterActive<N>(model, data, i, qdd, data.vdot);
  return true;
}

// S times the active entries of x for the joint above `s`: the joint's spatial velocity.
Vec6 SubspaceTimes(const Model& model, const Data& data, std::size_t s,
                   const std::vector<double>& x) {
  Vec6 out = Vec6::Zero();
  WithAxisCount(static_cast<int>(data.subspace[s].cols()), [&](auto axes) {
    constexpr int N = decltype(axes)::value;
    out.noalias() = Subspace<N>(data, s) * GatherActive<N>(model, data, s, x);
    return true;
  });
  return out;
}

// The pose, spatial velocity and spatial acceleration (in its own coordinates) of a root's
// base: the ground or a vehicle.
struct Frame {
  Mat3 rotation = Mat3::Identity();
  Vec3 position = Vec3::Zero();
  Vec6 velocity = Vec6::Zero();
  Vec6 acceleration = Vec6::Zero();
};

Frame BaseFrame(const Data& data, const FrameRef& base) {
  Frame frame;
  if (base.kind != FrameRef::Kind::kVehicle) return frame;
  const VehicleState& vehicle = data.vehicle[static_cast<std::size_t>(base.index)];
  frame.rotation = vehicle.rotation;
  frame.position = vehicle.position;
  const Vec3 w = vehicle.rotation.transpose() * vehicle.angular_velocity;
  frame.velocity << w, vehicle.rotation.transpose() * vehicle.velocity;
  // Spatial acceleration of a frame whose origin accelerates by a (classical): a - w x v.
  frame.acceleration << vehicle.rotation.transpose() * vehicle.angular_acceleration,
      vehicle.rotation.transpose() * vehicle.acceleration - w.cross(frame.velocity.tail<3>());
  return frame;
}

}  // namespace

Mat6 SpatialInertia(const Model& model, std::size_t segment) {
  Mat6 inertia = Mat6::Zero();
  inertia.topLeftCorner<3, 3>() = model.segment_inertia[segment];
  inertia.bottomRightCorner<3, 3>().diagonal().setConstant(model.segment_mass[segment]);
  return inertia;
}

void ComputeKinematics(const Model& model, Data& data) { ComputeKinematics(model, data, {}); }

void ComputeKinematics(const Model& model, Data& data, std::span<const std::uint8_t> segments) {
  for (std::size_t v = 0; v < data.vehicle.size(); ++v) {
    data.vehicle[v] = VehicleAt(model, v, data.time);
  }
  JointMotion motion;
  for (std::size_t s = 0; s < model.nsegment(); ++s) {
    if (!segments.empty() && !segments[s]) continue;
    const std::uint8_t locked = data.locked[s];
    ComputeJointPose(model, s, data.q, data.v, locked, motion);
    if (data.subspace_locked[s] != locked || SubspaceDependsOnPosition(model.joint_kind[s])) {
      ComputeJointSubspace(model, s, data.q, locked, data.subspace[s]);
      data.subspace_locked[s] = locked;
    }
    const Vec6 joint_velocity = SubspaceTimes(model, data, s, data.v);
    Transform& x = data.parent_to_child[s];
    // R_PC = F_parent R_J F_child^T (F: the joint frames), skipping identity frames.
    const Mat3& frame_parent = model.joint_frame_in_parent[s];
    const std::uint8_t identity = data.joint_frame_identity[s];
    Mat3 rotation_parent_child = motion.rotation;
    if (!(identity & 2u)) {
      rotation_parent_child = motion.rotation * model.joint_frame_in_child[s].transpose();
    }
    if (!(identity & 1u)) rotation_parent_child = frame_parent * rotation_parent_child;
    x.E = rotation_parent_child.transpose();
    x.r = model.joint_point_in_parent[s] - rotation_parent_child * model.joint_point_in_child[s];
    if (model.joint_kind[s] == JointKind::kFree || model.joint_kind[s] == JointKind::kSlip ||
        model.joint_kind[s] == JointKind::kPlanar) {
      x.r += frame_parent * motion.translation;
    }
    // The parent: a segment, or for a root its base (the ground or a vehicle).
    auto place = [&](const Mat3& parent_rotation, const Vec3& parent_position,
                     const Vec6& parent_velocity) {
      data.rotation[s] = parent_rotation * rotation_parent_child;
      data.position[s] = parent_position + parent_rotation * x.r;
      data.velocity[s] = x.ApplyMotion(parent_velocity) + joint_velocity;
      data.bias_acceleration[s] = CrossMotion(data.velocity[s], joint_velocity) + motion.bias;
    };
    const std::int32_t parent = model.segment_parent[s];
    if (parent >= 0) {
      const auto p = static_cast<std::size_t>(parent);
      place(data.rotation[p], data.position[p], data.velocity[p]);
    } else {
      const Frame base = BaseFrame(data, model.segment_base[s]);
      place(base.rotation, base.position, base.velocity);
      // A moving base's acceleration enters as the root's parent acceleration.
      data.bias_acceleration[s] += x.ApplyMotion(base.acceleration);
    }
  }
}

bool ComputeAccelerations(const Model& model, Data& data, Failure* failure) {
  const std::size_t n = model.nsegment();
  // Rigid-body inertias, and bias forces: gyroscopic terms less the applied wrenches.
  for (std::size_t s = 0; s < n; ++s) {
    const Mat3& J = model.segment_inertia[s];
    const double m = model.segment_mass[s];
    data.articulated_inertia[s] = SpatialInertia(model, s);
    const Vec6& v = data.velocity[s];
    Vec6 momentum;
    momentum << J * v.head<3>(), m * v.tail<3>();
    data.articulated_bias[s] = CrossForce(v, momentum) - data.external[s];
  }
  // Leaves to roots: articulated inertias and biases, each handed to the parent.
  for (std::size_t i = n; i-- > 0;) {
    const int count = static_cast<int>(data.subspace[i].cols());
    const bool regular = WithAxisCount(
        count, [&](auto axes) { return ArticulatedStep<decltype(axes)::value>(model, data, i); });
    if (!regular) {
      if (failure) {
        failure->where = model.segment_name[i];
        failure->cause =
            "the articulated inertia is singular (a massless segment without "
            "enough constraints?)";
      }
      return false;
    }
    const std::int32_t parent = model.segment_parent[i];
    if (count == 0 && parent >= 0) {
      // A locked joint: the segment moves with its parent and hands it all of its inertia.
      const Mat6& IA = data.articulated_inertia[i];
      HandToParent(model, data, i, static_cast<std::size_t>(parent), IA,
                   data.articulated_bias[i] + IA * data.bias_acceleration[i]);
    }
  }
  // Roots to leaves: accelerations; then the wrench each joint transmits.
  for (std::size_t i = 0; i < n; ++i) {
    const std::int32_t parent = model.segment_parent[i];
    Vec6 a = data.bias_acceleration[i];
    if (parent >= 0) {
      a += data.parent_to_child[i].ApplyMotion(data.acceleration[static_cast<std::size_t>(parent)]);
    }
    const int count = static_cast<int>(data.subspace[i].cols());
    if (count == 0) {
      const auto va = static_cast<std::size_t>(model.v_address[i]);
      for (int k = 0; k < model.v_count[i]; ++k) data.vdot[va + static_cast<std::size_t>(k)] = 0.0;
    }
    WithAxisCount(count, [&](auto axes) {
      return AccelerationStep<decltype(axes)::value>(model, data, i, a);
    });
    data.acceleration[i] = a;
    data.joint_wrench[i] = data.articulated_inertia[i] * a + data.articulated_bias[i];
    if (!a.allFinite()) {
      if (failure) {
        failure->where = model.segment_name[i];
        failure->cause = "the acceleration is not finite";
      }
      return false;
    }
  }
  return true;
}

void ForwardElements(const Model& model, Data& data) {
  ++data.evaluations;
  ComputeKinematics(model, data);
  ComputeElementForces(model, data);
}

bool Forward(const Model& model, Data& data, Failure* failure) {
  ForwardElements(model, data);
  return ForwardAccelerations(model, data, failure);
}

bool ForwardAccelerations(const Model& model, Data& data, Failure* failure) {
  ComputeJointTorques(model, data);
  if (!ComputeAccelerations(model, data, failure)) {
    // A singular (massless) segment: the tree alone leaves its motion open; constraints on it
    // may settle it, solved together with the tree's equations.
    if (model.nconstraint() == 0) return false;
    Failure singular;
    if (failure) singular = *failure;
    if (ApplyConstraintsToSingularTree(model, data, failure)) return true;
    if (failure) {
      failure->cause = fmt::format("{}; with the constraints: {}", singular.cause, failure->cause);
    }
    return false;
  }
  if (model.nconstraint() > 0) return ApplyConstraints(model, data, failure);
  return true;
}

}  // namespace sled::runtime
