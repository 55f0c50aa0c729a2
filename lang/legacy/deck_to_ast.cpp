// The mapping from a read deck to the scenario AST: one declaration per card entity, names from
// the deck, numbers in the deck's units, and a comment naming each declaration's card.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <numbers>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "lang/ast/make_expr.h"
#include "lang/legacy/convert.h"

namespace sled::lang::legacy {
namespace {

// --- Building the tree --------------------------------------------------------------------

ast::Unit MakeUnit(std::string_view text) {
  ast::Unit unit;
  int sign = 1;
  std::size_t i = 0;
  while (i < text.size()) {
    std::size_t end = text.find_first_of("*/", i);
    if (end == std::string_view::npos) end = text.size();
    std::string_view factor = text.substr(i, end - i);
    int exponent = 1;
    const std::size_t caret = factor.find('^');
    if (caret != std::string_view::npos) {
      exponent = std::stoi(std::string(factor.substr(caret + 1)));
      factor = factor.substr(0, caret);
    }
    unit.factors.push_back({std::string(factor), sign * exponent, {}});
    if (end < text.size()) sign = text[end] == '/' ? -1 : 1;
    i = end + 1;
  }
  return unit;
}

ast::Expr Number(double value, std::string_view unit = {}) {
  ast::Expr expr;
  expr.kind = ast::ExprKind::kNumber;
  expr.number = value == 0 ? 0.0 : value;  // never print `-0`
  if (!unit.empty()) expr.unit = MakeUnit(unit);
  return expr;
}

ast::Expr Vector(const Vec3& v, std::string_view unit) {
  ast::Expr expr;
  expr.kind = ast::ExprKind::kVector;
  for (const double c : v) expr.operands.push_back(Number(c));
  expr.unit = MakeUnit(unit);
  return expr;
}

ast::Expr Path(const std::string& dotted) {
  ast::Expr expr;
  expr.kind = ast::ExprKind::kPath;
  std::size_t start = 0;
  while (true) {
    const std::size_t dot = dotted.find('.', start);
    expr.path.push_back(dotted.substr(start, dot - start));
    if (dot == std::string::npos) break;
    start = dot + 1;
  }
  return expr;
}

ast::Expr String(std::string text) {
  ast::Expr expr;
  expr.kind = ast::ExprKind::kString;
  expr.text = std::move(text);
  return expr;
}

ast::Expr Call(std::string callee, std::vector<std::pair<std::string, ast::Expr>> arguments) {
  ast::Expr expr;
  expr.kind = ast::ExprKind::kCall;
  expr.path.push_back(std::move(callee));
  for (auto& argument : arguments) {
    expr.arguments.push_back(
        {std::move(argument.first), {}, std::make_unique<ast::Expr>(std::move(argument.second))});
  }
  return expr;
}

ast::Statement Attribute(std::string keyword, ast::Expr value) {
  ast::Statement statement;
  statement.keyword = std::move(keyword);
  statement.has_value = true;
  statement.values.push_back(std::move(value));
  return statement;
}

ast::Statement Declaration(std::string keyword, ast::Expr target, std::string comment = {}) {
  ast::Statement statement;
  statement.keyword = std::move(keyword);
  statement.target = std::move(target);
  statement.block = std::make_unique<ast::Block>();
  if (!comment.empty()) statement.leading_comments.push_back({" " + std::move(comment), {}, false});
  return statement;
}

void Add(ast::Statement& parent, ast::Statement child) {
  parent.block->statements.push_back(std::move(child));
}

ast::Statement Row(ast::Expr from, ast::Expr to) {
  ast::Statement row;
  row.kind = ast::StatementKind::kRow;
  std::vector<ast::Expr> chain;
  chain.push_back(std::move(from));
  chain.push_back(std::move(to));
  row.values.push_back(ast::MakeArrow(std::move(chain)));
  return row;
}

std::string CardComment(std::string_view card, std::uint32_t line) {
  return fmt::format("card {}, line {}", card, line);
}

bool IsZero(const Vec3& v) { return v[0] == 0 && v[1] == 0 && v[2] == 0; }

// The cosine and sine of an angle in degrees, exact at multiples of 90 degrees (a vehicle pitched
// -90 degrees moves along z, not along z plus 1e-17 of x).
std::optional<double> ExactCos(double degrees) {
  const double quarters = degrees / 90;
  if (quarters != std::floor(quarters) || std::fabs(quarters) > 1e6) return std::nullopt;
  static constexpr double kCos[] = {1, 0, -1, 0};
  return kCos[static_cast<int>(std::fmod(std::fmod(quarters, 4) + 4, 4))];
}
double CosDegrees(double degrees) {
  return ExactCos(degrees).value_or(std::cos(degrees * (std::numbers::pi / 180)));
}
double SinDegrees(double degrees) {
  return ExactCos(degrees - 90).value_or(std::sin(degrees * (std::numbers::pi / 180)));
}

// C.2.a: the vehicle's initial velocity, VIPS along its own x axis (yaw, then pitch; the roll
// turns about x itself), the axis its half-sine pulse brings to rest.
Vec3 VehicleVelocity(const VehicleCard& vehicle) {
  const double yaw = vehicle.orientation[0], pitch = vehicle.orientation[1];
  return {vehicle.speed * CosDegrees(yaw) * CosDegrees(pitch),
          vehicle.speed * SinDegrees(yaw) * CosDegrees(pitch), -vehicle.speed * SinDegrees(pitch)};
}

// --- Names --------------------------------------------------------------------------------

// A deck label as a sled name: lower case, words joined by `_`, never a word the grammar or the
// frames reserve, unique among `taken`. A name something else already has takes the `kind` of
// what it names (a function titled like a plane, `knee_bolster`, becomes `knee_bolster_force`),
// and a number only if that is taken too.
std::string NameOf(std::string_view label, std::string_view fallback, std::set<std::string>& taken,
                   std::string_view kind = {}) {
  std::string name;
  for (const char c : label) {
    if (std::isalnum(static_cast<unsigned char>(c))) {
      name += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    } else if (!name.empty() && name.back() != '_') {
      name += '_';
    }
  }
  while (!name.empty() && name.back() == '_') name.pop_back();
  if (name.size() > 24) name.resize(24);
  while (!name.empty() && name.back() == '_') name.pop_back();
  static const std::set<std::string> kReserved = {
      "at", "on", "with", "as",      "filter", "true",     "false",       "ground",      "x",
      "y",  "z",  "body", "segment", "joint",  "function", "relative_to", "expressed_in"};
  if (name.empty()) name = std::string(fallback);
  if (std::isdigit(static_cast<unsigned char>(name[0]))) name = std::string(fallback) + "_" + name;
  if (kReserved.count(name) != 0) name += "_";
  if (taken.count(name) != 0 && !kind.empty()) {
    while (name.back() == '_') name.pop_back();
    name += "_" + std::string(kind);
  }
  std::string unique = name;
  for (int n = 2; taken.count(unique) != 0; ++n) unique = fmt::format("{}_{}", name, n);
  taken.insert(unique);
  return unique;
}

// --- The mapping --------------------------------------------------------------------------

enum class Use { kContact, kBelt, kJoint };

class Mapper {
 public:
  Mapper(const Deck& deck, DiagnosticConsumer& diagnostics)
      : deck_(deck),
        diagnostics_(diagnostics),
        L(deck.units.length),
        F(deck.units.force),
        T(deck.units.time) {}

