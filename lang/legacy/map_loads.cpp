// DeckMapper (deck_mapper.h), card D.9: ATB's applied forces and torques as `load` statements.
// FORCE_TORQUE turns the direction (the x axis of the card's yaw, pitch and roll, in the
// segment's axes) with the segment, so every load is `frame = segment`; a force acts at the
// card's point, a torque (NFVSEG < 0) about the direction.
#include "lang/legacy/deck_mapper.h"

#include <cstdlib>
#include <string>

#include <fmt/format.h>

#include "lang/legacy/ast_pieces.h"

namespace sled::lang::legacy::mapping {

void DeckMapper::MapLoads(ast::Block& scenario) {
  for (std::size_t k = 0; k < deck_.loads.size(); ++k) {
    const LoadCard& card = deck_.loads[k];
    Ref segment_ref = card.segment;
    segment_ref.number = std::abs(segment_ref.number);
    const std::string segment = Segment(segment_ref, "NFVSEG");
    if (segment.empty()) continue;
    const bool torque = card.torque();
    auto function = FunctionFor(card.function, torque ? Use::kLoadTorque : Use::kLoadForce);
    if (!function) continue;
    const std::string name = NameOf(fmt::format("load_{}", k + 1), "load", taken_);
    ast::Statement load = Declaration("load", Path(name), CardComment("D.9", card.line));
    load.clauses.push_back({"on", {}, Path(segment)});
    const Vec3 direction = TurnedX(card.orientation[0], card.orientation[1]);
    if (torque) {
      Add(load, Attribute("torque", std::move(*function)));
      Add(load, Attribute("axis", Vector(direction, "")));
    } else {
      Add(load, Attribute("force", std::move(*function)));
      Add(load, Attribute("direction", Vector(direction, "")));
      if (!IsZero(card.point)) Add(load, Attribute("point", Vector(card.point, L)));
    }
    Add(load, Attribute("frame", Path("segment")));
    scenario.statements.push_back(std::move(load));
  }
}

}  // namespace sled::lang::legacy::mapping

namespace sled::lang::legacy::mapping {
namespace {

bool IsZeroFunction(const FunctionCard& function) {
  switch (function.form) {
    case FunctionCard::Form::kConstant:
      return function.constant == 0;
    case FunctionCard::Form::kPolynomial:
      for (const double c : function.coefficients) {
        if (c != 0) return false;
      }
      return true;
    case FunctionCard::Form::kTable:
      for (const auto& point : function.points) {
        if (point.second != 0) return false;
      }
      return true;
  }
  return false;
}

}  // namespace

// F.10. ATB's torque T = P (th - th0) - D (th' - th0') - I S (ACTUATOR_TORQUE) has th the
// pin's angle as sled measures it (JNTFNC signs the angle from x1 to x2 by the axis) but th'
// the rate of the opposite sense ((w1 - w2) along the axis), and APPLY adds T to the base
// segment and -T to the other. sled's child gets -kp (th - th0) - kd (th' - th0') - ki S, so a
// proximal base gives kp = P, kd = D, ki = -I, a distal base kp = -P, kd = -D, ki = I: exact
// but for the target's rate th0', which enters ATB's derivative term with the other sign
// either way. S is one sum for every actuator in ATB.
void DeckMapper::MapActuators(ast::Block& scenario) {
  const std::size_t count = deck_.actuators.size();
  for (std::size_t k = 0; k < count; ++k) {
    const ActuatorCard& card = deck_.actuators[k];
    const std::string joint = Joint(card.joint);
    const FunctionCard* target = Function(card.target);
    const FunctionCard* derivative = Function(card.derivative);
    const FunctionCard* integral = Function(card.integral);
    if (joint.empty() || target == nullptr || derivative == nullptr || integral == nullptr) {
      continue;
    }
    const bool integrates = !IsZeroFunction(*integral);
    if (integrates && k + 1 < count) {
      Report(DiagnosticKind::kDeckNotExpressible, card.integral,
             fmt::format("card {}: actuator {} has an integral gain (function {}), but ATB's "
                         "integral is one running sum that every actuator adds to and the last "
                         "one (actuator {}) carries from step to step (ACTUATOR_TORQUE, "
                         "UPDATE): this actuator's integral term is the last one's error, "
                         "which sled's actuator does not express",
                         card.integral.card, k + 1, card.integral.number, count),
             "give every actuator but the last an integral function that is 0");
      continue;
    }
    const bool proximal = card.base_is_proximal;
    auto target_name = FunctionFor(card.target, Use::kActuatorTarget);
    auto proportional =
        FunctionFor(card.proportional,
                    proximal ? Use::kActuatorProportional : Use::kActuatorProportionalNegated);
    auto rate_gain = FunctionFor(
        card.derivative, proximal ? Use::kActuatorDerivative : Use::kActuatorDerivativeNegated);
    if (!target_name || !proportional || !rate_gain) continue;
    const std::string name = NameOf(fmt::format("actuator_{}", k + 1), "actuator", taken_);
    ast::Statement actuator = Declaration(
        "actuator", Path(name),
        CardComment("F.10", card.line) +
            fmt::format(": base segment {} ({}); the signs are ATB's (APPLY, JNTFNC): {}",
                        card.base.number, proximal ? "proximal" : "distal",
                        proximal ? "positive P and D drive the joint towards its target, a "
                                   "positive I away from it"
                                 : "positive P and D drive the joint away from its target, a "
                                   "positive I towards it"));
    actuator.clauses.push_back({"on", {}, Path(joint)});
    Add(actuator, Attribute("target", std::move(*target_name)));
    Add(actuator, Attribute("proportional", std::move(*proportional)));
    Add(actuator, Attribute("derivative", std::move(*rate_gain)));
    if (integrates) {
      auto integral_gain = FunctionFor(
          card.integral, proximal ? Use::kActuatorIntegralNegated : Use::kActuatorIntegral);
      if (!integral_gain) continue;
      Add(actuator, Attribute("integral", std::move(*integral_gain)));
      Report(DiagnosticKind::kDeckApproximated, card.integral,
             fmt::format("card {}: ATB's integral term sums (th - th0) times each step's length "
                         "at the step's end (ACTUATOR_TORQUE, UPDATE), sled integrates it with "
                         "the motion under the error control: the two differ by about half a "
                         "step times the change of th - th0 (the step at most HMAX, {} {})",
                         card.integral.card, deck_.max_step, T));
    } else {
      used_.insert(integral->number);
    }
    if (!IsZeroFunction(*derivative) && target->form != FunctionCard::Form::kConstant) {
      Report(DiagnosticKind::kDeckApproximated, card.derivative,
             fmt::format("card {}: ATB's derivative term is D (th' + th0') in sled's senses, as "
                         "JNTFNC measures the rate th' in the sense opposite to the angle, "
                         "sled's D (th' - th0'): the torques differ by 2 D th0' while the "
                         "target (function {}) moves",
                         card.derivative.card, card.target.number));
    }
    scenario.statements.push_back(std::move(actuator));
  }
}

}  // namespace sled::lang::legacy::mapping
