// runtime::Model: the compiled scene. Flat, structure-of-arrays, SI units, sized once by
// compiler::Lower and never resized; it holds only what the scene uses. A Data (data.h) holds
// everything that changes during a run. The runtime knows nothing of the language: the only
// link back to the scenario is the side table of source positions.
//
// Dynamics are in joint coordinates: each body of segments is a tree whose root is a free
// segment (6 degrees of freedom) and whose other segments hang from joints. Solving this tree
// with the articulated-body recursion is the leaf-first elimination of the CVS block system
// (the joint constraint forces are eliminated, then recovered by the backward pass), so joints
// never drift apart. Closed loops (fixed-point, fixed-distance, rolling and sliding constraints)
// add Lagrange multipliers.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "runtime/airbag/airbag_table.h"
#include "runtime/contact/contact_table.h"
#include "runtime/forces/actuators.h"
#include "runtime/forces/applied_loads.h"
#include "runtime/forces/fluid_forces.h"
#include "runtime/model/model_types.h"
#include "runtime/restraint/belt_table.h"

namespace sled::runtime {

// Indices into the Model are plain std::int32_t, as its arrays are: what each one refers to (a
// segment, a function, -1 for none) is written once in runtime/model/model_fields.h, and
// ValidateModel checks every index against it when the Model is finalized.

// How a segment moves relative to its parent. kFree: a reference segment (position and
// quaternion); kBall: a quaternion; kPin: an angle about `joint_axis`; kSlip: a displacement
// along `joint_axis`; kEuler: precession, nutation and spin (z, then y, then x of the joint
// frame; each axis can be locked); kPlanar: a reference segment under 2-D symmetry, moving in
// the xz plane of its base (x, z and a turn about y; the velocities in base axes).
enum class JointKind : std::uint8_t { kFree, kBall, kPin, kSlip, kEuler, kPlanar };

// A function of one variable (CVS: constant, table with linear interpolation, polynomial up to
// degree five) and its unloading parameters.
struct FunctionTable {
  enum class Kind : std::uint8_t { kConstant, kTable, kPolynomial };
  std::vector<Kind> kind;
  std::vector<double> constant;
  std::vector<std::int32_t> first;  // into points (kTable) or coefficients (kPolynomial)
  std::vector<std::int32_t> count;
  std::vector<double> energy_loss;
  std::vector<double> permanent_set;
  std::vector<double> unload_slope;  // relative to the loading slope; 0 (or empty): none
  // ATB's unloading law (runtime/forces/atb_unloading.h): the function of the largest
  // deflection that gives the energy return R, and the one that gives the permanent set G (-1:
  // G = 0). atb_return -1 (or empty): the function unloads by the parameters above instead.
  std::vector<std::int32_t> atb_return;
  std::vector<std::int32_t> atb_set;
  // ATB's law only (each per function, or empty: none): the inertial spike, a function added to
  // the loading force until a largest deflection reaches atb_spike_end (-1: none), and the
  // origin D0 from which ATB integrates the loading energy and measures the permanent set.
  std::vector<std::int32_t> atb_spike;
  std::vector<double> atb_spike_end;
  std::vector<double> atb_origin;
  std::vector<double> points_x;
  std::vector<double> points_y;
  std::vector<double> coefficients;
  std::size_t size() const { return kind.size(); }
};

// Prescribed vehicle motion: the vehicle's acceleration as a function of time.
struct VehicleMotion {
  enum class Kind : std::uint8_t { kNone, kHalfSine, kTrapezoid, kTable, kSixDof };
  Kind kind = Kind::kNone;
  Vec3 axis = Vec3::UnitX();
  double start = 0.0;
  double delta_v = 0.0;
  double duration = 0.0;
  double peak = 0.0;
  double rise = 0.0;
  double dwell = 0.0;
  double fall = 0.0;
  std::vector<std::array<double, 2>> table;    // (t, a)
  std::vector<std::array<double, 7>> six_dof;  // t, linear (3), angular (3)
  // Derived from `table` or `six_dof` when the Model is made (IntegrateMotionRows, vehicle.h):
  // at each row, the velocity (3) and the displacement (3) its linear accelerations have given
  // by the row's time, per axis (a tabulated pulse fills the first of each), so the motion at a
  // time is found by a binary search for its row.
  std::vector<std::array<double, 6>> row_gain;
};

// A point of a turning vehicle's path relative to its starting pose (TabulateVehiclePath):
// rotation from the vehicle at t = 0, angular velocity in vehicle axes, and the displacement
// and velocity gained, in the axes of the vehicle at t = 0.
struct VehiclePathSample {
  double t = 0.0;  // from the start of the run
  Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();
  Vec3 angular_velocity = Vec3::Zero();
  Vec3 displacement = Vec3::Zero();
  Vec3 velocity = Vec3::Zero();
};

struct Model {
  std::string title;
  Vec3 gravity{0, 0, -9.80665};

