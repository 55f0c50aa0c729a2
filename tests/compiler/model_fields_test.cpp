// The one list of the Model's fields (runtime/model/model_fields.h): every field of every example
// and golden scene, corrupted in turn, is refused by ValidateModel with a message naming it, and
// changes the checkpoint fingerprint's part of its role (the dump too). Also FinalizeModel's
// derived structure and the check that a Data belongs to its Model.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <set>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "runtime/model/data.h"
#include "runtime/model/model_fields.h"
#include "runtime/model/model_structure.h"
#include "runtime/run/checkpoint.h"
#include "runtime/run/run.h"
#include "sled/compile.h"

namespace sled::runtime {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

const fs::path kRoot = SLED_SOURCE_ROOT;

// Every example and golden scene, compiled (and so finalized by the lowering).
const std::vector<Model>& Scenes() {
  static const std::vector<Model> scenes = [] {
    std::vector<fs::path> files;
    for (const fs::path& folder : {kRoot / "examples", kRoot / "tests" / "golden" / "model"}) {
      for (const auto& entry : fs::directory_iterator(folder)) {
        if (entry.path().extension() == ".sled") files.push_back(entry.path());
      }
    }
    std::sort(files.begin(), files.end());
    std::vector<Model> models;
    for (const fs::path& file : files) {
      CompileOptions options;
      options.stdlib = (kRoot / "stdlib").string();
      Compilation compiled = Compile(Source::File(file.string()), options);
      EXPECT_TRUE(compiled.ok()) << file << "\n" << compiled.Render();
      if (compiled.has_model()) models.push_back(std::move(compiled.model()));
    }
    return models;
  }();
  return scenes;
}

template <typename T>
struct IsVector : std::false_type {};
template <typename T, typename A>
struct IsVector<std::vector<T, A>> : std::true_type {};
template <typename T>
constexpr bool kIsVector = IsVector<std::decay_t<T>>::value;

// The member of `model` a field names (a walk of the list that stops at it).
template <typename Act>
void WithField(Model& model, const std::string& name, Act&& act) {
  auto visit = [&](const ModelField& field, auto& member) {
    if (name == field.name) act(field, member);
  };
  ForEachModelArray(model, visit);
  ForEachModelScalar(model, visit);
}

std::vector<ModelField> Fields() {
  std::vector<ModelField> fields;
  Model model;
  auto add = [&](const ModelField& field, const auto&) { fields.push_back(field); };
  ForEachModelArray(model, add);
  ForEachModelScalar(model, add);
  return fields;
}

bool IsArray(const ModelField& field) {
  return field.count != ModelCount::kScene && field.count != ModelCount::kRun &&
         field.count != ModelCount::kSettle;
}

// A scene in which the array has an entry.
const Model* SceneWith(const ModelField& field) {
  for (const Model& scene : Scenes()) {
    bool has = !IsArray(field);
    Model copy = scene;
    WithField(copy, field.name, [&](const ModelField&, auto& member) {
      if constexpr (kIsVector<decltype(member)>) has = !member.empty();
    });
    if (has) return &scene;
  }
  return nullptr;
}

// A different value of the same type.
template <typename T>
void Perturb(T& value) {
  if constexpr (std::is_same_v<T, std::string>) {
    value += "x";
  } else if constexpr (std::is_enum_v<T>) {
    value = static_cast<T>(static_cast<std::underlying_type_t<T>>(value) + 1);
  } else if constexpr (std::is_floating_point_v<T>) {
    value = std::isnan(value) ? 1.0 : value + 1 + std::abs(value);  // never itself
  } else if constexpr (std::is_integral_v<T>) {
    value = static_cast<T>(value + 1);
  } else if constexpr (std::is_same_v<T, Vec3> || std::is_same_v<T, Mat3>) {
    value(0, 0) += 1;
  } else if constexpr (std::is_same_v<T, FrameRef>) {
    value.kind = value.kind == FrameRef::Kind::kSegment ? FrameRef::Kind::kVehicle
                                                        : FrameRef::Kind::kSegment;
    value.index += 1;
  } else if constexpr (std::is_same_v<T, SourcePosition>) {
    value.line += 1;
  } else if constexpr (std::is_same_v<T, VehicleMotion>) {
    value.start += 1;
  } else if constexpr (std::is_same_v<T, VehiclePathSample>) {
    value.t += 1;
  } else if constexpr (std::is_same_v<T, std::array<std::int32_t, 2>> ||
                       std::is_same_v<T, std::array<std::int32_t, 3>>) {
    value[0] += 1;
  } else if constexpr (kIsVector<T>) {
    if (value.empty()) value.resize(1);
    Perturb(value[0]);
  } else {
    static_assert(sizeof(T) == 0, "a listed type Perturb does not know");
  }
}

// Every field of the list has an entry in some scene, so each test below covers all of them;
// the few no example uses are given one here (applied loads, polynomials, tie points...).
TEST(ModelFields, EverySceneIsValidAndFinalized) {
  ASSERT_GE(Scenes().size(), 10u);
  for (const Model& scene : Scenes()) {
    EXPECT_EQ(ValidateModel(scene), "") << scene.title;
    EXPECT_NE(scene.structure, nullptr) << scene.title;
    EXPECT_EQ(StructureOf(scene), scene.structure) << "a finalized Model's structure is reused";
  }
}

TEST(ModelFields, AWrongSizeIsRefusedNamingTheField) {
  int tested = 0;
  for (const ModelField& field : Fields()) {
    if (!IsArray(field)) continue;
    const Model* scene = SceneWith(field);
    if (scene == nullptr) continue;
    Model model = *scene;
    std::size_t before = CountOf(model, field.count);
    WithField(model, field.name, [](const ModelField&, auto& member) {
      if constexpr (requires { member.pop_back(); }) member.pop_back();
    });
    const std::string errors = ValidateModel(model);
    SCOPED_TRACE(field.name);
    ASSERT_NE(errors, "");
    // Shortening the array a count is read from shortens the count: the others are then long.
    if (CountOf(model, field.count) == before) {
      EXPECT_THAT(errors, HasSubstr(std::string("Model.") + field.name + " has"));
    }
    ++tested;
  }
  EXPECT_GE(tested, 150);
}

TEST(ModelFields, AnIndexOutOfRangeIsRefusedNamingTheEntry) {
  int tested = 0;
  for (const ModelField& field : Fields()) {
    if (field.indexes == ModelCount::kNone) continue;
    const Model* scene = SceneWith(field);
    if (scene == nullptr) continue;
    Model model = *scene;
    const auto past_end = static_cast<std::int32_t>(CountOf(model, field.indexes));
    WithField(model, field.name, [&](const ModelField&, auto& member) {
      if constexpr (kIsVector<decltype(member)>) {
        using E = std::decay_t<decltype(member[0])>;
        if constexpr (std::is_same_v<E, std::int32_t>) {
          member[0] = past_end;
        } else if constexpr (std::is_same_v<E, std::array<std::int32_t, 2>> ||
                             std::is_same_v<E, std::array<std::int32_t, 3>>) {
          member[0][0] = past_end;
        }
      }
    });
    SCOPED_TRACE(field.name);
    EXPECT_THAT(ValidateModel(model), HasSubstr(std::string("Model.") + field.name + "[0]"));
    ++tested;
  }
  EXPECT_GE(tested, 20);
}

TEST(ModelFields, ANumberThatIsNotFiniteIsRefusedNamingTheEntry) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  int tested = 0;
  for (const ModelField& field : Fields()) {
    const Model* scene = SceneWith(field);
    if (scene == nullptr || (field.checks & kNanAllowed) != 0) continue;
    Model model = *scene;
    bool numeric = false;
    WithField(model, field.name, [&](const ModelField&, auto& member) {
      using T = std::decay_t<decltype(member)>;
      if constexpr (std::is_same_v<T, double> || std::is_same_v<T, Vec3>) {
        numeric = true;
        if constexpr (std::is_same_v<T, double>) member = nan;
        if constexpr (std::is_same_v<T, Vec3>) member.x() = nan;
      } else if constexpr (kIsVector<decltype(member)>) {
        using E = std::decay_t<decltype(member[0])>;
        if constexpr (std::is_same_v<E, double>) {
          numeric = true, member[0] = nan;
        } else if constexpr (std::is_same_v<E, Vec3> || std::is_same_v<E, Mat3>) {
          numeric = true, member[0](0, 0) = nan;
        }
      }
    });
    if (!numeric) continue;
    SCOPED_TRACE(field.name);
    EXPECT_THAT(ValidateModel(model), HasSubstr(std::string("Model.") + field.name));
    ++tested;
  }
  EXPECT_GE(tested, 80);
}

