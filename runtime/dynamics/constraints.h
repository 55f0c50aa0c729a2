// Loop-closing constraints (docs/runtime.md): fixed-point, fixed-distance and sliding constraints
// between frames, solved with Lagrange multipliers in joint space.
//
// The articulated-body recursion gives the tree accelerations a0 = M^-1 (tau - C). The
// constraints phi(q) = 0 (m rows) add generalized forces J^T lambda, J = dphi/dq (m x nv) acting
// on the velocities, so the accelerations are a0 + da with
//
//   [ M   J^T    ] [ da ]   [ 0 ]
//   [ J  -eps I  ] [ -l ] = [ b ],   b = -(J a0 + Jdot v) - 2 beta (J v + phi_t) - beta^2 phi,
//
// where J a0 + Jdot v is phi's second derivative at the tree accelerations (taken from the point
// accelerations, so prescribed vehicle frames enter too) and the beta terms are Baumgarte's
// stabilisation of the drift (critically damped, beta = 1/T for a characteristic time T of the
// model; see ConstraintWorkspace::stabilisation_rate). M is the joint-space mass matrix of the
// composite-rigid-body algorithm (mass_matrix.h). The KKT matrix has a fixed sparsity pattern:
// M's entries are the (i, j) on a common root-to-leaf path and J's those of the joints between
// each constrained point and its root. KLU analyses the pattern once, when the Data is made
// (klu_analyze), and each evaluation only refactors numerically with the frozen pivot sequence
// (klu_refactor), factoring afresh with pivoting (klu_factor) only when the reciprocal pivot
// ratio (klu_rcond) has dropped a thousandfold since the last fresh factorization.
//
// The small regularisation eps (1e-10 of the largest diagonal of J M^-1 J^T, estimated from the
// diagonals of M) makes the matrix quasi-definite, so redundant rows (a planar linkage closed by
// a fixed point, whose out-of-plane rows vanish) and singular configurations give bounded
// multipliers instead of a singular matrix. One step of iterative refinement against the
// unregularised matrix (a second solve with the same factors) removes its 1e-10 relative error.
//
// MakeData calls SetUpConstraints, which also makes the initial state consistent: the
// positions are projected onto phi = 0 (Gauss-Newton steps in the metric of M) and the velocities
// onto J v + phi_t = 0 (the M-orthogonal projection, which is the velocity after an impulsive
// closure of the loop). ProjectConstraints does the same for any state, for an integrator's
// Project after each accepted step.
//
// Rolling constraints need the surface the point rolls on, which the Model does not carry yet:
// ApplyConstraints fails on one with a status naming it.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "runtime/model/data.h"

namespace sled::runtime {

struct KluSolver;  // the KLU objects, in constraints.cpp
struct KluSolverDeleter {
  void operator()(KluSolver* solver) const;
};

// The structure of the constraint system: its rows and the KKT matrix's sparsity pattern. It
// depends only on the Model, so FinalizeModel builds it once (ModelStructure) and every Data
// copies it.
struct ConstraintPattern {
  std::int32_t nv = 0;
  std::int32_t rows = 0;                  // m: 3 per fixed point, 1 per distance, 2 per sliding
  std::vector<std::int32_t> first_row;    // per constraint
  std::vector<std::int32_t> row_count;    // per constraint (0 for rolling)
  std::vector<Vec3> sliding_normal;       // two per constraint (sliding only): in the second frame
  std::vector<std::int32_t> kkt_pointer;  // compressed columns of the KKT matrix (nv + m)
  std::vector<std::int32_t> kkt_index;
  std::vector<std::int32_t> mass_position;       // nv x nv, column-major: into kkt_value or -1
  std::vector<std::int32_t> jacobian_position;   // m x nv, column-major: J (row r, column j)
  std::vector<std::int32_t> transpose_position;  // m x nv, column-major: J^T (j, r)
  std::vector<std::int32_t> diagonal_position;   // m: (nv + r, nv + r)
};
// The pattern of `model`'s constraints (empty without constraints).
ConstraintPattern BuildConstraintPattern(const Model& model);

struct ConstraintWorkspace : ConstraintPattern {
  std::vector<double> kkt_value;

  // --- Per evaluation (no allocation).
  Eigen::MatrixXd mass;               // nv x nv
  Eigen::MatrixXd jacobian;           // m x nv
  Eigen::MatrixXd point_jacobian;     // 3 x nv scratch
  Eigen::MatrixXd angular_jacobian;   // 3 x nv scratch
  std::vector<Mat6> composite;        // composite inertias
  Eigen::VectorXd phi;                // position error (m)
  Eigen::VectorXd phi_dot;            // velocity error (m)
  Eigen::VectorXd phi_ddot;           // second derivative at the tree accelerations (m)
  std::vector<double> solution;       // nv + m: right-hand side in, solution out
  std::vector<double> tree_residual;  // nv: tau - C of the tree (singular segments only)
  std::vector<double> residual;       // nv + m: iterative refinement
  std::vector<Vec6> segment_wrench;   // constraint wrench on each segment (frame, centre of mass)
  std::vector<double> q_saved;        // nq: the projection's line search

