#include "runtime/dynamics/constraints.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <klu.h>

#include "runtime/dynamics/dynamics.h"
#include "runtime/dynamics/frame_motion.h"
#include "runtime/dynamics/joint.h"
#include "runtime/dynamics/mass_matrix.h"
#include "runtime/dynamics/tree_bias.h"
#include "runtime/dynamics/vehicle.h"
#include "runtime/run/archive.h"

namespace sled::runtime {

struct KluSolver {
  klu_common common{};
  klu_symbolic* symbolic = nullptr;
  klu_numeric* numeric = nullptr;
  double factored_rcond = 0.0;  // klu_rcond just after the last fresh factorization
  // The KKT values of the last fresh factorization: its pivots are what every refactorization
  // reuses, so a checkpoint keeps them to make the same factorization again.
  std::vector<double> factored_values;
};

void KluSolverDeleter::operator()(KluSolver* solver) const {
  if (solver == nullptr) return;
  if (solver->numeric != nullptr) klu_free_numeric(&solver->numeric, &solver->common);
  if (solver->symbolic != nullptr) klu_free_symbolic(&solver->symbolic, &solver->common);
  delete solver;
}

void ConstraintWorkspaceDeleter::operator()(ConstraintWorkspace* workspace) const {
  delete workspace;
}

namespace {

// A refactorization with the frozen pivot sequence is kept while min|u_ii| / max|u_ii| stays
// within this factor of its value after the last fresh factorization with pivoting.
constexpr double kRcondDrop = 1e-3;
// The projection stops when every position error is below this [m] and every velocity error
// below kVelocityTolerance [m/s]: far below any tolerance a run uses, far above round-off.
constexpr double kPositionTolerance = 1e-12;
constexpr double kVelocityTolerance = 1e-12;
// Gauss-Newton iterations: a drift after a step takes one or two; assembling the initial state
// from a pose far off (or one at a singular configuration, a straight knee) may take many.
constexpr int kProjectionIterations = 50;
constexpr int kAssemblyIterations = 500;
constexpr int kLineSearchHalvings = 30;
// Below this distance [m] a fixed-distance constraint has no direction.
constexpr double kMinimumLength = 1e-12;
// The characteristic length of a constrained segment is at least this [m].
constexpr double kMinimumArm = 0.01;

bool Fail(Failure* failure, const std::string& where, std::string cause) {
  if (failure != nullptr) {
    failure->where = where;
    failure->cause = std::move(cause);
  }
  return false;
}

struct PointMotion {
  Vec3 position;
  Vec3 velocity;
  Vec3 acceleration;
};

PointMotion PointOf(const FrameMotion& frame, const Vec3& point) {
  const Vec3 arm = frame.rotation * point;
  const Vec3& w = frame.angular_velocity;
  return {frame.origin + arm, frame.velocity + w.cross(arm),
          frame.acceleration + frame.angular_acceleration.cross(arm) + w.cross(w.cross(arm))};
}

// Adds sign * d(velocity of the world point p moving with `segment`)/dv to `linear` (3 x nv) and
// sign * d(angular velocity)/dv to `angular`, each when given: one column per active axis of
// each joint from the segment to its root.
void AddJacobian(const Model& model, const Data& data, std::size_t segment, const Vec3& p,
                 double sign, Eigen::MatrixXd* linear, Eigen::MatrixXd* angular) {
  for (std::int32_t k = static_cast<std::int32_t>(segment); k >= 0;
       k = model.segment_parent[static_cast<std::size_t>(k)]) {
    const auto a = static_cast<std::size_t>(k);
    int axes[6];
    const int count = ActiveAxes(model, a, data.locked[a], axes);
    const Mat3& R = data.rotation[a];
    const Vec3 arm = p - data.position[a];
    for (int c = 0; c < count; ++c) {
      const auto column = static_cast<Eigen::Index>(model.v_address[a] + axes[c]);
      const Vec3 w = R * data.subspace[a].col(c).head<3>();
      const Vec3 v = R * data.subspace[a].col(c).tail<3>();
      if (linear != nullptr) linear->col(column) += sign * (v + w.cross(arm));
      if (angular != nullptr) angular->col(column) += sign * w;
    }
  }
}

void AddPointJacobian(const Model& model, const Data& data, const FrameRef& frame, const Vec3& p,
                      double sign, Eigen::MatrixXd* linear, Eigen::MatrixXd* angular) {
  if (frame.kind != FrameRef::Kind::kSegment) return;  // prescribed: no degrees of freedom
  AddJacobian(model, data, static_cast<std::size_t>(frame.index), p, sign, linear, angular);
}

// phi, phi_dot, the Jacobian and the constraint points from data's kinematics; phi_ddot too (at
// data.acceleration, the tree accelerations) when `with_acceleration`.
bool Evaluate(const Model& model, const Data& data, ConstraintWorkspace& w, bool with_acceleration,
              Failure* failure) {
  w.jacobian.setZero();
  for (std::size_t c = 0; c < model.nconstraint(); ++c) {
    const Model::ConstraintKind kind = model.constraint_kind[c];
    const FrameRef& first = model.constraint_first[c];
    const FrameRef& second = model.constraint_second[c];
    if (kind == Model::ConstraintKind::kRolling) {
      return Fail(failure, model.constraint_name[c],
                  "rolling constraints are not simulated yet (they need the surface the point "
                  "rolls on)");
    }
    if (first.kind != FrameRef::Kind::kSegment && second.kind != FrameRef::Kind::kSegment) {
      return Fail(failure, model.constraint_name[c],
                  "the constraint joins two prescribed frames (ground or vehicles): nothing can "
                  "move to satisfy it");
    }
    const FrameMotion f1 = MotionWithAcceleration(data, first);
    const FrameMotion f2 = MotionWithAcceleration(data, second);
    const PointMotion p1 = PointOf(f1, model.constraint_point_first[c]);
    const PointMotion p2 = PointOf(f2, model.constraint_point_second[c]);
    w.point_first[c] = p1.position;
    w.point_second[c] = p2.position;
    const Vec3 d = p1.position - p2.position;
    const Vec3 d_dot = p1.velocity - p2.velocity;
    const Vec3 d_ddot = p1.acceleration - p2.acceleration;
    const auto r0 = static_cast<Eigen::Index>(w.first_row[c]);
    w.point_jacobian.setZero();
    switch (kind) {
      case Model::ConstraintKind::kFixedPoint: {
        AddPointJacobian(model, data, first, p1.position, 1.0, &w.point_jacobian, nullptr);
        AddPointJacobian(model, data, second, p2.position, -1.0, &w.point_jacobian, nullptr);
        w.phi.segment<3>(r0) = d;
        w.phi_dot.segment<3>(r0) = d_dot;
        if (with_acceleration) w.phi_ddot.segment<3>(r0) = d_ddot;
        w.jacobian.middleRows<3>(r0) = w.point_jacobian;
        w.error[c] = d.norm();
        break;
      }
      case Model::ConstraintKind::kFixedDistance: {
        const double length = d.norm();
        if (!(length > kMinimumLength)) {
          return Fail(failure, model.constraint_name[c],
                      "the two points of the fixed-distance constraint coincide, so it has no "
                      "direction (use a fixed point for a zero distance)");
        }
        const Vec3 n = d / length;
        AddPointJacobian(model, data, first, p1.position, 1.0, &w.point_jacobian, nullptr);
        AddPointJacobian(model, data, second, p2.position, -1.0, &w.point_jacobian, nullptr);
        const double rate = n.dot(d_dot);
        w.phi[r0] = length - model.constraint_distance[c];
        w.phi_dot[r0] = rate;
        if (with_acceleration) {
          w.phi_ddot[r0] = n.dot(d_ddot) + (d_dot.squaredNorm() - rate * rate) / length;
        }
        for (Eigen::Index j = 0; j < w.nv; ++j) w.jacobian(r0, j) = n.dot(w.point_jacobian.col(j));
        w.error[c] = std::abs(w.phi[r0]);
        break;
      }
      case Model::ConstraintKind::kSliding: {
        // Rows t_k . (p1 - p2) with t_k fixed in the second frame: the first point stays on the
        // line through the second point along the axis.
        w.angular_jacobian.setZero();
        AddPointJacobian(model, data, first, p1.position, 1.0, &w.point_jacobian, nullptr);
        AddPointJacobian(model, data, second, p2.position, -1.0, &w.point_jacobian, nullptr);
        AddPointJacobian(model, data, second, p2.position, 1.0, nullptr, &w.angular_jacobian);
        double squared = 0.0;
        const Vec3& w2 = f2.angular_velocity;
        for (int k = 0; k < 2; ++k) {
          const Vec3 t = f2.rotation * w.sliding_normal[2 * c + static_cast<std::size_t>(k)];
          const Vec3 t_dot = w2.cross(t);
          w.phi[r0 + k] = t.dot(d);
          w.phi_dot[r0 + k] = t.dot(d_dot) + t_dot.dot(d);
          if (with_acceleration) {
            const Vec3 t_ddot = f2.angular_acceleration.cross(t) + w2.cross(t_dot);
            w.phi_ddot[r0 + k] = t.dot(d_ddot) + 2 * t_dot.dot(d_dot) + t_ddot.dot(d);
          }
          const Vec3 lever = t.cross(d);  // the rows turn with the second frame
          for (Eigen::Index j = 0; j < w.nv; ++j) {
            w.jacobian(r0 + k, j) =
                t.dot(w.point_jacobian.col(j)) + lever.dot(w.angular_jacobian.col(j));
          }
          squared += w.phi[r0 + k] * w.phi[r0 + k];
        }
        w.error[c] = std::sqrt(squared);
        break;
      }
      case Model::ConstraintKind::kRolling:
        break;
    }
  }
  return true;
}

// Assembles the KKT matrix from w.mass and w.jacobian and factors it: a refactorization with the
// frozen pivot sequence while it stays well conditioned, else a fresh factorization.
bool Factor(const Model& model, ConstraintWorkspace& w, Failure* failure) {
  const Eigen::Index nv = w.nv, m = w.rows;
  // eps: relative to the largest diagonal of J M^-1 J^T, estimated with the diagonal of M.
  double scale = 0.0;
  for (Eigen::Index r = 0; r < m; ++r) {
    double sum = 0.0;
    for (Eigen::Index j = 0; j < nv; ++j) {
      const double entry = w.jacobian(r, j);
      // A massless segment's coordinate has no mass on the diagonal: it adds no scale.
      if (entry != 0.0 && w.mass(j, j) > 0.0) sum += entry * entry / w.mass(j, j);
    }
    scale = std::max(scale, sum);
  }
  const double eps = w.regularisation * (scale > 0.0 ? scale : 1.0);
  for (Eigen::Index j = 0; j < nv; ++j) {
    for (Eigen::Index i = 0; i < nv; ++i) {
      const std::int32_t position = w.mass_position[static_cast<std::size_t>(i + j * nv)];
      if (position >= 0) w.kkt_value[static_cast<std::size_t>(position)] = w.mass(i, j);
    }
    for (Eigen::Index r = 0; r < m; ++r) {
      const auto k = static_cast<std::size_t>(r + j * m);
      if (w.jacobian_position[k] >= 0) {
        w.kkt_value[static_cast<std::size_t>(w.jacobian_position[k])] = w.jacobian(r, j);
        w.kkt_value[static_cast<std::size_t>(w.transpose_position[k])] = w.jacobian(r, j);
      }
    }
  }
  for (Eigen::Index r = 0; r < m; ++r) {
    w.kkt_value[static_cast<std::size_t>(w.diagonal_position[static_cast<std::size_t>(r)])] = -eps;
  }

  KluSolver& klu = *w.solver;
  const std::string& first_name = model.constraint_name.front();
  if (klu.symbolic == nullptr) {
    return Fail(failure, first_name, "KLU could not analyse the constraint equations");
  }
  if (klu.numeric != nullptr) {
    ++w.refactorizations;
    bool good = klu_refactor(w.kkt_pointer.data(), w.kkt_index.data(), w.kkt_value.data(),
                             klu.symbolic, klu.numeric, &klu.common) != 0;
    good = good && klu_rcond(klu.symbolic, klu.numeric, &klu.common) != 0 &&
           klu.common.rcond >= kRcondDrop * klu.factored_rcond;
    if (!good) klu_free_numeric(&klu.numeric, &klu.common);
  }
  if (klu.numeric == nullptr) {
    // Rare: the configuration has moved far enough for new pivots (this allocates).
    ++w.factorizations;
    klu.numeric = klu_factor(w.kkt_pointer.data(), w.kkt_index.data(), w.kkt_value.data(),
                             klu.symbolic, &klu.common);
    if (klu.numeric == nullptr || klu_rcond(klu.symbolic, klu.numeric, &klu.common) == 0 ||
        !(klu.common.rcond > 0.0)) {
      // Name the constraint or segment of the first zero pivot.
      const int column = klu.common.singular_col;
      std::string where = first_name;
      if (column >= 0 && column < w.nv) {
        for (std::size_t s = 0; s < model.nsegment(); ++s) {
          if (column >= model.v_address[s] && column < model.v_address[s] + model.v_count[s]) {
            where = model.segment_name[s];
          }
        }
      } else if (column >= w.nv && column < w.nv + w.rows) {
        for (std::size_t c = 0; c < model.nconstraint(); ++c) {
          if (column - w.nv >= w.first_row[c]) where = model.constraint_name[c];
        }
      }
      return Fail(failure, where,
                  "the constraint equations are singular (a massless segment, or constraints "
                  "that fight each other)");
    }
    klu.factored_rcond = klu.common.rcond;
    klu.factored_values = w.kkt_value;  // same size: no allocation
  }
  return true;
}

// Solves the factored KKT system in place in w.solution (right-hand side in, solution out).
bool SolveFactored(const Model& model, ConstraintWorkspace& w, std::span<double> b,
                   Failure* failure) {
  KluSolver& klu = *w.solver;
  ++w.solves;
  if (klu_solve(klu.symbolic, klu.numeric, w.nv + w.rows, 1, b.data(), &klu.common) == 0) {
    return Fail(failure, model.constraint_name.front(), "KLU could not solve the constraints");
  }
  for (double value : b) {
    if (!std::isfinite(value)) {
      return Fail(failure, model.constraint_name.front(), "the constraint forces are not finite");
    }
  }
  return true;
}

// Solves [M J^T; J 0] x = w.solution with the factored regularised matrix and one step of
// iterative refinement against the unregularised one, which takes the eps error of the
// multipliers from 1e-10 to round-off.
bool Solve(const Model& model, ConstraintWorkspace& w, Failure* failure) {
  const Eigen::Index nv = w.nv, m = w.rows;
  std::copy(w.solution.begin(), w.solution.end(), w.residual.begin());
  if (!SolveFactored(model, w, w.solution, failure)) return false;
  Eigen::Map<Eigen::VectorXd> x(w.solution.data(), nv + m);
  Eigen::Map<Eigen::VectorXd> r(w.residual.data(), nv + m);
  r.head(nv).noalias() -= w.mass * x.head(nv);
  r.head(nv).noalias() -= w.jacobian.transpose() * x.tail(m);
  r.tail(m).noalias() -= w.jacobian * x.head(nv);
  if (!SolveFactored(model, w, w.residual, failure)) return false;
  x += r;
  return true;
}

// Adds a world force acting at the world point p to a segment's constraint wrench.
void AddForce(const Data& data, ConstraintWorkspace& w, const FrameRef& frame, const Vec3& p,
              const Vec3& force) {
  if (frame.kind != FrameRef::Kind::kSegment) return;
  const auto s = static_cast<std::size_t>(frame.index);
  const Mat3& R = data.rotation[s];
  const Vec3 f = R.transpose() * force;
  const Vec3 arm = R.transpose() * (p - data.position[s]);
  w.segment_wrench[s].head<3>() += arm.cross(f);
  w.segment_wrench[s].tail<3>() += f;
}

// The forces of the multipliers at the constraint points, and the wrench on each segment.
void ConstraintForces(const Model& model, const Data& data, ConstraintWorkspace& w) {
  for (Vec6& wrench : w.segment_wrench) wrench.setZero();
  for (std::size_t c = 0; c < model.nconstraint(); ++c) {
    const auto r0 = static_cast<Eigen::Index>(w.first_row[c]);
    const FrameRef& first = model.constraint_first[c];
    const FrameRef& second = model.constraint_second[c];
    const Vec3& p1 = w.point_first[c];
    const Vec3& p2 = w.point_second[c];
    Vec3 force = Vec3::Zero();
    switch (model.constraint_kind[c]) {
      case Model::ConstraintKind::kFixedPoint:
        force = w.lambda.segment<3>(r0);
        AddForce(data, w, second, p2, -force);
        break;
      case Model::ConstraintKind::kFixedDistance:
        force = w.lambda[r0] * (p1 - p2).normalized();
        AddForce(data, w, second, p2, -force);
        break;
      case Model::ConstraintKind::kSliding: {
        const Mat3 rotation = MotionOf(data, second).rotation;
        for (int k = 0; k < 2; ++k) {
          force +=
              w.lambda[r0 + k] * (rotation * w.sliding_normal[2 * c + static_cast<std::size_t>(k)]);
        }
        // The reaction acts at the first point (the t x d torque of the rows).
        AddForce(data, w, second, p1, -force);
        break;
      }
      case Model::ConstraintKind::kRolling:
        break;
    }
    w.force_first[c] = force;
    AddForce(data, w, first, p1, force);
  }
}

// Spatial accelerations from data.vdot (roots to leaves), then the joint wrenches with the
// constraint wrenches (leaves to roots, as the recursive Newton-Euler algorithm): the same
// quantities ComputeAccelerations leaves, for the closed loops.
void UpdateAccelerationsAndWrenches(const Model& model, Data& data, const ConstraintWorkspace& w) {
  const std::size_t n = model.nsegment();
  for (std::size_t i = 0; i < n; ++i) {
    const std::int32_t parent = model.segment_parent[i];
    Vec6 a = data.bias_acceleration[i];
    if (parent >= 0) {
      a += data.parent_to_child[i].ApplyMotion(data.acceleration[static_cast<std::size_t>(parent)]);
    }
    int axes[6];
    const int count = ActiveAxes(model, i, data.locked[i], axes);
    const auto va = static_cast<std::size_t>(model.v_address[i]);
    for (int c = 0; c < count; ++c) {
      a += data.subspace[i].col(c) * data.vdot[va + static_cast<std::size_t>(axes[c])];
    }
    data.acceleration[i] = a;
    const Mat6 inertia = SpatialInertia(model, i);
    data.joint_wrench[i] = inertia * a + CrossForce(data.velocity[i], inertia * data.velocity[i]) -
                           data.external[i] - w.segment_wrench[i];
  }
  for (std::size_t i = n; i-- > 0;) {
    const std::int32_t parent = model.segment_parent[i];
    if (parent < 0) continue;
    data.joint_wrench[static_cast<std::size_t>(parent)] +=
        data.parent_to_child[i].TransposeApplyForce(data.joint_wrench[i]);
  }
}

// q <- q (+) dv: each joint's coordinates moved by the velocity increment dv taken over unit
// time, with the exact exponential map for quaternions (the increment PositionDerivative rates).
void AdvancePositions(const Model& model, const Data& data, std::span<const double> dv,
                      std::span<double> q) {
  auto turn = [&](std::size_t address, const Vec3& rotation_vector) {
    const double angle = rotation_vector.norm();
    Eigen::Quaterniond quaternion = QuaternionAt(q, address);
    if (angle > 0.0) {
      quaternion =
          quaternion * Eigen::Quaterniond(Eigen::AngleAxisd(angle, rotation_vector / angle));
    }
    quaternion.normalize();
    q[address] = quaternion.w();
    q[address + 1] = quaternion.x();
    q[address + 2] = quaternion.y();
    q[address + 3] = quaternion.z();
  };
  for (std::size_t s = 0; s < model.nsegment(); ++s) {
    const auto qa = static_cast<std::size_t>(model.q_address[s]);
    const auto va = static_cast<std::size_t>(model.v_address[s]);
    const std::uint8_t locked = data.locked[s];
    switch (model.joint_kind[s]) {
      case JointKind::kFree: {
        const Mat3 rotation = QuaternionAt(q, qa + 3).normalized().toRotationMatrix();
        const Vec3 translation = rotation * Vec3(dv[va + 3], dv[va + 4], dv[va + 5]);
        for (std::size_t k = 0; k < 3; ++k) q[qa + k] += translation[static_cast<Eigen::Index>(k)];
        turn(qa + 3, Vec3(dv[va], dv[va + 1], dv[va + 2]));
        break;
      }
      case JointKind::kBall:
        if (locked == 0) {
          turn(qa,
               model.joint_frame_in_child[s].transpose() * Vec3(dv[va], dv[va + 1], dv[va + 2]));
        }
        break;
      case JointKind::kPin:
      case JointKind::kSlip:
        if (locked == 0) q[qa] += dv[va];
        break;
      case JointKind::kEuler:
        for (std::size_t k = 0; k < 3; ++k) {
          if (!(locked & (1u << k))) q[qa + k] += dv[va + k];
        }
        break;
      case JointKind::kPlanar:
        for (std::size_t k = 0; k < 3; ++k) q[qa + k] += dv[va + k];
        break;
    }
  }
}

// The constraint with the largest position error, for messages.
const std::string& WorstConstraint(const Model& model, const ConstraintWorkspace& w) {
  std::size_t worst = 0;
  for (std::size_t c = 1; c < w.error.size(); ++c) {
    if (w.error[c] > w.error[worst]) worst = c;
  }
  return model.constraint_name[worst];
}

double MaxAbs(const Eigen::VectorXd& values) {
  return values.size() == 0 ? 0.0 : values.cwiseAbs().maxCoeff();
}

// Projects data.q and data.v (at data.time) onto the constraints; `position_error` and
// `velocity_error` receive the largest errors before projection. Leaves data's kinematics at
// the projected state.
bool ProjectState(const Model& model, Data& data, int iterations, Failure* failure,
                  double* position_error, double* velocity_error) {
  ConstraintWorkspace& w = *data.constraints;
  const auto nv = static_cast<std::size_t>(w.nv);
  std::span<double> dv(w.solution.data(), nv);
  ComputeKinematics(model, data);
  if (!Evaluate(model, data, w, false, failure)) return false;
  double error = MaxAbs(w.phi), norm = w.phi.norm();
  *position_error = error;
  for (int iteration = 0; error > kPositionTolerance; ++iteration) {
    if (iteration == iterations) {
      return Fail(failure, WorstConstraint(model, w),
                  fmt::format("the constraints cannot all be satisfied: a position error of {:g} "
                              "m remains after {} projections",
                              error, iterations));
    }
    // Gauss-Newton: the smallest step in the metric of M with J dq = -phi, halved until the
    // error decreases (far from the constraints the linearisation overshoots).
    CompositeRigidBodyMassMatrix(model, data, w.composite, w.mass);
    if (!Factor(model, w, failure)) return false;
    std::fill(w.solution.begin(), w.solution.end(), 0.0);
    for (Eigen::Index r = 0; r < w.rows; ++r) {
      w.solution[nv + static_cast<std::size_t>(r)] = -w.phi[r];
    }
    if (!Solve(model, w, failure)) return false;
    std::copy(data.q.begin(), data.q.end(), w.q_saved.begin());
    bool decreased = false;
    for (int halving = 0; halving < kLineSearchHalvings && !decreased; ++halving) {
      if (halving > 0) {
        for (double& value : dv) value *= 0.5;
      }
      std::copy(w.q_saved.begin(), w.q_saved.end(), data.q.begin());
      AdvancePositions(model, data, dv, data.q);
      ComputeKinematics(model, data);
      if (!Evaluate(model, data, w, false, failure)) return false;
      decreased = w.phi.norm() < norm;
    }
    if (!decreased) {
      std::copy(w.q_saved.begin(), w.q_saved.end(), data.q.begin());
      ComputeKinematics(model, data);
      if (!Evaluate(model, data, w, false, failure)) return false;
      return Fail(failure, WorstConstraint(model, w),
                  fmt::format("the constraints cannot all be satisfied: the position error "
                              "stalls at {:g} m",
                              error));
    }
    error = MaxAbs(w.phi);
    norm = w.phi.norm();
  }
  // Velocities: the M-orthogonal projection onto J v + phi_t = 0 (a second pass only if the
  // first left more than round-off).
  for (int pass = 0;; ++pass) {
    const double rate_error = MaxAbs(w.phi_dot);
    if (pass == 0) *velocity_error = rate_error;
    if (rate_error <= kVelocityTolerance || pass == 2) break;
    if (pass == 0) {  // M and J depend on q only
      CompositeRigidBodyMassMatrix(model, data, w.composite, w.mass);
      if (!Factor(model, w, failure)) return false;
    }
    std::fill(w.solution.begin(), w.solution.end(), 0.0);
    for (Eigen::Index r = 0; r < w.rows; ++r) {
      w.solution[nv + static_cast<std::size_t>(r)] = -w.phi_dot[r];
    }
    if (!Solve(model, w, failure)) return false;
    for (std::size_t j = 0; j < nv; ++j) data.v[j] += dv[j];
    ComputeKinematics(model, data);
    if (!Evaluate(model, data, w, false, failure)) return false;
  }
  return true;
}

// Beta = 1/T for a characteristic time T of the constrained segments: the period scale
// sqrt(L/g) of a pendulum as long as the largest lever arm L of a constrained point about its
// segment's centre of mass (at least 1 cm); a tenth of the run without gravity.
double StabilisationRate(const Model& model) {
  double arm = kMinimumArm;
  for (std::size_t c = 0; c < model.nconstraint(); ++c) {
    if (model.constraint_first[c].kind == FrameRef::Kind::kSegment) {
      arm = std::max(arm, model.constraint_point_first[c].norm());
    }
    if (model.constraint_second[c].kind == FrameRef::Kind::kSegment) {
      arm = std::max(arm, model.constraint_point_second[c].norm());
    }
  }
  const double g = model.gravity.norm();
  const double time =
      g > 0.0 ? std::sqrt(arm / g) : std::max(model.end_time - model.start_time, 1e-2) / 10;
  return 1.0 / time;
}

// A fixed distance whose line is perpendicular to every motion the joints allow (the two points
// and the centres of the joints between them on one line: the distance is the largest or the
// smallest the chain can have) has a vanishing row, |J| below this share of the two points'
// relative mobility |J_p1 - J_p2| (both in the metric of M^-1). Its multiplier is the
// regularisation's b / eps: holding the distance once a joint bends takes an unbounded force.
constexpr double kDegenerateRow = 1e-6;

// The first fixed-distance constraint at such an extreme of its distance, or -1; at data's
// kinematics and w.point_first/second (after Evaluate). Uses w.mass and w.point_jacobian.
std::int64_t DegenerateDistance(const Model& model, Data& data, ConstraintWorkspace& w) {
  CompositeRigidBodyMassMatrix(model, data, w.composite, w.mass);
  for (std::size_t c = 0; c < model.nconstraint(); ++c) {
    if (model.constraint_kind[c] != Model::ConstraintKind::kFixedDistance) continue;
    const Vec3 d = w.point_first[c] - w.point_second[c];
    if (!(d.norm() > kMinimumLength)) continue;  // Evaluate reports coincident points
    const Vec3 n = d.normalized();
    w.point_jacobian.setZero();
    AddPointJacobian(model, data, model.constraint_first[c], w.point_first[c], 1.0,
                     &w.point_jacobian, nullptr);
    AddPointJacobian(model, data, model.constraint_second[c], w.point_second[c], -1.0,
                     &w.point_jacobian, nullptr);
    double row = 0.0, mobility = 0.0;
    for (Eigen::Index j = 0; j < w.nv; ++j) {
      if (!(w.mass(j, j) > 0.0)) continue;  // a massless coordinate adds no scale (as Factor)
      const double along = n.dot(w.point_jacobian.col(j));
      row += along * along / w.mass(j, j);
      mobility += w.point_jacobian.col(j).squaredNorm() / w.mass(j, j);
    }
    if (mobility > 0.0 && row <= kDegenerateRow * kDegenerateRow * mobility) {
      return static_cast<std::int64_t>(c);
    }
  }
  return -1;
}

}  // namespace

void SetUpConstraints(const Model& model, const ConstraintPattern& pattern, Data& data) {
  const std::size_t nc = model.nconstraint();
  if (nc == 0) return;
  data.constraints.reset(new ConstraintWorkspace);
  ConstraintWorkspace& w = *data.constraints;
  static_cast<ConstraintPattern&>(w) = pattern;
  const std::size_t n = model.nsegment();
  const auto nv = static_cast<std::size_t>(model.nv);
  const auto rows = w.rows;
  const std::size_t size = nv + static_cast<std::size_t>(rows);
  w.kkt_value.assign(w.kkt_index.size(), 0.0);

  w.mass = Eigen::MatrixXd::Zero(model.nv, model.nv);
  w.jacobian = Eigen::MatrixXd::Zero(rows, model.nv);
  w.point_jacobian = Eigen::MatrixXd::Zero(3, model.nv);
  w.angular_jacobian = Eigen::MatrixXd::Zero(3, model.nv);
  w.composite.assign(n, Mat6::Zero());
  w.phi = Eigen::VectorXd::Zero(rows);
  w.phi_dot = Eigen::VectorXd::Zero(rows);
  w.phi_ddot = Eigen::VectorXd::Zero(rows);
  w.solution.assign(size, 0.0);
  w.tree_residual.assign(nv, 0.0);
  w.segment_wrench.assign(n, Vec6::Zero());
  w.q_saved.assign(static_cast<std::size_t>(model.nq), 0.0);
  w.residual.assign(size, 0.0);
  w.lambda = Eigen::VectorXd::Zero(rows);
  w.point_first.assign(nc, Vec3::Zero());
  w.point_second.assign(nc, Vec3::Zero());
  w.force_first.assign(nc, Vec3::Zero());
  w.error.assign(nc, 0.0);
  w.stabilisation_rate = StabilisationRate(model);

  // The symbolic analysis, once: BTF, then AMD on each block.
  w.solver.reset(new KluSolver);
  KluSolver& klu = *w.solver;
  klu.factored_values.assign(w.kkt_value.size(), 0.0);
  klu_defaults(&klu.common);
  klu.symbolic =
      klu_analyze(static_cast<int>(size), w.kkt_pointer.data(), w.kkt_index.data(), &klu.common);
  ++w.analyses;

  // A consistent initial state; the first numeric factorization happens here too. When the
  // constraints cannot be met the state stays as given and the first evaluation reports it.
  const std::vector<double> q = data.q, v = data.v;
  Failure ignored;
  if (!ProjectState(model, data, kAssemblyIterations, &w.setup_failure,
                    &w.initial_position_correction, &w.initial_velocity_correction)) {
    w.setup_failure.cause = "at the start: " + w.setup_failure.cause;
    w.setup_failed = true;
    data.q = q;
    data.v = v;
  } else if (const std::int64_t c = DegenerateDistance(model, data, w); c >= 0) {
    w.setup_failure.where = model.constraint_name[static_cast<std::size_t>(c)];
    w.setup_failure.cause =
        "at the start: no motion the joints allow changes the distance between the two points "
        "(they lie on one line with the centres of the joints between them, so the distance is "
        "the largest or smallest the joints reach): holding it would take an unbounded force as "
        "soon as a joint bends; move a point off that line";
    w.setup_failed = true;
  }
  if (klu.numeric == nullptr) {
    ComputeKinematics(model, data);
    if (Evaluate(model, data, w, false, &ignored)) {
      CompositeRigidBodyMassMatrix(model, data, w.composite, w.mass);
      Factor(model, w, &ignored);
    }
  }
}

namespace {

// The KKT solve of ApplyConstraints: [M J^T; J -eps] [dvdot; -lambda] = [first; -(phi'' + 2 beta
// phi' + beta^2 phi)] at the accelerations in data, dvdot added to data.vdot. `first` is zero
// after the articulated-body recursion (the tree's equations already hold) or tau - C - M vdot
// for a singular tree (vdot = 0).
bool SolveConstrainedAccelerations(const Model& model, Data& data, std::span<const double> first,
                                   Failure* failure) {
  ConstraintWorkspace& w = *data.constraints;
  if (w.setup_failed) {
    if (failure != nullptr) {
      failure->where = w.setup_failure.where;
      failure->cause = w.setup_failure.cause;
    }
    return false;
  }
  const auto nv = static_cast<std::size_t>(w.nv);
  if (!Evaluate(model, data, w, true, failure)) return false;
  CompositeRigidBodyMassMatrix(model, data, w.composite, w.mass);
  if (!Factor(model, w, failure)) return false;
  const double beta = w.stabilisation_rate;
  if (first.empty()) {
    std::fill(w.solution.begin(), w.solution.begin() + static_cast<std::ptrdiff_t>(nv), 0.0);
  } else {
    std::copy(first.begin(), first.end(), w.solution.begin());
  }
  for (Eigen::Index r = 0; r < w.rows; ++r) {
    w.solution[nv + static_cast<std::size_t>(r)] =
        -(w.phi_ddot[r] + 2 * beta * w.phi_dot[r] + beta * beta * w.phi[r]);
  }
  if (!Solve(model, w, failure)) return false;
  for (std::size_t j = 0; j < nv; ++j) data.vdot[j] += w.solution[j];
  for (Eigen::Index r = 0; r < w.rows; ++r) {
    w.lambda[r] = -w.solution[nv + static_cast<std::size_t>(r)];
  }
  ConstraintForces(model, data, w);
  UpdateAccelerationsAndWrenches(model, data, w);
  for (std::size_t s = 0; s < model.nsegment(); ++s) {
    if (!data.acceleration[s].allFinite()) {
      return Fail(failure, model.segment_name[s],
                  "the acceleration with the constraint forces is not finite");
    }
  }
  return true;
}

}  // namespace

bool ApplyConstraints(const Model& model, Data& data, Failure* failure) {
  if (!data.constraints) return true;
  return SolveConstrainedAccelerations(model, data, {}, failure);
}

bool ApplyConstraintsToSingularTree(const Model& model, Data& data, Failure* failure) {
  if (!data.constraints) return false;
  ConstraintWorkspace& w = *data.constraints;
  TreeBiasForces(model, data, w.tree_residual);
  return SolveConstrainedAccelerations(model, data, w.tree_residual, failure);
}

bool ProjectConstraints(const Model& model, Data& data, double t, std::span<double> y,
                        Failure* failure) {
  if (!data.constraints) return true;
  const auto nq = static_cast<std::size_t>(model.nq);
  LoadState(data, t, y);
  double position_error = 0.0, velocity_error = 0.0;
  if (!ProjectState(model, data, kProjectionIterations, failure, &position_error,
                    &velocity_error)) {
    return false;
  }
  data.constraints->setup_failed = false;  // the state is consistent now
  // Leave y untouched (bit for bit) when it was already consistent.
  if (position_error > kPositionTolerance) {
    std::copy(data.q.begin(), data.q.end(), y.begin());
  }
  if (position_error > kPositionTolerance || velocity_error > kVelocityTolerance) {
    std::copy(data.v.begin(), data.v.end(), y.begin() + static_cast<std::ptrdiff_t>(nq));
  }
  return true;
}

void SerializeConstraints(Archive& archive, ConstraintWorkspace& w) {
  KluSolver& klu = *w.solver;
  archive.Field(w.setup_failed);
  archive.Field(klu.factored_rcond);
  archive.Field(klu.factored_values);
  bool factored = klu.numeric != nullptr;
  archive.Field(factored);
  if (!archive.reading() || !archive.ok() || klu.symbolic == nullptr) return;
  if (klu.numeric != nullptr) klu_free_numeric(&klu.numeric, &klu.common);
  if (factored) {
    klu.numeric = klu_factor(w.kkt_pointer.data(), w.kkt_index.data(), klu.factored_values.data(),
                             klu.symbolic, &klu.common);
  }
}

void TakeConstraintHistory(const ConstraintWorkspace& workspace, ConstraintHistory& history) {
  const KluSolver& klu = *workspace.solver;
  history.setup_failed = workspace.setup_failed;
  history.setup_failure = workspace.setup_failure;
  history.factored = klu.numeric != nullptr;
  history.factored_rcond = klu.factored_rcond;
  history.factored_values = klu.factored_values;
}

void GiveConstraintHistory(const ConstraintHistory& history, ConstraintWorkspace& workspace) {
  KluSolver& klu = *workspace.solver;
  workspace.setup_failed = history.setup_failed;
  workspace.setup_failure = history.setup_failure;
  if (history.factored == (klu.numeric != nullptr) &&
      history.factored_rcond == klu.factored_rcond &&
      history.factored_values == klu.factored_values) {
    return;  // the same pivots: refactorizations come out the same
  }
  klu.factored_rcond = history.factored_rcond;
  klu.factored_values = history.factored_values;
  if (klu.symbolic == nullptr) return;
  if (klu.numeric != nullptr) klu_free_numeric(&klu.numeric, &klu.common);
  if (history.factored) {
    klu.numeric = klu_factor(workspace.kkt_pointer.data(), workspace.kkt_index.data(),
                             klu.factored_values.data(), klu.symbolic, &klu.common);
  }
}

}  // namespace sled::runtime
