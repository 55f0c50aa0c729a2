// The deck corpus of tests/legacy/corpus: decks written from the format reference, each with
// NAME.expect beside it, a table of the SI values its fields mean, derived by hand from the V.3
// input description (legacy-decks.md), not from sled. Each deck converts without an error (its
// `.lin` twin, when there is one, to the same scenario), compiles, runs, and every value of its
// table is compared with the compiled Model's.
//
// NAME.expect: `# options: --blank-zero` on its first line when the deck needs the option; then
// one line per value, `FIELD INDEX VALUE...` (a vector's three components, a function's argument
// and value), `#` comments.
#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

#include "legacy_test_deck.h"
#include "runtime/forces/functions.h"
#include "sled/compile.h"
#include "sled/simulate.h"

namespace sled::lang::legacy {
namespace {

namespace fs = std::filesystem;

const fs::path kCorpus = fs::path(SLED_SOURCE_ROOT) / "tests/legacy/corpus";

std::vector<double> Of(const runtime::Vec3& v) { return {v.x(), v.y(), v.z()}; }
std::vector<double> Diagonal(const runtime::Mat3& m) { return {m(0, 0), m(1, 1), m(2, 2)}; }
std::vector<double> Rows(const runtime::Mat3& m) {
  return {m(0, 0), m(0, 1), m(0, 2), m(1, 0), m(1, 1), m(1, 2), m(2, 0), m(2, 1), m(2, 2)};
}

// INDEX of a row: a number, or a name among `names` (the Model's segments, ellipsoids, planes).
std::size_t IndexOf(const std::string& index, const std::vector<std::string>& names) {
  if (!index.empty() && std::isdigit(static_cast<unsigned char>(index[0])))
    return static_cast<std::size_t>(std::stoul(index));
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (names[i] == index) return i;
  }
  std::string all;
  for (const std::string& name : names) all += " " + name;
  ADD_FAILURE() << "no " << index << " among" << all;
  return names.size();
}

// The Model's value of FIELD at INDEX; `args` are a function's argument (then the value is
// the function's there). Empty for a field the table does not know.
std::vector<double> ModelValue(const runtime::Model& m, const std::string& field,
                               const std::string& index, const std::vector<double>& args) {
  const runtime::ContactTable& c = m.contacts;
  const std::size_t i = IndexOf(index, field.rfind("ellipsoid_", 0) == 0 ? c.ellipsoid_name
                                       : field.rfind("plane_", 0) == 0   ? c.plane_name
                                                                         : m.segment_name);
  const double x = args.empty() ? 0.0 : args.back();
  auto at = [&](std::int32_t function) {
    return std::vector<double>{runtime::EvaluateFunction(m.functions, function, x)};
  };
  if (field == "gravity") return Of(m.gravity);
  if (field == "end_time") return {m.end_time};
  if (field == "output_every") return {m.output_every};
  if (field == "initial_step") return {m.initial_step};
  if (field == "max_step") return {m.max_step};
  if (field == "min_step") return {m.min_step};
  if (field == "relative_tolerance") return {m.relative_tolerance};
  if (field == "segment_mass") return {m.segment_mass.at(i)};
  if (field == "segment_inertia") return Diagonal(m.segment_inertia.at(i));
  if (field == "joint_point_in_parent") return Of(m.joint_point_in_parent.at(i));
  if (field == "joint_point_in_child") return Of(m.joint_point_in_child.at(i));
  if (field == "joint_viscous") return {m.joint_viscous.at(i)};
  if (field == "joint_coulomb") return {m.joint_coulomb.at(i)};
  if (field == "joint_stop") return {m.joint_stop.at(i)};
  if (field == "joint_twist_stop") return {m.joint_twist_stop.at(i)};
  if (field == "joint_restitution") return {m.joint_restitution.at(i)};
  if (field == "joint_locked") return {static_cast<double>(m.joint_locked.at(i))};
  if (field == "joint_lock_below") return {m.joint_lock_below.at(i)};
  if (field == "joint_unlock_above") return {m.joint_unlock_above.at(i)};
  if (field == "joint_axis") return Of(m.joint_axis.at(i));
  if (field == "joint_frame_in_parent") return Rows(m.joint_frame_in_parent.at(i));
  if (field == "joint_frame_in_child") return Rows(m.joint_frame_in_child.at(i));
  if (field == "joint_function_at")
    return at(m.joint_function.at(i).at(static_cast<std::size_t>(args.front())));
  if (field == "joint_function_energy_loss") {  // args: the axis (0, 1, 2)
    const std::int32_t f = m.joint_function.at(i).at(static_cast<std::size_t>(args.front()));
    return {m.functions.energy_loss.at(static_cast<std::size_t>(f))};
  }
  if (field == "ellipsoid_semi_axes") return Of(c.ellipsoid_semi_axes.at(i));
  if (field == "ellipsoid_center") return Of(c.ellipsoid_center.at(i));
  if (field == "ellipsoid_degree") return {c.ellipsoid_degree.at(i)};
  if (field == "plane_origin") return Of(c.plane_origin.at(i));
  if (field == "plane_edge_u") return Of(c.plane_edge_u.at(i));
  if (field == "plane_edge_v") return Of(c.plane_edge_v.at(i));
  if (field == "pair_friction") return {c.pair_friction.at(i)};
  if (field == "pair_force_at") return at(c.pair_function.at(i));
  if (field == "vehicle_position") return Of(m.vehicle_position.at(i));
  if (field == "vehicle_velocity") return Of(m.vehicle_velocity.at(i));
  if (field == "vehicle_delta_v") return {m.vehicle_motion.at(i).delta_v};
  if (field == "vehicle_duration") return {m.vehicle_motion.at(i).duration};
  if (field == "spring_damping") return {m.spring_damping.at(i)};
  if (field == "spring_free_length") return {m.spring_free_length.at(i)};
  if (field == "spring_force_at") return at(m.spring_function.at(i));
  if (field == "spring_point_first") return Of(m.spring_point_first.at(i));
  if (field == "output_point") return Of(m.output_point.at(i));
  if (field == "belt_slack") return {m.belts.slack.at(i)};
  if (field == "belt_friction") return {m.belts.friction.at(i)};
  if (field == "belt_force_at") return at(m.belts.function.at(i));
  if (field == "belt_point_position") return Of(m.belts.point_position.at(i));
  if (field == "constraint_point_first") return Of(m.constraint_point_first.at(i));
  if (field == "constraint_point_second") return Of(m.constraint_point_second.at(i));
  if (field == "root_position") {  // a reference segment's: its free joint's first coordinates
    const auto q = static_cast<std::size_t>(m.q_address.at(i));
    return {m.q0.at(q), m.q0.at(q + 1), m.q0.at(q + 2)};
  }
  if (field == "root_angular_velocity") {  // in the segment's axes: the free joint's first rates
    const auto v = static_cast<std::size_t>(m.v_address.at(i));
    return {m.v0.at(v), m.v0.at(v + 1), m.v0.at(v + 2)};
  }
  // ATB's R and G of a contact's or a belt's force function at a largest deflection (strain).
  auto factor = [&](std::int32_t function, bool energy_return) {
    const auto f = static_cast<std::size_t>(function);
    const auto& ids = energy_return ? m.functions.atb_return : m.functions.atb_set;
    return f < ids.size() && ids[f] >= 0 ? at(ids[f]) : std::vector<double>{};
  };
  if (field == "pair_energy_return_at") return factor(c.pair_function.at(i), true);
  if (field == "pair_permanent_set_at") return factor(c.pair_function.at(i), false);
  // ATB's inertial spike of a contact's force function (at a deflection), its end, and the
  // function's origin D0.
  auto per_function = [&](const auto& values, std::int32_t function) {
    const auto f = static_cast<std::size_t>(function);
    using Value = typename std::decay_t<decltype(values)>::value_type;
    return f < values.size() ? std::optional<Value>(values[f]) : std::nullopt;
  };
  if (field == "pair_spike_at") {
    const auto spike = per_function(m.functions.atb_spike, c.pair_function.at(i));
    return spike && *spike >= 0 ? at(*spike) : std::vector<double>{};
  }
  if (field == "pair_spike_end") {
    const auto end = per_function(m.functions.atb_spike_end, c.pair_function.at(i));
    return end ? std::vector<double>{*end} : std::vector<double>{};
  }
  if (field == "pair_origin") {
    const auto origin = per_function(m.functions.atb_origin, c.pair_function.at(i));
    return origin ? std::vector<double>{*origin} : std::vector<double>{};
  }
  if (field == "pair_rate_scaled_force_at") return at(c.pair_rate_scaled_force.at(i));
  if (field == "pair_rate_scale_at") return at(c.pair_rate_scale.at(i));
  if (field == "pair_rate_force_at") return at(c.pair_rate_force.at(i));
  if (field == "belt_energy_return_at") return factor(m.belts.function.at(i), true);
  if (field == "belt_permanent_set_at") return factor(m.belts.function.at(i), false);
  if (field == "mirror_twin") return {static_cast<double>(m.segment_mirror_twin.at(i))};
  if (field == "output_count") return {static_cast<double>(m.output_kind.size())};
  if (field == "harness_friction") return {m.belts.harness_friction.at(i)};
  const runtime::AirbagTable& a = m.airbags;
  if (field == "airbag_semi_axes") return Of(a.semi_axes.at(i));
  if (field == "airbag_deploy_time") return {a.deploy_time.at(i)};
  if (field == "airbag_ambient_pressure") return {a.ambient_pressure.at(i)};
  if (field == "airbag_inflow_temperature") return {a.inflow_temperature.at(i)};
  if (field == "airbag_gamma") return {a.gamma.at(i)};
  if (field == "airbag_gas_constant") return {a.gas_constant.at(i)};
  if (field == "airbag_free") return {static_cast<double>(a.free_bag.at(i))};
  if (field == "airbag_vent_opening_pressure") return {a.vent_opening_pressure.at(i)};
  if (field == "airbag_vent_area") return {a.vent_area.at(i)};
  if (field == "airbag_discharge_coefficient") return {a.discharge_coefficient.at(i)};
  if (field == "airbag_bag_mass") return {a.bag_mass.at(i)};
  if (field == "airbag_mass_factor") return {a.mass_factor.at(i)};
  if (field == "airbag_tether_stiffness") return {a.tether_stiffness.at(i)};
  if (field.rfind("fluid_", 0) == 0) {  // a row of the fluid table, by number
    const runtime::FluidTable& f = m.fluids;
    const auto row = static_cast<std::size_t>(std::stoul(index));
    if (field == "fluid_pressure_at") return at(f.pressure.at(row));
    if (field == "fluid_speed_at") return at(f.speed.at(row));
    if (field == "fluid_direction") return Of(f.direction.at(row));
    if (field == "fluid_drag") return {f.drag.at(row)};
    if (field == "fluid_density") return {f.density.at(row)};
    if (field == "fluid_level") return {f.level.at(row)};
    if (field == "fluid_carrier") {  // its kind (0 ground, 1 vehicle, 2 segment) and index
      return {static_cast<double>(f.carrier.at(row).kind),
              static_cast<double>(f.carrier.at(row).index)};
    }
  }
  if (field.rfind("load_", 0) == 0) {  // a row of the applied loads, by number (D.9 order)
    const runtime::LoadTable& l = m.loads;
    const auto row = static_cast<std::size_t>(std::stoul(index));
    if (field == "load_segment") return {static_cast<double>(l.segment.at(row))};
    if (field == "load_force_at") return at(l.force.at(row));
    if (field == "load_torque_at") return at(l.torque.at(row));
    if (field == "load_direction") return Of(l.direction.at(row));
    if (field == "load_axis") return Of(l.axis.at(row));
    if (field == "load_point") return Of(l.point.at(row));
    if (field == "load_in_segment") return {static_cast<double>(l.in_segment.at(row))};
  }
  if (field.rfind("actuator_", 0) == 0) {  // a row of the actuators, by number (F.10 order)
    const runtime::ActuatorTable& act = m.actuators;
    const auto row = static_cast<std::size_t>(std::stoul(index));
    if (field == "actuator_segment") return {static_cast<double>(act.segment.at(row))};
    if (field == "actuator_axis") return Of(act.axis.at(row));
    if (field == "actuator_target_at") return at(act.target.at(row));
    if (field == "actuator_proportional_at") return at(act.proportional.at(row));
    if (field == "actuator_derivative_at") return at(act.derivative.at(row));
    if (field == "actuator_integral_at") return at(act.integral.at(row));
    if (field == "actuator_integrates") return {act.state_address.at(row) >= 0 ? 1.0 : 0.0};
  }
  if (field == "q0") return {m.q0.at(i)};
  if (field == "v0") return {m.v0.at(i)};
  return {};
}

struct Expectation {
  int line = 0;
  std::string field;
  std::string index;         // a number, or a segment's, ellipsoid's or plane's name in the Model
  std::vector<double> args;  // a function's argument (joint_function_at: slot, then argument)
  std::vector<double> values;
};

// `FIELD INDEX VALUE...`; a function's `_at` row is `FIELD INDEX X VALUE` (joint_function_at:
// `INDEX SLOT X VALUE`, the slot 0 flexure, 1 twist).
std::vector<Expectation> ReadExpectations(const fs::path& path, std::string* options) {
  std::ifstream in(path);
  std::vector<Expectation> rows;
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (line.rfind("# options:", 0) == 0) *options = line.substr(10);
    if (line.empty() || line[0] == '#') continue;
    std::istringstream words(line);
    Expectation row;
    row.line = number;
    words >> row.field >> row.index;
    double value = 0;
    while (words >> value) row.values.push_back(value);
    const std::size_t args = row.field == "joint_function_at"                     ? 2
                             : row.field == "joint_function_energy_loss"          ? 1
                             : row.field.size() > 3 && row.field.ends_with("_at") ? 1
                                                                                  : 0;
    row.args.assign(row.values.begin(), row.values.begin() + static_cast<std::ptrdiff_t>(args));
    row.values.erase(row.values.begin(), row.values.begin() + static_cast<std::ptrdiff_t>(args));
    rows.push_back(std::move(row));
  }
  return rows;
}

