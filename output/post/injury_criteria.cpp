#include "output/post/injury_criteria.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <fmt/format.h>

#include "output/post/channel_filters.h"
#include "output/post/exceedance.h"
#include "output/post/head_injury_criterion.h"
#include "output/post/neck_injury_criterion.h"
#include "output/post/peak_load.h"
#include "output/post/severity_index.h"
#include "output/post/thoracic_trauma_index.h"
#include "output/post/tibia_index.h"
#include "output/post/viscous_criterion.h"
#include "output/post/whiplash_criterion.h"

namespace sled::runtime::post {
namespace {

using Kind = Model::CriterionKind;

constexpr double kStandardGravity = 9.80665;  // m/s^2 per g

// The channel class each criterion's inputs are filtered at (SAE J211 channel assignments).
int InputClass(Kind kind) {
  switch (kind) {
    case Kind::kHic15:
    case Kind::kHic36:
    case Kind::kHead3ms:
    case Kind::kGaddHead:
    case Kind::kNeckTension:
    case Kind::kNeckCompression:
      return 1000;
    case Kind::kChest3ms:
    case Kind::kGaddChest:
    // FMVSS 214 filters the SID's rib and spine accelerations with NHTSA's FIR100 (49 CFR 572.44),
    // whose first stage is this class; sled stops there (docs/load_cases.md), which keeps more of
    // the peak than FIR100 does.
    case Kind::kTti:
    // The chest's deflection for VC, as UN R94 practice filters it (crash-conventions.md §2.1).
    case Kind::kViscousCriterion:
      return 180;
    case Kind::kNij:
    case Kind::kNkm:
    case Kind::kFemurLoad:
    case Kind::kTibiaIndex:
      return 600;
    case Kind::kNic:
      return 60;  // UN GTR 7: head and T1 longitudinal accelerations at CFC 60
  }
  return 1000;
}

struct Limit {
  double value;
  const char* source;
};

// Limits for the Hybrid III 50th male where a regulation gives one.
Limit LimitOf(Kind kind) {
  switch (kind) {
    case Kind::kHic15:
      return {700.0, "FMVSS 208"};
    case Kind::kHic36:
      return {1000.0, "FMVSS 214, UN R94/R137"};
    case Kind::kHead3ms:
      return {80.0, "UN R94/R137"};
    case Kind::kChest3ms:
      return {60.0, "FMVSS 208"};
    case Kind::kGaddHead:
    case Kind::kGaddChest:
      return {1000.0, "Gadd (1966)"};
    case Kind::kNij:
      return {1.0, "FMVSS 208"};
    case Kind::kNeckTension:
      return {4170.0, "FMVSS 208"};
    case Kind::kNeckCompression:
      return {4000.0, "FMVSS 208"};
    case Kind::kFemurLoad:
      return {10008.0, "FMVSS 208"};
    case Kind::kNkm:
      return {1.0, "Schmitt et al. (2001)"};
    case Kind::kNic:
      return {15.0, "Bostrom et al. (1996)"};
    case Kind::kTti:
      return {85.0, "FMVSS 214 (SID, four-door)"};
    case Kind::kTibiaIndex:
      return {1.3, "UN R94"};
    case Kind::kViscousCriterion:
      return {1.0, "UN R94/R137"};
  }
  return {0.0, ""};
}

class Evaluator {
 public:
  Evaluator(const Model& model, const TimeSeries& raw)
      : model_(model),
        raw_(raw),
        period_(SamplePeriod(model)),
        start_(raw.rows() > 0 ? raw.values[0] : model.start_time),
        columns_(GroupColumns(model)) {}

