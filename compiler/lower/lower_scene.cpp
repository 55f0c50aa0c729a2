// Vehicles, spring–dampers, constraints, run settings and output requests; and the notes of
// what the Model leaves out.
#include <stdexcept>
#include <string>

#include <fmt/format.h>

#include "compiler/check/schema.h"
#include "compiler/lower/lowering.h"
#include "runtime/dynamics/mirror.h"
#include "runtime/dynamics/vehicle.h"
#include "runtime/run/relative_motion.h"

namespace sled::compiler::lowering {
namespace {

using runtime::Model;

runtime::VehicleMotion LowerMotion(const Motion& motion) {
  runtime::VehicleMotion out;
  switch (motion.kind) {
    case Motion::Kind::kNone:
      out.kind = runtime::VehicleMotion::Kind::kNone;
      break;
    case Motion::Kind::kHalfSine:
      out.kind = runtime::VehicleMotion::Kind::kHalfSine;
      break;
    case Motion::Kind::kTrapezoid:
      out.kind = runtime::VehicleMotion::Kind::kTrapezoid;
      break;
    case Motion::Kind::kTable:
      out.kind = runtime::VehicleMotion::Kind::kTable;
      break;
    case Motion::Kind::kSixDof:
      out.kind = runtime::VehicleMotion::Kind::kSixDof;
      break;
  }
  out.axis = ToEigen(motion.axis);
  out.start = motion.start;
  out.delta_v = motion.delta_v;
  out.duration = motion.duration;
  out.peak = motion.peak;
  out.rise = motion.rise;
  out.dwell = motion.dwell;
  out.fall = motion.fall;
  out.table = motion.table;
  out.six_dof = motion.six_dof;
  runtime::IntegrateMotionRows(out);
  return out;
}

void LowerVehicles(Lowering& lowering) {
  const CheckedScenario& scenario = lowering.scenario();
  Model& model = lowering.model();
  for (const Vehicle& vehicle : scenario.vehicles) {
    model.vehicle_name.push_back(vehicle.name);
    model.vehicle_motion.push_back(LowerMotion(vehicle.motion));
    model.vehicle_position.push_back(ToEigen(vehicle.position));
    model.vehicle_orientation.push_back(RotationMatrix(vehicle.orientation));
    model.vehicle_velocity.push_back(ToEigen(vehicle.velocity));
    model.vehicle_angular_velocity.push_back(runtime::Vec3::Zero());
  }
  for (const InitialCondition& initial : scenario.initial_conditions) {
    if (initial.kind != InitialCondition::Kind::kVehicle) continue;
    const auto v = static_cast<std::size_t>(initial.index);
    if (initial.position) model.vehicle_position.at(v) = ToEigen(*initial.position);
    if (initial.orientation) model.vehicle_orientation.at(v) = RotationMatrix(*initial.orientation);
    if (initial.velocity) model.vehicle_velocity.at(v) = ToEigen(*initial.velocity);
    if (initial.angular_velocity) {
      model.vehicle_angular_velocity.at(v) = ToEigen(*initial.angular_velocity);
    }
  }
  for (std::size_t v = 0; v < model.nvehicle(); ++v) {
    model.vehicle_path.push_back(runtime::TabulateVehiclePath(
        model.vehicle_motion[v], model.vehicle_orientation[v], model.vehicle_angular_velocity[v]));
  }
}

void LowerSprings(Lowering& lowering) {
  Model& model = lowering.model();
  for (const SpringDamper& spring : lowering.scenario().springs) {
    model.spring_name.push_back(spring.name);
    model.spring_first.push_back(lowering.Frame(spring.first));
    model.spring_second.push_back(lowering.Frame(spring.second));
    model.spring_point_first.push_back(ToEigen(spring.point_in_first));
    model.spring_point_second.push_back(ToEigen(spring.point_in_second));
    model.spring_function.push_back(lowering.Function(spring.stiffness));
    model.spring_damping.push_back(spring.damping);
    model.spring_free_length.push_back(
        spring.free_length ? *spring.free_length
                           : (lowering.WorldPoint(spring.first, spring.point_in_first) -
                              lowering.WorldPoint(spring.second, spring.point_in_second))
                                 .norm());
    model.spring_tension_only.push_back(spring.tension_only ? 1 : 0);
  }
}

// Applied loads: a segment's by its Model index; a joint's on the segment the joint carries,
// with its axis in the parent's frame (a pin's or slip's own axis, or the one the scene gives).
void LowerLoads(Lowering& lowering) {
  Model& model = lowering.model();
  runtime::LoadTable& loads = model.loads;
  for (const AppliedLoad& load : lowering.scenario().loads) {
    int segment = -1;
    runtime::LoadTable::Kind kind = runtime::LoadTable::Kind::kSegment;
    runtime::Vec3 axis = ToEigen(load.axis);
    if (load.across_joint) {
      for (std::size_t s = 0; s < lowering.joint_above.size(); ++s) {
        if (lowering.joint_above[s] == load.index) segment = static_cast<int>(s);
      }
      if (segment < 0) continue;  // a null joint's load is refused by the checker
      const auto s = static_cast<std::size_t>(segment);
      const JointType type = lowering.joint(load.index).type;
      if (type == JointType::kPin || type == JointType::kSlip) {
        axis = (model.joint_frame_in_parent[s] * model.joint_axis[s]).normalized();
      }
      kind = type == JointType::kSlip ? runtime::LoadTable::Kind::kJointForce
                                      : runtime::LoadTable::Kind::kJointTorque;
    } else {
      segment = lowering.new_index[static_cast<std::size_t>(load.index)];
    }
    loads.name.push_back(load.name);
    loads.source.push_back(lowering.Position(load.range));
    loads.kind.push_back(kind);
    loads.segment.push_back(segment);
    loads.force.push_back(lowering.Function(load.force));
    loads.torque.push_back(lowering.Function(load.torque));
    loads.direction.push_back(ToEigen(load.direction));
    loads.axis.push_back(axis);
    loads.point.push_back(ToEigen(load.point));
    loads.in_segment.push_back(load.in_segment ? 1 : 0);
  }
}

// Actuators: on the pin's child segment, with the pin's axis in the parent's frame; an integral
// gain adds the error's integral to the auxiliary states, starting at zero.
void LowerActuators(Lowering& lowering) {
  Model& model = lowering.model();
  runtime::ActuatorTable& table = model.actuators;
  for (const Actuator& actuator : lowering.scenario().actuators) {
    int segment = -1;
    for (std::size_t s = 0; s < lowering.joint_above.size(); ++s) {
      if (lowering.joint_above[s] == actuator.joint) segment = static_cast<int>(s);
    }
    if (segment < 0) continue;  // the checker refuses what is not a pin
    const auto s = static_cast<std::size_t>(segment);
    table.name.push_back(actuator.name);
    table.source.push_back(lowering.Position(actuator.range));
    table.segment.push_back(segment);
    table.axis.push_back((model.joint_frame_in_parent[s] * model.joint_axis[s]).normalized());
    table.target.push_back(lowering.Function(actuator.target));
    table.proportional.push_back(lowering.Function(actuator.proportional));
    table.derivative.push_back(lowering.Function(actuator.derivative));
    table.integral.push_back(lowering.Function(actuator.integral));
    table.state_address.push_back(actuator.integral >= 0 ? model.nw : -1);
    if (actuator.integral >= 0) {
      model.w0.push_back(0.0);
      ++model.nw;
    }
  }
}

void LowerConstraints(Lowering& lowering) {
  Model& model = lowering.model();
  for (std::size_t c = 0; c < lowering.scenario().constraints.size(); ++c) {
    // A constraint that became a root's joint to its base is no loop.
    if (lowering.constraint_is_base_joint[c]) continue;
    const Constraint& constraint = lowering.scenario().constraints[c];
    model.constraint_name.push_back(constraint.name);
    model.constraint_source.push_back(lowering.Position(constraint.range));
    switch (constraint.kind) {
      case Constraint::Kind::kFixedPoint:
        model.constraint_kind.push_back(Model::ConstraintKind::kFixedPoint);
        break;
      case Constraint::Kind::kFixedDistance:
        model.constraint_kind.push_back(Model::ConstraintKind::kFixedDistance);
        break;
      case Constraint::Kind::kRolling:
        throw std::logic_error("compiler::Lower: the checker refuses rolling constraints (E0422)");
      case Constraint::Kind::kSliding:
        model.constraint_kind.push_back(Model::ConstraintKind::kSliding);
        break;
      case Constraint::Kind::kWelded:
        throw std::logic_error(
            "compiler::Lower: a weld holds a reference segment to its base (E0426 otherwise)");
    }
    model.constraint_first.push_back(lowering.Frame(constraint.first));
    model.constraint_second.push_back(lowering.Frame(constraint.second));
    model.constraint_point_first.push_back(ToEigen(constraint.point_in_first));
    model.constraint_point_second.push_back(ToEigen(constraint.point_in_second));
    double distance = constraint.distance.value_or(0.0);
    if (constraint.kind == Constraint::Kind::kFixedDistance && !constraint.distance) {
      distance = (lowering.WorldPoint(constraint.first, constraint.point_in_first) -
                  lowering.WorldPoint(constraint.second, constraint.point_in_second))
                     .norm();
    }
    model.constraint_distance.push_back(distance);
    model.constraint_axis.push_back(ToEigen(constraint.axis));
  }
}

void LowerRunSettings(Lowering& lowering) {
  const RunSettings& run = lowering.scenario().run;
  Model& model = lowering.model();
  model.gravity = ToEigen(run.gravity);
  model.start_time = run.start;
  model.end_time = run.end;
  model.output_every = run.output_every;
  switch (run.method) {
    case IntegratorMethod::kAuto:
      model.integrator = "auto";
      break;
    case IntegratorMethod::kCvs:
      model.integrator = "cvs";
      break;
    case IntegratorMethod::kExponential:
      model.integrator = "exponential";
      break;
    case IntegratorMethod::kDormandPrince:
      model.integrator = "dopri5";
      break;
    case IntegratorMethod::kRosenbrock:
      model.integrator = "rosenbrock";
      break;
  }
  model.relative_tolerance = run.relative_tolerance;
  model.absolute_tolerance = run.absolute_tolerance;
  model.min_step = run.min_step;
  model.max_step = run.max_step.value_or(0.0);
  model.initial_step = run.initial_step.value_or(0.0);
  if (run.settle) {
    model.settle.duration = run.settle->duration;
    model.settle.damping = run.settle->damping;
    model.settle.velocity = run.settle->velocity;
    model.settle.angular_velocity = run.settle->angular_velocity;
    model.settle.force_change = run.settle->force_change;
  }
}

std::string_view OutputKeyword(OutputRequest::Kind kind) {
  return AllOutputSpecs().at(static_cast<std::size_t>(kind)).keyword;
}

void LowerOutputs(Lowering& lowering) {
  Model& model = lowering.model();
  for (const OutputRequest& output : lowering.scenario().outputs) {
    Model::OutputKind kind{};
    std::int32_t index = -1;
    bool mirrored = false;  // a right twin's output, read from its left twin
    using Kind = OutputRequest::Kind;
    switch (output.kind) {
      case Kind::kAcceleration:
      case Kind::kVelocity:
      case Kind::kPosition:
      case Kind::kAngularAcceleration:
      case Kind::kAngularVelocity:
      case Kind::kOrientation: {
        static constexpr Model::OutputKind kSegmentKinds[] = {
            Model::OutputKind::kAcceleration,    Model::OutputKind::kVelocity,
            Model::OutputKind::kPosition,        Model::OutputKind::kAngularAcceleration,
            Model::OutputKind::kAngularVelocity, Model::OutputKind::kOrientation};
        kind = kSegmentKinds[static_cast<int>(output.kind) - static_cast<int>(Kind::kAcceleration)];
        lowering.segment(output.index);
        mirrored = lowering.Dropped(output.index);
        index = lowering.new_index[static_cast<std::size_t>(
            mirrored ? lowering.mirror_twin[static_cast<std::size_t>(output.index)]
                     : output.index)];
        break;
      }
      case Kind::kJointAngle:
      case Kind::kJointTorque:
      case Kind::kJointForce: {
        kind = output.kind == Kind::kJointAngle    ? Model::OutputKind::kJointAngle
               : output.kind == Kind::kJointTorque ? Model::OutputKind::kJointTorque
                                                   : Model::OutputKind::kJointForce;
        const Joint& joint = lowering.joint(output.index);
        if (joint.type == JointType::kNull) {
          lowering.AddNote(lang::DiagnosticKind::kLeftOutOfModel, output.range,
                           fmt::format("`{} {}` is left out: `{}` is a null joint, which "
                                       "transmits no force",
                                       OutputKeyword(output.kind), output.label, joint.name));
          continue;
        }
        lowering.segment(joint.child);
        mirrored = lowering.Dropped(joint.child);
        index = lowering.new_index[static_cast<std::size_t>(
            mirrored ? lowering.mirror_twin[static_cast<std::size_t>(joint.child)] : joint.child)];
        break;
      }
      case Kind::kSpringForce:
        kind = Model::OutputKind::kSpringForce;
        index = output.index;
        if (index < 0 || static_cast<std::size_t>(index) >= model.nspring()) {
          throw std::logic_error(fmt::format("compiler::Lower: output `{}` names spring {} of {}",
                                             output.label, index, model.nspring()));
        }
        break;
      case Kind::kContactForce:
        LowerContactOutput(lowering, output);
        continue;
      case Kind::kBeltForce:
        kind = Model::OutputKind::kBeltForce;
        index = output.index;
        if (index < 0 || static_cast<std::size_t>(index) >= lowering.scenario().belts.size()) {
          throw std::logic_error(fmt::format("compiler::Lower: output `{}` names belt {} of {}",
                                             output.label, index,
                                             lowering.scenario().belts.size()));
        }
        break;
      case Kind::kAirbagPressure:
      case Kind::kAirbagVolume:
      case Kind::kAirbagGasMass:
      case Kind::kAirbagTemperature:
      case Kind::kAirbagVentFlow:
      case Kind::kAirbagForce: {
        index = lowering.airbag_index.at(static_cast<std::size_t>(output.index));
        if (index < 0) {
          lowering.AddNote(lang::DiagnosticKind::kLeftOutOfModel, output.range,
                           fmt::format("output `{} {}` is left out with its airbag",
                                       OutputKeyword(output.kind), output.label));
          continue;
        }
        kind = output.kind == Kind::kAirbagPressure      ? Model::OutputKind::kAirbagPressure
               : output.kind == Kind::kAirbagVolume      ? Model::OutputKind::kAirbagVolume
               : output.kind == Kind::kAirbagGasMass     ? Model::OutputKind::kAirbagGasMass
               : output.kind == Kind::kAirbagTemperature ? Model::OutputKind::kAirbagTemperature
               : output.kind == Kind::kAirbagVentFlow    ? Model::OutputKind::kAirbagVentFlow
                                                         : Model::OutputKind::kAirbagForce;
        break;
      }
    }
    // A point of the right twin lies in the left one's frame with y reversed.
    Lowering::Output lowered{
        kind,
        output.label,
        index,
        mirrored ? runtime::MirrorFrameVector(ToEigen(output.point)) : ToEigen(output.point),
        mirrored,
        FilterClassOf(output, kind),
        output.iso_filter,
        std::nullopt,
        false,
        0};
    if (output.relative_to) {
      // A right twin's frame is its left twin's, mirrored (runtime/run/relative_motion.h).
      FrameRef frame = *output.relative_to;
      lowered.frame_mirrored = lowering.Dropped(frame);
      if (lowered.frame_mirrored) {
        frame.index = lowering.mirror_twin[static_cast<std::size_t>(frame.index)];
      }
      lowered.frame = lowering.Frame(frame);
      lowered.frame_mode = static_cast<std::uint8_t>(output.expressed_in ? runtime::kExpressedIn
                                                                         : runtime::kRelativeTo);
    }
    lowering.AddOutput(lowered);
  }
}

}  // namespace

void LowerScene(Lowering& lowering) {
  LowerVehicles(lowering);
  LowerSprings(lowering);
  LowerLoads(lowering);
  LowerActuators(lowering);
  LowerConstraints(lowering);
  LowerRunSettings(lowering);
  LowerOutputs(lowering);
}

}  // namespace sled::compiler::lowering
