#include "compiler/check/schema.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace sled::compiler {
namespace {

using V = ValueType;
namespace d = dim;
constexpr double kInf = std::numeric_limits<double>::infinity();

// Shorthands keep the table readable: one line per attribute.
AttributeSpec Quantity(std::string_view name, Dimension dimension, std::string_view doc,
                       bool required = false, double min = -kInf, double max = kInf,
                       bool min_exclusive = false) {
  return {name, V::kQuantity, dimension, required, min, max, min_exclusive, {}, {}, 0, false, doc};
}
AttributeSpec Positive(std::string_view name, Dimension dimension, std::string_view doc,
                       bool required = false) {
  return Quantity(name, dimension, doc, required, 0.0, kInf, true);
}
AttributeSpec NonNegative(std::string_view name, Dimension dimension, std::string_view doc,
                          bool required = false) {
  return Quantity(name, dimension, doc, required, 0.0, kInf, false);
}
AttributeSpec Fraction(std::string_view name, std::string_view doc) {
  return Quantity(name, d::kDimensionless, doc, false, 0.0, 1.0, false);
}
AttributeSpec Vector(std::string_view name, Dimension dimension, std::string_view doc,
                     bool required = false) {
  return {name, V::kVector, dimension, required, -kInf, kInf, false, {}, {}, 0, false, doc};
}
AttributeSpec Bool(std::string_view name, std::string_view doc) {
  return {name, V::kBool, {}, false, -kInf, kInf, false, {}, {}, 0, false, doc};
}
AttributeSpec Text(std::string_view name, std::string_view doc) {
  return {name, V::kString, {}, false, -kInf, kInf, false, {}, {}, 0, false, doc};
}
AttributeSpec Reference(std::string_view name, std::string_view kinds, std::string_view doc,
                        bool required = false) {
  return {name, V::kReference, {}, required, -kInf, kInf, false, kinds, {}, 0, false, doc};
}
AttributeSpec References(std::string_view name, std::string_view kinds, std::string_view doc,
                         bool required = false) {
  return {name, V::kReferences, {}, required, -kInf, kInf, false, kinds, {}, 0, false, doc};
}
AttributeSpec Function(std::string_view name, Dimension argument, Dimension result,
                       std::string_view doc, bool required = false) {
  return {name, V::kFunction, result, required, -kInf, kInf, false, {}, argument, 0, false, doc};
}
AttributeSpec Points(std::string_view name, Dimension dimension, int count, std::string_view doc) {
  return {name, V::kPoints, dimension, true, -kInf, kInf, false, {}, {}, count, false, doc};
}
AttributeSpec Typed(std::string_view name, ValueType type, std::string_view doc,
                    bool required = false) {
  return {name, type, {}, required, -kInf, kInf, false, {}, {}, 0, false, doc};
}
AttributeSpec Repeatable(AttributeSpec spec) {
  spec.repeatable = true;
  return spec;
}

// The position statements `at SEGMENT = (x, y, z) mm` and `axes SEGMENT = (yaw, pitch, roll)`
// name one of the two connected frames; they are listed as attributes with a target.
AttributeSpec AtFrame(std::string_view doc) { return Repeatable(Vector("at", d::kLength, doc)); }

std::vector<BlockSpec> MakeSpecs() {
  // Declarations allowed wherever scene content may appear.
  const std::vector<DeclarationSpec> scene_declarations = {
      {"body", BlockKind::kBody, "a body: segments connected by joints"},
      {"vehicle", BlockKind::kVehicle, "a vehicle or sled with prescribed motion"},
      {"plane", BlockKind::kPlane, "a finite contact plane fixed in a frame"},
      {"ellipsoid", BlockKind::kEllipsoid, "an extra contact ellipsoid fixed in a frame"},
      {"function", BlockKind::kTable, "a named function: constant, table or polynomial"},
      {"contact", BlockKind::kContact, "a contact between a segment and a surface"},
      {"belt", BlockKind::kBelt, "a belt anchored in a frame, wrapping segments"},
      {"harness", BlockKind::kHarness, "several belts that act together"},
      {"airbag", BlockKind::kAirbag, "an ellipsoidal airbag that deploys and vents"},
      {"spring", BlockKind::kSpring, "a spring-damper between two frames"},
      {"load", BlockKind::kLoad,
       "an applied force or torque, a function of time, on a segment or across a joint"},
      {"actuator", BlockKind::kActuator,
       "a PID torque that drives a pin joint's angle towards a target, a function of time"},
      {"wind", BlockKind::kWind,
       "air moving at a speed that is a function of time: drag on the segments' ellipsoids"},
      {"water", BlockKind::kWater,
       "still water below a level surface: buoyancy and drag on the segments' ellipsoids"},
      {"tension", BlockKind::kSpring, "a tension-only element between two frames"},
      {"constraint", BlockKind::kConstraint, "a fixed-point, fixed-distance or sliding constraint"},
      {"initial", BlockKind::kInitial, "initial position, orientation, velocity or joint angles"},
      {"override", BlockKind::kOverride,
       "changes the characteristics of a joint of an imported body"},
      {"output", BlockKind::kOutput, "the time histories and injury criteria to compute"},
      {"time", BlockKind::kTime, "start, end and output step of the run"},
      {"integrator", BlockKind::kIntegrator, "the integration method and its tolerances"},
      {"restart", BlockKind::kRestart, "checkpoints and resuming"},
      {"settle", BlockKind::kSettle, "equilibrium settling before the run"},
      {"symmetry", BlockKind::kSymmetry, "2-D (planar) or mirror symmetry"},
      {"import", BlockKind::kFile, "a module of the standard library or the scene's folder"},
      {"param", BlockKind::kFile, "a parameter: a named value `--set` can change"},
      {"let", BlockKind::kFile, "a named value computed from others"},
  };
  const std::vector<DeclarationSpec> module_declarations = {
      {"body", BlockKind::kBody, "a body: segments connected by joints"},
      {"function", BlockKind::kTable, "a named function: constant, table or polynomial"},
      {"plane", BlockKind::kPlane, "a finite contact plane, fixed in the frame the import gives"},
      {"ellipsoid", BlockKind::kEllipsoid,
       "a contact ellipsoid, fixed in the frame the import gives"},
      {"import", BlockKind::kFile, "another module"},
      {"param", BlockKind::kFile, "a parameter"},
      {"let", BlockKind::kFile, "a named value computed from others"},
  };
  const Dimension kSpecificLength = d::kDimensionless;  // strain

  std::vector<BlockSpec> specs;
  specs.push_back({BlockKind::kFile, {}, [&] {
                     auto declarations = module_declarations;
                     declarations.push_back({"scenario", BlockKind::kScenario,
                                             "the scene: everything one run simulates"});
                     return declarations;
                   }()});
  specs.push_back({BlockKind::kModule, {}, module_declarations});
  specs.push_back(
      {BlockKind::kScenario,
       {Vector("gravity", d::kAcceleration, "gravity in the ground frame; default (0, 0, -1) g")},
       scene_declarations});
  specs.push_back({BlockKind::kBody,
                   {Reference("reference", "segment",
                              "the reference segment; default: the root of the "
                              "joint tree"),
                    Vector("h_point", d::kLength,
                           "the H-point (hip-joint centre) in the reference segment's frame"),
                    Typed("dummy", V::kWord,
                          "the crash-test dummy the body stands for, as ISO-MME channel codes "
                          "name it: hybrid3_50m, hybrid3_5f, thor, thor_hybrid3_legs, es2, "
                          "es2re, sid2s or human")},
                   {{"segment", BlockKind::kSegment, "a rigid segment"},
                    {"joint", BlockKind::kJoint, "a joint: ball, pin, euler, slip or null"},
                    {"ellipsoid", BlockKind::kEllipsoid, "an extra contact ellipsoid on a segment"},
                    {"function", BlockKind::kTable, "a function local to the body"},
                    {"param", BlockKind::kFile, "a parameter"},
                    {"let", BlockKind::kFile, "a named value"}}});
  specs.push_back(
      {BlockKind::kSegment,
       {Quantity("mass", d::kMass, "segment mass", true),
        Vector("inertia", d::kInertia, "principal moments of inertia (Ix, Iy, Iz)"),
        Vector("principal_axes", d::kAngle,
               "yaw, pitch and roll of the principal axes in the segment frame"),
        Bool("singular", "a massless segment held by constraints (mass and inertia zero)")},
       {{"ellipsoid", BlockKind::kSegmentEllipsoid, "a contact ellipsoid of the segment"}}});
  const std::vector<AttributeSpec> ellipsoid_attributes = {
      Vector("semi_axes", d::kLength, "semi-axes (a, b, c)", true),
      Vector("center", d::kLength, "centre in the frame"),
      Vector("orientation", d::kAngle, "yaw, pitch and roll of the axes in the frame"),
      Quantity("degree", d::kDimensionless, "2 for an ellipsoid; above 2 a hyper-ellipsoid", false,
               2.0, 32.0)};
  specs.push_back({BlockKind::kSegmentEllipsoid, ellipsoid_attributes, {}});
  specs.push_back({BlockKind::kEllipsoid, ellipsoid_attributes, {}});
  // A joint's characteristics: what an `override` of an imported body's joint may change.
  const std::vector<AttributeSpec> joint_characteristics = {
      Function(
          "flexure", d::kAngle, d::kTorque,
          "flexure torque against flexure angle; a slip joint's force against its displacement"),
      Function("twist", d::kAngle, d::kTorque, "twist torque against twist angle"),
      Function("precession", d::kAngle, d::kTorque, "Euler joint: precession torque"),
      Function("nutation", d::kAngle, d::kTorque, "Euler joint: nutation torque"),
      Function("spin", d::kAngle, d::kTorque, "Euler joint: spin torque"),
      NonNegative("viscous", d::kRotationalDamping,
                  "viscous torque coefficient (a slip joint's: force per speed)"),
      NonNegative("coulomb", d::kTorque, "Coulomb friction torque (a slip joint's: force)"),
      Fraction("energy_loss", "fraction of energy dissipated in the joint spring"),
      Quantity(
          "stop", d::kAngle,
          "flexure angle of the joint stop (a slip joint's: its displacement, at most 3.1416 m)",
          false, 0.0, 3.1416, true),
      Quantity("twist_stop", d::kAngle, "twist angle of the joint stop", false, 0.0, 3.1416, true),
      Bool("stop_impulse", "an impulse (with restitution) when the joint hits its stop"),
      Fraction("restitution", "coefficient of restitution at the stop"),
      Typed("locked", V::kLock,
            "true, false, or the Euler axes locked at the start: precession, nutation, spin"),
      NonNegative("lock_below", d::kTorque, "the joint locks when its torque falls below"),
      NonNegative("unlock_above", d::kTorque, "a locked joint unlocks above this torque")};
  std::vector<AttributeSpec> joint_attributes = {
      AtFrame("joint location in one of the two segments: `at pelvis = (0, 0, 120) mm`"),
      Repeatable(Vector("axes", d::kAngle,
                        "yaw, pitch, roll of the joint axes in one segment: `axes pelvis = "
                        "(0, 0, 0) deg`")),
      Vector("axis", d::kDimensionless, "pin or slip axis in the parent segment")};
  joint_attributes.insert(joint_attributes.end(), joint_characteristics.begin(),
                          joint_characteristics.end());
  specs.push_back({BlockKind::kJoint, joint_attributes, {}});
  specs.push_back({BlockKind::kOverride, joint_characteristics, {}});
  specs.push_back({BlockKind::kVehicle,
                   {Typed("motion", V::kMotion, "prescribed motion: half_sine, trapezoid or table"),
                    Vector("position", d::kLength, "initial position in the ground frame"),
                    Vector("orientation", d::kAngle, "initial yaw, pitch and roll"),
                    Vector("velocity", d::kVelocity, "initial velocity")},
                   {}});
  specs.push_back({BlockKind::kPlane,
                   {Points("corners", d::kLength, 3,
                           "P1, P2, P3: the plane is the parallelogram P1 + s(P2-P1) + t(P3-P1); "
                           "the normal is (P2-P1) x (P3-P1)")},
                   {}});
  specs.push_back({BlockKind::kTable,
                   {Fraction("energy_loss", "fraction of energy dissipated on unloading"),
                    Fraction("permanent_set", "permanent deflection as a fraction of the largest"),
                    Positive("unload_slope", d::kDimensionless,
                             "slope of the unloading line relative to the loading slope"),
                    Typed("unloading", V::kUnloading,
                          "ATB's law: atb(energy_return = R, permanent_set = G), each a number "
                          "or a function of the largest deflection; spike = S, spike_end = D for "
                          "an inertial spike, origin = D0 for where the function starts")},
                   {}});
  specs.push_back(
      {BlockKind::kContact,
       {Function("force", d::kLength, d::kForce, "force against deflection", true),
        NonNegative("damping", d::kDamping, "damping against deflection rate"),
        Quantity("friction", d::kDimensionless, "Coulomb friction coefficient", false, 0.0, 5.0),
        Bool("impulse", "an impulse at first contact"),
        Fraction("restitution", "coefficient of restitution of the first-contact impulse"),
        Function("rate_scaled_force", d::kLength, d::kForce,
                 "ATB's F2: a force against deflection, times `rate_scale`"),
        Function("rate_scale", d::kVelocity, d::kDimensionless,
                 "ATB's F3: the factor of `rate_scaled_force` against deflection rate"),
        Function("rate_force", d::kVelocity, d::kForce,
                 "ATB's F4: a force against deflection rate")},
       {}});
  const std::vector<AttributeSpec> belt_attributes = {
      Typed("path", V::kBeltPath, "anchor -> segment -> ... -> anchor", true),
      Function("force", kSpecificLength, d::kForce, "webbing force against strain", true),
      NonNegative("slack", d::kLength, "slack taken up before the belt carries load"),
      NonNegative("pretension", d::kForce, "initial belt force"),
      Quantity("friction", d::kDimensionless, "friction between belt and body", false, 0.0, 5.0)};
  specs.push_back({BlockKind::kBelt, belt_attributes, {}});
  specs.push_back({BlockKind::kHarness,
                   {Quantity("friction", d::kDimensionless, "friction at the harness tie points",
                             false, 0.0, 5.0)},
                   {{"belt", BlockKind::kBelt, "a belt of the harness"}}});
  specs.push_back(
      {BlockKind::kAirbag,
       {Vector("position", d::kLength, "deployment point in the frame", true),
        Vector("orientation", d::kAngle, "yaw, pitch and roll of the bag axes"),
        Vector("semi_axes", d::kLength, "semi-axes of the fully deployed bag", true),
        NonNegative("deploy_at", d::kTime, "time the bag starts to fill", true),
        Function("inflow", d::kTime, d::kMassFlow,
                 "gas mass inflow against time since "
                 "deployment",
                 true),
        NonNegative("vent_area", d::kArea, "vent area"),
        Positive("ambient_pressure", d::kPressure, "ambient pressure; default 101325 Pa"),
        Positive("gas_temperature", d::kTemperature,
                 "temperature of the inflator's gas; default 300 K"),
        Quantity("gamma", d::kDimensionless,
                 "ratio of specific heats of the gas, above 1 and at most 5/3; default 1.4", false,
                 1.0, 5.0 / 3.0, true),
        Positive("gas_constant", d::kSpecificGasConstant,
                 "specific gas constant of the gas; default 287 J/kg/K (air)"),
        Quantity("discharge_coefficient", d::kDimensionless,
                 "discharge coefficient of the vent; default 0.6", false, 0.0, 1.0, true),
        References("contacts", "segment", "segments the bag can touch"),
        Typed("model", V::kWord,
              "`energy` (default): sled's energy-balance bag, fixed in its frame; `atb_free`: "
              "ATB's free bag, a polytropic gas, a square-root vent and a free body on a spring"),
        NonNegative("bag_mass", d::kMass, "mass of the bag's fabric (atb_free); default 0"),
        Positive("mass_factor", d::kDimensionless,
                 "the moving mass over the gas and fabric mass, ATB's CMASS (atb_free); default 1"),
        NonNegative("tether_stiffness", d::kStiffness,
                    "spring from the back pole to `position` (atb_free); default 0"),
        NonNegative("vent_opening_pressure", d::kPressure,
                    "gauge pressure above which the vent flows (atb_free); default 0")},
       {}});
  specs.push_back(
      {BlockKind::kSpring,
       {AtFrame("attachment point in one of the two frames"),
        Function("stiffness", d::kLength, d::kForce, "force against elongation", true),
        NonNegative("damping", d::kDamping, "damping against elongation rate"),
        NonNegative("free_length", d::kLength, "unloaded length; default: the initial distance")},
       {}});
  specs.push_back(
      {BlockKind::kLoad,
       {Function("force", d::kTime, d::kForce, "force against time, along `direction`"),
        Function("torque", d::kTime, d::kTorque, "torque against time, about `axis`"),
        Vector("direction", d::kDimensionless, "direction of the force (a segment load)"),
        Vector("axis", d::kDimensionless, "axis of the torque"),
        Vector("point", d::kLength,
               "where the force acts, in the segment; default its centre "
               "of mass"),
        Typed("frame", V::kWord,
              "`ground` (default): direction and axis fixed in the ground; `segment`: turning "
              "with the segment")},
       {}});
  specs.push_back(
      {BlockKind::kActuator,
       {Function("target", d::kTime, d::kAngle, "the target angle against time", true),
        Function("proportional", d::kAngle, d::kRotationalStiffness,
                 "torque per radian of angle error, against the target angle", true),
        Function("derivative", d::kAngle, d::kRotationalDamping,
                 "torque per rad/s of rate error, against the target angle; default none"),
        Function("integral", d::kAngle, d::kTorque / (d::kAngle * d::kTime),
                 "torque per rad*s of the error's integral, against the target angle; default "
                 "none")},
       {}});
  specs.push_back(
      {BlockKind::kWind,
       {Function("speed", d::kTime, d::kVelocity, "the air's speed against time"),
        Function("pressure", d::kTime, d::kPressure,
                 "instead of `speed`: a blast's pressure against time, whatever the body's "
                 "motion"),
        Vector("direction", d::kDimensionless,
               "where the air goes, in the axes of `carried_by` (the ground's by default)", true),
        Reference("carried_by", "ground vehicle segment",
                  "the frame the air is at rest in but for `speed` (a cabin's air moves with its "
                  "vehicle); default the ground"),
        Positive("density", d::kDensity, "density of the air; default 1.225 kg/m^3"),
        NonNegative("drag", d::kDimensionless, "drag coefficient of the ellipsoids; default 1"),
        References("segments", "segment", "the segments whose contact ellipsoids the wind pushes",
                   true)},
       {}});
  specs.push_back(
      {BlockKind::kWater,
       {Quantity("level", d::kLength,
                 "height of the surface above the ground origin, against gravity; default 0"),
        Positive("density", d::kDensity, "density of the water; default 1000 kg/m^3"),
        NonNegative("drag", d::kDimensionless, "drag coefficient of the ellipsoids; default 1"),
        References("segments", "segment", "the segments whose contact ellipsoids float or sink",
                   true)},
       {}});
  specs.push_back(
      {BlockKind::kConstraint,
       {AtFrame("constrained point in one of the two frames"),
        NonNegative("distance", d::kLength, "fixed distance; default: the initial distance"),
        Vector("axis", d::kDimensionless, "sliding direction in the second frame")},
       {}});
  specs.push_back({BlockKind::kInitial,
                   {Vector("position", d::kLength, "position of the reference segment or vehicle"),
                    Vector("h_point", d::kLength,
                           "a body: where its H-point is, instead of its reference segment"),
                    Vector("orientation", d::kAngle, "yaw, pitch and roll"),
                    Vector("velocity", d::kVelocity, "linear velocity"),
                    Vector("angular_velocity", d::kAngularVelocity, "angular velocity"),
                    Vector("angles", d::kAngle,
                           "joint angles: (precession, nutation, spin) or flexure, "
                           "twist")},
                   {}});
  specs.push_back({BlockKind::kOutput,
                   {Typed("criteria", V::kCriteria, "injury criteria: hic15(occupant.head), ..."),
                    Typed("filter_standard", V::kWord,
                          "filter coefficients: `sae_j211` (default) or `iso_6487`")},
                   {}});
  specs.push_back({BlockKind::kTime,
                   {Positive("end", d::kTime, "end time of the run", true),
                    Positive("output_every", d::kTime, "output step", true),
                    NonNegative("start", d::kTime, "start time; default 0")},
                   {}});
  specs.push_back(
      {BlockKind::kIntegrator,
       {Quantity("tolerance", d::kDimensionless, "relative error tolerance per step", false, 0.0,
                 0.1, true),
        Positive("abs_tolerance", d::kDimensionless, "absolute error tolerance (SI units)"),
        Positive("min_step", d::kTime, "smallest step before the run fails"),
        Positive("max_step", d::kTime, "largest step"),
        Positive("initial_step", d::kTime, "first step")},
       {}});
  specs.push_back({BlockKind::kRestart,
                   {Positive("checkpoint_every", d::kTime, "write a checkpoint this often"),
                    Text("resume_from", "a checkpoint file to continue from")},
                   {}});
  specs.push_back({BlockKind::kSettle,
                   {Positive("duration", d::kTime, "longest time to settle under gravity", true),
                    Positive("damping", d::kFrequency,
                             "mass-proportional damping rate while settling; default 10 1/s"),
                    Positive("velocity", d::kVelocity,
                             "settled when every centre of mass is slower; default 1 mm/s"),
                    Positive("angular_velocity", d::kAngularVelocity,
                             "and every segment turns slower; default 0.01 rad/s"),
                    Positive("force_change", d::kDimensionless,
                             "and no contact, belt or spring force changes by more than this "
                             "fraction of the largest in 10 ms; default 0.01")},
                   {}});
  specs.push_back({BlockKind::kSymmetry,
                   {Repeatable(Typed("pair", V::kPair, "two segments mirrored in the xz plane"))},
                   {}});
  return specs;
}

}  // namespace

