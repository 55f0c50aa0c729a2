// The one list of the Model's fields (as MuJoCo lists mjModel's): every array with the count it is
// sized by, the role it plays and what its entries index, and every scalar. DumpModel,
// FingerprintOf (the checkpoints) and ValidateModel walk these lists, so a field added here is
// dumped, fingerprinted and checked without more code.
//
// To add a field: declare it in model.h (or its table), then add one line to the list below,
// beside the fields of its count:
//   X(COUNT, member, ROLE, INDEXES, CHECKS)
//   COUNT    the ModelCount its size must equal (Segment: nsegment, Position: nq, ...);
//   ROLE     Physics (fingerprinted: a checkpoint of another value is refused), Settings (the
//            integrator's: compared as text), Records (outputs, criteria, drawing: a resume may
//            change them) or Unhashed (names of places in the source, the title, the end time);
//   INDEXES  the ModelCount an integer entry indexes (None: not an index);
//   CHECKS   kPlain, or kOrNone (-1 allowed), kNanAllowed, kNonNegative, or'ed.
// Entries of a new type need a Text (dump), Hash and Check overload in model_fields.cpp; a new
// count needs a ModelCount, a name and a size in model_fields.cpp's CountOf.
#pragma once

#include <cstdint>
#include <string>

#include "runtime/model/model.h"