  void Evaluate(std::size_t c, std::vector<CriterionValue>& out) {
    const Kind kind = model_.criterion_kind[c];
    CriterionValue base;
    base.name = model_.criterion_name[c];
    base.target = model_.criterion_target[c];
    base.filter_class = InputClass(kind);
    const Limit limit = LimitOf(kind);
    base.has_limit = true;
    base.limit = limit.value;
    base.limit_source = limit.source;
    // The scene's own limit for its load case, with the standard it names.
    if (c < model_.criterion_limit.size() && !std::isnan(model_.criterion_limit[c])) {
      base.limit = model_.criterion_limit[c];
      base.limit_source = model_.criterion_standard[c];
    }
    standard_ = c < model_.criterion_filter_iso.size() && model_.criterion_filter_iso[c] != 0
                    ? FilterStandard::kIso6487
                    : FilterStandard::kSaeJ211;
    if (kind == Kind::kViscousCriterion) {
      EvaluateViscous(c, base, out);
      return;
    }
    std::array<std::vector<double>, 3> xyz;
    if (!FilterGroup(model_.criterion_output[c], base.filter_class, xyz, base)) {
      out.push_back(base);
      return;
    }
    switch (kind) {
      case Kind::kHic15:
      case Kind::kHic36: {
        const HicResult hic = HeadInjuryCriterion(ResultantG(xyz), period_, start_,
                                                  kind == Kind::kHic15 ? 0.015 : 0.036);
        out.push_back(Done(base, hic.value, "", hic.t1, hic.t2));
        break;
      }
      case Kind::kHead3ms:
      case Kind::kChest3ms: {
        const std::vector<double> resultant = ResultantG(xyz);
        for (const ExceedanceKind variant :
             {ExceedanceKind::kCumulative, ExceedanceKind::kContinuous}) {
          CriterionValue value = base;
          value.variant = variant == ExceedanceKind::kCumulative ? "cumulative" : "continuous";
          const ExceedanceResult clip =
              LevelExceededFor(resultant, period_, start_, 0.003, variant);
          if (!clip.defined) {
            value.reason = "the record is shorter than 3 ms";
            out.push_back(value);
            continue;
          }
          out.push_back(Done(value, clip.level, "g", clip.t_start, clip.t_end));
        }
        break;
      }
      case Kind::kGaddHead:
      case Kind::kGaddChest: {
        const double end = start_ + static_cast<double>(raw_.rows() - 1) * period_;
        out.push_back(Done(base, GaddSeverityIndex(ResultantG(xyz), period_), "", start_, end));
        break;
      }
      case Kind::kNeckTension:
      case Kind::kNeckCompression:
      case Kind::kFemurLoad: {
        std::vector<double> load = AxialCompression(model_.criterion_output[c], xyz);
        if (kind == Kind::kNeckTension) {
          for (double& value : load) value = -value;
        }
        const PeakResult peak = PositivePeak(load, period_, start_);
        out.push_back(Done(base, peak.value, "N", peak.time, peak.time));
        break;
      }
      case Kind::kNij:
      case Kind::kNkm:
        EvaluateNeck(c, kind == Kind::kNkm, base, xyz, out);
        break;
      case Kind::kNic:
      case Kind::kTti:
      case Kind::kTibiaIndex:
        EvaluatePair(c, kind, base, xyz, out);
        break;
      case Kind::kViscousCriterion:  // above: one channel, not three
        break;
    }
  }

 private:
  // The three components of output group `group`, filtered at `cfc`; false with the reason in
  // `value` when they cannot be.
  bool FilterGroup(std::int32_t group, int cfc, std::array<std::vector<double>, 3>& xyz,
                   CriterionValue& value) {
    if (raw_.rows() < 2) {
      value.reason = "the run produced fewer than two output rows";
      return false;
    }
    const std::size_t first = columns_.at(static_cast<std::size_t>(group));
    for (std::size_t i = 0; i < 3; ++i) {
      std::string error;
      if (!FilterColumn(raw_, first + i, period_, cfc, standard_, xyz[i], &error)) {
        value.reason = error;
        return false;
      }
    }
    return true;
  }

  // VC from a slip joint's displacement (its one channel): the joint's axis points from the
  // spine to the sternum, so the chest is compressed, D > 0, when the displacement is negative.
  // Hybrid III 50th male constants (SF 1.3, Dc 229 mm).
  void EvaluateViscous(std::size_t c, CriterionValue base, std::vector<CriterionValue>& out) {
    std::vector<double> deflection;
    std::string error;
    if (raw_.rows() < 5) {
      base.reason = "the run produced fewer than five output rows";
    } else if (FilterColumn(raw_, columns_.at(static_cast<std::size_t>(model_.criterion_output[c])),
                            period_, base.filter_class, standard_, deflection, &error)) {
      for (double& d : deflection) d = -d;
      const ViscousResult vc = ViscousCriterion(deflection, period_, start_, kHybridIII50thMaleVc);
      out.push_back(Done(base, vc.value, "m/s", vc.time, vc.time));
      return;
    } else {
      base.reason = error;
    }
    out.push_back(base);
  }

  static std::vector<double> ResultantG(const std::array<std::vector<double>, 3>& xyz) {
    std::vector<double> resultant(xyz[0].size());
    for (std::size_t k = 0; k < resultant.size(); ++k) {
      resultant[k] =
          std::sqrt(xyz[0][k] * xyz[0][k] + xyz[1][k] * xyz[1][k] + xyz[2][k] * xyz[2][k]) /
          kStandardGravity;
    }
    return resultant;
  }

