// The mapping from a read deck to the scenario AST (deck_mapper.h): the run settings, the body,
// the vehicles, the functions and the initial conditions; DeckToAst.
#include "lang/legacy/deck_mapper.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "lang/ast/make_expr.h"
#include "lang/legacy/ast_pieces.h"
#include "lang/legacy/convert.h"
#include "lang/legacy/rotations.h"

namespace sled::lang::legacy::mapping {
namespace {

// The unit of coefficient k >= 1 of a polynomial from `argument` (a unit such as in, or in/s)
// to `result` (empty: a ratio), with every divisor after the `/`: lbf/in^2, in^-1 (a ratio per
// inch), lbf*s^2/in^2 (a force per (in/s)^2), s/in (a ratio per in/s).
std::string CoefficientUnit(const std::string& result, const std::string& argument, std::size_t k) {
  const auto slash = argument.find('/');
  const std::string top = argument.substr(0, slash);
  const std::string bottom = slash == std::string::npos ? "" : argument.substr(slash + 1);
  const std::string power = k > 1 ? fmt::format("^{}", k) : "";
  std::string numerator = result;
  if (!bottom.empty()) numerator += (numerator.empty() ? "" : "*") + bottom + power;
  if (numerator.empty()) return fmt::format("{}^-{}", top, k);
  return numerator + "/" + top + power;
}

// C.2.a's VIPS is in miles per hour whatever A.3's units (the V.3 input description; ATB's
// VINO12 turns it into the deck's length over time), so it keeps that unit in the scenario.
constexpr std::string_view kVipsUnit = "mph";

// C.2.a: the vehicle's initial velocity in kVipsUnit, VIPS along its own x axis (yaw, then
// pitch; the roll turns about x itself), the axis its half-sine pulse brings to rest.
Vec3 VehicleVelocity(const VehicleCard& vehicle) {
  const Vec3 x = TurnedX(vehicle.orientation[0], vehicle.orientation[1]);
  return {vehicle.speed * x[0], vehicle.speed * x[1], vehicle.speed * x[2]};
}

// `v` turned by yaw, pitch and roll in degrees (about z, then y, then x: the rotation of sled's
// `orientation`, and the one VehicleVelocity turns x by), from a frame's axes to the ground's.
Vec3 Turned(const Vec3& ypr, const Vec3& v) {
  const double cy = CosDegrees(ypr[0]), sy = SinDegrees(ypr[0]);
  const double cp = CosDegrees(ypr[1]), sp = SinDegrees(ypr[1]);
  const double cr = CosDegrees(ypr[2]), sr = SinDegrees(ypr[2]);
  const double r[3][3] = {{cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr},
                          {sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr},
                          {-sp, cp * sr, cp * cr}};
  Vec3 out{};
  for (std::size_t i = 0; i < 3; ++i) out[i] = r[i][0] * v[0] + r[i][1] * v[1] + r[i][2] * v[2];
  return out;
}

// A point given in a vehicle's axes (G.2 IREF4), in the ground frame at the start: the
// vehicle's C.2.a position plus the point turned by its orientation, which is ATB's
// LIN_DISP(ref) + DIR_COS(ref) applied to the point (INPUT_LINEAR).
Vec3 VehicleToGround(const VehicleCard& vehicle, const Vec3& p) {
  const Vec3 turned = Turned(vehicle.orientation, p);
  return {vehicle.position[0] + turned[0], vehicle.position[1] + turned[1],
          vehicle.position[2] + turned[2]};
}

}  // namespace

ast::File DeckMapper::Map() {
  NameEverything();
  ast::Statement scenario =
      Declaration("scenario", String(deck_.title.empty() ? "converted deck" : deck_.title));
  scenario.leading_comments.push_back(
      {fmt::format(" Converted by `sled convert` from an ATB deck{}.",
                   deck_.date.empty() ? "" : " dated " + deck_.date),
       {},
       false});
  if (!deck_.subtitle.empty())
    scenario.leading_comments.push_back({" " + deck_.subtitle, {}, false});
  ast::Block& body = *scenario.block;

  ast::Statement g = Attribute("let", Number(deck_.g, L + "/" + T + "^2"));
  g.keyword = "let";
  g.target = Path("deck_g");
  g.leading_comments.push_back(
      {" " + CardComment("A.3", deck_.units_line) + ": weights are divided by G", {}, false});
  body.statements.push_back(std::move(g));
  body.statements.push_back(Attribute("gravity", Vector(deck_.gravity, L + "/" + T + "^2")));
  MapRunSettings(body);
  MapBody(body);
  MapVehicles(body);
  MapSurfaces(body);
  MapRestraints(body);
  MapLoads(body);
  MapActuators(body);
  MapWind(body);
  MapWater(body);
  MapFunctions(body);
  MapInitial(body);
  MapOutputs(body);

  ast::File file;
  file.body.statements.push_back(std::move(scenario));
  return file;
}

void DeckMapper::Report(DiagnosticKind kind, const Ref& ref, std::string message,
                        std::string help) {
  Diagnostic diagnostic = MakeDiagnostic(kind, ref.where, std::move(message));
  diagnostic.help = std::move(help);
  diagnostic.show_column_range = true;
  diagnostics_.Consume(std::move(diagnostic));
}

void DeckMapper::NameEverything() {
  body_ = NameOf(deck_.body_title, "body", taken_);
  for (const SegmentCard& segment : deck_.segments) {
    segments_.push_back(NameOf(segment.name, "segment", body_names_));
  }
  for (const JointCard& joint : deck_.joints) {
    joints_.push_back(NameOf(joint.name, "joint", body_names_));
  }
  for (const VehicleCard& vehicle : deck_.vehicles) {
    const std::string title = vehicle.title.substr(0, vehicle.title.find_first_of(" ,;:"));
    vehicles_.push_back(NameOf(title, "vehicle", taken_, "vehicle"));
  }
  for (const VehicleCard& prescribed : deck_.prescribed_segments) {
    const std::string title = prescribed.title.substr(0, prescribed.title.find_first_of(" ,;:"));
    prescribed_vehicles_.push_back(NameOf(title, "vehicle", taken_, "vehicle"));
  }
  for (const PlaneCard& plane : deck_.planes)
    planes_.push_back(NameOf(plane.title, "plane", taken_, "plane"));
  for (const BeltCard& belt : deck_.belts) {
    belts_.push_back(NameOf(belt.title, "belt", taken_, "belt"));
  }
}

// A segment of the body by deck number, or empty after reporting a bad number.
std::string DeckMapper::Segment(const Ref& ref, std::string_view what) {
  if (ref.number < 1 || ref.number > static_cast<int>(segments_.size())) {
    Report(DiagnosticKind::kDeckCountOutOfRange, ref,
           fmt::format("card {}: {} {} does not exist", ref.card, what, ref.number),
           fmt::format("segments are numbered 1 to {}", segments_.size()));
    return {};
  }
  return body_ + "." + segments_[static_cast<std::size_t>(ref.number - 1)];
}

// A joint of the body by deck number (B.3 order), or empty after reporting a bad number.
std::string DeckMapper::Joint(const Ref& ref) {
  if (ref.number < 1 || ref.number > static_cast<int>(joints_.size())) {
    Report(DiagnosticKind::kDeckCountOutOfRange, ref,
           fmt::format("card {}: joint {} does not exist", ref.card, ref.number),
           fmt::format("joints are numbered 1 to {}", joints_.size()));
    return {};
  }
  return body_ + "." + joints_[static_cast<std::size_t>(ref.number - 1)];
}

const FunctionCard* DeckMapper::Function(const Ref& ref) {
  for (const FunctionCard& function : deck_.functions) {
    if (function.number == ref.number) return &function;
  }
  Report(DiagnosticKind::kDeckUndefinedFunction, ref,
         fmt::format("card {}: function {} is not defined", ref.card, ref.number),
         "define it with E.1 and E.2 cards, or correct the number");
  return nullptr;
}

// The name under which a function is declared for one kind of use (its units depend on it).
std::optional<ast::Expr> DeckMapper::FunctionFor(const Ref& ref, Use use,
                                                 const UnloadingRefs& factors) {
  const FunctionCard* function = Function(ref);
  if (function == nullptr) return std::nullopt;
  auto unloading = Unloading(factors, use);
  if (!unloading || !CheckFunctionFields(*function, ref, use, *unloading)) return std::nullopt;
  auto key = std::make_tuple(function->number, static_cast<int>(use), unloading->atb, unloading->r,
                             unloading->g, unloading->spike);
  auto found = function_names_.find(key);
  if (found == function_names_.end()) {
    const bool load = use == Use::kLoadForce || use == Use::kLoadTorque;
    // An applied load's function may take either sign: it pushes against its direction.
    if (!load) CheckSign(*function, ref, use);
    const bool actuator = use >= Use::kActuatorTarget;
    const bool factor = !load && !actuator && use != Use::kContact && use != Use::kBelt &&
                        use != Use::kJoint && use != Use::kSlip;
    std::string name =
        NameOf(function->title, fmt::format("function_{}", function->number), taken_,
               actuator ? (use == Use::kActuatorTarget ? "target" : "gain")
               : factor ? "factor"
               : use == Use::kContact || use == Use::kSlip || use == Use::kLoadForce ? "force"
               : use == Use::kJoint || use == Use::kLoadTorque                       ? "torque"
                                                                                     : "webbing");
    found = function_names_.emplace(key, name).first;
    uses_.push_back({function, use, name, *unloading});
  }
  return Path(found->second);
}

// Where a function first pushes the wrong way for its use, as `sled check` judges a law (E0420):
// a contact's or a belt's force is positive for every positive deflection or strain, a joint's
// torque has the sign of its angle. Constants and tables by their values, a polynomial near zero
// by its lowest non-zero coefficient.
void DeckMapper::CheckSign(const FunctionCard& function, const Ref& ref, Use use) {
  // An R or G factor is a ratio ATB evaluates as given, of no direction, and the functions of
  // ATB's rate-dependent force may have either sign.
  if (use != Use::kContact && use != Use::kBelt && use != Use::kJoint && use != Use::kSlip) return;
  const bool both_ways = use == Use::kJoint || use == Use::kSlip;
  std::string wrong;
  switch (function.form) {
    case FunctionCard::Form::kConstant:
      if (function.constant < 0) wrong = fmt::format("its constant D2 is {}", function.constant);
      break;
    case FunctionCard::Form::kPolynomial:
      for (const double c : function.coefficients) {
        if (c == 0) continue;
        if (c < 0) wrong = fmt::format("its lowest non-zero E.3 coefficient is {}", c);
        break;
      }
      break;
    case FunctionCard::Form::kTable:
      for (const auto& [x, f] : function.points) {
        if ((x > 0 && f < 0) || (both_ways && x < 0 && f > 0)) {
          wrong = fmt::format("its E.4.b table gives {} at {}", f, x);
          break;
        }
      }
      break;
  }
  if (wrong.empty()) return;
  const char* law =
      use == Use::kJoint  ? "a joint's torque, which has the sign of the angle"
      : use == Use::kSlip ? "a slip joint's force, which has the sign of the displacement"
      : use == Use::kBelt ? "a belt's force, which is positive for every positive strain"
                          : "a contact's force, which is positive for every positive deflection";
  Diagnostic diagnostic = MakeDiagnostic(
      DiagnosticKind::kDeckInvalidValue, function.where,
      fmt::format("function {} (E.1, line {}) pushes the wrong way: {}; card {} uses it as {}",
                  function.number, function.line, wrong, ref.card, law));
  diagnostic.help = "give the function's values with a positive sign for a positive argument";
  diagnostic.show_column_range = true;
  diagnostics_.Consume(std::move(diagnostic));
}

// A friction coefficient from a constant function; zero for no function.
std::optional<double> DeckMapper::Friction(const Ref& ref) {
  if (ref.number == 0) return 0.0;
  const FunctionCard* function = Function(ref);
  if (function == nullptr) return std::nullopt;
  used_.insert(function->number);
  if (function->form != FunctionCard::Form::kConstant) {
    Report(DiagnosticKind::kDeckNotExpressible, ref,
           fmt::format("card {}: friction function {} is not a constant", ref.card, ref.number),
           "sled's `friction` is one coefficient; use a constant function (D1 = 0)");
    return std::nullopt;
  }
  if (function->constant < 0 || function->constant > kMaxFriction) {
    Report(function->constant < 0 ? DiagnosticKind::kDeckInvalidValue
                                  : DiagnosticKind::kDeckNotExpressible,
           ref,
           fmt::format("card {}: friction function {} is {} (E.2 D2, line {})", ref.card,
                       ref.number, function->constant, function->line),
           fmt::format("a friction coefficient is from 0 to {} in sled", kMaxFriction));
    return std::nullopt;
  }
  return function->constant;
}

void DeckMapper::MapRunSettings(ast::Block& body) {
  ast::Statement time = Declaration(
      "time", Path("x"), CardComment("A.4", deck_.control_line) + ": NSTEPS output steps of DT");
  time.target.reset();
  Add(time, Attribute("end", ast::MakeBinary('*', Number(deck_.steps), Number(deck_.dt, T))));
  Add(time, Attribute("output_every", Number(deck_.dt, T)));
  body.statements.push_back(std::move(time));
  ast::Statement integrator = Declaration("integrator", Path("auto"));
  if (deck_.first_step > 0) Add(integrator, Attribute("initial_step", Number(deck_.first_step, T)));
  if (deck_.max_step > 0) Add(integrator, Attribute("max_step", Number(deck_.max_step, T)));
  if (deck_.min_step > 0) Add(integrator, Attribute("min_step", Number(deck_.min_step, T)));
  if (deck_.tolerance > 0) {
    Add(integrator, Attribute("tolerance", Number(deck_.tolerance)));
    integrator.block->statements.back().leading_comments.push_back(
        {" cards B.6: the smallest relative error of the convergence tests", {}, false});
  }
  body.statements.push_back(std::move(integrator));
}

// A B.4 spring's linear, quadratic and cubic terms as a polynomial of the joint's coordinate.
ast::Expr DeckMapper::SpringPolynomial(const JointSpring& spring, const std::string& value_unit,
                                       const std::string& argument_unit) {
  std::vector<std::pair<std::string, ast::Expr>> coefficients;
  coefficients.emplace_back("", Number(0));
  coefficients.emplace_back("", Number(spring.linear, value_unit + "/" + argument_unit));
  if (spring.quadratic != 0 || spring.cubic != 0) {
    coefficients.emplace_back("",
                              Number(spring.quadratic, value_unit + "/" + argument_unit + "^2"));
  }
  if (spring.cubic != 0) {
    coefficients.emplace_back("", Number(spring.cubic, value_unit + "/" + argument_unit + "^3"));
  }
  return Call("polynomial", std::move(coefficients));
}

bool DeckMapper::HasSpring(const JointSpring& spring) const {
  return spring.function.number != 0 || spring.linear != 0 || spring.quadratic != 0 ||
         spring.cubic != 0;
}

void DeckMapper::AddSpring(ast::Statement& joint, const char* attribute, const JointSpring& spring,
                           bool slip) {
  if (spring.function.number != 0) {
    if (auto function = FunctionFor(spring.function, slip ? Use::kSlip : Use::kJoint)) {
      Add(joint, Attribute(attribute, std::move(*function)));
    }
  } else if (HasSpring(spring)) {
    ast::Statement polynomial =
        Attribute(attribute, slip ? SpringPolynomial(spring, F, L)
                                  : SpringPolynomial(spring, F + "*" + L, "deg"));
    // Each B.4 spring has its own energy-dissipation coefficient: the function's own
    // `energy_loss`, so a spring with none does not take another's as the joint's would give it.
    if (spring.energy_loss != 0) {
      polynomial.block = std::make_unique<ast::Block>();
      Add(polynomial, Attribute("energy_loss", Number(spring.energy_loss)));
    }
    Add(joint, std::move(polynomial));
  }
}

void DeckMapper::MapBody(ast::Block& scenario) {
  ast::Statement body =
      Declaration("body", Path(body_),
                  CardComment("B.1", deck_.body_line) + fmt::format(": {}", deck_.body_title));
  for (std::size_t i = 0; i < deck_.segments.size(); ++i) {
    const SegmentCard& card = deck_.segments[i];
    ast::Statement segment =
        Declaration("segment", Path(segments_[i]), CardComment("B.2.a", card.line));
    if (card.weight == 0) {
      Add(segment, Attribute("mass", Number(0, "kg")));
      Add(segment, Attribute("singular", Boolean(true)));
    } else {
      Add(segment, Attribute("mass", ast::MakeBinary('/', Number(card.weight, F), Path("deck_g"))));
      Add(segment, Attribute("inertia", Vector(card.inertia, F + "*" + T + "^2*" + L)));
    }
    if (card.has_principal_axes)
      Add(segment, Attribute("principal_axes", Vector(card.principal_axes, "deg")));
    if (!IsZero(card.semi_axes)) {
      ast::Statement ellipsoid =
          Declaration("ellipsoid", Path("x"),
                      card.ellipsoid_line ? CardComment("D.5", card.ellipsoid_line) : "");
      ellipsoid.target.reset();
      Add(ellipsoid, Attribute("semi_axes", Vector(card.semi_axes, L)));
      if (!IsZero(card.center)) Add(ellipsoid, Attribute("center", Vector(card.center, L)));
      if (!IsZero(card.ellipsoid_orientation))
        Add(ellipsoid, Attribute("orientation", Vector(card.ellipsoid_orientation, "deg")));
      if (card.degree != 2) Add(ellipsoid, Attribute("degree", Number(card.degree)));
      Add(segment, std::move(ellipsoid));
    }
    body.block->statements.push_back(std::move(segment));
  }
  for (std::size_t j = 0; j < deck_.joints.size(); ++j) {
    const JointCard& card = deck_.joints[j];
    const std::string& child = segments_[j + 1];
    const bool null = card.parent == 0;
    const std::string& parent = segments_[null ? 0 : static_cast<std::size_t>(card.parent - 1)];
    static constexpr const char* kTypes[] = {"ball", "pin", "euler", "slip"};
    const char* type = null ? "null" : kTypes[static_cast<int>(card.type)];
    ast::Statement joint = Declaration("joint", Path(joints_[j]), CardComment("B.3.a", card.line));
    std::vector<ast::Expr> chain;
    chain.push_back(Path(parent));
    chain.push_back(Path(child));
    joint.clauses.push_back({":", {}, Call(type, {{"", ast::MakeArrow(std::move(chain))}})});
    if (null) {
      joint.block.reset();
      body.block->statements.push_back(std::move(joint));
      continue;
    }
    ast::Statement at_parent = Attribute("at", Vector(card.at_parent, L));
    at_parent.target = Path(parent);
    ast::Statement at_child = Attribute("at", Vector(card.at_child, L));
    at_child.target = Path(child);
    Add(joint, std::move(at_parent));
    Add(joint, std::move(at_child));
    if (!IsZero(card.axes_parent)) {
      ast::Statement axes = Attribute("axes", Vector(card.axes_parent, "deg"));
      axes.target = Path(parent);
      Add(joint, std::move(axes));
    }
    if (!IsZero(card.axes_child)) {
      ast::Statement axes = Attribute("axes", Vector(card.axes_child, "deg"));
      axes.target = Path(child);
      Add(joint, std::move(axes));
    }
    if (card.type == JointType::kPin) {
      // ATB's pin turns about HB, the y axis of its joint axes in the proximal segment.
      const Mat axes = YawPitchRoll(card.axes_parent);
      Add(joint, Attribute("axis", Vector({axes[0][1], axes[1][1], axes[2][1]}, "")));
    }
    // A slip joint's coordinate is a length: its spring, stop, damping and friction are a force
    // against its displacement, read in the deck's force and length units.
    const bool slip = card.type == JointType::kSlip;
    const std::string coordinate_unit = slip ? L : std::string("deg");
    if (card.type == JointType::kEuler) {
      AddSpring(joint, "precession", card.flexure);
      AddSpring(joint, "nutation", card.twist);
      AddSpring(joint, "spin", card.spin);
    } else {
      AddSpring(joint, "flexure", card.flexure, slip);
      if (card.type == JointType::kBall) AddSpring(joint, "twist", card.twist);
    }
    if (card.flexure.stop != 0)
      Add(joint, Attribute("stop", Number(card.flexure.stop, coordinate_unit)));
    if (card.type == JointType::kBall && card.twist.stop != 0)
      Add(joint, Attribute("twist_stop", Number(card.twist.stop, "deg")));
    if (card.viscous != 0)
      Add(joint, Attribute("viscous", Number(card.viscous, (slip ? F : F + "*" + L) + "*" + T +
                                                               "/" + coordinate_unit)));
    if (card.coulomb != 0)
      Add(joint, Attribute("coulomb", Number(card.coulomb, slip ? F : F + "*" + L)));
    if (card.restitution != 0) Add(joint, Attribute("restitution", Number(card.restitution)));
    if (card.locked) Add(joint, Attribute("locked", Boolean(true)));
    // A slip joint's lock levels are forces, a pin's torques.
    const std::string level_unit = slip ? F : F + "*" + L;
    if (card.lock_below != 0)
      Add(joint, Attribute("lock_below", Number(card.lock_below, level_unit)));
    if (card.unlock_above != 0)
      Add(joint, Attribute("unlock_above", Number(card.unlock_above, level_unit)));
    body.block->statements.push_back(std::move(joint));
  }
  scenario.statements.push_back(std::move(body));
}

void DeckMapper::MapVehicles(ast::Block& scenario) {
  for (std::size_t v = 0; v < deck_.vehicles.size(); ++v) {
    scenario.statements.push_back(VehicleStatement(deck_.vehicles[v], vehicles_[v]));
  }
  MapPrescribedSegments(scenario);
}

// `vehicle NAME { position  orientation  velocity  motion }` of a C card.
ast::Statement DeckMapper::VehicleStatement(const VehicleCard& card, const std::string& name) {
  ast::Statement vehicle =
      Declaration("vehicle", Path(name),
                  CardComment("C.2.a", card.line) + (card.title.empty() ? "" : ": " + card.title));
  if (!IsZero(card.position)) Add(vehicle, Attribute("position", Vector(card.position, L)));
  if (!IsZero(card.orientation))
    Add(vehicle, Attribute("orientation", Vector(card.orientation, "deg")));
  if (card.speed != 0) {
    Add(vehicle, Attribute("velocity", Vector(VehicleVelocity(card), kVipsUnit)));
    Add(vehicle, Attribute("motion", Call("half_sine", {{"delta_v", Number(card.speed, kVipsUnit)},
                                                        {"duration", Number(card.duration, T)},
                                                        {"axis", ast::MakeNegation(Path("x"))}})));
  }
  return vehicle;
}

void DeckMapper::MapFunctions(ast::Block& scenario) {
  // Declared after their uses were seen, in the order of the E cards.
  std::vector<ast::Statement> statements;
  for (const FunctionCard& function : deck_.functions) {
    bool used = used_.count(function.number) != 0;
    for (const FunctionUse& use : uses_) {
      if (use.function != &function) continue;
      used = true;
      statements.push_back(FunctionStatement(function, use.use, use.name, use.unloading));
    }
    if (!used) {
      Report(DiagnosticKind::kDeckUnusedFunction, Ref{function.number, function.where, "E.1"},
             fmt::format("card E.1: function {} (`{}`) is used by no card and is left out",
                         function.number, function.title),
             "without a use its units are unknown; declare it by hand if you need it");
    }
  }
  for (auto& statement : statements) scenario.statements.push_back(std::move(statement));
}

namespace {

// An F.10 function's signature in the deck's units: the target angle (degrees, JNTFNC) against
// time, or a gain against the target angle, and whether its values change sign.
struct ActuatorSignature {
  std::string argument_unit, result_unit;
  const char* argument;
  const char* result;
  double sign;
};

ActuatorSignature ActuatorSignatureOf(DeckMapper::Use use, const std::string& force,
                                      const std::string& length, const std::string& time_unit) {
  using Use = DeckMapper::Use;
  const std::string torque = force + "*" + length;
  const double sign = use >= Use::kActuatorProportionalNegated ? -1.0 : 1.0;
  switch (use) {
    case Use::kActuatorTarget:
      return {time_unit, "deg", "time", "angle", 1.0};
    case Use::kActuatorProportional:
    case Use::kActuatorProportionalNegated:
      return {"deg", torque + "/deg", "angle", "rotational_stiffness", sign};
    case Use::kActuatorDerivative:
    case Use::kActuatorDerivativeNegated:
      return {"deg", torque + "*" + time_unit + "/deg", "angle", "rotational_damping", sign};
    default:
      return {"deg", torque + "/deg/" + time_unit, "angle", "integral_gain", sign};
  }
}

}  // namespace

ast::Statement DeckMapper::FunctionStatement(const FunctionCard& function, Use use,
                                             const std::string& name,
                                             const FunctionUnloading& unloading) {
  if (use >= Use::kActuatorTarget) {
    const ActuatorSignature signature = ActuatorSignatureOf(use, F, L, T);
    return FunctionDeclaration(function, name, signature.argument_unit, signature.result_unit,
                               signature.argument, signature.result, signature.sign, unloading);
  }
  const bool of_time = use == Use::kLoadForce || use == Use::kLoadTorque;
  const bool torque = use == Use::kJoint || use == Use::kLoadTorque;
  const bool ratio =
      use == Use::kContactFactor || use == Use::kBeltFactor || use == Use::kRateScale;
  const bool of_rate = use == Use::kRateScale || use == Use::kRateForce;
  const bool of_length = use == Use::kContact || use == Use::kSlip || use == Use::kContactFactor ||
                         use == Use::kRateScaledForce;
  const std::string argument_unit = of_length            ? L
                                    : of_rate            ? L + "/" + T
                                    : use == Use::kJoint ? "deg"
                                    : of_time            ? T
                                                         : "";
  const std::string result_unit = ratio ? "" : torque ? F + "*" + L : F;
  const char* argument = of_length            ? "deflection"
                         : of_rate            ? "velocity"
                         : use == Use::kJoint ? "angle"
                         : of_time            ? "time"
                                              : "strain";
  const char* result = ratio ? "ratio" : torque ? "torque" : "force";
  return FunctionDeclaration(function, name, argument_unit, result_unit, argument, result, 1.0,
                             unloading);
}

ast::Statement DeckMapper::FunctionDeclaration(const FunctionCard& function,
                                               const std::string& name,
                                               const std::string& argument_unit,
                                               const std::string& result_unit, const char* argument,
                                               const char* result, double sign,
                                               const FunctionUnloading& unloading) {
  ast::Statement statement =
      Declaration("function", Path(name),
                  CardComment("E.1", function.line) +
                      fmt::format(": function {}{}", function.number,
                                  function.title.empty() ? "" : ", " + function.title));
  statement.has_value = true;
  std::vector<ast::Expr> signature;
  signature.push_back(Path(argument));
  signature.push_back(Path(result));
  switch (function.form) {
    case FunctionCard::Form::kConstant:
      statement.values.push_back(
          Call("constant", {{"", Number(sign * function.constant + 0.0, result_unit)}}));
      break;
    case FunctionCard::Form::kPolynomial: {
      std::vector<std::pair<std::string, ast::Expr>> arguments;
      arguments.emplace_back("", ast::MakeArrow(std::move(signature)));
      std::size_t last = function.coefficients.size();
      while (last > 2 && function.coefficients[last - 1] == 0) --last;
      for (std::size_t k = 0; k < last; ++k) {
        std::string unit = result_unit;
        if (k > 0 && !argument_unit.empty()) unit = CoefficientUnit(result_unit, argument_unit, k);
        arguments.emplace_back("", Number(sign * function.coefficients[k] + 0.0, unit));
      }
      statement.values.push_back(Call("polynomial", std::move(arguments)));
      break;
    }
    case FunctionCard::Form::kTable:
      statement.values.push_back(Call("table", {{"", ast::MakeArrow(std::move(signature))}}));
      for (const auto& [x, y] : function.points) {
        Add(statement, Row(Number(x, argument_unit), Number(sign * y + 0.0, result_unit)));
      }
      break;
  }
  AddUnloading(statement, unloading);
  if (statement.block->statements.empty()) statement.block.reset();
  return statement;
}

void DeckMapper::MapInitial(ast::Block& scenario) {
  for (const InitialCard& card : deck_.initial_positions) {
    if (PrescribedCard(card.segment)) continue;  // placed by its C card (MapPrescribedSegments)
    const auto index = static_cast<std::size_t>(card.segment - 1);
    const std::string target = card.segment == 1 ? body_ : body_ + "." + segments_[index];
    ast::Statement initial = Declaration("initial", Path(target), CardComment("G.2", card.line));
    if (card.position_vehicle >= 0) {
      const auto v = static_cast<std::size_t>(card.position_vehicle);
      Add(initial,
          Attribute("position", Vector(VehicleToGround(deck_.vehicles[v], card.position), L)));
      initial.block->statements.back().leading_comments.push_back(
          {fmt::format(" IREF4: ({}, {}, {}) {} in the axes of vehicle `{}`, from its C.2.a "
                       "position and orientation",
                       card.position[0], card.position[1], card.position[2], L, vehicles_[v]),
           {},
           false});
    } else {
      Add(initial, Attribute("position", Vector(card.position, L)));
    }
    if (!card.equilibrium_note.empty()) {
      initial.block->statements.back().leading_comments.push_back(
          {card.equilibrium_note, {}, false});
    }
    const bool from_vehicle = deck_.velocities_from_vehicle && !deck_.vehicles.empty();
    const Vec3 velocity = from_vehicle ? VehicleVelocity(deck_.vehicles.back()) : card.velocity;
    if (!IsZero(velocity)) {
      Add(initial, Attribute("velocity", Vector(velocity, from_vehicle ? std::string(kVipsUnit)
                                                                       : L + "/" + T)));
      if (deck_.velocities_from_vehicle) {
        initial.block->statements.back().leading_comments.push_back(
            {" " + CardComment("G.1.a", deck_.velocity_source_line) +
                 ": I3 = 0, the primary vehicle's velocity",
             {},
             false});
      }
    }
    AddOrientation(initial, index);
    scenario.statements.push_back(std::move(initial));
  }
  MapPostures(scenario);
}

void DeckMapper::AddOrientation(ast::Statement& initial, std::size_t segment) {
  if (segment >= deck_.initial_orientations.size()) return;
  const OrientationCard& card = deck_.initial_orientations[segment];
  if (!IsZero(card.angles)) {
    Add(initial, Attribute("orientation", Vector(card.angles, "deg")));
    if (card.given != card.angles) {  // G.3.a ID1 to ID3: the same turn as sled's z-y-x angles
      initial.block->statements.back().leading_comments.push_back(
          {" G.3.a: " + GivenTurn(card), {}, false});
    }
  }
  if (!IsZero(card.angular_velocity)) {
    // G.3.a gives it in the segment's own axes, sled's `angular_velocity` is in the ground's.
    const Vec3 w = Turned(card.angles, card.angular_velocity);
    Add(initial, Attribute("angular_velocity", Vector(w, "deg/" + T)));
    if (!IsZero(card.angles)) {
      initial.block->statements.back().leading_comments.push_back(
          {fmt::format(" G.3.a: ({}, {}, {}) deg/{} in the segment's axes, turned to the ground's",
                       card.angular_velocity[0], card.angular_velocity[1], card.angular_velocity[2],
                       T),
           {},
           false});
    }
  }
}

}  // namespace sled::lang::legacy::mapping

namespace sled::lang::legacy {

ast::File DeckToAst(const Deck& deck, DiagnosticConsumer& diagnostics) {
  return mapping::DeckMapper(deck, diagnostics).Map();
}

}  // namespace sled::lang::legacy