void CheckDeck(const std::string& name) {
  SCOPED_TRACE(name);
  std::string flags;
  const std::vector<Expectation> rows = ReadExpectations(kCorpus / (name + ".expect"), &flags);
  ASSERT_FALSE(rows.empty());
  ConvertOptions options;
  options.blanks =
      flags.find("--blank-zero") != std::string::npos ? BlankMode::kZero : BlankMode::kIgnore;
  const Converted converted =
      ConvertText(ReadDeckFile((kCorpus / (name + ".ain")).string()), options, name + ".ain");
  ASSERT_EQ(converted.errors, 0) << converted.All();
  if (fs::exists(kCorpus / (name + ".lin"))) {
    options.format = DeckFormat::kList;
    const Converted list =
        ConvertText(ReadDeckFile((kCorpus / (name + ".lin")).string()), options, name + ".lin");
    ASSERT_EQ(list.errors, 0) << list.All();
    EXPECT_EQ(list.text, converted.text);
  }
  Compilation compiled =
      Compile(Source::Text(converted.text, (kCorpus / (name + ".sled")).string()));
  ASSERT_TRUE(compiled.ok()) << compiled.Render() << converted.text;
  const runtime::Model& model = compiled.model();
  for (const Expectation& row : rows) {
    const std::vector<double> actual = ModelValue(model, row.field, row.index, row.args);
    ASSERT_EQ(actual.size(), row.values.size())
        << name << ".expect:" << row.line << ": " << row.field << " (an unknown field?)";
    for (std::size_t k = 0; k < actual.size(); ++k) {
      EXPECT_NEAR(actual[k], row.values[k], 1e-9 * std::max(1.0, std::fabs(row.values[k])))
          << name << ".expect:" << row.line << ": " << row.field << " " << row.index
          << " component " << k;
    }
  }
  const RunResult run = Simulate(model);
  EXPECT_FALSE(run.failed()) << run.summary.failure.cause;
  EXPECT_GT(run.series.rows(), 1u);
}

TEST(LegacyDeckCorpus, EveryDeckConvertsChecksRunsAndMeansWhatV3Says) {
  int decks = 0;
  for (const auto& entry : fs::directory_iterator(kCorpus)) {
    if (entry.path().extension() != ".expect") continue;
    CheckDeck(entry.path().stem().string());
    ++decks;
  }
  EXPECT_GE(decks, 3);
}

}  // namespace
}  // namespace sled::lang::legacy