TEST(ModelFields, NegativeMassesAndSemiAxesAreRefused) {
  Model model = Scenes().front();
  model.segment_mass[0] = -1;
  EXPECT_THAT(ValidateModel(model), HasSubstr("Model.segment_mass[0] = -1: must not be negative"));
  EXPECT_NE(FinalizeModel(model), "");
  EXPECT_EQ(model.structure, nullptr);
}

// The fingerprint's parts as FingerprintOf makes them, without the channel names (which a
// corrupted output would send out of range).
struct Parts {
  std::uint64_t physics;
  std::string settings;
  std::string records;
};
Parts PartsOf(const Model& model) {
  return {HashModelFields(model, FieldRole::kPhysics), DumpModelFields(model, FieldRole::kSettings),
          DumpModelFields(model, FieldRole::kRecords)};
}

TEST(ModelFields, TheFingerprintIsMadeOfTheFieldsByRole) {
  for (const Model& scene : Scenes()) {
    const ModelFingerprint fingerprint = FingerprintOf(scene);
    const Parts parts = PartsOf(scene);
    EXPECT_EQ(fingerprint.physics, parts.physics);
    EXPECT_EQ(fingerprint.settings + "\n", parts.settings);
    EXPECT_TRUE(fingerprint.outputs.starts_with(parts.records));
  }
}