  ast::File Map() {
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
    MapFunctions(body);
    MapInitial(body);
    MapOutputs(body);

    ast::File file;
    file.body.statements.push_back(std::move(scenario));
    return file;
  }

 private:
  void Report(DiagnosticKind kind, const Ref& ref, std::string message, std::string help = {}) {
    Diagnostic diagnostic = MakeDiagnostic(kind, ref.where, std::move(message));
    diagnostic.help = std::move(help);
    diagnostic.show_column_range = true;
    diagnostics_.Consume(std::move(diagnostic));
  }

  void NameEverything() {
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
    for (const PlaneCard& plane : deck_.planes)
      planes_.push_back(NameOf(plane.title, "plane", taken_, "plane"));
    for (const BeltCard& belt : deck_.belts) {
      belts_.push_back(NameOf(belt.title, "belt", taken_, "belt"));
    }
  }

  std::string Primary() const { return vehicles_.empty() ? "ground" : vehicles_.back(); }

  // A segment of the body by deck number, or empty after reporting a bad number.
  std::string Segment(const Ref& ref, std::string_view what) {
    if (ref.number < 1 || ref.number > static_cast<int>(segments_.size())) {
      Report(DiagnosticKind::kDeckCountOutOfRange, ref,
             fmt::format("card {}: {} {} does not exist", ref.card, what, ref.number),
             fmt::format("segments are numbered 1 to {}", segments_.size()));
      return {};
    }
    return body_ + "." + segments_[static_cast<std::size_t>(ref.number - 1)];
  }

  // A joint of the body by deck number (B.3 order), or empty after reporting a bad number.
  std::string Joint(const Ref& ref) {
    if (ref.number < 1 || ref.number > static_cast<int>(joints_.size())) {
      Report(DiagnosticKind::kDeckCountOutOfRange, ref,
             fmt::format("card {}: joint {} does not exist", ref.card, ref.number),
             fmt::format("joints are numbered 1 to {}", joints_.size()));
      return {};
    }
    return body_ + "." + joints_[static_cast<std::size_t>(ref.number - 1)];
  }

  const FunctionCard* Function(const Ref& ref) {
    for (const FunctionCard& function : deck_.functions) {
      if (function.number == ref.number) return &function;
    }
    Report(DiagnosticKind::kDeckUndefinedFunction, ref,
           fmt::format("card {}: function {} is not defined", ref.card, ref.number),
           "define it with E.1 and E.2 cards, or correct the number");
    return nullptr;
  }

  // The name under which a function is declared for one kind of use (its units depend on it).
  std::optional<ast::Expr> FunctionFor(const Ref& ref, Use use) {
    const FunctionCard* function = Function(ref);
    if (function == nullptr) return std::nullopt;
    auto key = std::make_pair(function->number, static_cast<int>(use));
    auto found = function_names_.find(key);
    if (found == function_names_.end()) {
      std::string name =
          NameOf(function->title, fmt::format("function_{}", function->number), taken_,
                 use == Use::kContact ? "force"
                 : use == Use::kJoint ? "torque"
                                      : "webbing");
      found = function_names_.emplace(key, name).first;
      uses_.push_back({function, use, name});
    }
    return Path(found->second);
  }

  // A friction coefficient from a constant function; zero for no function.
  std::optional<double> Friction(const Ref& ref) {
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
    return function->constant;
  }

  void MapRunSettings(ast::Block& body) {
    ast::Statement time = Declaration(
        "time", Path("x"), CardComment("A.4", deck_.control_line) + ": NSTEPS output steps of DT");
    time.target.reset();
    Add(time, Attribute("end", ast::MakeBinary('*', Number(deck_.steps), Number(deck_.dt, T))));
    Add(time, Attribute("output_every", Number(deck_.dt, T)));
    body.statements.push_back(std::move(time));
    ast::Statement integrator = Declaration("integrator", Path("auto"));
    if (deck_.first_step > 0)
      Add(integrator, Attribute("initial_step", Number(deck_.first_step, T)));
    if (deck_.max_step > 0) Add(integrator, Attribute("max_step", Number(deck_.max_step, T)));
    if (deck_.min_step > 0) Add(integrator, Attribute("min_step", Number(deck_.min_step, T)));
    body.statements.push_back(std::move(integrator));
  }