namespace sled::runtime {

// What an array's size must equal, or what an index refers to.
enum class ModelCount : std::uint8_t {
  kNone,            // a scalar, or not an index
  kSegment,         // segment_name
  kJoint,           // the joint above each segment: nsegment
  kMirror,          // per segment, or empty without mirror symmetry
  kSegmentDummy,    // per segment, or empty when no body names a dummy type
  kPosition,        // nq
  kVelocity,        // nv
  kAuxiliary,       // nw
  kVehicle,         // vehicle_name
  kFunction,        // functions.kind
  kFunctionUnload,  // per function, or empty (a Model built without unloading slopes or ATB's law)
  kFunctionPoint,   // functions.points_x
  kCoefficient,     // functions.coefficients
  kSpring,          // spring_name
  kEllipsoid,       // contacts.ellipsoid_name
  kPlane,           // contacts.plane_name
  kPair,            // contacts.pair_kind
  kPairRate,        // per pair, or empty (a Model built without ATB's rate-dependent terms)
  kContactGroup,    // contacts.group_first
  kGroupPair,       // contacts.group_pairs
  kBelt,            // belts.name
  kBeltPoint,       // belts.point_wraps
  kHarness,         // belts.harness_name
  kTie,             // belts.tie_points
  kAirbag,          // airbags.name
  kAirbagContact,   // airbags.contact_segment
  kLoad,            // loads.name
  kActuator,        // actuators.name
  kFluid,           // fluids.medium
  kShape,           // shape_name
  kConstraint,      // constraint_name
  kOutput,          // output_kind
  kOutputMirror,    // per output, or empty without mirror symmetry
  kOutputFrame,     // per output, or empty when no output has a frame
  kOutputFilter,    // per output, or empty when nothing is filtered
  kCriterion,       // criterion_kind
  kRun,             // scalars: the run settings
  kSettle,          // scalars: settling
  kScene,           // scalars: the scene
};

enum class FieldRole : std::uint8_t { kPhysics, kSettings, kRecords, kUnhashed };

enum FieldCheck : unsigned {
  kPlain = 0,
  kOrNone = 1,       // an index that may be -1
  kNanAllowed = 2,   // NaN means "not given" (criterion_limit)
  kNonNegative = 4,  // masses, damping
};

// clang-format off
#define SLED_MODEL_ARRAYS(X)                                                              \
  X(Segment, segment_name, Physics, None, kPlain)                                          \
  X(SegmentDummy, segment_dummy, Records, None, kPlain)                                     \
  X(Segment, segment_parent, Physics, Segment, kOrNone)                                    \
  X(Segment, segment_base, Physics, None, kPlain)                                          \
  X(Segment, segment_mass, Physics, None, kNonNegative)                                    \
  X(Segment, segment_inertia, Physics, None, kPlain)                                       \
  X(Segment, segment_source, Unhashed, None, kPlain)                                       \
  X(Joint, joint_kind, Physics, None, kPlain)                                              \
  X(Joint, joint_name, Physics, None, kPlain)                                              \
  X(Joint, q_address, Physics, Position, kPlain)                                           \
  X(Joint, q_count, Physics, None, kPlain)                                                 \
  X(Joint, v_address, Physics, Velocity, kPlain)                                           \
  X(Joint, v_count, Physics, None, kPlain)                                                 \
  X(Joint, joint_point_in_parent, Physics, None, kPlain)                                   \
  X(Joint, joint_frame_in_parent, Physics, None, kPlain)                                   \
  X(Joint, joint_point_in_child, Physics, None, kPlain)                                    \
  X(Joint, joint_frame_in_child, Physics, None, kPlain)                                    \
  X(Joint, joint_axis, Physics, None, kPlain)                                              \
  X(Joint, joint_function, Physics, Function, kOrNone)                                     \
  X(Joint, joint_viscous, Physics, None, kPlain)                                           \
  X(Joint, joint_coulomb, Physics, None, kPlain)                                           \
  X(Joint, joint_stop, Physics, None, kPlain)                                              \
  X(Joint, joint_twist_stop, Physics, None, kPlain)                                        \
  X(Joint, joint_stop_impulse, Physics, None, kPlain)                                      \
  X(Joint, joint_restitution, Physics, None, kPlain)                                       \
  X(Joint, joint_locked, Physics, None, kPlain)                                            \
  X(Joint, joint_lock_below, Physics, None, kPlain)                                        \
  X(Joint, joint_unlock_above, Physics, None, kPlain)                                      \
  X(Joint, joint_source, Unhashed, None, kPlain)                                           \
  X(Mirror, segment_mirror_twin, Physics, None, kPlain)                                    \
  X(Mirror, mirror_normal, Physics, None, kPlain)                                          \
  X(Mirror, segment_mirror_count, Physics, None, kPlain)                                   \
  X(Position, q0, Physics, None, kPlain)                                                   \
  X(Velocity, v0, Physics, None, kPlain)                                                   \
  X(Auxiliary, w0, Physics, None, kPlain)                                                  \
  X(Vehicle, vehicle_name, Physics, None, kPlain)                                          \
  X(Vehicle, vehicle_motion, Physics, None, kPlain)                                        \
  X(Vehicle, vehicle_position, Physics, None, kPlain)                                      \
  X(Vehicle, vehicle_orientation, Physics, None, kPlain)                                   \
  X(Vehicle, vehicle_velocity, Physics, None, kPlain)                                      \
  X(Vehicle, vehicle_angular_velocity, Physics, None, kPlain)                              \
  X(Vehicle, vehicle_path, Physics, None, kPlain)                                          \
  X(Function, functions.kind, Physics, None, kPlain)                                       \
  X(Function, functions.constant, Physics, None, kPlain)                                   \
  X(Function, functions.first, Physics, None, kPlain)                                      \
  X(Function, functions.count, Physics, None, kPlain)                                      \
  X(Function, functions.energy_loss, Physics, None, kPlain)                                \
  X(Function, functions.permanent_set, Physics, None, kPlain)                              \
  X(FunctionUnload, functions.unload_slope, Physics, None, kNonNegative)                   \
  X(FunctionUnload, functions.atb_return, Physics, Function, kOrNone)                      \
  X(FunctionUnload, functions.atb_set, Physics, Function, kOrNone)                         \
  X(FunctionUnload, functions.atb_spike, Physics, Function, kOrNone)                       \
  X(FunctionUnload, functions.atb_spike_end, Physics, None, kPlain)                        \
  X(FunctionUnload, functions.atb_origin, Physics, None, kPlain)                           \
  X(FunctionPoint, functions.points_x, Physics, None, kPlain)                              \
  X(FunctionPoint, functions.points_y, Physics, None, kPlain)                              \
  X(Coefficient, functions.coefficients, Physics, None, kPlain)                            \
  X(Spring, spring_name, Physics, None, kPlain)                                            \
  X(Spring, spring_first, Physics, None, kPlain)                                           \
  X(Spring, spring_second, Physics, None, kPlain)                                          \
  X(Spring, spring_point_first, Physics, None, kPlain)                                     \
  X(Spring, spring_point_second, Physics, None, kPlain)                                    \
  X(Spring, spring_function, Physics, Function, kOrNone)                                   \
  X(Spring, spring_damping, Physics, None, kPlain)                                         \
  X(Spring, spring_free_length, Physics, None, kPlain)                                     \
  X(Spring, spring_tension_only, Physics, None, kPlain)                                    \
  X(Ellipsoid, contacts.ellipsoid_name, Physics, None, kPlain)                             \
  X(Ellipsoid, contacts.ellipsoid_frame, Physics, None, kPlain)                            \
  X(Ellipsoid, contacts.ellipsoid_center, Physics, None, kPlain)                           \
  X(Ellipsoid, contacts.ellipsoid_axes, Physics, None, kPlain)                             \
  X(Ellipsoid, contacts.ellipsoid_semi_axes, Physics, None, kNonNegative)                  \
  X(Ellipsoid, contacts.ellipsoid_degree, Physics, None, kPlain)                           \
  X(Ellipsoid, contacts.ellipsoid_radius, Physics, None, kNonNegative)                     \
  X(Plane, contacts.plane_name, Physics, None, kPlain)                                     \
  X(Plane, contacts.plane_frame, Physics, None, kPlain)                                    \
  X(Plane, contacts.plane_origin, Physics, None, kPlain)                                   \
  X(Plane, contacts.plane_edge_u, Physics, None, kPlain)                                   \
  X(Plane, contacts.plane_edge_v, Physics, None, kPlain)                                   \
  X(Plane, contacts.plane_normal, Physics, None, kPlain)                                   \
  X(Pair, contacts.pair_kind, Physics, None, kPlain)                                       \
  X(Pair, contacts.pair_first, Physics, Ellipsoid, kPlain)                                 \
  X(Pair, contacts.pair_second, Physics, None, kPlain)                                     \
  X(Pair, contacts.pair_function, Physics, Function, kPlain)                               \
  X(Pair, contacts.pair_damping, Physics, None, kNonNegative)                              \
  X(PairRate, contacts.pair_rate_scaled_force, Physics, Function, kOrNone)                     \
  X(PairRate, contacts.pair_rate_scale, Physics, Function, kOrNone)                            \
  X(PairRate, contacts.pair_rate_force, Physics, Function, kOrNone)                            \
  X(Pair, contacts.pair_damping_depth, Physics, None, kNonNegative)                        \
  X(Pair, contacts.pair_friction, Physics, None, kNonNegative)                             \
  X(Pair, contacts.pair_impulse, Physics, None, kPlain)                                    \
  X(Pair, contacts.pair_restitution, Physics, None, kPlain)                                \
  X(Pair, contacts.pair_source, Unhashed, None, kPlain)                                    \
  X(ContactGroup, contacts.group_first, Records, GroupPair, kPlain)                        \
  X(ContactGroup, contacts.group_count, Records, None, kPlain)                             \
  X(GroupPair, contacts.group_pairs, Records, Pair, kPlain)                                \
  X(Belt, belts.name, Physics, None, kPlain)                                               \
  X(Belt, belts.function, Physics, Function, kPlain)                                       \
  X(Belt, belts.slack, Physics, None, kPlain)                                              \
  X(Belt, belts.pretension, Physics, None, kPlain)                                         \
  X(Belt, belts.friction, Physics, None, kNonNegative)                                     \
  X(Belt, belts.harness, Physics, Harness, kOrNone)                                        \
  X(Belt, belts.first_point, Physics, BeltPoint, kPlain)                                   \
  X(Belt, belts.point_count, Physics, None, kPlain)                                        \
  X(BeltPoint, belts.point_frame, Physics, None, kPlain)                                   \
  X(BeltPoint, belts.point_wraps, Physics, None, kPlain)                                   \
  X(BeltPoint, belts.point_position, Physics, None, kPlain)                                \
  X(BeltPoint, belts.point_axes, Physics, None, kPlain)                                    \
  X(BeltPoint, belts.point_semi_axes, Physics, None, kNonNegative)                         \
  X(Harness, belts.harness_name, Physics, None, kPlain)                                    \
  X(Harness, belts.harness_friction, Physics, None, kNonNegative)                          \
  X(Tie, belts.tie_points, Physics, BeltPoint, kPlain)                                     \
  X(Tie, belts.tie_harness, Physics, Harness, kPlain)                                      \
  X(Airbag, airbags.name, Physics, None, kPlain)                                           \
  X(Airbag, airbags.frame, Physics, None, kPlain)                                          \
  X(Airbag, airbags.deploy_point, Physics, None, kPlain)                                   \
  X(Airbag, airbags.axes, Physics, None, kPlain)                                           \
  X(Airbag, airbags.semi_axes, Physics, None, kNonNegative)                                \
  X(Airbag, airbags.deploy_time, Physics, None, kPlain)                                    \
  X(Airbag, airbags.inflow, Physics, Function, kPlain)                                     \
  X(Airbag, airbags.inflow_temperature, Physics, None, kNonNegative)                       \
  X(Airbag, airbags.vent_area, Physics, None, kNonNegative)                                \
  X(Airbag, airbags.discharge_coefficient, Physics, None, kNonNegative)                    \
  X(Airbag, airbags.ambient_pressure, Physics, None, kNonNegative)                         \
  X(Airbag, airbags.gamma, Physics, None, kNonNegative)                                    \
  X(Airbag, airbags.gas_constant, Physics, None, kNonNegative)                             \
  X(Airbag, airbags.state_address, Physics, Auxiliary, kPlain)                             \
  X(Airbag, airbags.free_bag, Physics, None, kPlain)                                      \
  X(Airbag, airbags.bag_mass, Physics, None, kNonNegative)                                 \
  X(Airbag, airbags.mass_factor, Physics, None, kNonNegative)                              \
  X(Airbag, airbags.tether_stiffness, Physics, None, kNonNegative)                         \
  X(Airbag, airbags.vent_opening_pressure, Physics, None, kNonNegative)                    \
  X(Airbag, airbags.first_contact, Physics, None, kPlain)                                  \
  X(Airbag, airbags.contact_count, Physics, None, kPlain)                                  \
  X(Airbag, airbags.source, Unhashed, None, kPlain)                                        \
  X(AirbagContact, airbags.contact_segment, Physics, Segment, kPlain)                      \
  X(AirbagContact, airbags.contact_center, Physics, None, kPlain)                          \
  X(AirbagContact, airbags.contact_axes, Physics, None, kPlain)                            \
  X(AirbagContact, airbags.contact_semi_axes, Physics, None, kNonNegative)                 \
  X(AirbagContact, airbags.contact_radius, Physics, None, kNonNegative)                    \
  X(Load, loads.name, Physics, None, kPlain)                                               \
  X(Load, loads.source, Unhashed, None, kPlain)                                            \
  X(Load, loads.kind, Physics, None, kPlain)                                               \
  X(Load, loads.segment, Physics, Segment, kPlain)                                         \
  X(Load, loads.force, Physics, Function, kOrNone)                                         \
  X(Load, loads.torque, Physics, Function, kOrNone)                                        \
  X(Load, loads.direction, Physics, None, kPlain)                                          \
  X(Load, loads.axis, Physics, None, kPlain)                                               \
  X(Load, loads.point, Physics, None, kPlain)                                              \
  X(Load, loads.in_segment, Physics, None, kPlain)                                         \
  X(Actuator, actuators.name, Physics, None, kPlain)                                       \
  X(Actuator, actuators.source, Unhashed, None, kPlain)                                    \
  X(Actuator, actuators.segment, Physics, Segment, kPlain)                                 \
  X(Actuator, actuators.axis, Physics, None, kPlain)                                       \
  X(Actuator, actuators.target, Physics, Function, kPlain)                                 \
  X(Actuator, actuators.proportional, Physics, Function, kPlain)                           \
  X(Actuator, actuators.derivative, Physics, Function, kOrNone)                            \
  X(Actuator, actuators.integral, Physics, Function, kOrNone)                              \
  X(Actuator, actuators.state_address, Physics, Auxiliary, kOrNone)                        \
  X(Fluid, fluids.medium, Physics, None, kPlain)                                           \
  X(Fluid, fluids.segment, Physics, Segment, kPlain)                                       \
  X(Fluid, fluids.center, Physics, None, kPlain)                                           \
  X(Fluid, fluids.axes, Physics, None, kPlain)                                             \
  X(Fluid, fluids.semi_axes, Physics, None, kNonNegative)                                  \
  X(Fluid, fluids.drag, Physics, None, kNonNegative)                                       \
  X(Fluid, fluids.density, Physics, None, kNonNegative)                                    \
  X(Fluid, fluids.speed, Physics, Function, kOrNone)                                       \
  X(Fluid, fluids.pressure, Physics, Function, kOrNone)                                    \
  X(Fluid, fluids.direction, Physics, None, kPlain)                                        \
  X(Fluid, fluids.carrier, Physics, None, kPlain)                                          \
  X(Fluid, fluids.level, Physics, None, kPlain)                                            \
  X(Shape, shape_name, Records, None, kPlain)                                              \
  X(Shape, shape_segment, Records, Segment, kPlain)                                        \
  X(Shape, shape_center, Records, None, kPlain)                                            \
  X(Shape, shape_axes, Records, None, kPlain)                                              \
  X(Shape, shape_semi_axes, Records, None, kNonNegative)                                   \
  X(Shape, shape_degree, Records, None, kPlain)                                            \
  X(Constraint, constraint_name, Physics, None, kPlain)                                    \
  X(Constraint, constraint_source, Unhashed, None, kPlain)                                 \
  X(Constraint, constraint_kind, Physics, None, kPlain)                                    \
  X(Constraint, constraint_first, Physics, None, kPlain)                                   \
  X(Constraint, constraint_second, Physics, None, kPlain)                                  \
  X(Constraint, constraint_point_first, Physics, None, kPlain)                             \
  X(Constraint, constraint_point_second, Physics, None, kPlain)                            \
  X(Constraint, constraint_distance, Physics, None, kPlain)                                \
  X(Constraint, constraint_axis, Physics, None, kPlain)                                    \
  X(Output, output_kind, Records, None, kPlain)                                            \
  X(Output, output_label, Records, None, kPlain)                                           \
  X(Output, output_index, Records, None, kPlain)                                           \
  X(Output, output_point, Records, None, kPlain)                                           \
  X(OutputMirror, output_mirrored, Records, None, kPlain)                                  \
  X(OutputFrame, output_relative, Records, None, kPlain)                                   \
  X(OutputFrame, output_frame, Records, None, kPlain)                                      \
  X(OutputFrame, output_frame_mirrored, Records, None, kPlain)                             \
  X(OutputFilter, output_filter_class, Records, None, kPlain)                              \
  X(OutputFilter, output_filter_iso, Records, None, kPlain)                                \
  X(Criterion, criterion_kind, Records, None, kPlain)                                      \
  X(Criterion, criterion_name, Records, None, kPlain)                                      \
  X(Criterion, criterion_target, Records, None, kPlain)                                    \
  X(Criterion, criterion_output, Records, Output, kPlain)                                  \
  X(Criterion, criterion_second_output, Records, Output, kOrNone)                          \
  X(Criterion, criterion_filter_iso, Records, None, kPlain)                                \
  X(Criterion, criterion_limit, Records, None, kNanAllowed)                                \
  X(Criterion, criterion_standard, Records, None, kPlain)

// Scalars: X(LINE, member, ROLE, CHECKS); LINE is the dump line they are printed on.
#define SLED_MODEL_SCALARS(X)                                                             \
  X(Scene, title, Unhashed, kPlain)                                                        \
  X(Scene, gravity, Physics, kPlain)                                                       \
  X(Scene, nq, Physics, kNonNegative)                                                      \
  X(Scene, nv, Physics, kNonNegative)                                                      \
  X(Scene, nw, Physics, kNonNegative)                                                      \
  X(Scene, mirror_plane_y, Physics, kPlain)                                                \
  X(Run, start_time, Settings, kPlain)                                                     \
  X(Run, end_time, Unhashed, kPlain)                                                       \
  X(Run, output_every, Settings, kNonNegative)                                             \
  X(Run, integrator, Settings, kPlain)                                                     \
  X(Run, relative_tolerance, Settings, kNonNegative)                                       \
  X(Run, absolute_tolerance, Settings, kNonNegative)                                       \
  X(Run, min_step, Settings, kNonNegative)                                                 \
  X(Run, max_step, Settings, kNonNegative)                                                 \
  X(Run, initial_step, Settings, kNonNegative)                                             \
  X(Settle, settle.duration, Physics, kNonNegative)                                        \
  X(Settle, settle.damping, Physics, kNonNegative)                                         \
  X(Settle, settle.velocity, Physics, kNonNegative)                                        \
  X(Settle, settle.angular_velocity, Physics, kNonNegative)                                \
  X(Settle, settle.force_change, Physics, kNonNegative)                                    \
  X(Settle, settle.check_every, Physics, kNonNegative)
// clang-format on

// One listed field as the walkers see it.
struct ModelField {
  const char* name;  // as spelt in the Model: "segment_mass", "contacts.pair_first"
  ModelCount count;  // its size (arrays), or the dump line it is on (scalars)
  FieldRole role;
  ModelCount indexes;  // kNone: not an index
  unsigned checks;     // FieldCheck bits
};

// Calls visit(field, member) for every listed array, then scalar, in list order. With a
// non-const Model the members can be changed (the tests corrupt each in turn).
template <typename M, typename Visit>
void ForEachModelArray(M& model, Visit&& visit) {
#define SLED_VISIT_ARRAY(count, member, role, indexes, checks)                                \
  visit(ModelField{#member, ModelCount::k##count, FieldRole::k##role, ModelCount::k##indexes, \
                   checks},                                                                   \
        model.member);
  SLED_MODEL_ARRAYS(SLED_VISIT_ARRAY)
#undef SLED_VISIT_ARRAY
}
template <typename M, typename Visit>
void ForEachModelScalar(M& model, Visit&& visit) {
#define SLED_VISIT_SCALAR(line, member, role, checks)                                            \
  visit(ModelField{#member, ModelCount::k##line, FieldRole::k##role, ModelCount::kNone, checks}, \
        model.member);
  SLED_MODEL_SCALARS(SLED_VISIT_SCALAR)
#undef SLED_VISIT_SCALAR
}

// The name of a count as the dump and the messages spell it ("segment", "contact_pair").
const char* CountName(ModelCount count);
// How many entries a count has in `model` (0 for kNone and the scalar lines).
std::size_t CountOf(const Model& model, ModelCount count);
// Whether every array of a count may also be empty (mirror symmetry, output frames, filters).
bool CountMayBeEmpty(ModelCount count);

// FNV-1a of every listed field of `role`: its name, its size and its values' bytes.
std::uint64_t HashModelFields(const Model& model, FieldRole role);
// DumpModel's lines of the fields of `role` only (all roles: DumpModel).
std::string DumpModelFields(const Model& model, FieldRole role);

}  // namespace sled::runtime
