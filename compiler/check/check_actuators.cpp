// Joint actuators: `actuator NAME on JOINT { target = ...  proportional = ... }` drives a pin
// joint's angle towards a target angle that is a function of time with a PID torque whose gains
// are functions of the target angle (runtime/forces/actuators.h). Only a pin has the one angle
// the law is written for: any other joint is E0205.
#include <fmt/format.h>

#include "compiler/check/checkers.h"

namespace sled::compiler::internal {

void LoadChecker::CheckActuators() {
  for (const Pending& pending : actuators_) {
    Actuator& actuator = scenario_.actuators[static_cast<std::size_t>(pending.index)];
    Scope& scope = *pending.scope;
    const ast::Statement& statement = *pending.statement;
    const BoundBlock bound = Bind(BlockKind::kActuator, statement.block.get(), statement.range);
    actuator.range = statement.range;
    const auto target = ReadFunction(scope, bound, BlockKind::kActuator, "target");
    const auto proportional = ReadFunction(scope, bound, BlockKind::kActuator, "proportional");
    const auto derivative = ReadFunction(scope, bound, BlockKind::kActuator, "derivative");
    const auto integral = ReadFunction(scope, bound, BlockKind::kActuator, "integral");
    RefuseUnloading(target, bound, "target", "an actuator");
    RefuseUnloading(proportional, bound, "proportional", "an actuator");
    RefuseUnloading(derivative, bound, "derivative", "an actuator");
    RefuseUnloading(integral, bound, "integral", "an actuator");
    actuator.target = target.value_or(-1);
    actuator.proportional = proportional.value_or(-1);
    actuator.derivative = derivative.value_or(-1);
    actuator.integral = integral.value_or(-1);
    const ast::Clause* on = statement.FindClause("on");
    if (!on) {
      Report(DiagnosticKind::kMalformedStatement, statement.range,
             "an actuator names the joint it drives: `actuator NAME on JOINT { ... }`", "no `on`",
             "add `on` and a pin joint");
      continue;
    }
    Entity* joint = Resolve(scope, on->value, {EntityKind::kJoint});
    if (!joint) continue;
    actuator.joint = joint->index;
    const Joint& driven = scenario_.joints[static_cast<std::size_t>(joint->index)];
    if (driven.type != JointType::kPin) {
      Report(DiagnosticKind::kWrongKindOfName, on->value.range,
             fmt::format("actuator `{}` drives `{}`, which is not a pin joint", actuator.name,
                         driven.name),
             "not a pin",
             "an actuator turns a pin about its axis; drive another joint with a `load NAME on "
             "JOINT { torque = ... }`");
    }
  }
}

}  // namespace sled::compiler::internal
