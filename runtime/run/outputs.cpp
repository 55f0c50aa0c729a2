#include "runtime/run/outputs.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "runtime/airbag/airbag_outputs.h"
#include "runtime/contact/contact_outputs.h"
#include "runtime/dynamics/joint.h"
#include "runtime/dynamics/mirror.h"
#include "runtime/forces/forces.h"
#include "runtime/restraint/belts.h"
#include "runtime/run/relative_motion.h"

namespace sled::runtime {
namespace {

struct ChannelGroup {
  const char* quantity;
  const char* unit;
  std::vector<const char*> components;
};

// The channels one request produces.
ChannelGroup GroupOf(const Model& model, std::size_t k) {
  static const std::vector<const char*> kXyz = {"x", "y", "z"};
  switch (model.output_kind[k]) {
    case Model::OutputKind::kAcceleration:
      return {"acceleration", "m/s^2", kXyz};
    case Model::OutputKind::kVelocity:
      return {"velocity", "m/s", kXyz};
    case Model::OutputKind::kPosition:
      return {"position", "m", kXyz};
    case Model::OutputKind::kAngularAcceleration:
      return {"angular_acceleration", "rad/s^2", kXyz};
    case Model::OutputKind::kAngularVelocity:
      return {"angular_velocity", "rad/s", kXyz};
    case Model::OutputKind::kOrientation:
      return {"orientation", "rad", {"yaw", "pitch", "roll"}};
    case Model::OutputKind::kJointAngle: {
      const auto s = static_cast<std::size_t>(model.output_index[k]);
      switch (model.joint_kind[s]) {
        case JointKind::kBall:
          return {"joint_angle", "rad", {"flexure", "twist"}};
        case JointKind::kEuler:
          return {"joint_angle", "rad", {"precession", "nutation", "spin"}};
        case JointKind::kSlip:
          return {"joint_displacement", "m", {"axis"}};
        default:
          return {"joint_angle", "rad", {"axis"}};
      }
    }
    case Model::OutputKind::kJointTorque:
      return {"joint_torque", "N*m", kXyz};
    case Model::OutputKind::kJointForce:
      return {"joint_force", "N", kXyz};
    case Model::OutputKind::kSpringForce:
      return {"spring_force", "N", {"axial"}};
    case Model::OutputKind::kContactForce:
      return {"contact_force", "N", {"x", "y", "z", "normal"}};
    case Model::OutputKind::kContactPoint:
      return {"contact_point", "m", kXyz};
    case Model::OutputKind::kContactDeflection:
      return {"contact_deflection", "m", {"normal"}};
      break;
    case Model::OutputKind::kBeltForce:
      return {"belt_force", "N", {}};  // named by AppendBeltChannelNames
    case Model::OutputKind::kAirbagPressure:
      return {"airbag_pressure", "Pa", {"gauge"}};
    case Model::OutputKind::kAirbagVolume:
      return {"airbag_volume", "m^3", {"gas"}};
    case Model::OutputKind::kAirbagGasMass:
      return {"airbag_gas_mass", "kg", {"inside"}};
    case Model::OutputKind::kAirbagTemperature:
      return {"airbag_temperature", "K", {"gas"}};
    case Model::OutputKind::kAirbagVentFlow:
      return {"airbag_vent_flow", "kg/s", {"out"}};
    case Model::OutputKind::kAirbagForce:
      return {"airbag_force", "N", {}};  // named by AppendAirbagForceChannelNames
  }
  return {"value", "", {"value"}};
}

bool IsRelative(const Model& model, std::size_t k) {
  return k < model.output_relative.size() && model.output_relative[k] != 0;
}

// A segment request `relative_to` a frame (the quantity seen from the frame, in its axes) or
// `expressed_in` it (the quantity relative to the ground, in the frame's axes). A right twin (of
// the body or the frame) is its left twin's motion reflected, and its point is in its own axes
// again.
Vec3 RelativeValue(const Model& model, const Data& data, std::size_t k) {
  const bool body_mirrored = !model.output_mirrored.empty() && model.output_mirrored[k] != 0;
  const FrameMotion body =
      WorldMotion(model, data, {FrameRef::Kind::kSegment, model.output_index[k]}, body_mirrored);
  const FrameMotion frame =
      WorldMotion(model, data, model.output_frame[k], model.output_frame_mirrored[k] != 0);
  const Vec3 point =
      body_mirrored ? MirrorFrameVector(model.output_point[k]) : Vec3(model.output_point[k]);
  if (model.output_relative[k] == kExpressedIn) {
    const FrameMotion ground;
    const Mat3 to_frame = frame.rotation.transpose();
    switch (model.output_kind[k]) {
      case Model::OutputKind::kVelocity:
        return to_frame * PointRelativeTo(body, point, ground).velocity;
      case Model::OutputKind::kAcceleration:
        return to_frame * PointRelativeTo(body, point, ground).acceleration;
      case Model::OutputKind::kAngularVelocity:
        return to_frame * body.angular_velocity;
      case Model::OutputKind::kAngularAcceleration:
        return to_frame * body.angular_acceleration;
      default:
        break;  // position and orientation take only `relative_to` (compiler/check)
    }
    return Vec3::Zero();
  }
  switch (model.output_kind[k]) {
    case Model::OutputKind::kPosition:
      return PointRelativeTo(body, point, frame).position;
    case Model::OutputKind::kVelocity:
      return PointRelativeTo(body, point, frame).velocity;
    case Model::OutputKind::kAcceleration:
      return PointRelativeTo(body, point, frame).acceleration;
    case Model::OutputKind::kOrientation:
      return YawPitchRoll(RotationRelativeTo(body, frame).rotation);
    case Model::OutputKind::kAngularVelocity:
      return RotationRelativeTo(body, frame).angular_velocity;
    case Model::OutputKind::kAngularAcceleration:
      return RotationRelativeTo(body, frame).angular_acceleration;
    default:
      break;
  }
  return Vec3::Zero();
}

}  // namespace

std::vector<std::string> ChannelNames(const Model& model) {
  std::vector<std::string> names;
  for (std::size_t k = 0; k < model.output_kind.size(); ++k) {
    if (model.output_kind[k] == Model::OutputKind::kBeltForce) {
      AppendBeltChannelNames(model, static_cast<std::size_t>(model.output_index[k]),
                             model.output_label[k], names);
      continue;
    }
    if (model.output_kind[k] == Model::OutputKind::kAirbagForce) {
      AppendAirbagForceChannelNames(model, static_cast<std::size_t>(model.output_index[k]),
                                    model.output_label[k], names);
      continue;
    }
    const ChannelGroup group = GroupOf(model, k);
    for (const char* component : group.components) {
      names.push_back(fmt::format("{}.{}.{} [{}]", model.output_label[k], group.quantity, component,
                                  group.unit));
    }
  }
  return names;
}

std::size_t ChannelCount(const Model& model, std::size_t group) {
  // Belts and airbag forces name their channels themselves: count those names.
  std::vector<std::string> names;
  const auto index = static_cast<std::size_t>(model.output_index[group]);
  switch (model.output_kind[group]) {
    case Model::OutputKind::kBeltForce:
      AppendBeltChannelNames(model, index, model.output_label[group], names);
      return names.size();
    case Model::OutputKind::kAirbagForce:
      AppendAirbagForceChannelNames(model, index, model.output_label[group], names);
      return names.size();
    default:
      return GroupOf(model, group).components.size();
  }
}

void EvaluateChannels(const Model& model, const Data& data, std::span<double> values) {
  std::size_t column = 0;
  bool mirrored = false;
  // A right twin's output: the left segment's value, mirrored as the quantity's kind says.
  auto put = [&](const Vec3& v, Vec3 (*mirror)(const Vec3&)) {
    const Vec3 out = mirrored ? mirror(v) : v;
    for (int i = 0; i < 3; ++i) values[column++] = out[i];
  };
  for (std::size_t k = 0; k < model.output_kind.size(); ++k) {
    mirrored = k < model.output_mirrored.size() && model.output_mirrored[k] != 0;
    const auto index = static_cast<std::size_t>(model.output_index[k]);
    const Vec3& point = model.output_point[k];
    if (IsRelative(model, k)) {
      mirrored = false;  // RelativeValue reflects right twins itself
      put(RelativeValue(model, data, k), nullptr);
      continue;
    }
    switch (model.output_kind[k]) {
      case Model::OutputKind::kAcceleration: {
        // Classical acceleration of a body-fixed point, from the spatial acceleration.
        const Vec3 w = data.velocity[index].head<3>();
        const Vec3 v = data.velocity[index].tail<3>();
        const Vec3 alpha = data.acceleration[index].head<3>();
        const Vec3 a = data.acceleration[index].tail<3>();
        put(a + w.cross(v) + alpha.cross(point) + w.cross(w.cross(point)), MirrorFrameVector);
        break;
      }
      case Model::OutputKind::kVelocity: {
        const PointState state =
            PointInFrame(data, {FrameRef::Kind::kSegment, model.output_index[k]}, point);
        put(state.velocity, MirrorWorldVector);
        break;
      }
      case Model::OutputKind::kPosition: {
        const PointState state =
            PointInFrame(data, {FrameRef::Kind::kSegment, model.output_index[k]}, point);
        // The mirror plane is y = mirror_plane_y of the ground.
        put(mirrored ? Vec3(state.position + Vec3(0, -2 * model.mirror_plane_y, 0))
                     : state.position,
            MirrorWorldVector);
        break;
      }
      case Model::OutputKind::kAngularAcceleration:
        put(data.acceleration[index].head<3>(), MirrorFramePseudovector);
        break;
      case Model::OutputKind::kAngularVelocity:
        put(data.velocity[index].head<3>(), MirrorFramePseudovector);
        break;
      case Model::OutputKind::kOrientation:
        put(YawPitchRoll(data.rotation[index]), MirrorYawPitchRoll);
        break;
      case Model::OutputKind::kJointAngle: {
        const auto qa = static_cast<std::size_t>(model.q_address[index]);
        switch (model.joint_kind[index]) {
          case JointKind::kBall: {
            const SwingTwist angles = DecomposeSwingTwist(QuaternionAt(data.q, qa).normalized());
            values[column++] = angles.flexure;
            values[column++] = angles.twist;
            break;
          }
          case JointKind::kEuler:
            for (std::size_t i = 0; i < 3; ++i) values[column++] = data.q[qa + i];
            break;
          default:
            values[column++] = data.q[qa];
            break;
        }
        break;
      }
      case Model::OutputKind::kJointTorque: {
        // The wrench at the centre of mass, moved to the joint point.
        const Vec6& wrench = data.joint_wrench[index];
        const Vec3& joint_point = model.joint_point_in_child[index];
        put(wrench.head<3>() - joint_point.cross(wrench.tail<3>()), MirrorFramePseudovector);
        break;
      }
      case Model::OutputKind::kJointForce:
        put(data.joint_wrench[index].tail<3>(), MirrorFrameVector);
        break;
      case Model::OutputKind::kSpringForce:
        values[column++] = data.spring_force[index];
        break;
      case Model::OutputKind::kContactForce: {
        const ContactGroupValues contact = EvaluateContactGroup(model, data, index);
        put(contact.force, MirrorWorldVector);
        values[column++] = contact.normal_force;
        break;
      }
      case Model::OutputKind::kContactPoint:
        put(EvaluateContactGroup(model, data, index).point, MirrorWorldVector);
        break;
      case Model::OutputKind::kContactDeflection:
        values[column++] = EvaluateContactGroup(model, data, index).deflection;
        break;
      case Model::OutputKind::kBeltForce:
        column += WriteBeltChannels(model, data, index, values.subspan(column));
        break;
      case Model::OutputKind::kAirbagPressure:
        values[column++] = data.airbags.pressure[index] - model.airbags.ambient_pressure[index];
        break;
      case Model::OutputKind::kAirbagVolume:
        values[column++] = data.airbags.volume[index];
        break;
      case Model::OutputKind::kAirbagGasMass:
        values[column++] = data.w[static_cast<std::size_t>(model.airbags.state_address[index])];
        break;
      case Model::OutputKind::kAirbagTemperature:
        values[column++] = data.airbags.temperature[index];
        break;
      case Model::OutputKind::kAirbagVentFlow:
        values[column++] = data.airbags.vent_flow[index];
        break;
      case Model::OutputKind::kAirbagForce:
        column += WriteAirbagForceChannels(model, data, index, values.subspan(column));
        break;
    }
  }
}

}  // namespace sled::runtime
