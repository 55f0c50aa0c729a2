// runtime::DumpModel: a stable text form of a Model for `sled check --dump-model` and golden
// tests, written by walking model_fields.h's list: a line per scalar group, the sizes, then a line
// per entity of each count with every listed field (a count of coordinates or table points is
// one line per field). Numbers in their shortest round-trip form; matrices row by row. Equal
// dumps mean equal models.
#include <string>
#include <type_traits>

#include <fmt/format.h>

#include "runtime/model/model.h"
#include "runtime/model/model_fields.h"
#include "runtime/run/relative_motion.h"

namespace sled::runtime {
namespace {

std::string Text(const std::string& text) { return fmt::format("\"{}\"", text); }

template <typename T>
requires std::is_arithmetic_v<T> std::string Text(T value) {
  if constexpr (std::is_floating_point_v<T>) {
    return fmt::format("{}", value);
  } else {
    return fmt::format("{}", static_cast<std::int64_t>(value));
  }
}

// Enums without a name table print their number.
template <typename T>
requires std::is_enum_v<T> std::string Text(T value) {
  return Text(static_cast<std::underlying_type_t<T>>(value));
}

std::string Text(const Vec3& v) { return fmt::format("({}, {}, {})", v.x(), v.y(), v.z()); }

std::string Text(const Mat3& m) {
  return fmt::format("[[{}, {}, {}], [{}, {}, {}], [{}, {}, {}]]", m(0, 0), m(0, 1), m(0, 2),
                     m(1, 0), m(1, 1), m(1, 2), m(2, 0), m(2, 1), m(2, 2));
}

std::string Text(const FrameRef& frame) {
  switch (frame.kind) {
    case FrameRef::Kind::kVehicle:
      return fmt::format("vehicle {}", frame.index);
    case FrameRef::Kind::kSegment:
      return fmt::format("segment {}", frame.index);
    case FrameRef::Kind::kGround:
      break;
  }
  return "ground";
}

std::string Text(const SourcePosition& source) {
  if (source.file.empty() && source.line == 0) return "-";
  return fmt::format("{}:{}:{}", source.file, source.line, source.column);
}

const char* Name(Model::ConstraintKind kind) {
  switch (kind) {
    case Model::ConstraintKind::kFixedPoint:
      return "fixed_point";
    case Model::ConstraintKind::kFixedDistance:
      return "fixed_distance";
    case Model::ConstraintKind::kRolling:
      return "rolling";
    case Model::ConstraintKind::kSliding:
      return "sliding";
  }
  return "?";
}

const char* Name(Model::OutputKind kind) {
  switch (kind) {
    case Model::OutputKind::kAcceleration:
      return "acceleration";
    case Model::OutputKind::kVelocity:
      return "velocity";
    case Model::OutputKind::kPosition:
      return "position";
    case Model::OutputKind::kAngularAcceleration:
      return "angular_acceleration";
    case Model::OutputKind::kAngularVelocity:
      return "angular_velocity";
    case Model::OutputKind::kOrientation:
      return "orientation";
    case Model::OutputKind::kJointAngle:
      return "joint_angle";
    case Model::OutputKind::kJointTorque:
      return "joint_torque";
    case Model::OutputKind::kJointForce:
      return "joint_force";
    case Model::OutputKind::kSpringForce:
      return "spring_force";
    case Model::OutputKind::kContactForce:
      return "contact_force";
    case Model::OutputKind::kContactPoint:
      return "contact_point";
    case Model::OutputKind::kContactDeflection:
      return "contact_deflection";
    case Model::OutputKind::kBeltForce:
      return "belt_force";
    case Model::OutputKind::kAirbagPressure:
      return "airbag_pressure";
    case Model::OutputKind::kAirbagVolume:
      return "airbag_volume";
    case Model::OutputKind::kAirbagGasMass:
      return "airbag_gas_mass";
    case Model::OutputKind::kAirbagTemperature:
      return "airbag_temperature";
    case Model::OutputKind::kAirbagVentFlow:
      return "airbag_vent_flow";
    case Model::OutputKind::kAirbagForce:
      return "airbag_force";
  }
  return "?";
}

std::string MotionText(const VehicleMotion& motion) {
  switch (motion.kind) {
    case VehicleMotion::Kind::kNone:
      return "none";
    case VehicleMotion::Kind::kHalfSine:
      return fmt::format("half_sine axis {} start {} delta_v {} duration {}", Text(motion.axis),
                         motion.start, motion.delta_v, motion.duration);
    case VehicleMotion::Kind::kTrapezoid:
      return fmt::format("trapezoid axis {} start {} peak {} rise {} dwell {} fall {}",
                         Text(motion.axis), motion.start, motion.peak, motion.rise, motion.dwell,
                         motion.fall);
    case VehicleMotion::Kind::kTable: {
      std::string out =
          fmt::format("table axis {} start {} rows [", Text(motion.axis), motion.start);
      for (std::size_t i = 0; i < motion.table.size(); ++i) {
        out +=
            fmt::format("{}({}, {})", i == 0 ? "" : ", ", motion.table[i][0], motion.table[i][1]);
      }
      return out + "]";
    }
    case VehicleMotion::Kind::kSixDof: {
      std::string out = fmt::format("six_dof start {} rows [", motion.start);
      for (std::size_t i = 0; i < motion.six_dof.size(); ++i) {
        const auto& r = motion.six_dof[i];
        out += fmt::format("{}({}, {}, {}, {}, {}, {}, {})", i == 0 ? "" : ", ", r[0], r[1], r[2],
                           r[3], r[4], r[5], r[6]);
      }
      return out + "]";
    }
  }
  return "?";
}

std::string Text(JointKind kind) { return JointKindName(kind); }
std::string Text(Model::ConstraintKind kind) { return Name(kind); }
std::string Text(Model::OutputKind kind) { return Name(kind); }

std::string Text(FunctionTable::Kind kind) {
  switch (kind) {
    case FunctionTable::Kind::kConstant:
      return "constant";
    case FunctionTable::Kind::kTable:
      return "table";
    case FunctionTable::Kind::kPolynomial:
      return "polynomial";
  }
  return Text(static_cast<int>(kind));
}

std::string Text(ContactTable::PairKind kind) {
  return kind == ContactTable::PairKind::kPlaneEllipsoid ? "plane_ellipsoid"
                                                         : "ellipsoid_ellipsoid";
}

std::string Text(const VehicleMotion& motion) { return MotionText(motion); }

// A turning vehicle's tabulated path is derived from its motion: its length says enough.
std::string Text(const std::vector<VehiclePathSample>& path) {
  return fmt::format("{}_samples", path.size());
}

template <typename T, std::size_t N>
std::string Text(const std::array<T, N>& values) {
  std::string out = "[";
  for (std::size_t i = 0; i < N; ++i) out += (i == 0 ? "" : ", ") + Text(values[i]);
  return out + "]";
}

template <typename T>
std::string List(const std::vector<T>& values) {
  std::string out = "[";
  for (std::size_t i = 0; i < values.size(); ++i) out += (i == 0 ? "" : ", ") + Text(values[i]);
  return out + "]";
}

// Counts whose entries are coordinates or table entries: one line per field, not per entry
// (none for an empty field).
bool Listed(ModelCount count) {
  return count == ModelCount::kPosition || count == ModelCount::kVelocity ||
         count == ModelCount::kAuxiliary || count == ModelCount::kFunctionPoint ||
         count == ModelCount::kCoefficient || count == ModelCount::kGroupPair;
}

constexpr ModelCount kFirstArrayCount = ModelCount::kSegment;
constexpr ModelCount kLastArrayCount = ModelCount::kCriterion;

std::string Dump(const Model& m, bool all_roles, FieldRole role) {
  std::string out;
  auto included = [&](const ModelField& field) { return all_roles || field.role == role; };
  for (const ModelCount line : {ModelCount::kScene, ModelCount::kRun, ModelCount::kSettle}) {
    std::string text;
    ForEachModelScalar(m, [&](const ModelField& field, const auto& member) {
      if (field.count == line && included(field))
        text += fmt::format(" {} {}", field.name, Text(member));
    });
    if (!text.empty()) out += CountName(line) + text + '\n';
  }
  if (all_roles) {
    out += "sizes";
    for (auto c = static_cast<int>(kFirstArrayCount); c <= static_cast<int>(kLastArrayCount); ++c) {
      const auto count = static_cast<ModelCount>(c);
      if (!CountMayBeEmpty(count))
        out += fmt::format(" {} {}", CountName(count), CountOf(m, count));
    }
    out += '\n';
  }
  for (auto c = static_cast<int>(kFirstArrayCount); c <= static_cast<int>(kLastArrayCount); ++c) {
    const auto count = static_cast<ModelCount>(c);
    if (Listed(count)) {
      ForEachModelArray(m, [&](const ModelField& field, const auto& member) {
        if (field.count == count && included(field) && !member.empty())
          out += fmt::format("{} {}\n", field.name, List(member));
      });
      continue;
    }
    for (std::size_t i = 0; i < CountOf(m, count); ++i) {
      std::string text;
      ForEachModelArray(m, [&](const ModelField& field, const auto& member) {
        if (field.count == count && included(field) && i < member.size()) {
          text += fmt::format(" {} {}", field.name, Text(member[i]));
        }
      });
      if (!text.empty()) out += fmt::format("{} {}{}\n", CountName(count), i, text);
    }
  }
  return out;
}

}  // namespace

std::string DumpModel(const Model& model) { return Dump(model, true, FieldRole::kPhysics); }

std::string DumpModelFields(const Model& model, FieldRole role) { return Dump(model, false, role); }

}  // namespace sled::runtime
