// What a CVS-III / ATB deck says, card group by card group, after reading and validation: the
// reader fills it, the mapping turns it into the AST. Numbers stay in the deck's units; indices
// are the deck's (1-based). Each entry keeps the line of its card for the comments of the
// generated scenario, and references keep their field's range for diagnostics.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "lang/source/source_range.h"

namespace sled::lang::legacy {

using Vec3 = std::array<double, 3>;

// A number on a card that refers to something else (a segment, a plane, a function).
struct Ref {
  int number = 0;
  SourceRange where;
  std::string card;  // the card's label, for messages
};

// NF(3) and NF(4) of an F.x.b card: ATB's R factor (the share of the loading energy the
// unloading curve gives back) and G factor (the permanent deflection as a share of the largest),
// each a function of the largest deflection; number 0: none (R = 1, G = 0: elastic).
struct UnloadingRefs {
  Ref r_factor, g_factor;
  // NF(2) > 0: ATB's inertial spike, added to the loading force until the deflection first
  // reaches the spike function's E.2 D3 (DEF_NEW_QUADRATIC, DEF_NEW_CUBIC); 0: none.
  Ref spike;
  // Negative NF(2), NF(3), NF(4): ATB's rate-dependent force F2(D) F3(D') + F4(D')
  // (FUNC_RATE_DEP), the functions |NF|; number 0: none. Only with no spike, R or G.
  Ref rate_scaled_force, rate_scale, rate_force;
  bool HasRateTerms() const {
    return rate_scaled_force.number != 0 || rate_scale.number != 0 || rate_force.number != 0;
  }
};

struct DeckUnits {
  std::string length;  // sled unit symbols: "in", "lbf", "s"
  std::string force;
  std::string time;
};

// The five numbers of a B.4 joint spring (or a reference to a joint function).
struct JointSpring {
  double linear = 0, quadratic = 0, cubic = 0, energy_loss = 0, stop = 0;
  Ref function;  // number > 0: a negative first coefficient named E function |n|
};

struct SegmentCard {
  std::uint32_t line = 0;
  std::string name;
  double weight = 0;
  Vec3 inertia{}, semi_axes{}, center{};
  bool has_principal_axes = false;
  Vec3 principal_axes{};
  // A D.5 card may replace the contact ellipsoid.
  std::uint32_t ellipsoid_line = 0;
  Vec3 ellipsoid_orientation{};
  double degree = 2;
};

enum class JointType { kBall, kPin, kEuler, kSlip };

struct JointCard {
  std::uint32_t line = 0;
  std::string name;
  int parent = 0;  // JNT(J); the child is segment J + 1; 0 starts a new reference body
  JointType type = JointType::kBall;
  Vec3 at_parent{}, at_child{}, axes_parent{}, axes_child{};
  JointSpring flexure, twist, spin;  // spin for Euler joints only (B.4.b)
  Vec3 initial_angles{};             // Euler joints: ANG on B.4.b
  double viscous = 0, coulomb = 0, restitution = 0;
  double coulomb_rate = 0;  // B.5.a VISC(3): the rate of full Coulomb friction
  // A slip joint with a negative IEULER starts locked (UPDATE_JOINTS) and slides for good once
  // the size of its axial force passes `unlock_above` (COMP_MAX = -TENS_MAX; 0: never).
  // A pin (JTYPE 1) locks when its torque falls below `lock_below`; JTYPE -1 starts locked.
  // A ball of JTYPE 2 or -2 (`lockable`) does the same with the size of its torque vector; a
  // ball of JTYPE 0 never locks (UPDATE_JOINTS).
  bool locked = false;
  bool lockable = false;
  double unlock_above = 0, lock_below = 0;
  int jtype = 0;            // B.3.a JTYPE as read (EQUILB rewrites VISC(4) of negative ones)
  double unlock_level = 0;  // B.5.a VISC(4) as read
};

struct VehicleCard {
  std::uint32_t line = 0;
  std::string title;
  Vec3 orientation{}, position{};
  double speed = 0, duration = 0;
  // MSEG: 0 the primary vehicle, above NSEG a further vehicle segment, 1 to NSEG a body segment
  // whose motion the card prescribes (Deck::prescribed_segments).
  int segment = 0;
};

struct PlaneCard {
  std::uint32_t line = 0;
  std::string title;
  std::array<Vec3, 3> corners{};
};

struct BeltCard {
  std::uint32_t line = 0;
  std::string title;
  Vec3 anchor_a{}, anchor_b{};
  double slack = 0;
  // From F.2.b.
  std::uint32_t contact_line = 0;
  Ref segment, force, friction;
  UnloadingRefs unloading;
  bool output = false;
};

// A frame named by an ATB segment number: a body segment (1-based), a vehicle (0-based, deck
// order) or the ground.
struct DeckFrame {
  enum class Kind { kSegment, kVehicle, kGround } kind = Kind::kGround;
  int index = 0;
};

// D.6: a constraint between a point of one frame and a point of another (KQTYPE 1: the points
// held together; 2: held at their initial distance).
struct ConstraintCard {
  std::uint32_t line = 0;
  enum class Kind { kFixedPoint, kFixedDistance } kind = Kind::kFixedPoint;
  DeckFrame first, second;
  Vec3 at_first{}, at_second{};
};

// D.4 and F.6: an airbag, ATB's free bag, deploying from its point in the primary vehicle, its
// gas constants mapped and its cylinder tabulated.
struct AirbagCard {
  std::uint32_t line = 0;           // D.4.a
  std::uint32_t cylinder_line = 0;  // D.4.d
  std::string title;
  Vec3 semi_axes{};
  Vec3 orientation{};    // YB: yaw, pitch, roll of ATB's bag axes (it deploys along their -x)
  Vec3 deploy_point{};   // in the primary vehicle
  double deploy_at = 0;  // CYTD
  double ambient_pressure = 0, gas_temperature = 0, gamma = 0;
  double gas_constant = 0;  // CYR, per weight (length / temperature)
  double vent_discharge = 0, vent_area = 0;
  // ATB's free bag: the temperature that gives ATB's SWITCH (FillFreeBag), the vent's discharge
  // coefficient rescaled to the density ATB vents at, and the bag's body.
  double reference_temperature = 0;
  double bag_weight = 0;                          // XBM
  double vent_pressure = 0;                       // CYPV
  double spring = 0;                              // SPRK
  double mass_factor = 0;                         // CMASS
  std::vector<std::pair<double, double>> inflow;  // time since CYTD -> mass flow (F * T / L)
  std::uint32_t contact_line = 0;                 // F.6
  std::vector<Ref> contacts;                      // F.6's segments
};

// F.8: a harness (D.1 NHRNSS), belts through points. A belt's first and last points are anchors in
// the harness's frame, the points between them are body segments whose ellipsoid the webbing
// wraps.
struct HarnessPoint {
  std::uint32_t line = 0;  // F.8.d.1
  Ref segment;             // KS: a wrapped point's body segment; an end's KS as given
  Ref friction;            // NF(5)
  Vec3 anchor{};           // an end: BAR(1..3) plus the F.8.d.2 offset, in the harness's frame
  int tie = 0;             // an end: the tie point (KS / 100), 0 for none
  bool ring = false;       // a guide ring: a point between the ends fixed in the harness's frame
};

struct HarnessBeltCard {
  std::uint32_t line = 0;  // F.8.c
  int number = 0;          // ATB's belt number in its harness
  int part = 0;            // split at guide rings: 1, 2, ... from the first point; 0 unsplit
  Ref force;
  UnloadingRefs unloading;
  double slack = 0;  // XLONG
  std::vector<HarnessPoint> points;
};

struct HarnessCard {
  std::uint32_t line = 0;  // F.8.a
  int vehicle = -1;        // the anchors' frame: a vehicle (0-based, deck order) or -1, the ground
  std::vector<HarnessBeltCard> belts;
};

// D.5 for a vehicle (NSEG < M <= NSEG + NVEH: the vehicle's own ellipsoid) or an extra one
// (M >= NGRND: on whatever frame the F.3.b cards that name it put it; `vehicle` is 0).
struct VehicleEllipsoidCard {
  std::uint32_t line = 0;
  int vehicle = 0;  // 1-based among the vehicles
  int number = 0;   // M
  Vec3 semi_axes{}, center{}, orientation{};
  double degree = 2;
  SourceRange where;  // of M
};

struct SpringCard {
  std::uint32_t line = 0;
  Ref first, second;
  Vec3 at_first{}, at_second{};
  double free_length = 0, linear = 0, quadratic = 0, damping = 0;
};

// D.9 (D.1.a NFORCE of them): a force or torque of magnitude f(time), function NFVNT, on body
// segment |NFVSEG|: NFVSEG > 0 a force at `point` (segment axes, from its centre of mass) along
// the x axis of the segment's axes turned by `orientation` (yaw, pitch, roll in degrees);
// NFVSEG < 0 a torque about that axis. The direction turns with the segment (FORCE_TORQUE).
struct LoadCard {
  std::uint32_t line = 0;
  Ref segment;   // NFVSEG, signed
  Ref function;  // |NFVNT|
  Vec3 point{}, orientation{};
  bool torque() const { return segment.number < 0; }
};

// F.10 (D.1.b NRTORQ of them): a PID actuator on pin joint `joint` (INPUT_ROBOTICS), its torque
// (ACTUATOR_TORQUE) P(th0) (th - th0) - D(th0) (th' - th0') - I(th0) S with th0 = target(time),
// th the pin's angle (JNTFNC: x1 x x2 along the axis), th' the rate (w1 - w2) along the axis and
// S ATB's running sum of (th - th0) dt; APPLY adds it to `base` (the joint's proximal or distal
// segment) and its opposite to the other.
struct ActuatorCard {
  std::uint32_t line = 0;
  Ref joint, base, target, proportional, derivative, integral;
  bool base_is_proximal = true;
};

struct FunctionCard {
  std::uint32_t line = 0;
  SourceRange where;  // E.1 columns 1-4
  int number = 0;
  std::string title;
  enum class Form { kConstant, kPolynomial, kTable } form = Form::kConstant;
  double constant = 0;
  double first_part_end = 0;                      // E.2 |D1|: where ATB ends the first part
  std::vector<double> coefficients;               // A0..A5
  std::vector<std::pair<double, double>> points;  // (D, F(D))
  // E.2 D0 (where ATB starts the function's integral and its permanent set), D3 and D4 (read by
  // the uses that give them a meaning), with their columns for messages.
  double origin = 0, d3 = 0, d4 = 0;
  SourceRange origin_where, d3_where, d4_where;
};

struct ContactCard {
  std::uint32_t line = 0;
  bool with_plane = false;  // F.1 (plane) or F.3 (segment)
  Ref segment, other, force, friction;
  UnloadingRefs unloading;
  // F.3: MS_SEG(1) and MS_SEG(3), the ellipsoids of `segment` and `other` (0: the frame's own).
  Ref ellipsoid, other_ellipsoid;
  bool output = false;
};

// E.6 (D.1.a NWINDF of them, after the E cards): a wind-force function. With RK (the ratio of
// specific heats) not 0, the dynamic pressure of segment NSV's velocity relative to NSR's, air of
// density RK PR / C^2; with RK 0, a table of time against a pressure vector (FX, FY, FZ), also
// read as the drag coefficient against time (FX) when F.7.b names it as one.
struct WindFunctionCard {
  std::uint32_t line = 0;
  SourceRange where;  // E.6.a columns 1-4
  int number = 0;
  std::string title;
  double heat_ratio = 0, sonic_speed = 0, pressure = 0;  // RK, C, PR
  Ref moving, reference;                                 // NSV, NSR (0: the ground)
  std::uint32_t table_line = 0;                          // E.6.d's first card
  std::vector<std::array<double, 4>> rows;               // RK 0: T, FX, FY, FZ
};

// F.7.b: a segment in the wind, its ellipsoid pushed where it crosses a plane.
struct WindCard {
  std::uint32_t line = 0;
  Ref segment;  // |MWSEG(1)|; negative: ATB's grid method
  bool grid = false;
  Ref ellipsoid;      // MWSEG(2)
  Ref plane_segment;  // MWSEG(3)
  Ref plane;          // MWSEG(4)
  Ref force;          // MWSEG(5): an E.6 function
  Ref drag;           // MWSEG(6): an E.6 table of the drag coefficient, 0: Cd = 1
};

// F.9.a to F.9.m (D.1.a NWATER): still water, its surface through OFFSET normal to the water
// frame's z (which points into the water), of specific weight WGAM, and the ellipsoids in it.
struct WaterCard {
  std::uint32_t line = 0;  // F.9.a
  Vec3 offset{}, frame{};
  double depth = 0, specific_weight = 0;
  struct Ellipsoid {
    std::uint32_t line = 0;  // F.9.f
    Ref ellipsoid, segment;
    double drag = 0;  // COED, or BCOED when 0
  };
  std::vector<Ellipsoid> ellipsoids;
};

struct InitialCard {
  std::uint32_t line = 0;
  int segment = 0;
  Vec3 position{}, velocity{};
  // G.2 IREF4: the vehicle (0-based, C card order) in whose axes `position` is given, from its
  // C.2.a position; -1: the inertial frame.
  int position_vehicle = -1;
  // G.1.a I1 = 15: how ATB's equilibrium solve moved `position` (equilibrium_solve.h).
  std::string equilibrium_note;
};

// G.3.a: a segment's yaw, pitch and roll (degrees) from the frame ID4 names, and its angular
// velocity in its own axes. A reference segment's turn from the ground; a jointed segment's
// decide its joint's initial angles (the mapper computes them).
struct OrientationCard {
  std::uint32_t line = 0;
  // `angles` are sled's z-y-x angles of the card's turn; `given` the card's yaw, pitch and roll,
  // turned in the axis order `order` (ID1 to ID3; ATB's default 1, 2, 3).
  Vec3 angles{}, angular_velocity{}, given{};
  std::array<int, 3> order{1, 2, 3};
  enum class Reference {
    kGround,     // ID4 0 or the ground's number
    kFrame,      // ID4 > 0: the axes of segment or vehicle `frame` (ATB numbering)
    kJointAxes,  // ID4 < 0: the proximal segment's joint axes (the joint's own angles)
  } reference = Reference::kGround;
  int frame = 0;
  SourceRange angles_where;     // columns 1-30
  SourceRange reference_where;  // columns 70-72
};

// H.1 to H.9: one time history. `frame` is KREF's frame when it names one; without it the
// default of the card: H.1 and H.4 in the segment's own axes, the relative ones (H.2, H.3, H.5,
// H.6) relative to the primary vehicle.
struct OutputCard {
  std::uint32_t line = 0;
  enum class Kind {
    kAcceleration,         // H.1: point total acceleration, in KREF's axes
    kVelocity,             // H.2: point velocity relative to KREF
    kPosition,             // H.3: point displacement relative to KREF
    kAngularAcceleration,  // H.4: in KREF's axes
    kAngularVelocity,      // H.5: relative to KREF
    kOrientation,          // H.6: relative to KREF
    kJointParameters,      // H.7: the joint's angles and torques
    kJointForce,           // H.9: joint force and torque
  } kind = Kind::kAcceleration;
  Ref segment;  // MSG: the segment (H.7 and H.9: the joint)
  Vec3 point{};
  Ref reference;  // KREF
  std::optional<DeckFrame> frame;
};

struct Deck {
  std::string date, title, subtitle;
  DeckUnits units;
  std::uint32_t units_line = 0;
  Vec3 gravity{};
  double g = 0;
  std::uint32_t control_line = 0;
  int steps = 0;
  double dt = 0, first_step = 0, max_step = 0, min_step = 0;
  // B.6: the smallest relative error its convergence tests give, sled's `tolerance`; 0: none.
  double tolerance = 0;
  std::vector<int> print_controls;
  std::string body_title;
  std::uint32_t body_line = 0;
  std::vector<SegmentCard> segments;
  std::vector<JointCard> joints;
  std::vector<VehicleCard> vehicles;  // the primary vehicle (MSEG = 0) last, as in the deck
  // C cards with MSEG a body segment (a reference segment): its motion prescribed by the card.
  // Not vehicle segments: they take no number among the vehicles (INPUT_VEHICLE).
  std::vector<VehicleCard> prescribed_segments;
  std::vector<PlaneCard> planes;
  std::vector<BeltCard> belts;
  std::vector<VehicleEllipsoidCard> vehicle_ellipsoids;
  std::vector<VehicleEllipsoidCard> extra_ellipsoids;
  std::uint32_t symmetry_line = 0;
  std::vector<Ref> symmetry;  // per segment
  std::vector<SpringCard> springs;
  std::vector<LoadCard> loads;          // D.9
  std::vector<ActuatorCard> actuators;  // F.10
  std::vector<ConstraintCard> constraints;
  std::vector<AirbagCard> airbags;
  std::vector<FunctionCard> functions;
  std::vector<ContactCard> contacts;
  std::vector<HarnessCard> harnesses;
  std::vector<WindFunctionCard> wind_functions;
  std::vector<WindCard> winds;
  std::optional<WaterCard> water;
  // G.1.a I3 = 0: the reference segments start with the primary vehicle's velocity (and its
  // angular velocity, zero for the motions sled converts); else the G cards give them.
  bool velocities_from_vehicle = true;
  std::uint32_t velocity_source_line = 0;
  std::vector<InitialCard> initial_positions;
  std::vector<OrientationCard> initial_orientations;  // per segment
  std::vector<OutputCard> outputs;
};

}  // namespace sled::lang::legacy
