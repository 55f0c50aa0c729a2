// The checker's output: a scenario with every name resolved, every number in SI units, and
// every physical rule the checker knows verified. Lowering (compiler::Lower) turns it into the
// flat runtime::Model; the dumper prints it for tests and `sled check --dump-checked`.
//
// Indices refer into the vectors of the same CheckedScenario. Every entity keeps the source range
// of its declaration, so the runtime's side table can name the line of a runtime warning.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "compiler/units/dimension.h"
#include "lang/source/source_range.h"

namespace sled::compiler {

using Vec3 = std::array<double, 3>;
using lang::SourceRange;

// Something positions can be given in: the ground (inertial frame), a vehicle or a segment.
struct FrameRef {
  enum class Kind { kGround, kVehicle, kSegment };
  Kind kind = Kind::kGround;
  int index = -1;  // into vehicles or segments; -1 for the ground
  friend bool operator==(const FrameRef&, const FrameRef&) = default;
};

// A function of one variable as in CVS: constant, table (linear interpolation) or a polynomial of
// degree up to five, with the CVS unloading parameters for force–deflection use.
struct Function {
  enum class Kind { kConstant, kTable, kPolynomial };
  std::string name;  // empty for an inline function
  Kind kind = Kind::kConstant;
  Dimension argument;  // dimension of x
  Dimension result;    // dimension of f(x)
  double constant = 0.0;
  std::vector<std::array<double, 2>> points;  // kTable: (x, f(x)), x strictly increasing
  std::vector<double> coefficients;           // kPolynomial: c0 + c1 x + ... + c5 x^5
  // Unloading (CVS force–deflection): fraction of energy dissipated on unloading, permanent
  // deflection as a fraction of the largest deflection, and an optional unloading slope.
  double energy_loss = 0.0;
  double permanent_set = 0.0;
  std::optional<double> unload_slope;
  // ATB's unloading law (`unloading = atb(...)`): the functions of the largest deflection that
  // give the energy return R and the permanent set G (indices into CheckedScenario::functions;
  // -1: none, G = 0).
  bool atb_unloading = false;
  int energy_return = -1;
  int atb_permanent_set = -1;
  // ATB's inertial spike (a function added to the loading force until the largest deflection
  // reaches atb_spike_end; -1: none) and the origin D0 of the loading energy and permanent set.
  int atb_spike = -1;
  double atb_spike_end = 0.0;
  double atb_origin = 0.0;
  SourceRange range;
};

// A function reference: an index into CheckedScenario::functions (inline functions are added there
// with an empty name).
using FunctionId = int;

struct Ellipsoid {
  std::string name;
  FrameRef frame;
  Vec3 semi_axes{};
  Vec3 center{};        // in the frame
  Vec3 orientation{};   // yaw, pitch, roll [rad] of the ellipsoid axes in the frame
  double degree = 2.0;  // above 2: hyper-ellipsoid
  SourceRange range;
};

struct Segment {
  std::string name;  // qualified: occupant.pelvis
  int body = -1;
  double mass = 0.0;
  Vec3 inertia{};         // principal moments [kg*m^2]
  Vec3 principal_axes{};  // yaw, pitch, roll [rad] of the principal axes in the segment frame
  bool singular = false;  // massless, kept in place by constraints
  std::vector<int> ellipsoids;
  SourceRange range;
};

enum class JointType { kBall, kPin, kEuler, kSlip, kNull };

struct Joint {
  std::string name;
  JointType type = JointType::kBall;
  int parent = -1;  // segment
  int child = -1;   // segment
  Vec3 location_in_parent{};
  Vec3 location_in_child{};
  Vec3 axes_in_parent{};  // yaw, pitch, roll [rad] of the joint axes in each segment
  Vec3 axes_in_child{};
  Vec3 axis{0, 0, 1};  // pin and slip joints: unit vector in the parent
  // Torque characteristics: flexure and twist for ball and pin joints; precession, nutation and
  // spin for Euler joints. -1 when absent.
  FunctionId flexure = -1;
  FunctionId twist = -1;
  FunctionId precession = -1;
  FunctionId nutation = -1;
  FunctionId spin = -1;
  double viscous = 0.0;              // [N*m*s/rad]
  double coulomb = 0.0;              // [N*m]
  double energy_loss = 0.0;          // fraction dissipated per loading cycle
  std::optional<double> stop;        // flexure stop angle [rad]
  std::optional<double> twist_stop;  // [rad]
  bool stop_impulse = false;
  double restitution = 0.0;
  // Locking: axes locked at the start (bit 0 precession, 1 nutation, 2 spin; all three for a
  // locked ball or pin joint), and the torque levels that lock and unlock them.
  unsigned locked_axes = 0;
  std::optional<double> lock_below;
  std::optional<double> unlock_above;
  SourceRange range;
};

struct Body {
  std::string name;
  std::vector<int> segments;
  std::vector<int> joints;
  std::vector<int> reference_segments;  // the root of each tree (null joints start new ones)
  std::optional<Vec3> h_point;          // in the (first) reference segment's frame
  // The dummy it stands for, as its ISO/TS 13499 dummy type ("H3"; runtime/model/dummy_types.h);
  // empty when it names none.
  std::string dummy;
  SourceRange range;
};

struct Motion {
  enum class Kind { kNone, kHalfSine, kTrapezoid, kTable, kSixDof };
  Kind kind = Kind::kNone;
  Vec3 axis{1, 0, 0};  // direction of the acceleration for single-axis pulses
  double start = 0.0;
  double delta_v = 0.0;   // kHalfSine
  double duration = 0.0;  // kHalfSine
  double peak = 0.0;      // kTrapezoid: peak acceleration and the three phases
  double rise = 0.0;
  double dwell = 0.0;
  double fall = 0.0;
  std::vector<std::array<double, 2>> table;    // kTable: (t, a)
  std::vector<std::array<double, 7>> six_dof;  // kSixDof: t, linear (3), angular (3) acceleration
};

struct Vehicle {
  std::string name;
  Motion motion;
  Vec3 position{};
  Vec3 orientation{};
  Vec3 velocity{};
  SourceRange range;
};

struct Plane {
  std::string name;
  FrameRef frame;
  std::array<Vec3, 3> corners{};  // P1, P2, P3: a parallelogram; normal (P2-P1)x(P3-P1)
  SourceRange range;
};

// One side of a contact: a segment's ellipsoid, or a surface.
struct SurfaceRef {
  enum class Kind { kEllipsoid, kPlane };
  Kind kind = Kind::kEllipsoid;
  int index = -1;
  friend bool operator==(const SurfaceRef&, const SurfaceRef&) = default;
};

struct Contact {
  SurfaceRef first;       // an ellipsoid on a segment
  SurfaceRef second;      // a plane or another ellipsoid
  FunctionId force = -1;  // deflection -> force
  double damping = 0.0;   // [N*s/m]
  // ATB's rate-dependent terms: rate_scaled_force(d) * rate_scale(d') + rate_force(d').
  FunctionId rate_scaled_force = -1;  // deflection -> force
  FunctionId rate_scale = -1;         // deflection rate -> ratio
  FunctionId rate_force = -1;         // deflection rate -> force
  double friction = 0.0;
  bool impulse = false;  // first-contact impulse
  double restitution = 0.0;
  SourceRange range;
};

// A point of a belt's path: an anchor fixed in a frame, or a segment whose ellipsoid it wraps.
struct BeltPoint {
  enum class Kind { kAnchor, kSegment };
  Kind kind = Kind::kAnchor;
  FrameRef frame;    // kAnchor: where the point is fixed
  Vec3 point{};      // kAnchor: position in that frame
  int segment = -1;  // kSegment
};

struct Belt {
  std::string name;
  int harness = -1;
  FrameRef frame;
  std::vector<BeltPoint> path;
  FunctionId force = -1;  // strain -> force
  double slack = 0.0;
  double pretension = 0.0;
  double friction = 0.0;
  SourceRange range;
};

struct Harness {
  std::string name;
  FrameRef frame;
  std::vector<int> belts;
  double friction = 0.0;
  SourceRange range;
};

struct Airbag {
  std::string name;
  FrameRef frame;
  Vec3 position{};
  Vec3 orientation{};
  Vec3 semi_axes{};
  double deploy_time = 0.0;
  FunctionId inflow = -1;  // time -> mass flow
  double vent_area = 0.0;
  double ambient_pressure = 101325.0;
  double gas_temperature = 300.0;  // of the inflator's gas [K]
  double gamma = 1.4;
  double gas_constant = 287.0;  // [J/(kg K)]
  double discharge_coefficient = 0.6;
  std::vector<int> contact_segments;
  // `model = atb_free`: ATB's free bag (polytropic gas, square-root vent, a free body on a spring).
  bool free_bag = false;
  double bag_mass = 0.0;               // [kg]
  double mass_factor = 1.0;            // ATB's CMASS
  double tether_stiffness = 0.0;       // [N/m]
  double vent_opening_pressure = 0.0;  // gauge [Pa]
  SourceRange range;
};

// Spring–dampers and tension elements between two points on two frames.
struct SpringDamper {
  std::string name;
  bool tension_only = false;
  FrameRef first;
  FrameRef second;
  Vec3 point_in_first{};
  Vec3 point_in_second{};
  FunctionId stiffness = -1;  // deflection -> force
  double damping = 0.0;
  std::optional<double> free_length;  // default: the initial distance
  SourceRange range;
};

// A force or torque that is a function of time (ATB's applied loads): on a segment, or across a
// joint (on its child, with the reaction on its parent).
struct AppliedLoad {
  std::string name;
  bool across_joint = false;
  int index = -1;           // the segment, or the joint
  FunctionId force = -1;    // time -> force; -1: none
  FunctionId torque = -1;   // time -> torque; -1: none
  Vec3 direction{1, 0, 0};  // of the force: unit, in the ground or the segment
  Vec3 axis{0, 0, 1};       // of the torque: unit, in the ground or the segment (segment loads),
                            // in the parent segment (ball and Euler joints)
  Vec3 point{};             // where a segment's force acts, in the segment frame
  bool in_segment = false;  // a segment load's direction and axis turn with the segment
  SourceRange range;
};

// An `actuator` (runtime/forces/actuators.h): a PID torque about a pin joint's axis that drives
// its angle towards `target`; the gains are functions of the target angle, SI units.
struct Actuator {
  std::string name;
  int joint = -1;
  FunctionId target = -1;        // time -> angle
  FunctionId proportional = -1;  // angle -> torque per angle
  FunctionId derivative = -1;    // angle -> torque per angular rate; -1: none
  FunctionId integral = -1;      // angle -> torque per angle*time; -1: none
  SourceRange range;
};

// A `wind` or `water` block (runtime/forces/fluid_forces.h): the fluid and the segments whose
// contact ellipsoids it acts on; SI units.
struct Fluid {
  enum class Medium { kWind, kWater };
  Medium medium = Medium::kWind;
  FunctionId speed = -1;     // wind: time -> speed
  FunctionId pressure = -1;  // wind, instead of a speed: time -> pressure of a blast
  Vec3 direction{1, 0, 0};   // wind: unit, where the air goes, in the axes of `carrier`
  FrameRef carrier;          // wind: the frame the air is at rest in but for its speed
  double density = 0.0;
  double drag = 1.0;   // drag coefficient
  double level = 0.0;  // water: height of the surface above the ground origin, against gravity
  std::vector<int> segments;
  SourceRange range;
};

struct Constraint {
  // kWelded: a reference segment moving rigidly with the ground or a vehicle (a segment whose
  // motion is prescribed, ATB's MSEG); the lowering makes it the root's locked joint to its base.
  enum class Kind { kFixedPoint, kFixedDistance, kRolling, kSliding, kWelded };
  std::string name;
  Kind kind = Kind::kFixedPoint;
  FrameRef first;
  FrameRef second;
  Vec3 point_in_first{};
  Vec3 point_in_second{};
  std::optional<double> distance;  // kFixedDistance; default: the initial distance
  Vec3 axis{1, 0, 0};              // kSliding: direction in the second frame
  SourceRange range;
};

struct InitialCondition {
  enum class Kind { kBody, kSegment, kJoint, kVehicle };
  Kind kind = Kind::kBody;
  int index = -1;
  std::optional<Vec3> position;
  std::optional<Vec3> orientation;
  std::optional<Vec3> velocity;
  std::optional<Vec3> angular_velocity;
  std::optional<Vec3> joint_angles;  // kJoint: (precession, nutation, spin) or (flexure..)
  SourceRange range;
  SourceRange position_range;  // of the `position` statement, when given
  SourceRange velocity_range;  // of the `velocity` statement, when given
};

struct OutputRequest {
  enum class Kind {
    kAcceleration,
    kVelocity,
    kPosition,
    kAngularAcceleration,
    kAngularVelocity,
    kOrientation,
    kJointAngle,
    kJointTorque,
    kJointForce,
    kContactForce,
    kBeltForce,
    kAirbagPressure,
    kSpringForce,
    kAirbagVolume,
    kAirbagGasMass,
    kAirbagTemperature,
    kAirbagVentFlow,
    kAirbagForce,
  };
  Kind kind = Kind::kAcceleration;
  std::string label;          // channel prefix: `as` name or the target's name
  int index = -1;             // segment, joint, contact, belt, airbag or spring
  std::vector<int> contacts;  // kContactForce: every contact pair the request names (index is
                              // the first): a segment's ellipsoids give one pair each
  Vec3 point{};               // point requests: the point in the segment frame
  // `relative_to FRAME` on a segment request: the quantity relative to that frame (a segment, a
  // vehicle or the ground), in its axes; none for the absolute quantity of docs/language.md §17.
  std::optional<FrameRef> relative_to;
  // `expressed_in FRAME` instead: the quantity relative to the ground, in that frame's axes.
  bool expressed_in = false;
  // The SAE J211 class of the filtered channels [Hz]: 0 none, -1 the default for the kind; and
  // whether the block's filter_standard is ISO 6487.
  int filter_class = -1;
  bool iso_filter = false;
  SourceRange range;
};

struct Criterion {
  enum class Kind {
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
    kViscousCriterion,
    kNkm,
    kNic,
    kTti,
    kTibiaIndex,
  };
  Kind kind = Kind::kHic15;
  int segment = -1;  // head, chest criteria
  int joint = -1;    // neck, femur and tibia criteria
  // The second input of NIC (the joint at T1, a joint index) and TTI (the lower spine, a
  // segment index): CriterionSpec::second_kind says which.
  int second = -1;
  // The scene's own limit (SI, in the criterion's dimension) and the standard it comes from;
  // none: the default limit of the criterion's standard.
  std::optional<double> limit;
  std::string standard;
  // The block's filter_standard is ISO 6487.
  bool iso_filter = false;
  SourceRange range;
};

// In the order of the language's names (check_settings.cpp): auto, exponential, dopri5,
// rosenbrock, cvs.
enum class IntegratorMethod { kAuto, kExponential, kDormandPrince, kRosenbrock, kCvs };
enum class Symmetry { kNone, kPlanar, kMirror };

// The most output rows a run may have: every row stays in memory (time series, animation frames)
// until the run ends, so a million rows of a full occupant already take about a gigabyte.
inline constexpr double kMaxOutputRows = 1e6;

// A `settle` block: the damped pre-simulation before the run (runtime/run/settle.h); SI units.
struct SettleSettings {
  double duration = 0.0;
  double damping = 10.0;
  double velocity = 1e-3;
  double angular_velocity = 0.01;
  double force_change = 0.01;
};

struct RunSettings {
  double start = 0.0;
  double end = 0.0;
  double output_every = 0.0;
  IntegratorMethod method = IntegratorMethod::kAuto;
  double relative_tolerance = 1e-6;
  double absolute_tolerance = 1e-9;
  double min_step = 1e-9;
  std::optional<double> max_step;
  std::optional<double> initial_step;
  Vec3 gravity{0, 0, -9.80665};
  std::optional<double> checkpoint_every;
  std::string resume_from;
  std::optional<SettleSettings> settle;
  Symmetry symmetry = Symmetry::kNone;
  std::vector<std::array<int, 2>> mirror_pairs;  // segment pairs mirrored in the xz plane
};

// A `param` of the scene (not of an imported module): what `--set` and `sled sweep` may change.
struct ScenarioParameter {
  std::string name;
  std::vector<double> value;  // SI; one component for a scalar, three for a vector
  Dimension dimension;
  bool bare = false;   // written without a unit (a bare zero fits any dimension)
  bool valid = false;  // false when its value did not check
  SourceRange range;   // of its name in the declaration
};

// A declared name or a use of one, for editors (`sled lsp`: go to definition, references,
// hover). A declaration's `use` is its own name; a use's `declaration` is where the name it
// resolved to was declared (another file's range for an imported name).
struct NameReference {
  SourceRange use;
  SourceRange declaration;
  std::string name;  // qualified where the declaring scope has a prefix: occupant.pelvis
  std::string kind;  // segment, joint, body, module, function, parameter, ...
  int index = -1;    // into the vector of that kind; -1 for modules, the ground and parameters
  bool is_declaration = false;
  // Parameters and `let`s: the value in SI, empty when it did not check.
  std::vector<double> value;
  Dimension dimension;
};

struct CheckedScenario {
  // False for a file without a `scenario` block: a module for `import`, which can be checked
  // but not run.
  bool has_scenario = false;
  std::string title;
  RunSettings run;
  std::vector<Function> functions;
  std::vector<Body> bodies;
  std::vector<Segment> segments;
  std::vector<Joint> joints;
  std::vector<Ellipsoid> ellipsoids;
  std::vector<Vehicle> vehicles;
  std::vector<Plane> planes;
  std::vector<Contact> contacts;
  std::vector<Harness> harnesses;
  std::vector<Belt> belts;
  std::vector<Airbag> airbags;
  std::vector<SpringDamper> springs;
  std::vector<AppliedLoad> loads;
  std::vector<Actuator> actuators;
  std::vector<Fluid> fluids;
  std::vector<Constraint> constraints;
  std::vector<InitialCondition> initial_conditions;
  std::vector<OutputRequest> outputs;
  std::vector<Criterion> criteria;
  std::vector<ScenarioParameter> parameters;  // in declaration order; not part of Dump
  // Every declaration and every resolved use of a name, in the order the checker met them
  // (imports checked twice appear twice); not part of Dump.
  std::vector<NameReference> references;
};

// A stable, range-free text form: equal dumps mean equal checked scenarios.
std::string Dump(const CheckedScenario& scenario);

}  // namespace sled::compiler
