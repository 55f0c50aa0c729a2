// Channel filter classes and injury criteria: each output group gets its SAE J211 class (the
// request's `filter`, else the default for its kind), and each criterion the output groups it
// reads, added to the Model when the scene did not request them.
#include <limits>

#include <fmt/format.h>

#include "compiler/check/schema.h"
#include "compiler/lower/lowering.h"
#include "runtime/dynamics/mirror.h"

namespace sled::compiler::lowering {
namespace {

using runtime::Model;

constexpr double kStandardGravity = 9.80665;  // m/s^2 per g, the unit of the 3 ms criteria

// J211's channel classes for what a request measures: accelerations as head, pelvis and rib
// accelerometers (CFC 1000), joint forces as neck load cells (CFC 1000), joint torques as neck
// moments (CFC 600), spring and belt forces as belt load cells (CFC 60). Positions, velocities
// and angles are states of the simulation, not measured signals: not filtered.
int DefaultFilterClass(Model::OutputKind kind) {
  switch (kind) {
    case Model::OutputKind::kAcceleration:
    case Model::OutputKind::kAngularAcceleration:
    case Model::OutputKind::kJointForce:
      return 1000;
    case Model::OutputKind::kJointTorque:
      return 600;
    case Model::OutputKind::kSpringForce:
    case Model::OutputKind::kBeltForce:
      return 60;
    case Model::OutputKind::kAirbagForce:
      return 600;  // as a contact force
    case Model::OutputKind::kAirbagPressure:
    case Model::OutputKind::kAirbagVolume:
    case Model::OutputKind::kAirbagGasMass:
    case Model::OutputKind::kAirbagTemperature:
    case Model::OutputKind::kAirbagVentFlow:
      return 0;  // states of the simulated gas, not measured signals
    case Model::OutputKind::kContactForce:
      return 600;  // as a femur or knee load cell
    case Model::OutputKind::kContactDeflection:
      return 180;  // as a chest deflection
    case Model::OutputKind::kContactPoint:
    case Model::OutputKind::kVelocity:
    case Model::OutputKind::kPosition:
    case Model::OutputKind::kAngularVelocity:
    case Model::OutputKind::kOrientation:
    case Model::OutputKind::kJointAngle:
      return 0;
  }
  return 0;
}

runtime::Model::CriterionKind ModelKind(Criterion::Kind kind) {
  using K = runtime::Model::CriterionKind;
  switch (kind) {
    case Criterion::Kind::kHic15:
      return K::kHic15;
    case Criterion::Kind::kHic36:
      return K::kHic36;
    case Criterion::Kind::kHead3ms:
      return K::kHead3ms;
    case Criterion::Kind::kChest3ms:
      return K::kChest3ms;
    case Criterion::Kind::kGaddHead:
      return K::kGaddHead;
    case Criterion::Kind::kGaddChest:
      return K::kGaddChest;
    case Criterion::Kind::kNij:
      return K::kNij;
    case Criterion::Kind::kNeckTension:
      return K::kNeckTension;
    case Criterion::Kind::kNeckCompression:
      return K::kNeckCompression;
    case Criterion::Kind::kNkm:
      return K::kNkm;
    case Criterion::Kind::kNic:
      return K::kNic;
    case Criterion::Kind::kTti:
      return K::kTti;
    case Criterion::Kind::kTibiaIndex:
      return K::kTibiaIndex;
    case Criterion::Kind::kViscousCriterion:  // of a slip joint (a segment's is noted, not lowered)
      return K::kViscousCriterion;
    case Criterion::Kind::kFemurLoad:
      return K::kFemurLoad;
  }
  return K::kFemurLoad;
}

// The output group of `kind` for Model segment `index` at `point` of the segment (its centre of
// mass by default), adding one named `label` when the scene has none. Accelerations are in the
// segment's own axes, as an accelerometer fixed to it reads them (docs/language.md §17).
std::int32_t FindOrAddOutput(Lowering& lowering, Model::OutputKind kind, std::int32_t index,
                             bool mirrored, const std::string& label,
                             const runtime::Vec3& point = runtime::Vec3::Zero()) {
  Model& model = lowering.model();
  for (std::size_t k = 0; k < model.output_kind.size(); ++k) {
    const bool same_side =
        model.output_mirrored.empty() || (model.output_mirrored[k] != 0) == mirrored;
    const bool absolute = model.output_relative.empty() || model.output_relative[k] == 0;
    if (model.output_kind[k] == kind && model.output_index[k] == index && same_side && absolute &&
        model.output_point[k] == point) {
      return static_cast<std::int32_t>(k);
    }
  }
  // A label the scene already uses for the same kind would give two columns one name.
  bool taken = false;
  for (std::size_t k = 0; k < model.output_kind.size(); ++k) {
    taken = taken || (model.output_kind[k] == kind && model.output_label[k] == label);
  }
  lowering.AddOutput({kind, taken ? label + ".cg" : label, index, point, mirrored,
                      static_cast<std::int16_t>(DefaultFilterClass(kind)), false, std::nullopt,
                      false, 0});
  return static_cast<std::int32_t>(model.output_kind.size() - 1);
}

// The Model segment that carries checked segment `old` (its left twin under mirror symmetry).
std::pair<std::int32_t, bool> ModelSegment(const Lowering& lowering, int old) {
  const bool mirrored = lowering.Dropped(old);
  const int kept = mirrored ? lowering.mirror_twin[static_cast<std::size_t>(old)] : old;
  return {lowering.new_index[static_cast<std::size_t>(kept)], mirrored};
}

}  // namespace

std::int16_t FilterClassOf(const OutputRequest& request, Model::OutputKind kind) {
  return static_cast<std::int16_t>(request.filter_class >= 0 ? request.filter_class
                                                             : DefaultFilterClass(kind));
}

void LowerCriteria(Lowering& lowering) {
  const CheckedScenario& scenario = lowering.scenario();
  Model& model = lowering.model();
  for (const Criterion& criterion : scenario.criteria) {
    const std::string_view name =
        AllCriterionSpecs().at(static_cast<std::size_t>(criterion.kind)).name;
    std::int32_t output = -1;
    std::int32_t second_output = -1;
    std::string target;
    if (criterion.segment >= 0) {
      const Segment& segment = lowering.segment(criterion.segment);
      target = segment.name;
      if (criterion.kind == Criterion::Kind::kViscousCriterion) {
        lowering.AddNote(lang::DiagnosticKind::kLeftOutOfModel, criterion.range,
                         fmt::format("injury criterion `{}({})` needs a chest deflection, which a "
                                     "rigid thorax segment does not have (its contacts' "
                                     "penetrations measure the padding, not the ribcage); left "
                                     "out (a chest of two segments on a slip joint has one: "
                                     "give `viscous_criterion` that joint)",
                                     name, target));
        continue;
      }
      const auto [index, mirrored] = ModelSegment(lowering, criterion.segment);
      output = FindOrAddOutput(lowering, Model::OutputKind::kAcceleration, index, mirrored, target);
      if (criterion.kind == Criterion::Kind::kNic) {
        // T1: the parent of the joint at the base of the neck, at the joint's point.
        const Joint& t1 = lowering.joint(criterion.second);
        const auto [t1_index, t1_mirrored] = ModelSegment(lowering, t1.parent);
        const runtime::Vec3 point = t1_mirrored
                                        ? runtime::MirrorFrameVector(ToEigen(t1.location_in_parent))
                                        : ToEigen(t1.location_in_parent);
        second_output = FindOrAddOutput(lowering, Model::OutputKind::kAcceleration, t1_index,
                                        t1_mirrored, t1.name + ".t1", point);
      } else if (criterion.kind == Criterion::Kind::kTti) {
        const auto [spine_index, spine_mirrored] = ModelSegment(lowering, criterion.second);
        second_output = FindOrAddOutput(lowering, Model::OutputKind::kAcceleration, spine_index,
                                        spine_mirrored, lowering.segment(criterion.second).name);
      }
    } else {
      const Joint& joint = lowering.joint(criterion.joint);
      target = joint.name;
      if (joint.type == JointType::kNull) {
        lowering.AddNote(lang::DiagnosticKind::kLeftOutOfModel, criterion.range,
                         fmt::format("injury criterion `{}({})` is left out: `{}` is a null "
                                     "joint, which transmits no force",
                                     name, target, target));
        continue;
      }
      const auto [index, mirrored] = ModelSegment(lowering, joint.child);
      // The Viscous Criterion reads the slip joint's sliding, the chest's deflection.
      output = FindOrAddOutput(lowering,
                               criterion.kind == Criterion::Kind::kViscousCriterion
                                   ? Model::OutputKind::kJointAngle
                                   : Model::OutputKind::kJointForce,
                               index, mirrored, target);
      if (criterion.kind == Criterion::Kind::kNij || criterion.kind == Criterion::Kind::kNkm ||
          criterion.kind == Criterion::Kind::kTibiaIndex) {
        second_output =
            FindOrAddOutput(lowering, Model::OutputKind::kJointTorque, index, mirrored, target);
      }
    }
    model.criterion_kind.push_back(ModelKind(criterion.kind));
    model.criterion_name.emplace_back(name);
    model.criterion_target.push_back(target);
    model.criterion_output.push_back(output);
    model.criterion_second_output.push_back(second_output);
    model.criterion_filter_iso.push_back(criterion.iso_filter ? 1 : 0);
    // The scene's own limit, in the unit the criterion reports (g for the 3 ms criteria and TTI).
    const bool in_g = criterion.kind == Criterion::Kind::kHead3ms ||
                      criterion.kind == Criterion::Kind::kChest3ms ||
                      criterion.kind == Criterion::Kind::kTti;
    model.criterion_limit.push_back(criterion.limit
                                        ? *criterion.limit / (in_g ? kStandardGravity : 1.0)
                                        : std::numeric_limits<double>::quiet_NaN());
    model.criterion_standard.push_back(criterion.standard);
  }
}

}  // namespace sled::compiler::lowering