  ast::Expr Torque(const JointSpring& spring, const Ref& owner, std::string_view angle_unit) {
    (void)owner;
    std::vector<std::pair<std::string, ast::Expr>> coefficients;
    coefficients.emplace_back("", Number(0));
    coefficients.emplace_back("",
                              Number(spring.linear, F + "*" + L + "/" + std::string(angle_unit)));
    if (spring.quadratic != 0 || spring.cubic != 0) {
      coefficients.emplace_back(
          "", Number(spring.quadratic, F + "*" + L + "/" + std::string(angle_unit) + "^2"));
    }
    if (spring.cubic != 0) {
      coefficients.emplace_back(
          "", Number(spring.cubic, F + "*" + L + "/" + std::string(angle_unit) + "^3"));
    }
    return Call("polynomial", std::move(coefficients));
  }

  bool HasSpring(const JointSpring& spring) const {
    return spring.function.number != 0 || spring.linear != 0 || spring.quadratic != 0 ||
           spring.cubic != 0;
  }

  void AddSpring(ast::Statement& joint, const char* attribute, const JointSpring& spring) {
    if (spring.function.number != 0) {
      if (auto function = FunctionFor(spring.function, Use::kJoint)) {
        Add(joint, Attribute(attribute, std::move(*function)));
      }
    } else if (HasSpring(spring)) {
      Add(joint, Attribute(attribute, Torque(spring, spring.function, "deg")));
    }
  }