std::string_view BlockName(BlockKind kind) {
  switch (kind) {
    case BlockKind::kFile:
      return "file";
    case BlockKind::kScenario:
      return "scenario";
    case BlockKind::kModule:
      return "module";
    case BlockKind::kBody:
      return "body";
    case BlockKind::kSegment:
      return "segment";
    case BlockKind::kSegmentEllipsoid:
      return "segment ellipsoid";
    case BlockKind::kJoint:
      return "joint";
    case BlockKind::kVehicle:
      return "vehicle";
    case BlockKind::kPlane:
      return "plane";
    case BlockKind::kEllipsoid:
      return "ellipsoid";
    case BlockKind::kTable:
      return "function";
    case BlockKind::kContact:
      return "contact";
    case BlockKind::kBelt:
      return "belt";
    case BlockKind::kHarness:
      return "harness";
    case BlockKind::kAirbag:
      return "airbag";
    case BlockKind::kSpring:
      return "spring";
    case BlockKind::kConstraint:
      return "constraint";
    case BlockKind::kLoad:
      return "load";
    case BlockKind::kActuator:
      return "actuator";
    case BlockKind::kInitial:
      return "initial";
    case BlockKind::kOutput:
      return "output";
    case BlockKind::kTime:
      return "time";
    case BlockKind::kIntegrator:
      return "integrator";
    case BlockKind::kRestart:
      return "restart";
    case BlockKind::kSettle:
      return "settle";
    case BlockKind::kWind:
      return "wind";
    case BlockKind::kWater:
      return "water";
    case BlockKind::kOverride:
      return "override";
    case BlockKind::kSymmetry:
      return "symmetry";
  }
  return "block";
}

