// The counts of model_fields.h's list and the fingerprint hash that walks it.
#include "runtime/model/model_fields.h"

#include <algorithm>
#include <type_traits>

namespace sled::runtime {

const char* CountName(ModelCount count) {
  switch (count) {
    case ModelCount::kNone:
      return "none";
    case ModelCount::kSegment:
      return "segment";
    case ModelCount::kJoint:
      return "joint";
    case ModelCount::kMirror:
      return "mirror";
    case ModelCount::kSegmentDummy:
      return "segment_dummy";
    case ModelCount::kPosition:
      return "position";
    case ModelCount::kVelocity:
      return "velocity";
    case ModelCount::kAuxiliary:
      return "auxiliary_state";
    case ModelCount::kVehicle:
      return "vehicle";
    case ModelCount::kFunction:
      return "function";
    case ModelCount::kFunctionUnload:
      return "function_unload";
    case ModelCount::kFunctionPoint:
      return "function_point";
    case ModelCount::kCoefficient:
      return "function_coefficient";
    case ModelCount::kSpring:
      return "spring";
    case ModelCount::kEllipsoid:
      return "contact_ellipsoid";
    case ModelCount::kPlane:
      return "contact_plane";
    case ModelCount::kPair:
      return "contact_pair";
    case ModelCount::kPairRate:
      return "contact_pair_rate";
    case ModelCount::kContactGroup:
      return "contact_group";
    case ModelCount::kGroupPair:
      return "contact_group_pair";
    case ModelCount::kBelt:
      return "belt";
    case ModelCount::kBeltPoint:
      return "belt_point";
    case ModelCount::kHarness:
      return "harness";
    case ModelCount::kTie:
      return "tie";
    case ModelCount::kAirbag:
      return "airbag";
    case ModelCount::kAirbagContact:
      return "airbag_contact";
    case ModelCount::kLoad:
      return "load";
    case ModelCount::kActuator:
      return "actuator";
    case ModelCount::kFluid:
      return "fluid";
    case ModelCount::kShape:
      return "shape";
    case ModelCount::kConstraint:
      return "constraint";
    case ModelCount::kOutput:
      return "output";
    case ModelCount::kOutputMirror:
      return "output_mirror";
    case ModelCount::kOutputFrame:
      return "output_frame";
    case ModelCount::kOutputFilter:
      return "output_filter";
    case ModelCount::kCriterion:
      return "criterion";
    case ModelCount::kRun:
      return "run";
    case ModelCount::kSettle:
      return "settle";
    case ModelCount::kScene:
      return "scene";
  }
  return "?";
}

std::size_t CountOf(const Model& m, ModelCount count) {
  switch (count) {
    case ModelCount::kSegment:
    case ModelCount::kJoint:
    case ModelCount::kMirror:
    case ModelCount::kSegmentDummy:
      return m.segment_name.size();
    case ModelCount::kPosition:
      return static_cast<std::size_t>(std::max(m.nq, 0));
    case ModelCount::kVelocity:
      return static_cast<std::size_t>(std::max(m.nv, 0));
    case ModelCount::kAuxiliary:
      return static_cast<std::size_t>(std::max(m.nw, 0));
    case ModelCount::kVehicle:
      return m.vehicle_name.size();
    case ModelCount::kFunction:
    case ModelCount::kFunctionUnload:
      return m.functions.kind.size();
    case ModelCount::kFunctionPoint:
      return m.functions.points_x.size();
    case ModelCount::kCoefficient:
      return m.functions.coefficients.size();
    case ModelCount::kSpring:
      return m.spring_name.size();
    case ModelCount::kEllipsoid:
      return m.contacts.ellipsoid_name.size();
    case ModelCount::kPlane:
      return m.contacts.plane_name.size();
    case ModelCount::kPair:
    case ModelCount::kPairRate:
      return m.contacts.pair_kind.size();
    case ModelCount::kContactGroup:
      return m.contacts.group_first.size();
    case ModelCount::kGroupPair:
      return m.contacts.group_pairs.size();
    case ModelCount::kBelt:
      return m.belts.name.size();
    case ModelCount::kBeltPoint:
      return m.belts.point_wraps.size();
    case ModelCount::kHarness:
      return m.belts.harness_name.size();
    case ModelCount::kTie:
      return m.belts.tie_points.size();
    case ModelCount::kAirbag:
      return m.airbags.name.size();
    case ModelCount::kAirbagContact:
      return m.airbags.contact_segment.size();
    case ModelCount::kLoad:
      return m.loads.name.size();
    case ModelCount::kActuator:
      return m.actuators.name.size();
    case ModelCount::kFluid:
      return m.fluids.medium.size();
    case ModelCount::kShape:
      return m.shape_name.size();
    case ModelCount::kConstraint:
      return m.constraint_name.size();
    case ModelCount::kOutput:
    case ModelCount::kOutputMirror:
    case ModelCount::kOutputFrame:
    case ModelCount::kOutputFilter:
      return m.output_kind.size();
    case ModelCount::kCriterion:
      return m.criterion_kind.size();
    case ModelCount::kNone:
    case ModelCount::kRun:
    case ModelCount::kSettle:
    case ModelCount::kScene:
      break;
  }
  return 0;
}

bool CountMayBeEmpty(ModelCount count) {
  return count == ModelCount::kMirror || count == ModelCount::kSegmentDummy ||
         count == ModelCount::kFunctionUnload || count == ModelCount::kPairRate ||
         count == ModelCount::kOutputMirror || count == ModelCount::kOutputFrame ||
         count == ModelCount::kOutputFilter;
}

namespace {

// FNV-1a over the fields' values, each with its name and size, so that moving a value from one
// field to the next changes the hash too.
class FieldHasher {
 public:
  std::uint64_t value() const { return hash_; }