  void MapBody(ast::Block& scenario) {
    ast::Statement body =
        Declaration("body", Path(body_),
                    CardComment("B.1", deck_.body_line) + fmt::format(": {}", deck_.body_title));
    for (std::size_t i = 0; i < deck_.segments.size(); ++i) {
      const SegmentCard& card = deck_.segments[i];
      ast::Statement segment =
          Declaration("segment", Path(segments_[i]), CardComment("B.2.a", card.line));
      if (card.weight == 0) {
        Add(segment, Attribute("mass", Number(0, "kg")));
        Add(segment, Attribute("singular", ast::Expr{}));
        segment.block->statements.back().values[0].kind = ast::ExprKind::kBool;
        segment.block->statements.back().values[0].text = "true";
      } else {
        Add(segment,
            Attribute("mass", ast::MakeBinary('/', Number(card.weight, F), Path("deck_g"))));
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
      ast::Statement joint =
          Declaration("joint", Path(joints_[j]), CardComment("B.3.a", card.line));
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
      if (card.type == JointType::kEuler) {
        AddSpring(joint, "precession", card.flexure);
        AddSpring(joint, "nutation", card.twist);
        AddSpring(joint, "spin", card.spin);
      } else {
        AddSpring(joint, "flexure", card.flexure);
        if (card.type == JointType::kBall) AddSpring(joint, "twist", card.twist);
      }
      if (card.flexure.energy_loss != 0)
        Add(joint, Attribute("energy_loss", Number(card.flexure.energy_loss)));
      if (card.flexure.stop != 0) Add(joint, Attribute("stop", Number(card.flexure.stop, "deg")));
      if (card.type == JointType::kBall && card.twist.stop != 0)
        Add(joint, Attribute("twist_stop", Number(card.twist.stop, "deg")));
      if (card.viscous != 0)
        Add(joint, Attribute("viscous", Number(card.viscous, F + "*" + L + "*" + T + "/deg")));
      if (card.coulomb != 0) Add(joint, Attribute("coulomb", Number(card.coulomb, F + "*" + L)));
      if (card.restitution != 0) Add(joint, Attribute("restitution", Number(card.restitution)));
      body.block->statements.push_back(std::move(joint));
    }
    scenario.statements.push_back(std::move(body));
  }

  void MapVehicles(ast::Block& scenario) {
    for (std::size_t v = 0; v < deck_.vehicles.size(); ++v) {
      const VehicleCard& card = deck_.vehicles[v];
      ast::Statement vehicle = Declaration(
          "vehicle", Path(vehicles_[v]),
          CardComment("C.2.a", card.line) + (card.title.empty() ? "" : ": " + card.title));
      if (!IsZero(card.position)) Add(vehicle, Attribute("position", Vector(card.position, L)));
      if (!IsZero(card.orientation))
        Add(vehicle, Attribute("orientation", Vector(card.orientation, "deg")));
      if (card.speed != 0) {
        Add(vehicle, Attribute("velocity", Vector(VehicleVelocity(card), L + "/" + T)));
        Add(vehicle,
            Attribute("motion", Call("half_sine", {{"delta_v", Number(card.speed, L + "/" + T)},
                                                   {"duration", Number(card.duration, T)},
                                                   {"axis", ast::MakeNegation(Path("x"))}})));
      }
      scenario.statements.push_back(std::move(vehicle));
    }
  }

  void MapSurfaces(ast::Block& scenario) {
    for (std::size_t p = 0; p < deck_.planes.size(); ++p) {
      const PlaneCard& card = deck_.planes[p];
      ast::Statement plane = Declaration("plane", Path(planes_[p]), CardComment("D.2", card.line));
      plane.clauses.push_back({"on", {}, Path(Primary())});
      ast::Statement corners;
      corners.keyword = "corners";
      corners.has_value = true;
      for (const Vec3& corner : card.corners) corners.values.push_back(Vector(corner, L));
      Add(plane, std::move(corners));
      scenario.statements.push_back(std::move(plane));
    }
    for (const VehicleEllipsoidCard& card : deck_.vehicle_ellipsoids) {
      const std::string& vehicle = vehicles_[static_cast<std::size_t>(card.vehicle - 1)];
      const std::string name = NameOf(vehicle + "_ellipsoid", "ellipsoid", taken_);
      vehicle_ellipsoid_names_[card.vehicle] = name;  // a later card replaces an earlier one
      scenario.statements.push_back(EllipsoidOn(card, name, vehicle));
    }
    std::vector<ast::Statement> contacts;
    for (const ContactCard& card : deck_.contacts) {
      std::string segment, other;
      if (card.with_plane) {
        segment = Segment(card.segment, "segment");
        other = planes_[static_cast<std::size_t>(card.other.number - 1)];
      } else {
        segment = Surface(card.segment, card.ellipsoid, scenario);
        other = Surface(card.other, card.other_ellipsoid, scenario);
      }
      auto force = FunctionFor(card.force, Use::kContact);
      const auto friction = Friction(card.friction);
      if (segment.empty() || other.empty() || !force || !friction) continue;
      ast::Statement contact = Declaration(
          "contact", Path(segment), CardComment(card.with_plane ? "F.1.b" : "F.3.b", card.line));
      contact.clauses.push_back({"with", {}, Path(other)});
      Add(contact, Attribute("force", std::move(*force)));
      if (*friction != 0) Add(contact, Attribute("friction", Number(*friction)));
      if (card.output) contact_outputs_.emplace_back(segment, other);
      contacts.push_back(std::move(contact));
    }
    for (const VehicleEllipsoidCard& card : deck_.extra_ellipsoids) {
      if (placed_extras_.count(card.number) == 0) {
        Report(DiagnosticKind::kDeckIgnoredField, Ref{card.number, card.where, "D.5"},
               fmt::format("extra ellipsoid {} (D.5, line {}) is named by no F.3.b card, so ATB "
                           "puts it on no segment; it is left out",
                           card.number, card.line),
               "name it in MS_SEG(1) or MS_SEG(3) of an F.3.b card, or remove the D.5 card");
      }
    }
    for (ast::Statement& contact : contacts) scenario.statements.push_back(std::move(contact));
  }

  ast::Statement EllipsoidOn(const VehicleEllipsoidCard& card, const std::string& name,
                             const std::string& frame) {
    ast::Statement ellipsoid = Declaration("ellipsoid", Path(name), CardComment("D.5", card.line));
    ellipsoid.clauses.push_back({"on", {}, Path(frame)});
    Add(ellipsoid, Attribute("semi_axes", Vector(card.semi_axes, L)));
    if (!IsZero(card.center)) Add(ellipsoid, Attribute("center", Vector(card.center, L)));
    if (!IsZero(card.orientation))
      Add(ellipsoid, Attribute("orientation", Vector(card.orientation, "deg")));
    if (card.degree != 2) Add(ellipsoid, Attribute("degree", Number(card.degree)));
    return ellipsoid;
  }

  // The surface of an F.3.b side: frame `frame` (a body segment or a vehicle) with ellipsoid
  // `ellipsoid` (0 or the frame's own number: the frame's own; at or above NGRND an extra D.5
  // ellipsoid, declared on this frame the first time a card puts it there). Empty after a report.
  std::string Surface(const Ref& frame, const Ref& ellipsoid, ast::Block& scenario) {
    const int segments = static_cast<int>(segments_.size());
    const int vehicles = static_cast<int>(vehicles_.size());
    std::string frame_name;
    if (frame.number >= 1 && frame.number <= segments) {
      frame_name = body_ + "." + segments_[static_cast<std::size_t>(frame.number - 1)];
    } else if (frame.number > segments && frame.number <= segments + vehicles) {
      frame_name = vehicles_[static_cast<std::size_t>(frame.number - segments - 1)];
    } else {
      Report(DiagnosticKind::kDeckCountOutOfRange, frame,
             fmt::format("card {}: segment {} does not exist", frame.card, frame.number),
             fmt::format("body segments are 1 to {} and vehicles {} to {}", segments, segments + 1,
                         segments + vehicles));
      return {};
    }
    const bool vehicle = frame.number > segments;
    if (ellipsoid.number == 0 || ellipsoid.number == frame.number) {
      if (!vehicle) return frame_name;
      const auto found = vehicle_ellipsoid_names_.find(frame.number - segments);
      if (found != vehicle_ellipsoid_names_.end()) return found->second;
      Report(DiagnosticKind::kDeckInvalidValue, frame,
             fmt::format("card {}: vehicle segment {} has no ellipsoid", frame.card, frame.number),
             fmt::format("give it one with a D.5 card numbered {}", frame.number));
      return {};
    }
    // A later D.5 card of the same number replaces an earlier one, as in ATB.
    for (auto it = deck_.extra_ellipsoids.rbegin(); it != deck_.extra_ellipsoids.rend(); ++it) {
      const VehicleEllipsoidCard& card = *it;
      if (card.number != ellipsoid.number) continue;
      auto key = std::make_pair(card.number, frame_name);
      auto found = extra_names_.find(key);
      if (found == extra_names_.end()) {
        const std::string name =
            NameOf(fmt::format("{}_ellipsoid_{}", frame_name.substr(frame_name.rfind('.') + 1),
                               card.number),
                   "ellipsoid", taken_);
        found = extra_names_.emplace(key, name).first;
        placed_extras_.insert(card.number);
        scenario.statements.push_back(EllipsoidOn(card, name, frame_name));
      }
      return found->second;
    }
    Report(DiagnosticKind::kDeckInvalidValue, ellipsoid,
           fmt::format("card {}: ellipsoid {} is neither segment {}'s own nor an extra D.5 "
                       "ellipsoid",
                       ellipsoid.card, ellipsoid.number, frame.number),
           "leave the field 0 for the segment's own ellipsoid, or give an extra ellipsoid's "
           "number (a D.5 card's M at or above NGRND)");
    return {};
  }

  void MapRestraints(ast::Block& scenario) {
    for (std::size_t b = 0; b < deck_.belts.size(); ++b) {
      const BeltCard& card = deck_.belts[b];
      if (card.contact_line == 0) continue;  // the F.2.b card was missing: reported by the reader
      const std::string segment = Segment(card.segment, "segment");
      auto force = FunctionFor(card.force, Use::kBelt);
      const auto friction = Friction(card.friction);
      if (segment.empty() || !force || !friction) continue;
      ast::Statement belt = Declaration(
          "belt", Path(belts_[b]),
          CardComment("D.3", card.line) + fmt::format(" and F.2.b, line {}", card.contact_line));
      belt.clauses.push_back({"on", {}, Path(Primary())});
      std::vector<ast::Expr> path;
      path.push_back(Vector(card.anchor_a, L));
      path.push_back(Path(segment));
      path.push_back(Vector(card.anchor_b, L));
      AddBeltAttributes(belt, std::move(path), std::move(*force), card.slack, *friction);
      if (card.output) belt_outputs_.push_back(belts_[b]);
      scenario.statements.push_back(std::move(belt));
    }
    MapHarnesses(scenario);
    MapAirbags(scenario);
    for (std::size_t s = 0; s < deck_.springs.size(); ++s) {
      const SpringCard& card = deck_.springs[s];
      const std::string first = Segment(card.first, "segment M");
      const std::string second = Segment(card.second, "segment N");
      if (first.empty() || second.empty()) continue;
      const std::string name = NameOf(fmt::format("spring_{}", s + 1), "spring", taken_);
      ast::Statement spring = Declaration("spring", Path(name), CardComment("D.8", card.line));
      std::vector<ast::Expr> chain;
      chain.push_back(Path(first));
      chain.push_back(Path(second));
      spring.clauses.push_back({":", {}, ast::MakeArrow(std::move(chain))});
      AddAttachments(spring, first, card.at_first, second, card.at_second);
      std::vector<std::pair<std::string, ast::Expr>> coefficients;
      coefficients.emplace_back("", Number(0));
      coefficients.emplace_back("", Number(card.linear, F + "/" + L));
      if (card.quadratic != 0)
        coefficients.emplace_back("", Number(card.quadratic, F + "/" + L + "^2"));
      Add(spring, Attribute("stiffness", Call("polynomial", std::move(coefficients))));
      if (card.damping != 0)
        Add(spring, Attribute("damping", Number(card.damping, F + "*" + T + "/" + L)));
      if (card.free_length != 0) Add(spring, Attribute("free_length", Number(card.free_length, L)));
      scenario.statements.push_back(std::move(spring));
    }
    MapConstraints(scenario);
    // D.7: mutual pairs become mirror pairs.
    ast::Statement symmetry =
        Declaration("symmetry", Path("mirror"), CardComment("D.7", deck_.symmetry_line));
    for (std::size_t i = 0; i < deck_.symmetry.size(); ++i) {
      const Ref& ref = deck_.symmetry[i];
      if (ref.number == 0) continue;
      const auto other = static_cast<std::size_t>(ref.number - 1);
      if (other >= deck_.symmetry.size() ||
          deck_.symmetry[other].number != static_cast<int>(i + 1)) {
        Report(DiagnosticKind::kDeckInvalidValue, ref,
               fmt::format("card {}: segment {} names {} as its mirror, but not the reverse",
                           ref.card, i + 1, ref.number),
               "symmetry pairs are mutual");
        continue;
      }
      if (other < i) continue;
      ast::Statement pair;
      pair.keyword = "pair";
      pair.has_value = true;
      pair.values.push_back(Path(body_ + "." + segments_[i]));
      pair.values.push_back(Path(body_ + "." + segments_[other]));
      Add(symmetry, std::move(pair));
    }
    if (!symmetry.block->statements.empty()) scenario.statements.push_back(std::move(symmetry));
  }

  // `at FIRST = ...` and `at SECOND = ...` of a spring or constraint.
  void AddAttachments(ast::Statement& statement, const std::string& first, const Vec3& at_first,
                      const std::string& second, const Vec3& at_second) {
    for (const auto& [frame, at] : {std::pair{&first, &at_first}, std::pair{&second, &at_second}}) {
      ast::Statement attachment = Attribute("at", Vector(*at, L));
      attachment.target = Path(*frame);
      Add(statement, std::move(attachment));
    }
  }

  std::string FrameName(const DeckFrame& frame) const {
    switch (frame.kind) {
      case DeckFrame::Kind::kSegment:
        return body_ + "." + segments_[static_cast<std::size_t>(frame.index - 1)];
      case DeckFrame::Kind::kVehicle:
        return vehicles_[static_cast<std::size_t>(frame.index)];
      case DeckFrame::Kind::kGround:
        break;
    }
    return "ground";
  }

  // D.4 and F.6 (--approximate-airbags): `airbag NAME on PRIMARY { ... }`, fixed at the
  // deployment point, with the cylinder's flow as a named inflow table.
  void MapAirbags(ast::Block& scenario) {
    for (std::size_t b = 0; b < deck_.airbags.size(); ++b) {
      const AirbagCard& card = deck_.airbags[b];
      const std::string name =
          NameOf(card.title, fmt::format("airbag_{}", b + 1), taken_, "airbag");
      const std::string inflow_name = NameOf(name + "_inflow", "inflow", taken_);
      ast::Statement inflow = Declaration("function", Path(inflow_name),
                                          CardComment("D.4.d", card.cylinder_line) +
                                              ": ATB's cylinder, its flow from CYTD tabulated");
      std::vector<ast::Expr> signature;
      signature.push_back(Path("time"));
      signature.push_back(Path("mass_flow"));
      inflow.has_value = true;
      inflow.values.push_back(Call("table", {{"", ast::MakeArrow(std::move(signature))}}));
      for (const auto& [t, flow] : card.inflow) {
        Add(inflow, Row(Number(t, T), Number(flow, F + "*" + T + "/" + L)));
      }
      scenario.statements.push_back(std::move(inflow));

      ast::Statement airbag = Declaration(
          "airbag", Path(name),
          CardComment("D.4.a", card.line) + (card.title.empty() ? "" : ": " + card.title) +
              (card.contact_line ? fmt::format(" (F.6, line {})", card.contact_line) : ""));
      airbag.clauses.push_back({"on", {}, Path(Primary())});
      Add(airbag, Attribute("position", Vector(card.deploy_point, L)));
      // ATB's bag deploys along its -x; sled's along its x: turn the axes half a turn about z.
      double yaw = card.orientation[0] + 180;
      if (yaw > 180) yaw -= 360;
      const Vec3 orientation{yaw, -card.orientation[1], -card.orientation[2]};
      if (!IsZero(orientation)) Add(airbag, Attribute("orientation", Vector(orientation, "deg")));
      Add(airbag, Attribute("semi_axes", Vector(card.semi_axes, L)));
      Add(airbag, Attribute("deploy_at", Number(card.deploy_at, T)));
      Add(airbag, Attribute("inflow", Path(inflow_name)));
      Add(airbag, Attribute("gas_temperature", Number(card.gas_temperature, "K")));
      Add(airbag, Attribute("gamma", Number(card.gamma)));
      // ATB's gas constant is per weight; per mass it is times G.
      Add(airbag,
          Attribute("gas_constant",
                    ast::MakeBinary('*', Number(card.gas_constant, L + "/K"), Path("deck_g"))));
      if (card.vent_area > 0 && card.vent_discharge > 0) {
        Add(airbag, Attribute("vent_area", Number(card.vent_area, L + "^2")));
        Add(airbag, Attribute("discharge_coefficient", Number(card.vent_discharge)));
      }
      Add(airbag, Attribute("ambient_pressure", Number(card.ambient_pressure, F + "/" + L + "^2")));
      ast::Statement contacts;
      contacts.keyword = "contacts";
      contacts.has_value = true;
      for (const Ref& segment : card.contacts) {
        const std::string path = Segment(segment, "segment");
        if (!path.empty()) contacts.values.push_back(Path(path));
      }
      if (!contacts.values.empty()) Add(airbag, std::move(contacts));
      scenario.statements.push_back(std::move(airbag));
    }
  }

  // D.6: `constraint constraint_N : fixed_point(A -> B) { at A = ...  at B = ... }`.
  void MapConstraints(ast::Block& scenario) {
    for (std::size_t c = 0; c < deck_.constraints.size(); ++c) {
      const ConstraintCard& card = deck_.constraints[c];
      const std::string first = FrameName(card.first), second = FrameName(card.second);
      ast::Statement constraint = Declaration(
          "constraint", Path(NameOf(fmt::format("constraint_{}", c + 1), "constraint", taken_)),
          CardComment("D.6", card.line));
      std::vector<ast::Expr> chain;
      chain.push_back(Path(first));
      chain.push_back(Path(second));
      const char* kind =
          card.kind == ConstraintCard::Kind::kFixedPoint ? "fixed_point" : "fixed_distance";
      constraint.clauses.push_back({":", {}, Call(kind, {{"", ast::MakeArrow(std::move(chain))}})});
      AddAttachments(constraint, first, card.at_first, second, card.at_second);
      scenario.statements.push_back(std::move(constraint));
    }
  }

  void AddBeltAttributes(ast::Statement& belt, std::vector<ast::Expr> path, ast::Expr force,
                         double slack, double friction) {
    Add(belt, Attribute("path", ast::MakeArrow(std::move(path))));
    Add(belt, Attribute("force", std::move(force)));
    if (slack > 0) Add(belt, Attribute("slack", Number(slack, L)));
    if (friction != 0) Add(belt, Attribute("friction", Number(friction)));
  }

  // One friction coefficient for several points that each name a friction function; empty after
  // reporting a point whose coefficient differs from the first's.
  std::optional<double> CommonFriction(const std::vector<const Ref*>& refs, std::string_view what) {
    std::optional<double> common;
    const Ref* first = nullptr;
    for (const Ref* ref : refs) {
      const auto friction = Friction(*ref);
      if (!friction) return std::nullopt;
      if (!common) {
        common = friction;
        first = ref;
      } else if (*friction != *common) {
        Report(DiagnosticKind::kDeckNotExpressible, *ref,
               fmt::format("card {}: a friction of {} here and {} at {}", ref->card, *friction,
                           *common, first->card),
               fmt::format("sled takes one friction for {}; give its points the same "
                           "friction function",
                           what));
        return std::nullopt;
      }
    }
    return common.value_or(0.0);
  }

  // F.8: `harness NAME on FRAME { friction  belt NAME { path ... } }`, the harness friction from
  // its tie points, each belt's friction from the points it wraps.
  void MapHarnesses(ast::Block& scenario) {
    for (std::size_t h = 0; h < deck_.harnesses.size(); ++h) {
      const HarnessCard& card = deck_.harnesses[h];
      if (card.belts.empty()) continue;  // no belt with points: nothing acts in ATB either
      ast::Statement harness =
          Declaration("harness", Path(NameOf(fmt::format("harness_{}", h + 1), "harness", taken_)),
                      CardComment("F.8.a", card.line));
      if (card.vehicle >= 0) {
        harness.clauses.push_back(
            {"on", {}, Path(vehicles_[static_cast<std::size_t>(card.vehicle)])});
      }
      std::vector<const Ref*> tie_friction;
      for (const HarnessBeltCard& belt : card.belts) {
        for (const HarnessPoint* end : {&belt.points.front(), &belt.points.back()}) {
          if (end->tie != 0) tie_friction.push_back(&end->friction);
        }
      }
      const auto friction = CommonFriction(tie_friction, "a harness's tie points");
      if (!friction) continue;
      if (*friction != 0) Add(harness, Attribute("friction", Number(*friction)));
      bool complete = true;
      for (std::size_t b = 0; b < card.belts.size(); ++b) {
        const HarnessBeltCard& belt = card.belts[b];
        if (belt.points.size() < 3) continue;  // reported by the reader
        std::vector<ast::Expr> path;
        std::vector<const Ref*> wrap_friction;
        path.push_back(Vector(belt.points.front().anchor, L));
        for (std::size_t k = 1; k + 1 < belt.points.size(); ++k) {
          const std::string segment = Segment(belt.points[k].segment, "segment KS");
          if (segment.empty()) complete = false;
          path.push_back(Path(segment));
          wrap_friction.push_back(&belt.points[k].friction);
        }
        path.push_back(Vector(belt.points.back().anchor, L));
        auto force = FunctionFor(belt.force, Use::kBelt);
        const auto wrap = CommonFriction(wrap_friction, "a belt's wrapped segments");
        if (!force || !wrap || !complete) {
          complete = false;
          continue;
        }
        ast::Statement out = Declaration("belt", Path(fmt::format("belt_{}", b + 1)),
                                         CardComment("F.8.c", belt.line));
        AddBeltAttributes(out, std::move(path), std::move(*force), belt.slack, *wrap);
        Add(harness, std::move(out));
      }
      if (complete) scenario.statements.push_back(std::move(harness));
    }
  }

  void MapFunctions(ast::Block& scenario) {
    // Declared after their uses were seen, in the order of the E cards.
    std::vector<ast::Statement> statements;
    for (const FunctionCard& function : deck_.functions) {
      bool used = used_.count(function.number) != 0;
      for (const FunctionUse& use : uses_) {
        if (use.function != &function) continue;
        used = true;
        statements.push_back(FunctionStatement(function, use.use, use.name));
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

  ast::Statement FunctionStatement(const FunctionCard& function, Use use, const std::string& name) {
    const std::string argument_unit = use == Use::kContact ? L : use == Use::kJoint ? "deg" : "";
    const std::string result_unit = use == Use::kJoint ? F + "*" + L : F;
    const char* argument = use == Use::kContact ? "deflection"
                           : use == Use::kJoint ? "angle"
                                                : "strain";
    const char* result = use == Use::kJoint ? "torque" : "force";
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
            Call("constant", {{"", Number(function.constant, result_unit)}}));
        statement.block.reset();
        break;
      case FunctionCard::Form::kPolynomial: {
        std::vector<std::pair<std::string, ast::Expr>> arguments;
        arguments.emplace_back("", ast::MakeArrow(std::move(signature)));
        std::size_t last = function.coefficients.size();
        while (last > 2 && function.coefficients[last - 1] == 0) --last;
        for (std::size_t k = 0; k < last; ++k) {
          std::string unit = result_unit;
          if (k > 0 && !argument_unit.empty())
            unit += "/" + argument_unit + (k > 1 ? fmt::format("^{}", k) : "");
          arguments.emplace_back("", Number(function.coefficients[k], unit));
        }
        statement.values.push_back(Call("polynomial", std::move(arguments)));
        statement.block.reset();
        break;
      }
      case FunctionCard::Form::kTable:
        statement.values.push_back(Call("table", {{"", ast::MakeArrow(std::move(signature))}}));
        for (const auto& [x, y] : function.points) {
          Add(statement, Row(Number(x, argument_unit), Number(y, result_unit)));
        }
        break;
    }
    return statement;
  }

  void MapInitial(ast::Block& scenario) {
    for (const InitialCard& card : deck_.initial_positions) {
      const auto index = static_cast<std::size_t>(card.segment - 1);
      const std::string target = card.segment == 1 ? body_ : body_ + "." + segments_[index];
      ast::Statement initial = Declaration("initial", Path(target), CardComment("G.2", card.line));
      Add(initial, Attribute("position", Vector(card.position, L)));
      const Vec3 velocity = deck_.velocities_from_vehicle && !deck_.vehicles.empty()
                                ? VehicleVelocity(deck_.vehicles.back())
                                : card.velocity;
      if (!IsZero(velocity)) {
        Add(initial, Attribute("velocity", Vector(velocity, L + "/" + T)));
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
    for (std::size_t s = 0; s < deck_.initial_orientations.size(); ++s) {
      const bool reference =
          std::any_of(deck_.initial_positions.begin(), deck_.initial_positions.end(),
                      [&](const InitialCard& c) { return c.segment == static_cast<int>(s + 1); });
      const OrientationCard& card = deck_.initial_orientations[s];
      if (reference || (IsZero(card.angles) && IsZero(card.angular_velocity))) continue;
      ast::Statement initial =
          Declaration("initial", Path(body_ + "." + segments_[s]), CardComment("G.3.a", card.line));
      AddOrientation(initial, s);
      scenario.statements.push_back(std::move(initial));
    }
    for (std::size_t j = 0; j < deck_.joints.size(); ++j) {
      const JointCard& card = deck_.joints[j];
      if (card.type != JointType::kEuler || IsZero(card.initial_angles)) continue;
      ast::Statement initial =
          Declaration("initial", Path(body_ + "." + joints_[j]), CardComment("B.4.b", card.line));
      Add(initial, Attribute("angles", Vector(card.initial_angles, "deg")));
      scenario.statements.push_back(std::move(initial));
    }
  }

  void AddOrientation(ast::Statement& initial, std::size_t segment) {
    if (segment >= deck_.initial_orientations.size()) return;
    const OrientationCard& card = deck_.initial_orientations[segment];
    if (!IsZero(card.angles)) Add(initial, Attribute("orientation", Vector(card.angles, "deg")));
    if (!IsZero(card.angular_velocity))
      Add(initial, Attribute("angular_velocity", Vector(card.angular_velocity, "deg/" + T)));
  }

  // One H request. KREF 0 is each card's default: H.1 and H.4 in the segment's own axes (sled's
  // default too), the relative H.2, H.3, H.5 and H.6 relative to the primary vehicle.
  void MapOutput(const OutputCard& card, ast::Statement& block) {
    using Kind = OutputCard::Kind;
    auto request = [&](const char* keyword, const std::string& target) {
      ast::Statement statement;
      statement.keyword = keyword;
      statement.target = Path(target);
      return statement;
    };
    if (card.kind == Kind::kJointParameters || card.kind == Kind::kJointForce) {
      const std::string joint = Joint(card.segment);
      if (joint.empty()) return;
      const bool parameters = card.kind == Kind::kJointParameters;
      if (parameters) {
        Report(DiagnosticKind::kDeckApproximated, card.segment,
               fmt::format("card {}: ATB's H.7 lists seven joint parameters of joint {}; sled "
                           "outputs its angles and torques (`joint_angle`, `joint_torque`)",
                           card.segment.card, card.segment.number),
               "docs/legacy.md, H cards");
      }
      Add(block, request(parameters ? "joint_angle" : "joint_force", joint));
      Add(block, request("joint_torque", joint));
      return;
    }
    const std::string segment = Segment(card.segment, "segment");
    if (segment.empty()) return;
    static constexpr const char* kKeywords[] = {"acceleration",     "velocity",
                                                "position",         "angular_acceleration",
                                                "angular_velocity", "orientation"};
    ast::Statement statement = request(kKeywords[static_cast<int>(card.kind)], segment);
    const bool point = card.kind == Kind::kAcceleration || card.kind == Kind::kVelocity ||
                       card.kind == Kind::kPosition;
    if (point) statement.clauses.push_back({"at", {}, Vector(card.point, L)});
    const bool in_axes =
        card.kind == Kind::kAcceleration || card.kind == Kind::kAngularAcceleration;
    if (in_axes) {
      if (card.frame)
        statement.clauses.push_back({"expressed_in", {}, Path(FrameName(*card.frame))});
    } else {
      const std::string frame = card.frame ? FrameName(*card.frame) : Primary();
      statement.clauses.push_back({"relative_to", {}, Path(frame)});
      if (card.kind == Kind::kVelocity && card.frame &&
          card.frame->kind == DeckFrame::Kind::kSegment) {
        // ATB's H.2 is R^T (v_p - v_F); seen from a turning frame sled also takes away the
        // frame's turning, w_F x r (the deck's vehicles only translate: there it is exact).
        Report(DiagnosticKind::kDeckApproximated, card.reference,
               fmt::format("card {}: KREF {} is a body segment, which turns: ATB's relative "
                           "velocity is the difference of the two velocities in its axes, "
                           "sled's the velocity seen from it, which differs by the segment's "
                           "angular velocity times the distance between the point and it",
                           card.reference.card, card.reference.number),
               "for ATB's quantity, request `velocity ... expressed_in` of both and subtract");
      }
    }
    Add(block, std::move(statement));
  }

  void MapOutputs(ast::Block& scenario) {
    ast::Statement output =
        Declaration("output", Path("x"), "cards H.1 to H.9, and NOUT of the F cards");
    output.target.reset();
    for (const OutputCard& card : deck_.outputs) MapOutput(card, output);
    for (const auto& [a, b] : contact_outputs_) {
      ast::Statement request;
      request.keyword = "contact_force";
      request.target = Path(a);
      request.clauses.push_back({"with", {}, Path(b)});
      Add(output, std::move(request));
    }
    for (const std::string& belt : belt_outputs_) {
      ast::Statement request;
      request.keyword = "belt_force";
      request.target = Path(belt);
      Add(output, std::move(request));
    }
    if (!output.block->statements.empty()) scenario.statements.push_back(std::move(output));
  }

  struct FunctionUse {
    const FunctionCard* function;
    Use use;
    std::string name;
  };

  const Deck& deck_;
  DiagnosticConsumer& diagnostics_;
  const std::string L, F, T;
  std::set<std::string> taken_{"deck_g"};
  std::set<std::string> body_names_;
  std::string body_;
  std::vector<std::string> segments_, joints_, vehicles_, planes_, belts_;
  std::map<int, std::string> vehicle_ellipsoid_names_;              // by 1-based vehicle
  std::map<std::pair<int, std::string>, std::string> extra_names_;  // (M, frame) -> name
  std::set<int> placed_extras_;
  std::map<std::pair<int, int>, std::string> function_names_;
  std::vector<FunctionUse> uses_;
  std::set<int> used_;
  std::vector<std::pair<std::string, std::string>> contact_outputs_;
  std::vector<std::string> belt_outputs_;
};

}  // namespace

ast::File DeckToAst(const Deck& deck, DiagnosticConsumer& diagnostics) {
  return Mapper(deck, diagnostics).Map();
}

}  // namespace sled::lang::legacy