const std::vector<BlockSpec>& AllBlockSpecs() {
  static const std::vector<BlockSpec> kSpecs = MakeSpecs();
  return kSpecs;
}

const BlockSpec& SpecOf(BlockKind kind) {
  for (const BlockSpec& spec : AllBlockSpecs()) {
    if (spec.kind == kind) return spec;
  }
  throw std::logic_error("compiler::SpecOf: no schema for block kind");
}

const AttributeSpec* FindAttribute(BlockKind kind, std::string_view name) {
  for (const AttributeSpec& attribute : SpecOf(kind).attributes) {
    if (attribute.name == name) return &attribute;
  }
  return nullptr;
}

const DeclarationSpec* FindDeclaration(BlockKind kind, std::string_view keyword) {
  for (const DeclarationSpec& declaration : SpecOf(kind).declarations) {
    if (declaration.keyword == keyword) return &declaration;
  }
  return nullptr;
}

std::vector<std::string> KeywordsOf(BlockKind kind) {
  std::vector<std::string> words;
  for (const AttributeSpec& attribute : SpecOf(kind).attributes) {
    words.emplace_back(attribute.name);
  }
  for (const DeclarationSpec& declaration : SpecOf(kind).declarations) {
    words.emplace_back(declaration.keyword);
  }
  if (kind == BlockKind::kOutput) {
    for (const OutputSpec& output : AllOutputSpecs()) words.emplace_back(output.keyword);
  }
  return words;
}