  // --- Segments, in tree order: a segment's parent comes before it (nsegment entries).
  std::vector<std::string> segment_name;
  // The ISO/TS 13499 dummy type of the segment's body ("H3", "00"; runtime/model/dummy_types.h),
  // for the ISO-MME codes; empty when no body of the scene names a dummy.
  std::vector<std::string> segment_dummy;
  std::vector<std::int32_t> segment_parent;  // -1 for a root: a reference segment
  // For a root: the frame its joint attaches to. A floating reference segment has a kFree joint
  // to the ground; a root held at a point of the ground or of a vehicle (a pendulum, an occupant
  // tethered to a sled) has a ball or pin joint to that frame, whose joint point and frame are
  // then given in the base frame.
  std::vector<FrameRef> segment_base;
  std::vector<double> segment_mass;
  std::vector<Mat3> segment_inertia;    // about the centre of mass, in the segment frame
  std::vector<JointKind> joint_kind;    // of the joint above the segment (kFree for a root)
  std::vector<std::string> joint_name;  // empty for a root
  std::vector<std::int32_t> q_address;  // first position coordinate of the joint
  std::vector<std::int32_t> v_address;  // first velocity coordinate of the joint
  std::vector<std::int32_t> q_count;
  std::vector<std::int32_t> v_count;
  // Joint geometry: the joint point and the joint frame in the parent and in the child.
  std::vector<Vec3> joint_point_in_parent;
  std::vector<Mat3> joint_frame_in_parent;  // columns: joint axes in parent coordinates
  std::vector<Vec3> joint_point_in_child;
  std::vector<Mat3> joint_frame_in_child;
  std::vector<Vec3> joint_axis;  // pin and slip: unit axis in the joint frame
  // Joint characteristics (functions of angle giving torque; -1 when absent).
  std::vector<std::array<std::int32_t, 3>> joint_function;  // flexure, twist, -; or
                                                            // precession, nutation, spin
  std::vector<double> joint_viscous;
  std::vector<double> joint_coulomb;
  std::vector<double> joint_stop;        // flexure stop [rad]; <= 0 when none
  std::vector<double> joint_twist_stop;  // [rad]; <= 0 when none
  std::vector<std::uint8_t> joint_stop_impulse;
  std::vector<double> joint_restitution;
  std::vector<std::uint8_t> joint_locked;  // initial lock mask: bit k locks axis k
  std::vector<double> joint_lock_below;    // < 0 when none
  std::vector<double> joint_unlock_above;  // < 0 when none

  // Mirror symmetry (the xz plane of the ground): a left segment whose right twin the Model
  // leaves out, hanging from a segment in the plane, hands its parent its articulated inertia
  // and bias twice, as itself and as its mirror image about `mirror_normal` (the plane's normal
  // in the parent's frame). Empty when there is no mirror symmetry.
  std::vector<std::uint8_t> segment_mirror_twin;
  std::vector<Vec3> mirror_normal;
  // How many segments of the scene each Model segment stands for in sums over the scene
  // (energies, the work of elements on vehicles): 2 for a left segment whose right twin the
  // Model leaves out and for every segment below it (segment_mirror_twin marks only the top of
  // such a subtree, where the doubling enters the dynamics), 1 otherwise. Empty when there is
  // no mirror symmetry.
  std::vector<std::uint8_t> segment_mirror_count;
  double mirror_plane_y = 0.0;  // the plane y = mirror_plane_y of the ground

  std::int32_t nq = 0;  // position coordinates (quaternions count four)
  std::int32_t nv = 0;  // velocity coordinates (degrees of freedom)
  // Auxiliary states: the states force elements own and integrate with the motion (an airbag's
  // gas mass and internal energy). The integrated state is y = [q; v; w]; each owner records
  // where its states start in w.
  std::int32_t nw = 0;

  // --- Initial state, as lowered: generalized positions and velocities.
  std::vector<double> q0;
  std::vector<double> v0;
  std::vector<double> w0;  // auxiliary states (nw)

  // --- Vehicles (prescribed motion).
  std::vector<std::string> vehicle_name;
  std::vector<VehicleMotion> vehicle_motion;
  std::vector<Vec3> vehicle_position;          // at t = 0
  std::vector<Mat3> vehicle_orientation;       // at t = 0, vehicle to world
  std::vector<Vec3> vehicle_velocity;          // at t = 0
  std::vector<Vec3> vehicle_angular_velocity;  // at t = 0, world axes
  // A vehicle that turns (an angular acceleration table or an initial angular velocity) has its
  // path tabulated when the Model is built; empty for one that only translates.
  std::vector<std::vector<VehiclePathSample>> vehicle_path;

