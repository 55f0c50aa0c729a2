// DeckMapper: a read Deck (deck.h) to the scenario AST, one declaration per card entity, names
// from the deck, numbers in the deck's units and a comment naming each declaration's card. Its
// methods are defined by card group: deck_to_ast.cpp (the run, the body, vehicles, functions,
// initial conditions), map_restraints.cpp (surfaces, belts, springs, airbags, constraints,
// harnesses), map_unloading.cpp (ATB's R and G factors), map_posture.cpp (the joint angles of
// G.3.a) and map_outputs.cpp (the H cards).
#pragma once

#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <tuple>
#include <utility>
#include <vector>

#include "lang/ast/ast.h"
#include "lang/diagnostics/diagnostic.h"
#include "lang/legacy/deck.h"
#include "lang/legacy/rotations.h"

namespace sled::lang::legacy::mapping {

// A G.3.a card's yaw, pitch and roll as the deck gives them, for a comment; with the rotation
// order when it makes sled's z-y-x angles differ from them (map_posture.cpp).
std::string GivenTurn(const OrientationCard& card);

class DeckMapper {
 public:
  // How a function is used: its argument and result units depend on it.
  // kSlip: a slip joint's spring, a force against its displacement along the slip axis.
  // kLoadForce, kLoadTorque: a D.9 applied force or torque against time.
  // kContactFactor, kBeltFactor: an R or G factor that changes with the largest deflection of
  // a contact's or a webbing's force function (its argument), to a ratio.
  // kRateScaledForce, kRateScale, kRateForce: F2(D), F3(D'), F4(D') of ATB's rate-dependent
  // contact force.
  // kActuatorTarget: an F.10 target angle against time; kActuatorProportional, ...Derivative,
  // ...Integral: its gains against the target angle, each also Negated (the values' signs
  // turned, for the side APPLY puts ATB's torque on).
  enum class Use {
    kContact,
    kBelt,
    kJoint,
    kSlip,
    kLoadForce,
    kLoadTorque,
    kContactFactor,
    kBeltFactor,
    kRateScaledForce,
    kRateScale,
    kRateForce,
    kActuatorTarget,
    kActuatorProportional,
    kActuatorDerivative,
    kActuatorIntegral,
    kActuatorProportionalNegated,
    kActuatorDerivativeNegated,
    kActuatorIntegralNegated
  };

  DeckMapper(const Deck& deck, DiagnosticConsumer& diagnostics)
      : deck_(deck),
        diagnostics_(diagnostics),
        L(deck.units.length),
        F(deck.units.force),
        T(deck.units.time) {}
  ast::File Map();