  // +1 when the child segment's z axis points from the joint towards its centre of mass, so
  // that a force on the child along the axis pushes it away from the joint (compression).
  double AxialSense(std::int32_t group) const {
    const auto segment =
        static_cast<std::size_t>(model_.output_index[static_cast<std::size_t>(group)]);
    return model_.joint_point_in_child[segment].z() > 0.0 ? -1.0 : 1.0;
  }

  std::vector<double> AxialCompression(std::int32_t group,
                                       const std::array<std::vector<double>, 3>& force) const {
    std::vector<double> compression(force[2]);
    for (double& value : compression) value *= AxialSense(group);
    return compression;
  }

  // Nij (axial force and moment) or Nkm (shear force and moment), with their quadrants.
  void EvaluateNeck(std::size_t c, bool nkm, const CriterionValue& base,
                    const std::array<std::vector<double>, 3>& force,
                    std::vector<CriterionValue>& out) {
    std::array<std::vector<double>, 3> moment;
    CriterionValue value = base;
    if (!FilterGroup(model_.criterion_second_output[c], base.filter_class, moment, value)) {
      out.push_back(value);
      return;
    }
    std::vector<double> tension = AxialCompression(model_.criterion_output[c], force);
    for (double& t : tension) t = -t;
    std::vector<double> flexion(moment[1]);
    for (double& m : flexion) m = -m;
    // The moment is taken about the joint point, which is the condyle: no load-cell offset.
    // Nkm's shear is the force along the head's x: anterior when the neck pushes it forward.
    const NijResult nij =
        nkm ? NeckInjuryCriterion(force[0], force[0], flexion, 0.0, kNkmIntercepts, period_, start_)
            : NeckInjuryCriterion(tension, force[0], flexion, 0.0, kHybridIII50thMale, period_,
                                  start_);
    out.push_back(Done(value, nij.value, "", nij.time, nij.time));
    for (std::size_t q = 0; q < nij.quadrants.size(); ++q) {
      CriterionValue term = base;
      term.variant = nkm ? NkmQuadrantName(static_cast<NeckQuadrant>(q))
                         : QuadrantName(static_cast<NeckQuadrant>(q));
      const QuadrantPeak& peak = nij.quadrants[q];
      if (!peak.reached) {
        term.reason = "the neck load never entered this quadrant";
        out.push_back(term);
        continue;
      }
      out.push_back(Done(term, peak.value, "", peak.time, peak.time));
    }
  }

  // The criteria of two output groups that are not Nij's form: NIC (head and T1 accelerations
  // along x), TTI (rib and lower spine accelerations along y) and the Tibia Index (the joint's
  // axial force and bending moments).
  void EvaluatePair(std::size_t c, Kind kind, const CriterionValue& base,
                    const std::array<std::vector<double>, 3>& first,
                    std::vector<CriterionValue>& out) {
    std::array<std::vector<double>, 3> second;
    CriterionValue value = base;
    if (!FilterGroup(model_.criterion_second_output[c], base.filter_class, second, value)) {
      out.push_back(value);
      return;
    }
    if (kind == Kind::kNic) {
      const NicResult nic = NeckInjuryCriterionOfRearImpact(second[0], first[0], period_, start_);
      out.push_back(Done(value, nic.value, "m^2/s^2", nic.time, nic.time));
    } else if (kind == Kind::kTti) {
      std::vector<double> rib(first[1]), spine(second[1]);
      for (double& a : rib) a /= kStandardGravity;
      for (double& a : spine) a /= kStandardGravity;
      const TtiResult tti = ThoracicTraumaIndex(rib, spine, period_, start_);
      out.push_back(Done(value, tti.value, "g", std::min(tti.rib_time, tti.spine_time),
                         std::max(tti.rib_time, tti.spine_time)));
    } else {
      const TibiaResult ti =
          TibiaIndex(second[0], second[1], first[2], period_, start_, kHybridIII50thMaleTibia);
      out.push_back(Done(value, ti.value, "", ti.time, ti.time));
    }
  }

  static CriterionValue Done(CriterionValue value, double result, const char* unit, double t1,
                             double t2) {
    value.computed = true;
    value.value = result;
    value.unit = unit;
    value.window_start = t1;
    value.window_end = t2;
    value.pass = !value.has_limit || result <= value.limit;
    return value;
  }

  const Model& model_;
  const TimeSeries& raw_;
  double period_;
  double start_;
  std::vector<std::size_t> columns_;
  FilterStandard standard_ = FilterStandard::kSaeJ211;
};

}  // namespace

std::vector<CriterionValue> EvaluateCriteria(const Model& model, const TimeSeries& raw) {
  std::vector<CriterionValue> out;
  Evaluator evaluator(model, raw);
  for (std::size_t c = 0; c < model.ncriterion(); ++c) evaluator.Evaluate(c, out);
  return out;
}

}  // namespace sled::runtime::post