  // --- Functions.
  FunctionTable functions;

  // --- Spring–dampers and tension elements between two frames.
  std::vector<std::string> spring_name;
  std::vector<FrameRef> spring_first;
  std::vector<FrameRef> spring_second;
  std::vector<Vec3> spring_point_first;       // in the first frame
  std::vector<Vec3> spring_point_second;      // in the second frame
  std::vector<std::int32_t> spring_function;  // elongation -> force; -1: none
  std::vector<double> spring_damping;
  std::vector<double> spring_free_length;
  std::vector<std::uint8_t> spring_tension_only;

  // --- Contacts: plane–ellipsoid and ellipsoid–ellipsoid pairs (runtime/contact/).
  ContactTable contacts;
  // --- Belts and harnesses.
  BeltTable belts;
  // --- Airbags: uniform-pressure bags with gas states in w.
  AirbagTable airbags;
  // --- Applied loads: forces and torques that are functions of time
  // (runtime/forces/applied_loads.h).
  LoadTable loads;
  // --- Joint actuators: PID torques about pin axes (runtime/forces/actuators.h).
  ActuatorTable actuators;
  // --- Wind and water on segment ellipsoids (runtime/forces/fluid_forces.h).
  FluidTable fluids;
  // --- Drawing only (the animation; the dynamics never reads them): the shapes of the segments
  // that are not contact ellipsoids, so that every segment is drawn: its declared ellipsoids, or
  // for a segment without any the ellipsoid of uniform density with its mass and inertia.
  std::vector<std::string> shape_name;
  std::vector<std::int32_t> shape_segment;
  std::vector<Vec3> shape_center;  // in the segment frame
  std::vector<Mat3> shape_axes;    // columns: the shape's axes in the segment frame
  std::vector<Vec3> shape_semi_axes;
  std::vector<double> shape_degree;  // 2 for an ellipsoid

  // --- Loop-closing constraints (solved with Lagrange multipliers).
  enum class ConstraintKind : std::uint8_t { kFixedPoint, kFixedDistance, kRolling, kSliding };
  std::vector<std::string> constraint_name;
  std::vector<SourcePosition> constraint_source;  // where the scene declares it, for failures
  std::vector<ConstraintKind> constraint_kind;
  std::vector<FrameRef> constraint_first;
  std::vector<FrameRef> constraint_second;
  std::vector<Vec3> constraint_point_first;
  std::vector<Vec3> constraint_point_second;
  std::vector<double> constraint_distance;
  std::vector<Vec3> constraint_axis;

  // --- Run settings.
  double start_time = 0.0;
  double end_time = 0.0;
  double output_every = 0.0;
  std::string integrator = "auto";
  double relative_tolerance = 1e-6;
  double absolute_tolerance = 1e-9;
  double min_step = 1e-9;
  double max_step = 0.0;      // 0: none
  double initial_step = 0.0;  // 0: automatic

  // --- Settling before the run (runtime/run/settle.h): a damped pre-simulation with the vehicles
  // held at their starting pose, until the convergence test holds. None when duration is 0.
  struct Settle {
    double duration = 0.0;           // the longest pre-simulation [s]
    double damping = 10.0;           // mass-proportional damping rate [1/s]
    double velocity = 1e-3;          // every centre of mass slower than this [m/s]
    double angular_velocity = 0.01;  // every segment turning slower than this [rad/s]
    double force_change = 0.01;      // contact, belt and spring forces changed by less than this
                                     // fraction of the largest of them over one check interval
    double check_every = 0.01;       // [s]
  };
  Settle settle;