 private:
  void Report(DiagnosticKind kind, const Ref& ref, std::string message, std::string help = {});
  void NameEverything();
  std::string Primary() const { return vehicles_.empty() ? "ground" : vehicles_.back(); }
  // A segment of the body by deck number, or empty after reporting a bad number.
  std::string Segment(const Ref& ref, std::string_view what);
  // A joint of the body by deck number (B.3 order), or empty after reporting a bad number.
  std::string Joint(const Ref& ref);
  const FunctionCard* Function(const Ref& ref);
  // An R or G factor: a constant, or the name of its declared function of x_max.
  struct FactorValue {
    double constant = 0;
    std::string function;
    bool operator<(const FactorValue& other) const {
      return std::tie(constant, function) < std::tie(other.constant, other.function);
    }
  };
  // The unloading of a force function (map_unloading.cpp): elastic, or ATB's law with the R
  // and G factors of the card that uses it, its inertial spike (the spike's declared name, and
  // its end, E.2 D3) and the force function's origin (E.2 D0, map_function_fields.cpp), both in
  // `argument_unit` (the deflection's, or none for a webbing's strain).
  struct FunctionUnloading {
    bool atb = false;
    FactorValue r{1.0, {}}, g{0.0, {}};
    FactorValue spike{0.0, {}};
    double spike_end = 0;
    double origin = 0;
    std::string argument_unit;
  };
  // The name under which a function is declared for one kind of use (its units depend on it)
  // and one unloading (ATB's R and G factors of the card that uses it).
  std::optional<ast::Expr> FunctionFor(const Ref& ref, Use use, const UnloadingRefs& factors = {});
  // A factor function's constant, or its declaration as a function of the argument of `use`'s
  // force function; `none` for no function; empty after a report.
  std::optional<FactorValue> Factor(const Ref& ref, Use use, double none);
  // The unloading of a force function of `use` under a card's R and G factors; empty after a
  // report.
  std::optional<FunctionUnloading> Unloading(const UnloadingRefs& refs, Use use);
  // The inertial spike of a card (NF(2) > 0): its declaration and end into `unloading`; false
  // after a report.
  bool AddSpike(const Ref& spike, Use use, FunctionUnloading& unloading);
  // E.2's D0, D3 and D4 of `function` in `use` (map_function_fields.cpp): D0 as the origin of
  // ATB's law where ATB integrates the function, ignored where no argument reaches below it,
  // refused elsewhere; D3 as a spike's end; D4 refused. False after a refusal.
  bool CheckFunctionFields(const FunctionCard& function, const Ref& ref, Use use,
                           FunctionUnloading& unloading);
  // `unloading = atb(...)` in a function's block, when it has ATB's law.
  void AddUnloading(ast::Statement& statement, const FunctionUnloading& unloading);
  // A contact's `rate_scaled_force`, `rate_scale` and `rate_force` from ATB's rate-dependent
  // functions; false after a report.
  bool AddRateTerms(ast::Statement& contact, const UnloadingRefs& refs);
  // E0507 for rate-dependent functions on a card whose element (a belt's webbing) has none;
  // true when it refused.
  bool RefuseRateTerms(const UnloadingRefs& refs, std::string_view element);
  // E0512 at the function's E.1 card when it pushes the wrong way for `use` (as E0420 would).
  void CheckSign(const FunctionCard& function, const Ref& ref, Use use);
  // The largest friction coefficient the language takes (`friction`, 0 to 5).
  static constexpr double kMaxFriction = 5.0;
  // A friction coefficient from a constant function; zero for no function.
  std::optional<double> Friction(const Ref& ref);
  void MapRunSettings(ast::Block& body);
  ast::Expr SpringPolynomial(const JointSpring& spring, const std::string& value_unit,
                             const std::string& argument_unit);
  bool HasSpring(const JointSpring& spring) const;
  void AddSpring(ast::Statement& joint, const char* attribute, const JointSpring& spring,
                 bool slip = false);
  void MapBody(ast::Block& scenario);
  void MapVehicles(ast::Block& scenario);
  ast::Statement VehicleStatement(const VehicleCard& card, const std::string& name);
  // C cards with MSEG a body segment (map_prescribed.cpp): a vehicle of the card's motion and a
  // weld of the segment to it.
  void MapPrescribedSegments(ast::Block& scenario);
  // The C card that prescribes body segment `segment` (1-based), or null.
  const VehicleCard* PrescribedCard(int segment) const;
  void MapSurfaces(ast::Block& scenario);
  ast::Statement EllipsoidOn(const VehicleEllipsoidCard& card, const std::string& name,
                             const std::string& frame);
  // The surface of an F.3.b side: frame `frame` (a body segment or a vehicle) with ellipsoid
  // `ellipsoid` (0 or the frame's own number: the frame's own; at or above NGRND an extra D.5
  // ellipsoid, declared on this frame the first time a card puts it there). Empty after a report.
  std::string Surface(const Ref& frame, const Ref& ellipsoid, ast::Block& scenario);
  void MapRestraints(ast::Block& scenario);
  // D.9 (map_loads.cpp): `load NAME on SEGMENT { force  direction  point  frame = segment }`, or
  // a `torque` about an `axis`.
  void MapLoads(ast::Block& scenario);
  // F.10 (map_loads.cpp): `actuator NAME on JOINT { target  proportional  derivative  integral }`
  // with the signs of ATB's APPLY and JNTFNC.
  void MapActuators(ast::Block& scenario);
  // `at FIRST = ...` and `at SECOND = ...` of a spring or constraint.
  void AddAttachments(ast::Statement& statement, const std::string& first, const Vec3& at_first,
                      const std::string& second, const Vec3& at_second);
  std::string FrameName(const DeckFrame& frame) const;
  // D.4 and F.6: `airbag NAME on PRIMARY { model = atb_free ... }`, ATB's free bag, with the
  // cylinder's flow as a named inflow table.
  void MapAirbags(ast::Block& scenario);
  // D.6: `constraint constraint_N : fixed_point(A -> B) { at A = ...  at B = ... }`.
  void MapConstraints(ast::Block& scenario);
  void AddBeltAttributes(ast::Statement& belt, std::vector<ast::Expr> path, ast::Expr force,
                         double slack, double friction);
  // One friction coefficient for several points that each name a friction function; empty after
  // reporting a point whose coefficient differs from the first's.
  std::optional<double> CommonFriction(const std::vector<const Ref*>& refs, std::string_view what);
  // F.8: `harness NAME on FRAME { friction  belt NAME { path ... } }`, the harness friction from
  // its tie points, each belt's friction from the points it wraps.
  void MapHarnesses(ast::Block& scenario);
  // E.6, F.7 and F.9 (map_fluids.cpp): `wind { ... }` and `water { ... }`.
  const WindFunctionCard* WindFunction(const Ref& ref);
  bool IsGround(int number) const;
  std::string SegmentInFluid(const Ref& ref, const Ref& ellipsoid, std::string_view fluid,
                             std::string_view field);
  void MapWind(ast::Block& scenario);
  // One wind: the F.7.b cards that name the same wind and drag functions (map_fluids.cpp).
  void MapOneWind(ast::Block& scenario, const std::vector<const WindCard*>& cards);
  void MapWater(ast::Block& scenario);
  void MapFunctions(ast::Block& scenario);
  ast::Statement FunctionStatement(const FunctionCard& function, Use use, const std::string& name,
                                   const FunctionUnloading& unloading);
  // A function's declaration with its signature in the deck's units, its values times `sign`.
  ast::Statement FunctionDeclaration(const FunctionCard& function, const std::string& name,
                                     const std::string& argument_unit,
                                     const std::string& result_unit, const char* argument,
                                     const char* result, double sign,
                                     const FunctionUnloading& unloading);
  void MapInitial(ast::Block& scenario);
  // G.3.a of the segments that hang from joints (and B.4.b's Euler angles): `initial JOINT {
  // angles = ... }` where the deck's orientations turn a joint (map_posture.cpp).
  void MapPostures(ast::Block& scenario);
  // G.3.a angular velocities of the segments that hang from joints (with I3 not 0), given each
  // segment's axes in the ground's, `world` (map_posture.cpp).
  void MapJointRates(ast::Block& scenario, const std::vector<Mat>& world);
  void AddOrientation(ast::Statement& initial, std::size_t segment);
  // One H request. KREF 0 is each card's default: H.1 and H.4 in the segment's own axes (sled's
  // default too), the relative H.2, H.3, H.5 and H.6 relative to the primary vehicle.
  void MapOutput(const OutputCard& card, ast::Statement& block);
  void MapOutputs(ast::Block& scenario);
  // Adds one request of `card`; a second with the same column name is named with `as`, the
  // same request twice is added once.
  void AddRequest(ast::Statement& block, ast::Statement request, const OutputCard& card);
  struct FunctionUse {
    const FunctionCard* function;
    Use use;
    std::string name;
    FunctionUnloading unloading;
  };
  const Deck& deck_;
  DiagnosticConsumer& diagnostics_;
  const std::string L, F, T;
  std::set<std::string> taken_{"deck_g"};
  std::set<std::string> body_names_;
  std::string body_;
  std::vector<std::string> segments_, joints_, vehicles_, planes_, belts_;
  std::vector<std::string> prescribed_vehicles_;                    // by Deck::prescribed_segments
  std::map<int, std::string> vehicle_ellipsoid_names_;              // by 1-based vehicle
  std::map<std::pair<int, std::string>, std::string> extra_names_;  // (M, frame) -> name
  std::set<int> placed_extras_;
  // (number, use, ATB's law, R, G, spike) -> the declared name
  std::map<std::tuple<int, int, bool, FactorValue, FactorValue, FactorValue>, std::string>
      function_names_;
  // A spike's declaration is under way: its D3 is its end, not refused.
  bool declaring_spike_ = false;
  // (function, E.2 field) already reported, once for all its uses.
  std::set<std::pair<int, int>> reported_fields_;
  std::vector<FunctionUse> uses_;
  std::set<int> used_;
  std::vector<std::pair<std::string, std::string>> contact_outputs_;
  std::vector<std::string> belt_outputs_;
  std::map<std::string, std::set<std::string>> output_labels_;  // request -> its points
  std::set<std::string> taken_outputs_;                         // names given with `as`
};

}  // namespace sled::lang::legacy::mapping
