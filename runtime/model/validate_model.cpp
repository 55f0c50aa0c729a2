// runtime::ValidateModel: every array of model_fields.h's list against its count, every index
// against what it indexes, every number finite (and not negative where the list says so), then
// the structure no single field shows: the tree order, the coordinate addresses, the ranges of
// table points, belt points and airbag contacts, and what each output and contact pair refers to.
#include <cmath>
#include <string>
#include <type_traits>
#include <vector>

#include <fmt/format.h>

#include "runtime/model/model.h"
#include "runtime/model/model_fields.h"

namespace sled::runtime {
namespace {

constexpr std::size_t kMostErrors = 20;

class Validator {
 public:
  explicit Validator(const Model& model) : model_(model) {}

  std::string Run() {
    ForEachModelArray(
        model_, [&](const ModelField& field, const auto& member) { CheckArray(field, member); });
    ForEachModelScalar(model_, [&](const ModelField& field, const auto& member) {
      CheckValue(field, field.name, member);
    });
    // The structure is read only from arrays of the right size.
    if (errors_.empty()) CheckStructure();
    std::string out;
    for (std::size_t i = 0; i < errors_.size() && i < kMostErrors; ++i) {
      out += (i == 0 ? "" : "\n") + errors_[i];
    }
    if (errors_.size() > kMostErrors) {
      out += fmt::format("\n(and {} more)", errors_.size() - kMostErrors);
    }
    return out;
  }

 private:
  template <typename T>
  void CheckArray(const ModelField& field, const std::vector<T>& values) {
    const std::size_t expected = CountOf(model_, field.count);
    if (values.size() != expected && !(values.empty() && CountMayBeEmpty(field.count))) {
      Error("Model.{} has {} entries where the model's {} count is {}", field.name, values.size(),
            CountName(field.count), expected);
      return;
    }
    for (std::size_t i = 0; i < values.size(); ++i) {
      CheckValue(field, fmt::format("{}[{}]", field.name, i), values[i]);
    }
  }

  template <typename... Args>
  void Error(fmt::format_string<Args...> format, Args&&... args) {
    errors_.push_back(fmt::format(format, std::forward<Args>(args)...));
  }

  void CheckValue(const ModelField& field, const std::string& where, double value) {
    if (std::isnan(value) && (field.checks & kNanAllowed) != 0) return;
    if (!std::isfinite(value)) {
      Error("Model.{} = {}: not a finite number", where, value);
    } else if ((field.checks & kNonNegative) != 0 && value < 0) {
      Error("Model.{} = {}: must not be negative", where, value);
    }
  }
  template <typename T>
  requires std::is_integral_v<T> || std::is_enum_v<T>
  void CheckValue(const ModelField& field, const std::string& where, T value) {
    if constexpr (std::is_integral_v<T>) {
      if (field.indexes != ModelCount::kNone) {
        CheckIndex(where, static_cast<std::int64_t>(value), field.indexes,
                   (field.checks & kOrNone) != 0);
      } else if ((field.checks & kNonNegative) != 0 && value < 0) {
        Error("Model.{} = {}: must not be negative", where, value);
      }
    }
  }
  template <typename Derived>
  void CheckValue(const ModelField& field, const std::string& where,
                  const Eigen::MatrixBase<Derived>& value) {
    if (!value.allFinite()) {
      Error("Model.{} has a component that is not a finite number", where);
    } else if ((field.checks & kNonNegative) != 0 && value.minCoeff() < 0) {
      Error("Model.{} has a negative component", where);
    }
  }
  template <typename T, std::size_t N>
  void CheckValue(const ModelField& field, const std::string& where, const std::array<T, N>& v) {
    for (std::size_t k = 0; k < N; ++k) CheckValue(field, fmt::format("{}[{}]", where, k), v[k]);
  }
  void CheckValue(const ModelField& /*field*/, const std::string& where, const FrameRef& frame) {
    if (frame.kind == FrameRef::Kind::kVehicle) {
      CheckIndex(where + ".index", frame.index, ModelCount::kVehicle, false);
    } else if (frame.kind == FrameRef::Kind::kSegment) {
      CheckIndex(where + ".index", frame.index, ModelCount::kSegment, false);
    }
  }
  void CheckValue(const ModelField& field, const std::string& where, const VehicleMotion& motion) {
    for (const double value : {motion.start, motion.delta_v, motion.duration, motion.peak,
                               motion.rise, motion.dwell, motion.fall}) {
      CheckValue(field, where, value);
    }
    CheckValue(field, where + ".axis", motion.axis);
    for (const auto& row : motion.table) CheckValue(field, where + ".table", row);
    for (const auto& row : motion.six_dof) CheckValue(field, where + ".six_dof", row);
  }
  void CheckValue(const ModelField& field, const std::string& where,
                  const std::vector<VehiclePathSample>& path) {
    for (const VehiclePathSample& sample : path) {
      CheckValue(field, where, sample.t);
      CheckValue(field, where, sample.rotation.coeffs());
      CheckValue(field, where, sample.angular_velocity);
      CheckValue(field, where, sample.displacement);
      CheckValue(field, where, sample.velocity);
    }
  }
  void CheckValue(const ModelField&, const std::string&, const std::string&) {}
  void CheckValue(const ModelField&, const std::string&, const SourcePosition&) {}