TEST(ModelFields, TheFingerprintChangesWithEveryFieldOfItsRole) {
  int tested = 0;
  std::vector<std::string> unused;
  for (const ModelField& field : Fields()) {
    const Model* scene = SceneWith(field);
    if (scene == nullptr) {
      unused.push_back(field.name);
      continue;
    }
    SCOPED_TRACE(field.name);
    Model model = *scene;
    const Parts before = PartsOf(model);
    const std::string dump = DumpModel(model);
    WithField(model, field.name, [](const ModelField&, auto& member) { Perturb(member); });
    const Parts after = PartsOf(model);
    EXPECT_EQ(before.physics != after.physics, field.role == FieldRole::kPhysics);
    EXPECT_EQ(before.settings != after.settings, field.role == FieldRole::kSettings);
    EXPECT_EQ(before.records != after.records, field.role == FieldRole::kRecords);
    if (std::string(field.name) != "vehicle_path") {
      EXPECT_NE(DumpModel(model), dump);
    }
    ++tested;
  }
  // Every field has an entry in some scene, so every test here covers all of them.
  EXPECT_EQ(unused, std::vector<std::string>{}) << "no scene has an entry of these fields";
  EXPECT_EQ(tested, static_cast<int>(Fields().size()));
}

TEST(ModelFields, AChangedModelGetsItsStructureRebuilt) {
  Model model = Scenes().front();
  const auto finalized = model.structure;
  model.joint_frame_in_child.back() = Mat3::Identity() * 2;
  EXPECT_NE(StructureOf(model), finalized);
}

TEST(ModelData, ADataIsUsedOnlyWithItsModel) {
  const Model& model = Scenes().front();
  const Model copy = model;
  Data data = MakeData(model);
  EXPECT_NO_THROW(CheckDataOf(model, data));
  EXPECT_THROW(CheckDataOf(copy, data), std::logic_error);
  TimeSeries series;
  EXPECT_THROW(runtime::Run(copy, data, series, {}), std::logic_error);
}

}  // namespace
}  // namespace sled::runtime