std::vector<BlockKind> BlocksAllowing(std::string_view keyword) {
  std::vector<BlockKind> kinds;
  for (const BlockSpec& spec : AllBlockSpecs()) {
    const bool has = FindAttribute(spec.kind, keyword) || FindDeclaration(spec.kind, keyword) ||
                     (spec.kind == BlockKind::kOutput && FindOutput(keyword));
    if (has) kinds.push_back(spec.kind);
  }
  return kinds;
}

const std::vector<OutputSpec>& AllOutputSpecs() {
  static const std::vector<OutputSpec> kOutputs = {
      {"acceleration", "segment", true, "linear acceleration of a point on a segment"},
      {"velocity", "segment", true, "linear velocity of a point on a segment"},
      {"position", "segment", true, "position of a point on a segment"},
      {"angular_acceleration", "segment", false, "angular acceleration of a segment"},
      {"angular_velocity", "segment", false, "angular velocity of a segment"},
      {"orientation", "segment", false, "yaw, pitch and roll of a segment"},
      {"joint_angle", "joint", false, "joint angles"},
      {"joint_torque", "joint", false, "joint torques"},
      {"joint_force", "joint", false, "joint constraint force"},
      {"contact_force", "contact", false, "contact force of `A with B`"},
      {"belt_force", "belt", false, "belt force"},
      {"airbag_pressure", "airbag", false, "airbag gauge pressure"},
      {"spring_force", "spring", false, "spring-damper or tension element force"},
      {"airbag_volume", "airbag", false, "volume of the airbag's gas"},
      {"airbag_gas_mass", "airbag", false, "mass of gas in the airbag"},
      {"airbag_temperature", "airbag", false, "temperature of the airbag's gas"},
      {"airbag_vent_flow", "airbag", false, "mass flow out of the airbag's vent"},
      {"airbag_force", "airbag", false, "force of the airbag on each segment it touches"},
  };
  return kOutputs;
}