  void Bytes(const void* data, std::size_t size) {
    const auto* bytes = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < size; ++i) {
      hash_ ^= bytes[i];
      hash_ *= 1099511628211ull;
    }
  }
  void Add(std::string_view text) {
    Add(static_cast<std::uint64_t>(text.size()));
    Bytes(text.data(), text.size());
  }
  void Add(const std::string& text) { Add(std::string_view(text)); }
  void Add(const char* text) { Add(std::string_view(text)); }
  template <typename T>
  requires std::is_arithmetic_v<T> || std::is_enum_v<T>
  void Add(T value) {
    if constexpr (std::is_same_v<T, bool>) {
      Add(static_cast<std::uint8_t>(value ? 1 : 0));
    } else {
      Bytes(&value, sizeof value);
    }
  }
  void Add(const Vec3& v) {
    for (int i = 0; i < 3; ++i) Add(v[i]);
  }
  void Add(const Mat3& m) {
    for (int i = 0; i < 9; ++i) Add(m.data()[i]);
  }
  void Add(const Eigen::Quaterniond& q) { Add(Vec3(q.vec())), Add(q.w()); }
  void Add(const FrameRef& frame) { Add(frame.kind), Add(frame.index); }
  void Add(const SourcePosition& source) { Add(source.file), Add(source.line), Add(source.column); }
  template <typename T, std::size_t N>
  void Add(const std::array<T, N>& values) {
    for (const T& value : values) Add(value);
  }
  void Add(const VehicleMotion& motion) {
    Add(motion.kind), Add(motion.axis), Add(motion.start), Add(motion.delta_v);
    Add(motion.duration), Add(motion.peak), Add(motion.rise), Add(motion.dwell), Add(motion.fall);
    Add(motion.table), Add(motion.six_dof);
  }
  void Add(const VehiclePathSample& sample) {
    Add(sample.t), Add(sample.rotation), Add(sample.angular_velocity);
    Add(sample.displacement), Add(sample.velocity);
  }
  template <typename T>
  void Add(const std::vector<T>& values) {
    Add(static_cast<std::uint64_t>(values.size()));
    for (const T& value : values) Add(value);
  }

 private:
  std::uint64_t hash_ = 14695981039346656037ull;
};

}  // namespace

std::uint64_t HashModelFields(const Model& model, FieldRole role) {
  FieldHasher hasher;
  auto add = [&](const ModelField& field, const auto& member) {
    if (field.role != role) return;
    hasher.Add(field.name);
    hasher.Add(member);
  };
  ForEachModelArray(model, add);
  ForEachModelScalar(model, add);
  return hasher.value();
}

}  // namespace sled::runtime