  void CheckIndex(const std::string& where, std::int64_t index, ModelCount target, bool or_none) {
    const auto count = static_cast<std::int64_t>(CountOf(model_, target));
    if ((index >= 0 && index < count) || (or_none && index == -1)) return;
    Error("Model.{} = {}: not a {} index (the model has {}{})", where, index, CountName(target),
          count, or_none ? "; -1 for none" : "");
  }

  // [first, first + count) within [0, size).
  void CheckRange(const std::string& what, std::int64_t first, std::int64_t count,
                  std::size_t size) {
    if (first < 0 || count < 0 || first + count > static_cast<std::int64_t>(size)) {
      Error("Model.{}: entries {}..{} are outside the {} there are", what, first, first + count,
            size);
    }
  }

  void CheckStructure() {
    const Model& m = model_;
    for (std::size_t s = 0; s < m.nsegment(); ++s) {
      if (m.segment_parent[s] >= static_cast<std::int32_t>(s)) {
        Error("Model.segment_parent[{}] = {}: a parent must come before its child", s,
              m.segment_parent[s]);
      }
      if (m.q_count[s] != PositionCount(m.joint_kind[s]) ||
          m.v_count[s] != VelocityCount(m.joint_kind[s])) {
        Error("Model.q_count[{}], v_count[{}] = {}, {}: a {} joint has {} and {}", s, s,
              m.q_count[s], m.v_count[s], JointKindName(m.joint_kind[s]),
              PositionCount(m.joint_kind[s]), VelocityCount(m.joint_kind[s]));
      }
      CheckRange(fmt::format("q_address[{}]", s), m.q_address[s], m.q_count[s],
                 CountOf(m, ModelCount::kPosition));
      CheckRange(fmt::format("v_address[{}]", s), m.v_address[s], m.v_count[s],
                 CountOf(m, ModelCount::kVelocity));
    }
    const FunctionTable& f = m.functions;
    for (std::size_t i = 0; i < f.size(); ++i) {
      if (f.kind[i] == FunctionTable::Kind::kTable) {
        CheckRange(fmt::format("functions.first[{}] (table)", i), f.first[i], f.count[i],
                   f.points_x.size());
      } else if (f.kind[i] == FunctionTable::Kind::kPolynomial) {
        CheckRange(fmt::format("functions.first[{}] (polynomial)", i), f.first[i], f.count[i],
                   f.coefficients.size());
      }
    }
    const BeltTable& belts = m.belts;
    for (std::size_t b = 0; b < belts.size(); ++b) {
      CheckRange(fmt::format("belts.first_point[{}]", b), belts.first_point[b],
                 belts.point_count[b], belts.npoint());
      if (belts.point_count[b] < 2) {
        Error("Model.belts.point_count[{}] = {}: a belt runs between two anchors at least", b,
              belts.point_count[b]);
      }
    }
    const AirbagTable& bags = m.airbags;
    for (std::size_t b = 0; b < bags.size(); ++b) {
      CheckRange(fmt::format("airbags.first_contact[{}]", b), bags.first_contact[b],
                 bags.contact_count[b], bags.ncontact());
      CheckRange(fmt::format("airbags.state_address[{}]", b), bags.state_address[b],
                 bags.state_count(b), CountOf(m, ModelCount::kAuxiliary));
    }
    const ContactTable& contacts = m.contacts;
    for (std::size_t k = 0; k < contacts.npair(); ++k) {
      const bool plane = contacts.pair_kind[k] == ContactTable::PairKind::kPlaneEllipsoid;
      CheckIndex(fmt::format("contacts.pair_second[{}]", k), contacts.pair_second[k],
                 plane ? ModelCount::kPlane : ModelCount::kEllipsoid, false);
    }
    for (std::size_t g = 0; g < contacts.group_first.size(); ++g) {
      CheckRange(fmt::format("contacts.group_first[{}]", g), contacts.group_first[g],
                 contacts.group_count[g], contacts.group_pairs.size());
    }
    for (std::size_t o = 0; o < m.output_kind.size(); ++o) {
      CheckIndex(fmt::format("output_index[{}]", o), m.output_index[o],
                 OutputTarget(m.output_kind[o]), false);
    }
  }

  // What an output's index refers to, by its kind.
  static ModelCount OutputTarget(Model::OutputKind kind) {
    using K = Model::OutputKind;
    switch (kind) {
      case K::kSpringForce:
        return ModelCount::kSpring;
      case K::kContactForce:
      case K::kContactPoint:
      case K::kContactDeflection:
        return ModelCount::kContactGroup;
      case K::kBeltForce:
        return ModelCount::kBelt;
      case K::kAirbagPressure:
      case K::kAirbagVolume:
      case K::kAirbagGasMass:
      case K::kAirbagTemperature:
      case K::kAirbagVentFlow:
      case K::kAirbagForce:
        return ModelCount::kAirbag;
      default:
        return ModelCount::kSegment;  // a segment, or a joint by its child segment
    }
  }

  const Model& model_;
  std::vector<std::string> errors_;
};

}  // namespace

std::string ValidateModel(const Model& model) { return Validator(model).Run(); }

}  // namespace sled::runtime