  // --- Results of the last ApplyConstraints, for outputs.
  Eigen::VectorXd lambda;          // multipliers (m): the generalized constraint force is J^T l
  std::vector<Vec3> point_first;   // world position of each constraint's first point
  std::vector<Vec3> point_second;  // and of its second point
  std::vector<Vec3> force_first;   // world force on the first frame at its point; the second
                                   // frame takes the opposite force (sliding: at the first point)
  std::vector<double> error;       // per constraint: position error (norm of its rows) [m]

  // --- Settings, chosen from the Model by SetUpConstraints.
  // beta [1/s]: 1/T with T = sqrt(L/g), the time scale of a pendulum as long as the largest
  // lever arm L of a constrained point about its segment's centre of mass (at least 1 cm); a
  // tenth of the run when there is no gravity. Slow against any step an integrator takes, so it
  // adds no stiffness; the drift it corrects is the integrator's local error.
  double stabilisation_rate = 0.0;
  double regularisation = 1e-10;  // eps relative to the largest diagonal of J M^-1 J^T

  // --- What the set-up did to the initial state.
  double initial_position_correction = 0.0;  // largest |phi| before projection [m]
  double initial_velocity_correction = 0.0;  // largest |phi_dot| before projection [m/s]
  // When the initial state could not be projected (constraints that cannot all be met, or a
  // start too far off for Gauss-Newton), the state stays as given and every ApplyConstraints
  // reports this until a ProjectConstraints succeeds.
  bool setup_failed = false;
  Failure setup_failure;

  // --- Counters: symbolic analyses (once per Data), fresh factorizations, refactorizations.
  std::int64_t analyses = 0;
  std::int64_t factorizations = 0;
  std::int64_t refactorizations = 0;
  std::int64_t solves = 0;

  std::unique_ptr<KluSolver, KluSolverDeleter> solver;
};

// Sizes the workspace with `pattern` (the Model's, BuildConstraintPattern), analyses it with KLU,
// factors it at the initial state and projects data.q and data.v onto the constraints (see
// setup_failed when that fails). Called by MakeData; does nothing without constraints. Allocates
// (it is the one-time set-up).
void SetUpConstraints(const Model& model, const ConstraintPattern& pattern, Data& data);

// After ComputeAccelerations: adds the constraint forces, so data.vdot, data.acceleration and
// data.joint_wrench are those of the closed loops, and records the multipliers and forces in
// data.constraints. False with `failure` naming the constraint when the system is singular or a
// constraint cannot be evaluated.
bool ApplyConstraints(const Model& model, Data& data, Failure* failure);

// When ComputeAccelerations fails on a singular (massless) segment: solves the tree's equations
// M vdot = tau - C together with the constraints in one KKT system, so a massless segment whose
// motion the constraints determine moves as they say. False, naming a constraint, when the
// constraints leave some motion of a massless segment undetermined (a singular KKT matrix).
bool ApplyConstraintsToSingularTree(const Model& model, Data& data, Failure* failure);

// Writes or reads (a checkpoint) what the constraint solver carries between evaluations: the
// set-up state and the factorization whose pivots later refactorizations reuse.
class Archive;
void SerializeConstraints(Archive& archive, ConstraintWorkspace& workspace);

// The same in memory, to hand another Data of the Model the solver's state (the output rows'
// Data, runtime/run/output_rows.h): Give makes the same factorization again only when the
// receiver's differs, so copying an unchanged one costs a comparison.
struct ConstraintHistory {
  bool setup_failed = false;
  Failure setup_failure;
  bool factored = false;
  double factored_rcond = 0.0;
  std::vector<double> factored_values;
};
void TakeConstraintHistory(const ConstraintWorkspace& workspace, ConstraintHistory& history);
void GiveConstraintHistory(const ConstraintHistory& history, ConstraintWorkspace& workspace);

// Projects the state y = [q; v; w; W] at time t onto phi = 0 and J v + phi_t = 0 (Gauss-Newton in
// the metric of M; converged when |phi| <= 1e-12 m). Uses data's caches as scratch. For
// OdeSystem::Project after an accepted step; changes y by the drift only.
bool ProjectConstraints(const Model& model, Data& data, double t, std::span<double> y,
                        Failure* failure);

}  // namespace sled::runtime