const OutputSpec* FindOutput(std::string_view keyword) {
  for (const OutputSpec& output : AllOutputSpecs()) {
    if (output.keyword == keyword) return &output;
  }
  return nullptr;
}

const std::vector<CriterionSpec>& AllCriterionSpecs() {
  static const std::vector<CriterionSpec> kCriteria = {
      {"hic15", "segment", "Head Injury Criterion over 15 ms windows"},
      {"hic36", "segment", "Head Injury Criterion over 36 ms windows"},
      {"head_3ms", "segment", "head resultant acceleration exceeded for 3 ms"},
      {"chest_3ms", "segment", "chest resultant acceleration exceeded for 3 ms"},
      {"gsi_head", "segment", "Gadd Severity Index of the head (ATB HSI)"},
      {"gsi_chest", "segment", "Gadd Severity Index of the chest (ATB CSI)"},
      {"nij", "joint", "neck injury criterion from the upper neck joint"},
      {"neck_tension", "joint", "peak neck tension"},
      {"neck_compression", "joint", "peak neck compression"},
      {"femur_load", "joint", "peak axial femur load"},
      {"viscous_criterion", "segment", "Viscous Criterion of the chest"},
      {"nkm", "joint", "neck injury criterion of rear impacts, from the upper neck joint"},
      {"nic", "segment", "Neck Injury Criterion of rear impacts (the head, and T1 at a joint)",
       "t1", "joint"},
      {"tti", "segment", "Thoracic Trauma Index of side impacts (a rib, and the lower spine)",
       "spine", "segment"},
      {"tibia_index", "joint", "Tibia Index from a tibia's load cell"},
  };
  return kCriteria;
}

