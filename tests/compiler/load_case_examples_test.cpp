// The standard load-case examples end to end, as a user runs them: `sled run` exits 0, the scene
// settles before the run and starts it at rest (below the threshold its `settle` block states,
// read both from summary.json and from the first row of the time histories), and the criteria
// are computed and judged against the limits of their standard.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "tests/compiler/csv_table.h"
#include "tests/compiler/mini_json.h"
#include "tests/compiler/sled_process.h"

namespace sled {
namespace {

namespace fs = std::filesystem;
using testing::JsonReader;
using testing::ReadText;
using testing::SledResult;

// The speed of a point's velocity channels (ground frame) at a row.
double Speed(const testing::CsvTable& table, std::size_t row, const std::string& prefix) {
  double sum = 0.0;
  for (const char* axis : {"x", "y", "z"}) {
    const std::size_t column = table.Column(prefix + ".velocity." + axis + " [m/s]");
    EXPECT_LT(column, table.names.size()) << prefix << " has no velocity channels";
    if (column >= table.names.size()) return NAN;
    sum += table.rows[row][column] * table.rows[row][column];
  }
  return std::sqrt(sum);
}

// SAE J211-1 Appendix C (crash-conventions.md §2.5), written here apart from the runtime's filter:
// the 2-pole Butterworth run forward and then backward, each end padded by 100 samples reflected
// through the end point so that the passes start settled.
std::vector<double> FilterJ211(const std::vector<double>& x, double cfc, double dt) {
  const double wd = 2.0 * M_PI * cfc * 2.0775;
  const double wa = std::tan(wd * dt / 2.0);
  const double d = 1.0 + std::sqrt(2.0) * wa + wa * wa;
  const double a0 = wa * wa / d;
  const double b1 = -2.0 * (wa * wa - 1.0) / d;
  const double b2 = (-1.0 + std::sqrt(2.0) * wa - wa * wa) / d;
  const std::size_t pad = std::min<std::size_t>(100, x.size() - 1);
  std::vector<double> y;
  for (std::size_t i = pad; i > 0; --i) y.push_back(2 * x.front() - x[i]);
  y.insert(y.end(), x.begin(), x.end());
  for (std::size_t i = 1; i <= pad; ++i) y.push_back(2 * x.back() - x[x.size() - 1 - i]);
  auto pass = [&](std::vector<double>& v) {
    std::vector<double> out(v.size());
    for (std::size_t i = 0; i < v.size(); ++i) {
      const double x1 = i >= 1 ? v[i - 1] : v[0];
      const double x2 = i >= 2 ? v[i - 2] : v[0];
      const double y1 = i >= 1 ? out[i - 1] : v[0];
      const double y2 = i >= 2 ? out[i - 2] : v[0];
      out[i] = a0 * (v[i] + 2 * x1 + x2) + b1 * y1 + b2 * y2;
    }
    v = out;
  };
  pass(y);
  std::reverse(y.begin(), y.end());
  pass(y);
  std::reverse(y.begin(), y.end());
  return {y.begin() + static_cast<std::ptrdiff_t>(pad),
          y.begin() + static_cast<std::ptrdiff_t>(pad + x.size())};
}

std::vector<double> ColumnOf(const testing::CsvTable& table, const std::string& name) {
  const std::size_t c = table.Column(name);
  EXPECT_LT(c, table.names.size()) << "no channel " << name;
  std::vector<double> values;
  if (c >= table.names.size()) return values;
  for (const auto& row : table.rows) values.push_back(row[c]);
  return values;
}

double PeakMagnitude(const std::vector<double>& values) {
  double peak = 0.0;
  for (double v : values) peak = std::max(peak, std::abs(v));
  return peak;
}

// The criterion `name` (its main value, not a variant) of a summary.
const testing::Json* Criterion(const testing::Json& summary, const std::string& name) {
  const testing::Json& criteria = summary["criteria"];
  for (std::size_t i = 0; i < criteria.size(); ++i) {
    if (criteria[i]["name"].text == name && criteria[i]["variant"].text.empty()) {
      return &criteria[i];
    }
  }
  ADD_FAILURE() << "no criterion " << name;
  return nullptr;
}

// A component (axis 0, 1, 2) of a vehicle's ground-frame `field` (`position`, `velocity`) in a
// `--dump-at` printout: the line after the vehicle's name, `  velocity [m/s] = (x, y, z)`.
double DumpedVehicle(const std::string& dump, const std::string& vehicle, const std::string& field,
                     int axis) {
  const std::size_t name = dump.find("\n" + vehicle + "\n");
  const std::size_t line =
      dump.find("  " + field + " ", name == std::string::npos ? dump.size() : name);
  const std::size_t open = dump.find('(', line == std::string::npos ? dump.size() : line);
  EXPECT_NE(open, std::string::npos) << "no " << field << " of " << vehicle;
  if (open == std::string::npos) return NAN;
  const char* at = dump.c_str() + open + 1;
  double value = 0.0;
  for (int i = 0; i <= axis; ++i) {
    char* end = nullptr;
    value = std::strtod(at, &end);
    at = end + 1;  // past the comma
  }
  return value;
}

// Every criterion is computed and judged against a limit whose standard is named (its variants,
// a quadrant or a clip, may be "not computed" when the load never entered them).
void ExpectEveryCriterionJudged(const testing::Json& summary) {
  const testing::Json& criteria = summary["criteria"];
  EXPECT_GT(criteria.size(), 0U);
  for (std::size_t i = 0; i < criteria.size(); ++i) {
    if (!criteria[i]["variant"].text.empty()) continue;
    SCOPED_TRACE(criteria[i]["name"].text);
    EXPECT_EQ(criteria[i]["value"].kind, testing::Json::Kind::kNumber);
    EXPECT_EQ(criteria[i]["limit"].kind, testing::Json::Kind::kNumber);
    EXPECT_FALSE(criteria[i]["limit_source"].text.empty());
  }
}

// The energy balance closes: the residual is a small part of the energy that moved.
void ExpectEnergyBalanceCloses(const testing::Json& summary) {
  EXPECT_LT(std::abs(summary["energy_balance"]["relative_residual"].number), 1e-4);
}

// A load-case example run as a user runs it, with the state printed at one time.
struct ExampleRun {
  bool ok = false;
  testing::Json summary;
  testing::CsvTable table;
  std::string dump;  // the `--dump-at` printout
};

class LoadCaseExamples : public testing::SledProcessTest {
 protected:
  // Runs `examples/NAME.sled` with `--dump-at DUMP_AT` and checks what every load case must
  // show: every criterion judged against a named standard, and the energy balance closed.
  ExampleRun RunExample(const std::string& name, const std::string& dump_at) {
    ExampleRun run;
    const fs::path out = temp() / "out";
    const SledResult result =
        Sled({"run", "examples/" + name + ".sled", "-o", out.string(), "--dump-at", dump_at});
    EXPECT_EQ(result.exit_code, 0) << result.err;
    if (result.exit_code != 0) return run;
    run.summary = JsonReader::Parse(ReadText(out / "summary.json"));
    run.table = testing::ReadCsv(out / "timeseries.csv");
    run.dump = ReadText(out / ("dump_" + dump_at + ".txt"));
    ExpectEveryCriterionJudged(run.summary);
    ExpectEnergyBalanceCloses(run.summary);
    run.ok = !run.table.rows.empty();
    return run;
  }
};

TEST_F(LoadCaseExamples, TheRearImpactSettlesStartsAtRestAndJudgesItsCriteria) {
  const fs::path out = temp() / "out";
  const SledResult result = Sled({"run", "examples/rear_impact.sled", "-o", out.string()});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_THAT(result.err, ::testing::HasSubstr("sled: settled in"));
  const testing::Json summary = JsonReader::Parse(ReadText(out / "summary.json"));
  EXPECT_EQ(summary["status"].text, "ok");
  const testing::Json& settle = summary["settle"];
  EXPECT_TRUE(settle["converged"].boolean);
  // The threshold the example's `settle` block states: 5 mm/s.
  EXPECT_DOUBLE_EQ(settle["velocity_tolerance"].number, 0.005);
  EXPECT_LE(settle["largest_velocity"].number, 0.005);
  const testing::CsvTable table = testing::ReadCsv(out / "timeseries.csv");
  ASSERT_FALSE(table.rows.empty());
  EXPECT_LT(Speed(table, 0, "occupant.head"), 0.005);
  EXPECT_LT(Speed(table, 0, "occupant.pelvis"), 0.005);
  // The head restraint catches the head: the contact carries load during the run.
  const std::size_t restraint = table.Column("occupant.head.head_restraint.contact_force.x [N]");
  ASSERT_LT(restraint, table.names.size());
  double largest = 0.0;
  for (const auto& row : table.rows) largest = std::max(largest, std::abs(row[restraint]));
  EXPECT_GT(largest, 10.0);
  // At rest means in equilibrium: at the start (the pulse's onset, no acceleration yet) every
  // centre of mass the example watches accelerates by less than 0.1 g.
  for (const char* segment : {"occupant.head", "occupant.thorax", "occupant.pelvis"}) {
    double sum = 0.0;
    for (const char* axis : {"x", "y", "z"}) {
      const double a =
          table.rows[0][table.Column(std::string(segment) + ".acceleration." + axis + " [m/s^2]")];
      sum += a * a;
    }
    EXPECT_LT(std::sqrt(sum), 0.1 * 9.80665) << segment;
  }
  // Every criterion computed, with its limit and the standard it comes from; Nkm and NIC, the
  // rear impact's neck criteria, among them.
  const testing::Json& criteria = summary["criteria"];
  bool nkm = false;
  bool nic = false;
  for (std::size_t i = 0; i < criteria.size(); ++i) {
    if (!criteria[i]["variant"].text.empty()) continue;  // a quadrant or clip variant
    SCOPED_TRACE(criteria[i]["name"].text);
    EXPECT_EQ(criteria[i]["value"].kind, testing::Json::Kind::kNumber);
    EXPECT_EQ(criteria[i]["limit"].kind, testing::Json::Kind::kNumber);
    EXPECT_FALSE(criteria[i]["limit_source"].text.empty());
    nkm = nkm || criteria[i]["name"].text == "nkm";
    nic = nic || criteria[i]["name"].text == "nic";
  }
  EXPECT_TRUE(nkm);
  EXPECT_TRUE(nic);
}

TEST_F(LoadCaseExamples, TheSideImpactMovesTheBuckByItsPulseAndJudgesTtiFromItsChannels) {
  const ExampleRun run = RunExample("side_impact", "0.1");
  ASSERT_TRUE(run.ok);
  const testing::Json& summary = run.summary;
  EXPECT_TRUE(summary["settle"]["converged"].boolean);
  // The half-sine's closed form: after the 50 ms pulse the buck moves at -delta_v along y, and
  // by 100 ms it has gone delta_v T / 2 + delta_v (0.1 s - T).
  const double dv = 20.2 / 3.6;
  EXPECT_NEAR(DumpedVehicle(run.dump, "sled", "velocity", 1), -dv, 1e-6);
  EXPECT_NEAR(DumpedVehicle(run.dump, "sled", "position", 1), -(dv * 0.05 / 2 + dv * 0.05), 1e-6);
  // TTI from the raw lateral accelerations (each segment's own y), filtered here at CFC 180:
  // (peak rib + peak lower spine) / 2 in g.
  const testing::CsvTable& table = run.table;
  ASSERT_GT(table.rows.size(), 100U);
  const double dt = table.rows[1][0] - table.rows[0][0];
  const double rib =
      PeakMagnitude(FilterJ211(ColumnOf(table, "occupant.thorax.acceleration.y [m/s^2]"), 180, dt));
  const double spine = PeakMagnitude(
      FilterJ211(ColumnOf(table, "occupant.abdomen.acceleration.y [m/s^2]"), 180, dt));
  const testing::Json* tti = Criterion(summary, "tti");
  ASSERT_NE(tti, nullptr);
  EXPECT_NEAR((*tti)["value"].number, 0.5 * (rib + spine) / 9.80665, 0.01 * (*tti)["value"].number);
  EXPECT_DOUBLE_EQ((*tti)["limit"].number, 85.0);
  EXPECT_EQ((*tti)["limit_source"].text, "FMVSS 214 (SID, four-door)");
  // The door loads the chest, the pelvis and (through the window) the head.
  for (const char* pair :
       {"occupant.thorax.door.trim", "occupant.pelvis.door.trim", "occupant.head.door.window"}) {
    EXPECT_GT(PeakMagnitude(ColumnOf(table, std::string(pair) + ".contact_force.normal [N]")),
              100.0)
        << pair;
  }
}

TEST_F(LoadCaseExamples, TheChildOnTheBoosterIsHeldByTheLapBeltAndTheSledStopsFrom50Kmh) {
  const ExampleRun run = RunExample("child_booster", "0.12");
  ASSERT_TRUE(run.ok);
  const testing::Json& summary = run.summary;
  EXPECT_TRUE(summary["settle"]["converged"].boolean);
  EXPECT_LE(summary["settle"]["largest_velocity"].number, 0.005);
  // R44's stand-in stops the sled from 50 km/h: its velocity change after the 93.6 ms pulse is
  // -50 km/h along x (the sled starts at rest, so its velocity is -50 km/h).
  EXPECT_NEAR(DumpedVehicle(run.dump, "sled", "velocity", 0), -50.0 / 3.6, 1e-6);
  // The lap belt, anchored at the booster's guides, carries the pelvis: it takes load and the
  // pelvis moves forward in the sled by less than 150 mm (with the guides ahead of the pelvis,
  // where the webbing lay behind it, the pelvis went over 250 mm forward before the shoulder belt
  // stopped it: so this can fail).
  const testing::CsvTable& table = run.table;
  const std::vector<double> pelvis_x =
      ColumnOf(table, "child.pelvis.relative_to.sled.position.x [m]");
  ASSERT_FALSE(pelvis_x.empty());
  const double excursion = *std::max_element(pelvis_x.begin(), pelvis_x.end()) - pelvis_x.front();
  EXPECT_GT(excursion, 0.0);
  EXPECT_LT(excursion, 0.15);
  EXPECT_GT(PeakMagnitude(ColumnOf(table, "three_point.lap.belt_force.span1 [N]")), 1000.0);
}

TEST_F(LoadCaseExamples, TheYieldingSeatBackTurnsOnItsReclinerWhileItsFrameStaysWelded) {
  const ExampleRun run = RunExample("rear_impact_yielding_seat", "0.1");
  ASSERT_TRUE(run.ok);
  const testing::Json& summary = run.summary;
  EXPECT_TRUE(summary["settle"]["converged"].boolean);
  // The trapezoid by delta-v: after its 90 ms the sled moves forward at 16 km/h.
  EXPECT_NEAR(DumpedVehicle(run.dump, "sled", "velocity", 0), 16.0 / 3.6, 1e-6);
  const testing::CsvTable& table = run.table;
  // Three fixed points hold the frame: its pose in the sled does not move (to 0.1 mm, 1 mrad).
  for (const char* axis : {"x", "y", "z"}) {
    const std::vector<double> p =
        ColumnOf(table, std::string("seat.frame.relative_to.sled.position.") + axis + " [m]");
    ASSERT_FALSE(p.empty());
    const auto [low, high] = std::minmax_element(p.begin(), p.end());
    EXPECT_LT(*high - *low, 1e-4) << axis;
  }
  for (const char* angle : {"yaw", "pitch", "roll"}) {
    EXPECT_LT(
        PeakMagnitude(ColumnOf(
            table, std::string("seat.frame.relative_to.sled.orientation.") + angle + " [rad]")),
        1e-3)
        << angle;
  }
  // The back yields: the occupant turns it rearward past the characteristic's knee at -5 deg
  // (1.2 kN*m), and the head restraint on it carries the head.
  const std::vector<double> recliner = ColumnOf(table, "seat.recliner.joint_angle.axis [rad]");
  ASSERT_FALSE(recliner.empty());
  EXPECT_LT(*std::min_element(recliner.begin(), recliner.end()), -5.0 * M_PI / 180.0);
  EXPECT_GT(PeakMagnitude(
                ColumnOf(table, "occupant.head.seat.back.head_restraint.contact_force.normal [N]")),
            100.0);
}

TEST_F(LoadCaseExamples, TheChildPedestrianIsStruckWhenTheBumperReachesItsThigh) {
  const ExampleRun run = RunExample("pedestrian_child", "0.1");
  ASSERT_TRUE(run.ok);
  const testing::Json& summary = run.summary;
  const testing::Json* hic = Criterion(summary, "hic15");
  ASSERT_NE(hic, nullptr);
  EXPECT_EQ((*hic)["limit_source"].text, "EU pedestrian headform, Phase 1");
  EXPECT_DOUBLE_EQ((*hic)["limit"].number, 1000.0);
  // Braking at 0.7 g reached over a 100 ms ramp: by then the car has lost 0.7 g * 0.1 s / 2.
  EXPECT_NEAR(DumpedVehicle(run.dump, "car", "velocity", 0), 40.0 / 3.6 - 0.7 * 9.80665 * 0.1 / 2.0,
              1e-6);
  // First contact where the geometry puts it: the bumper face starts 200 mm behind the child's
  // pelvis and the left thigh's surface is 53.6 + 50.4 mm behind it (hip joint and thigh
  // semi-axis of child6), so the bumper closes the 96 mm at 40 km/h (braking moves it by
  // microns in that time) after 8.64 ms.
  const testing::CsvTable& table = run.table;
  const std::vector<double> bumper =
      ColumnOf(table, "pedestrian.upper_leg_l.front.bumper.contact_force.normal [N]");
  ASSERT_EQ(bumper.size(), table.rows.size());
  double first = NAN;
  for (std::size_t row = 0; row < bumper.size(); ++row) {
    if (bumper[row] > 0.0) {
      first = table.rows[row][0];
      break;
    }
  }
  EXPECT_NEAR(first, 0.096 / (40.0 / 3.6), 2e-4);
  // The head strikes the bonnet.
  EXPECT_GT(PeakMagnitude(ColumnOf(table, "pedestrian.head.front.bonnet.contact_force.normal [N]")),
            1000.0);
}

}  // namespace
}  // namespace sled
