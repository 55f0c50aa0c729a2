// The structured Jacobian A = N + U V^T (runtime/integrate/structured_jacobian.h) of the
// multibody equations y = [q; v; w; W], for the exponential and Rosenbrock methods:
//
// - N: the kinematics q' = G(q) v, block diagonal by joint (a quaternion's four rates from the
//   three angular velocities, a free joint's position rates from its body-frame velocity), found
//   from PositionDerivative with the k-th velocity of every joint set at once (it is linear in v
//   and local to each joint): six calls.
// - U V^T: the stiffness and damping of the force elements, one rank-one term per independent
//   direction in which they push:
//   * joint characteristics (torque functions and stops, viscous and Coulomb damping) depend on
//     their joint's own coordinates only, so one difference quotient per joint axis moves all
//     joints at once (twelve torque evaluations); each loaded axis gives u = M^-1 e_axis and v
//     its torque's derivatives;
//   * elements in space (contacts, spring-dampers, belts, airbags) depend on the poses and
//     velocities of the segments they couple (force_coupling.h): each colour of segments is
//     moved along the twelve directions of a pose and a velocity at once, one force evaluation
//     each, giving per segment the 6 x 12 derivatives of its wrench by each neighbour's motion,
//     plus those by the airbag gas; a 6 x 6 eigen-decomposition of each segment's rows keeps
//     its independent load directions p (a ball on a floor has one), with u = M^-1 J^T p (one
//     articulated-body pass with the constraints) and v the derivatives of p's load carried to
//     the state by the segment Jacobians J and G's pseudo-inverse;
//   * the airbag gas's own rates (w' by q, v and w) as rows of their own.
//   Terms whose rate (|v . u|, or sqrt|v . N u| for a stiffness) is below kStiffRate / step are
//   left to the explicit part of the methods, and at most max_rank() of the stiffest are kept.
// Left out: gyroscopic and Coriolis terms and the change of lever arms with position: not
// stiff, and the methods that use A stay correct with any A.
#pragma once

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <cstddef>
#include <span>
#include <vector>

#include "runtime/forces/force_coupling.h"
#include "runtime/integrate/structured_jacobian.h"
#include "runtime/model/data.h"

namespace sled::runtime {

class MultibodyJacobian {
 public:
  // A term is stiff at step h when h times its rate is at least this.
  static constexpr double kStiffRate = 0.2;
  // The most terms kept (the cost of the phi-functions grows as the cube of twice this).
  static constexpr std::size_t kMaxRank = 24;

  explicit MultibodyJacobian(const Model& model);

  std::size_t max_rank() const { return max_rank_; }

  // Fills `jacobian` (cleared, sized for StateSize(model) and max_rank()) at state y, time t, for
  // a step of about `step`. Uses `data` as scratch: its caches hold a perturbed state
  // afterwards (the next evaluation loads the state again). False, with `failure` saying where
  // and why, when an articulated-body pass or the constraints fail.
  bool Form(Data& data, double t, std::span<const double> y, double step,
            StructuredJacobian& jacobian, Failure* failure);

 private:
  using Block = Eigen::Matrix<double, 6, 12>;

  void FormKinematics(Data& data, StructuredJacobian& jacobian);
  void JointTerms(Data& data);
  void SpaceDerivatives(Data& data);
  void SpaceTerms(Data& data);
  void AirbagTerms(Data& data);
  // u = the accelerations (and nothing else) a unit load causes: generalized force e_coordinate
  // (coordinate >= 0) or the wrench on `segment`. Needs Prepare first.
  bool PrepareResponses(Data& data, Failure* failure);
  bool Response(Data& data, std::ptrdiff_t coordinate, std::size_t segment, const Vec6& wrench,
                Eigen::Ref<Eigen::VectorXd> u, Failure* failure);
  // out(v-part) += J_s^T a (a: a wrench on segment s, or a row over its twists).
  void AddTransposeJacobian(const Data& data, std::size_t segment, const Vec6& a,
                            Eigen::Ref<Eigen::VectorXd> out) const;
  // Adds the state covector of a row over segment s's twist (pose, then velocity): its
  // velocity part J^T vel into v, its pose part J^T pose into pose_covector_, which
  // FlushPoseCovector then carries to the q-part of v by G's pseudo-inverse.
  void AddSegmentRow(const Data& data, std::size_t segment, const Eigen::Matrix<double, 1, 12>& row,
                     Eigen::Ref<Eigen::VectorXd> v);
  void FlushPoseCovector(Eigen::Ref<Eigen::VectorXd> v);
  // A candidate term; false when the store is full.
  Eigen::Index NewCandidate();

  const Model& model_;
  ForceCoupling coupling_;
  std::size_t n_ = 0, nq_ = 0, nv_ = 0, nw_ = 0;
  std::size_t max_rank_ = 0;

  // Per segment: G (q_count x v_count) and its pseudo-inverse.
  using SmallBlock = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 7, 7>;
  static void PseudoInverse(const SmallBlock& g, SmallBlock& inverse);
  std::vector<SmallBlock> g_, g_inverse_;
  // Candidate terms: columns of u and v; a unit load per candidate (coordinate or segment and
  // wrench) for its response.
  Eigen::MatrixXd candidate_u_, candidate_v_;
  std::vector<std::ptrdiff_t> load_coordinate_;
  std::vector<std::size_t> load_segment_;
  std::vector<Vec6> load_wrench_;
  Eigen::Index candidates_ = 0;
  std::vector<double> rate_;
  std::vector<Eigen::Index> order_;

  // Saved base kinematics and forces, and the space derivatives.
  std::vector<Mat3> rotation_;
  std::vector<Vec3> position_;
  std::vector<Vec6> velocity_;
  std::vector<Vec6> wrench_world_;  // base wrenches, moment and force in world axes
  std::vector<double> wdot_;
  ContactState saved_contacts_;
  BeltState saved_belts_;
  AirbagState saved_airbags_;
  std::vector<double> q_, v_, tau_;
  std::vector<std::vector<Block>> blocks_;                        // [segment][neighbour]
  std::vector<Eigen::Matrix<double, 6, Eigen::Dynamic>> by_gas_;  // [segment]: d wrench / d w
  std::vector<char> loaded_;  // segment has a nonzero derivative
  std::vector<std::vector<Eigen::Matrix<double, Eigen::Dynamic, 12>>> gas_by_segment_;  // [bag][k]
  Eigen::MatrixXd gas_by_gas_;                                                          // nw x nw
  std::vector<double> scratch_q_, scratch_v_, qdot_, response_base_, nu_;
  // Without loop constraints or mirror twins the responses come from the mass matrix (the
  // composite-rigid-body algorithm and a Cholesky factor, then one solve per term), else from an
  // articulated-body pass per term.
  bool use_mass_matrix_ = false;
  Eigen::MatrixXd mass_;
  Eigen::LLT<Eigen::MatrixXd> cholesky_;
  std::vector<Mat6> composite_;
  Eigen::VectorXd load_;
  Eigen::MatrixXd joint_dq_, joint_dv_;  // nv x 6: torque derivatives by each joint's k-th axis
  Eigen::VectorXd pose_covector_;        // nv
};

}  // namespace sled::runtime