const CriterionSpec* FindCriterion(std::string_view name) {
  for (const CriterionSpec& criterion : AllCriterionSpecs()) {
    if (criterion.name == name) return &criterion;
  }
  return nullptr;
}

const std::vector<QuantityName>& AllQuantityNames() {
  static const std::vector<QuantityName> kNames = {
      {"deflection", d::kLength},
      {"elongation", d::kLength},
      {"length", d::kLength},
      {"distance", d::kLength},
      {"position", d::kLength},
      {"strain", d::kDimensionless},
      {"ratio", d::kDimensionless},
      {"force", d::kForce},
      {"torque", d::kTorque},
      {"angle", d::kAngle},
      {"rotational_stiffness", d::kRotationalStiffness},
      {"rotational_damping", d::kRotationalDamping},
      {"integral_gain", d::kTorque / (d::kAngle * d::kTime)},
      {"time", d::kTime},
      {"velocity", d::kVelocity},
      {"acceleration", d::kAcceleration},
      {"angular_velocity", d::kAngularVelocity},
      {"angular_acceleration", d::kAngularAcceleration},
      {"mass_flow", d::kMassFlow},
      {"pressure", d::kPressure},
      {"volume", d::kVolume},
      {"area", d::kArea},
      {"mass", d::kMass},
  };
  return kNames;
}

const QuantityName* FindQuantityName(std::string_view name) {
  for (const QuantityName& quantity : AllQuantityNames()) {
    if (quantity.name == name) return &quantity;
  }
  return nullptr;
}

}  // namespace sled::compiler
