// The scene-level post-processing: a Model's criteria read their output groups, filter them at
// the criterion's class, and give the reference values of the half-sine pulse; joint loads take
// the sense of the child segment's axis; a sample rate too low for a class is reported, not
// computed; only the groups with a class appear among the filtered channels.
#include <cmath>
#include <numbers>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "output/post/channel_filters.h"
#include "output/post/injury_criteria.h"

namespace sled::runtime::post {
namespace {

using ::testing::HasSubstr;

constexpr double kG = 9.80665;

// A Model with two segments (a head, and a thigh whose hip is 174 mm up its z axis), the head's
// acceleration group and the hip's joint-force group, and no criteria yet.
Model PostModel(double output_every) {
  Model model;
  model.start_time = 0;
  model.end_time = 0.06;
  model.output_every = output_every;
  model.segment_name = {"dummy.head", "dummy.thigh"};
  model.joint_point_in_child = {Vec3::Zero(), Vec3(0, 0, 0.174)};
  model.output_kind = {Model::OutputKind::kAcceleration, Model::OutputKind::kJointForce};
  model.output_label = {"dummy.head", "dummy.hip"};
  model.output_index = {0, 1};
  model.output_point = {Vec3::Zero(), Vec3::Zero()};
  model.output_filter_class = {1000, 0};
  model.output_filter_iso = {0, 0};
  return model;
}

void AddCriterion(Model& model, Model::CriterionKind kind, const char* name, int output) {
  model.criterion_kind.push_back(kind);
  model.criterion_name.emplace_back(name);
  model.criterion_target.emplace_back(model.output_label[static_cast<std::size_t>(output)]);
  model.criterion_output.push_back(output);
  model.criterion_second_output.push_back(-1);
  model.criterion_filter_iso.push_back(0);
}

// Rows of time, head acceleration (x, y, z) and hip force (x, y, z): a 60 g, 15 ms half-sine
// along x from 10 ms, and a force pushing the thigh down its axis, 5 kN at the peak of a 20 ms
// half-sine.
TimeSeries PulseSeries(const Model& model) {
  TimeSeries series;
  series.names = {"a.x", "a.y", "a.z", "f.x", "f.y", "f.z"};
  series.columns = 7;
  const auto rows = static_cast<std::size_t>(std::lround(model.end_time / model.output_every)) + 1;
  for (std::size_t k = 0; k < rows; ++k) {
    const double t = static_cast<double>(k) * model.output_every;
    const double head =
        t >= 0.01 && t <= 0.025 ? 60 * kG * std::sin(std::numbers::pi * (t - 0.01) / 0.015) : 0.0;
    const double force =
        t >= 0.01 && t <= 0.03 ? -5000 * std::sin(std::numbers::pi * (t - 0.01) / 0.02) : 0.0;
    for (const double v : {t, head, 0.0, 0.0, 0.0, 0.0, force}) series.values.push_back(v);
  }
  return series;
}

const CriterionValue& Find(const std::vector<CriterionValue>& values, const std::string& name,
                           const std::string& variant = "") {
  for (const CriterionValue& v : values) {
    if (v.name == name && v.variant == variant) return v;
  }
  ADD_FAILURE() << "no " << name << " " << variant;
  return values.front();
}

TEST(EvaluateCriteria, HeadAndChestCriteriaOfTheHalfSinePulse) {
  Model model = PostModel(1e-4);
  AddCriterion(model, Model::CriterionKind::kHic15, "hic15", 0);
  AddCriterion(model, Model::CriterionKind::kHead3ms, "head_3ms", 0);
  AddCriterion(model, Model::CriterionKind::kChest3ms, "chest_3ms", 0);
  const std::vector<CriterionValue> values = EvaluateCriteria(model, PulseSeries(model));
  ASSERT_EQ(values.size(), 5u);  // hic15, then both variants of each 3 ms criterion
  const CriterionValue& hic = Find(values, "hic15");
  ASSERT_TRUE(hic.computed) << hic.reason;
  // crash-conventions.md §2.2: 173.4 over 2.5-12.5 ms of the pulse; CFC 1000 barely touches a
  // 15 ms pulse.
  EXPECT_NEAR(hic.value, 173.4, 0.5);
  EXPECT_NEAR(hic.window_start, 0.0125, 2e-4);
  EXPECT_NEAR(hic.window_end, 0.0225, 2e-4);
  EXPECT_EQ(hic.filter_class, 1000);
  EXPECT_EQ(hic.limit, 700);
  EXPECT_TRUE(hic.pass);
  for (const char* name : {"head_3ms", "chest_3ms"}) {
    for (const char* variant : {"cumulative", "continuous"}) {
      const CriterionValue& clip = Find(values, name, variant);
      ASSERT_TRUE(clip.computed) << name << " " << variant;
      EXPECT_NEAR(clip.value, 57.06, 0.2) << name << " " << variant;
      EXPECT_EQ(clip.unit, "g");
    }
  }
  EXPECT_EQ(Find(values, "chest_3ms", "continuous").filter_class, 180);
  EXPECT_EQ(Find(values, "chest_3ms", "cumulative").limit, 60);
  EXPECT_TRUE(Find(values, "chest_3ms", "cumulative").pass);  // 57 g is below 60 g
}

TEST(EvaluateCriteria, FemurCompressionFollowsTheChildAxis) {
  // The hip sits at +z of the thigh, so a force on the thigh along -z pushes it away from the
  // hip: compression.
  Model model = PostModel(1e-4);
  AddCriterion(model, Model::CriterionKind::kFemurLoad, "femur_load", 1);
  AddCriterion(model, Model::CriterionKind::kNeckTension, "neck_tension", 1);
  const std::vector<CriterionValue> values = EvaluateCriteria(model, PulseSeries(model));
  const CriterionValue& femur = Find(values, "femur_load");
  ASSERT_TRUE(femur.computed) << femur.reason;
  EXPECT_NEAR(femur.value, 5000, 5);
  EXPECT_NEAR(femur.window_start, 0.02, 1e-4);
  EXPECT_EQ(femur.unit, "N");
  EXPECT_EQ(femur.limit, 10008);
  EXPECT_TRUE(femur.pass);
  EXPECT_NEAR(Find(values, "neck_tension").value, 0.0, 5);  // never pulled
}

TEST(EvaluateCriteria, NkmAddsTheShearAndMomentTermsOfTheirQuadrant) {
  // The joint-force group read as both force and moment: a shear of 422.5 N along +x (half of
  // Fint = 845 N) and My = -44.05 N*m, a flexion of half of Mint = 88.1 N*m, both half-sines
  // peaking together at 20 ms, so Nkm peaks at 0.5 + 0.5 = 1.0 in the flexion-anterior quadrant.
  Model model = PostModel(1e-4);
  AddCriterion(model, Model::CriterionKind::kNkm, "nkm", 1);
  model.criterion_second_output.back() = 1;
  TimeSeries series = PulseSeries(model);
  for (std::size_t k = 0; k < series.rows(); ++k) {
    double* row = &series.values[k * series.columns];
    const double t = row[0];
    const double shape =
        t >= 0.01 && t <= 0.03 ? std::sin(std::numbers::pi * (t - 0.01) / 0.02) : 0;
    row[4] = 422.5 * shape;
    row[5] = -44.05 * shape;
    row[6] = 0.0;
  }
  const std::vector<CriterionValue> values = EvaluateCriteria(model, series);
  const CriterionValue& nkm = Find(values, "nkm");
  ASSERT_TRUE(nkm.computed) << nkm.reason;
  EXPECT_NEAR(nkm.value, 1.0, 0.005);  // CFC 600 barely touches a 20 ms half-sine
  EXPECT_NEAR(nkm.window_start, 0.02, 2e-4);
  EXPECT_EQ(nkm.filter_class, 600);
  EXPECT_EQ(nkm.limit, 1.0);
  EXPECT_EQ(nkm.limit_source, "Schmitt et al. (2001)");
  EXPECT_NEAR(Find(values, "nkm", "NFA").value, nkm.value, 1e-12);
  // Posterior shear in extension only from the filter's ringing around the pulse.
  const CriterionValue& nep = Find(values, "nkm", "NEP");
  EXPECT_LT(nep.computed ? nep.value : 0.0, 0.01);
}

// Rows whose two groups carry `first(t)` and `second(t)` (x, y, z each) over the 60 ms record.
template <typename First, typename Second>
TimeSeries SeriesOf(const Model& model, First first, Second second) {
  TimeSeries series = PulseSeries(model);
  for (std::size_t k = 0; k < series.rows(); ++k) {
    double* row = &series.values[k * series.columns];
    const Vec3 a = first(row[0]), b = second(row[0]);
    for (int i = 0; i < 3; ++i) {
      row[1 + i] = a[i];
      row[4 + i] = b[i];
    }
  }
  return series;
}

// NIC reads the head (first group) and T1 (second) along x: T1 at a constant 20 m/s^2 ahead of
// a still head gives NIC(t) = 0.2 * 20 + (20 t)^2, 5.44 m^2/s^2 at the end of the 60 ms record;
// CFC 60 leaves a constant as it is.
TEST(EvaluateCriteria, NicReadsTheHeadAndT1AlongX) {
  Model model = PostModel(1e-4);
  AddCriterion(model, Model::CriterionKind::kNic, "nic", 0);
  model.criterion_second_output.back() = 1;
  const std::vector<CriterionValue> values = EvaluateCriteria(
      model,
      SeriesOf(
          model, [](double) { return Vec3(0, 5, 0); }, [](double) { return Vec3(20, 0, 0); }));
  const CriterionValue& nic = Find(values, "nic");
  ASSERT_TRUE(nic.computed) << nic.reason;
  EXPECT_NEAR(nic.value, 0.2 * 20 + std::pow(20 * 0.06, 2), 5.44e-3);
  EXPECT_EQ(nic.unit, "m^2/s^2");
  EXPECT_EQ(nic.filter_class, 60);
  EXPECT_EQ(nic.limit, 15.0);
  EXPECT_EQ(nic.limit_source, "Bostrom et al. (1996)");
}

// TTI: the rib (first group) and the lower spine (second) along y, half-sines of 60 ms that CFC
// 180 barely touches: (|-50 g| + 30 g) / 2 = 40 g.
TEST(EvaluateCriteria, TtiAveragesTheRibAndSpinePeaksAlongY) {
  Model model = PostModel(1e-4);
  AddCriterion(model, Model::CriterionKind::kTti, "tti", 0);
  model.criterion_second_output.back() = 1;
  const auto shape = [](double t) { return std::sin(std::numbers::pi * t / 0.06); };
  const std::vector<CriterionValue> values = EvaluateCriteria(
      model, SeriesOf(
                 model, [&](double t) { return Vec3(9 * kG, -50 * kG * shape(t), 0); },
                 [&](double t) { return Vec3(0, 30 * kG * shape(t), 7 * kG); }));
  const CriterionValue& tti = Find(values, "tti");
  ASSERT_TRUE(tti.computed) << tti.reason;
  EXPECT_NEAR(tti.value, 40.0, 0.04);
  EXPECT_EQ(tti.unit, "g");
  EXPECT_EQ(tti.filter_class, 180);
  EXPECT_EQ(tti.limit, 85.0);
}

// The Tibia Index: the joint's axial force (first group, z) and its bending moments (second, x
// and y) peaking together: 90 N*m / 225 N*m + 6 kN / 35.9 kN.
TEST(EvaluateCriteria, TibiaIndexAddsTheMomentAndForceTerms) {
  Model model = PostModel(1e-4);
  model.output_filter_class = {0, 0};
  AddCriterion(model, Model::CriterionKind::kTibiaIndex, "tibia_index", 1);
  model.criterion_second_output.back() = 0;
  const auto shape = [](double t) { return std::sin(std::numbers::pi * t / 0.06); };
  const std::vector<CriterionValue> values = EvaluateCriteria(
      model, SeriesOf(
                 model, [&](double t) { return Vec3(54 * shape(t), -72 * shape(t), 9); },
                 [&](double t) { return Vec3(300, 0, -6000 * shape(t)); }));
  const CriterionValue& ti = Find(values, "tibia_index");
  ASSERT_TRUE(ti.computed) << ti.reason;
  EXPECT_NEAR(ti.value, 90.0 / 225.0 + 6000.0 / 35900.0, 1e-3);
  EXPECT_NEAR(ti.window_start, 0.03, 2e-4);
  EXPECT_EQ(ti.filter_class, 600);
  EXPECT_EQ(ti.limit, 1.3);
  EXPECT_EQ(ti.limit_source, "UN R94");
}

TEST(EvaluateCriteria, ASceneLimitReplacesTheDefaultWithItsStandard) {
  Model model = PostModel(1e-4);
  AddCriterion(model, Model::CriterionKind::kHic15, "hic15", 0);
  model.criterion_limit = {150.0};
  model.criterion_standard = {"a test standard"};
  const std::vector<CriterionValue> values = EvaluateCriteria(model, PulseSeries(model));
  const CriterionValue& hic = Find(values, "hic15");
  EXPECT_EQ(hic.limit, 150.0);
  EXPECT_EQ(hic.limit_source, "a test standard");
  EXPECT_FALSE(hic.pass);  // 173.4 is above 150
}

TEST(EvaluateCriteria, TooLowASampleRateIsReportedNotComputed) {
  Model model = PostModel(1e-3);  // 1 kHz: enough for CFC 60 only
  AddCriterion(model, Model::CriterionKind::kHic36, "hic36", 0);
  const std::vector<CriterionValue> values = EvaluateCriteria(model, PulseSeries(model));
  ASSERT_EQ(values.size(), 1u);
  EXPECT_FALSE(values[0].computed);
  EXPECT_THAT(values[0].reason, HasSubstr("CFC 1000"));
  EXPECT_THAT(values[0].reason, HasSubstr("output_every"));
}

TEST(FilterOutputChannels, OnlyGroupsWithAClassAreFiltered) {
  const Model model = PostModel(1e-4);
  const TimeSeries raw = PulseSeries(model);
  const FilteredChannels filtered = FilterOutputChannels(model, raw);
  EXPECT_TRUE(filtered.warnings.empty());
  ASSERT_EQ(filtered.series.names, (std::vector<std::string>{"a.x", "a.y", "a.z"}));
  ASSERT_EQ(filtered.series.rows(), raw.rows());
  // The pulse's peak survives CFC 1000 within a tenth of a percent.
  double peak = 0;
  for (std::size_t row = 0; row < raw.rows(); ++row) {
    EXPECT_EQ(filtered.series.values[row * 4], raw.values[row * 7]);
    peak = std::max(peak, filtered.series.values[row * 4 + 1]);
  }
  EXPECT_NEAR(peak / (60 * kG), 1.0, 1e-3);

  const Model coarse = PostModel(1e-3);
  const FilteredChannels refused = FilterOutputChannels(coarse, PulseSeries(coarse));
  ASSERT_EQ(refused.warnings.size(), 1u);
  EXPECT_THAT(refused.warnings[0], HasSubstr("dummy.head"));
  EXPECT_TRUE(refused.series.names.empty());
}

}  // namespace
}  // namespace sled::runtime::post