  // --- Output requests, as compiled channel groups.
  enum class OutputKind : std::uint8_t {
    kAcceleration,
    kVelocity,
    kPosition,
    kAngularAcceleration,
    kAngularVelocity,
    kOrientation,
    kJointAngle,
    kJointTorque,
    kJointForce,
    kSpringForce,
    kContactForce,       // index: a contact output group; world frame, on the first surface
    kContactPoint,       // index: a contact output group; world frame
    kContactDeflection,  // index: a contact output group
    kBeltForce,          // index: a belt
    kAirbagPressure,     // index: an airbag; gauge pressure
    kAirbagVolume,       // index: an airbag; volume of the gas
    kAirbagGasMass,      // index: an airbag
    kAirbagTemperature,  // index: an airbag
    kAirbagVentFlow,     // index: an airbag; mass flow out of the vent
    kAirbagForce,        // index: an airbag; on each segment it touches, world frame
  };
  std::vector<OutputKind> output_kind;
  std::vector<std::string> output_label;   // channel prefix, e.g. occupant.head
  std::vector<std::int32_t> output_index;  // segment, joint (= child segment), spring, belt,
                                           // airbag or contact output group
  std::vector<Vec3> output_point;          // in the segment frame
  // Mirror symmetry: 1 when the output is of a right segment (or joint) the Model leaves out,
  // read from its left twin and mirrored. Empty when there is no mirror symmetry.
  std::vector<std::uint8_t> output_mirrored;
  // Segment requests measured in a frame (OutputFrame, runtime/run/relative_motion.h): 1 seen from
  // output_frame (`relative_to`), 2 relative to the ground in its axes (`expressed_in`), 0 as
  // docs/runtime.md says; output_frame_mirrored is 1 when that frame is a right twin the Model
  // leaves out, read from its left twin. Empty when no output has a frame.
  std::vector<std::uint8_t> output_relative;
  std::vector<FrameRef> output_frame;
  std::vector<std::uint8_t> output_frame_mirrored;
  // SAE J211 channel frequency class of each group's filtered channels (0: not filtered), and
  // 1 where ISO 6487 gives the coefficients. Empty: nothing filtered.
  std::vector<std::int16_t> output_filter_class;
  std::vector<std::uint8_t> output_filter_iso;

  // --- Injury criteria, computed after the run from the output channels (output/post/).
  enum class CriterionKind : std::uint8_t {
    kHic15,
    kHic36,
    kHead3ms,
    kChest3ms,
    kGaddHead,
    kGaddChest,
    kNij,
    kNeckTension,
    kNeckCompression,
    kFemurLoad,
    kNkm,
    kNic,
    kTti,
    kTibiaIndex,
    kViscousCriterion,  // of a slip joint between the spine and the sternum
  };
  std::vector<CriterionKind> criterion_kind;
  std::vector<std::string> criterion_name;    // as the language spells it: hic15
  std::vector<std::string> criterion_target;  // the segment or joint: occupant.head
  // The output group it reads: the acceleration of the segment's centre of mass, the joint
  // force, or (the Viscous Criterion) a slip joint's displacement; and a second group (else -1):
  // the joint torque for Nij, Nkm and the Tibia Index, the acceleration of T1 for NIC and of the
  // lower spine for TTI. Accelerations are in each segment's own axes, joint loads in the child's.
  std::vector<std::int32_t> criterion_output;
  std::vector<std::int32_t> criterion_second_output;
  std::vector<std::uint8_t> criterion_filter_iso;  // 1: ISO 6487 coefficients
  // A limit the scene gives a criterion (`limit = ...`, with the standard it comes from), in
  // the criterion's unit; NaN: the default limit of its standard (output/post/injury_criteria).
  std::vector<double> criterion_limit;
  std::vector<std::string> criterion_standard;

  // --- Side table: where each entity was declared.
  std::vector<SourcePosition> segment_source;
  std::vector<SourcePosition> joint_source;  // by child segment

  // --- Derived by FinalizeModel (runtime/model/model_structure.h); not a field of the list.
  std::shared_ptr<const struct ModelStructure> structure;

  std::size_t nsegment() const { return segment_name.size(); }
  std::size_t nvehicle() const { return vehicle_name.size(); }
  std::size_t nspring() const { return spring_name.size(); }
  std::size_t nconstraint() const { return constraint_name.size(); }
  std::size_t ncriterion() const { return criterion_kind.size(); }
};

// The Model's fields are listed once, in runtime/model/model_fields.h: the dump, the checkpoint
// fingerprint and the validation walk that list.

// A stable text form of the model for `sled check --dump-model` and golden tests.
std::string DumpModel(const Model& model);

// Every problem of the Model, one per line (the first 20), each naming the field and entry:
// sizes against their counts, indices in range, finite numbers, masses and other magnitudes not
// negative, the tree order and the coordinate and table ranges. Empty when the Model is valid.
std::string ValidateModel(const Model& model);
// Validates the Model and, when it is valid, derives its structure once (model.structure), so
// every Data made from it only allocates. Returns ValidateModel's errors (the structure is then
// left empty). compiler::Lower calls it; a Model built by hand should too.
std::string FinalizeModel(Model& model);

// The keyword of a joint kind as the language spells it ("free" for a floating root).
const char* JointKindName(JointKind kind);
// Coordinates of a joint kind: positions (quaternions count four) and velocities.
int PositionCount(JointKind kind);
int VelocityCount(JointKind kind);
// Appends the characteristics of a joint that has none (no torque functions, damping, stops or
// locks) for the segment just added: what a floating root or a plain joint starts with.
void AppendPlainJointCharacteristics(Model& model);

}  // namespace sled::runtime
