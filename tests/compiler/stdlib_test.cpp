// The standard library against its documentation (docs/language.md §22): the male50's masses,
// ellipsoids and ranges of motion, the interior's surfaces and the frame its import gives, and
// the pulses against their closed forms (delta-v and stopping distance integrated here).
#include <cmath>
#include <fstream>
#include <iterator>
#include <map>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "compiler/check/check.h"
#include "lang/diagnostics/render.h"
#include "lang/syntax/parser.h"
#include "tests/compiler/sled_process.h"

namespace sled::compiler {
namespace {

using ::testing::Contains;
using ::testing::HasSubstr;

constexpr double kDeg = 3.14159265358979323846 / 180.0;

struct Checked {
  CheckedScenario scenario;
  std::vector<std::string> messages;
  int errors = 0;
  int warnings = 0;
};

// Checks a file's text; diagnostics rendered one line each.
Checked CheckSource(const std::string& text, const std::string& path) {
  lang::SourceManager sources;
  const lang::FileId file = sources.Add(path, text);
  lang::DiagnosticCollector collector;
  CheckOptions options;
  options.diagnostics = &collector;
  options.stdlib_root = std::string(SLED_SOURCE_ROOT) + "/stdlib";
  Checked out;
  out.scenario = ParseAndCheck(sources, file, options);
  for (const auto& d : collector.diagnostics()) {
    out.messages.push_back(lang::RenderCompact(sources, d));
  }
  out.errors = collector.error_count();
  out.warnings = collector.warning_count();
  return out;
}

// A scenario around the given statements.
Checked CheckScene(const std::string& statements, const std::string& path = "stdlib_test.sled") {
  return CheckSource(
      "scenario \"t\" {\n  time { end = 100 ms  output_every = 1 ms }\n" + statements + "\n}\n",
      path);
}

std::string Report(const Checked& c) { return fmt::format("{}", fmt::join(c.messages, "\n")); }

// Linear interpolation inside a table function's rows (the tests ask only inside them).
double Evaluate(const Function& f, double x) {
  for (std::size_t i = 1; i < f.points.size(); ++i) {
    if (x <= f.points[i][0]) {
      const auto& a = f.points[i - 1];
      const auto& b = f.points[i];
      return a[1] + (b[1] - a[1]) * (x - a[0]) / (b[0] - a[0]);
    }
  }
  ADD_FAILURE() << "x = " << x << " beyond the table";
  return 0;
}

const Joint& JointNamed(const CheckedScenario& s, const std::string& name) {
  for (const Joint& j : s.joints) {
    if (j.name == name) return j;
  }
  throw std::runtime_error("no joint " + name);
}

TEST(StdlibMale50, MassesAreTheDocumentedOnesAndSumTo77_99Kilograms) {
  const Checked c = CheckScene("  import std.humans.male50 as occupant");
  ASSERT_EQ(c.errors + c.warnings, 0) << Report(c);
  const std::map<std::string, double> documented = {
      {"pelvis", 8.71},      {"abdomen", 12.74},     {"thorax", 12.45},      {"neck", 1.08},
      {"head", 4.33},        {"upper_arm_l", 2.11},  {"upper_arm_r", 2.11},  {"lower_arm_l", 1.74},
      {"lower_arm_r", 1.74}, {"upper_leg_l", 11.04}, {"upper_leg_r", 11.04}, {"lower_leg_l", 3.38},
      {"lower_leg_r", 3.38}, {"foot_l", 1.07},       {"foot_r", 1.07}};
  ASSERT_EQ(c.scenario.segments.size(), documented.size());
  double total = 0;
  for (const Segment& s : c.scenario.segments) {
    const std::string name = s.name.substr(std::string("occupant.").size());
    ASSERT_TRUE(documented.count(name)) << s.name;
    EXPECT_NEAR(s.mass, documented.at(name), 1e-9) << s.name;
    total += s.mass;
  }
  EXPECT_NEAR(total, 77.99, 1e-9);
  // de Leva's mass fractions of the whole body: trunk 43.46 % of 78 kg in three segments.
  EXPECT_NEAR(8.71 + 12.74 + 12.45, 0.4346 * 78, 0.01);
}

TEST(StdlibMale50, EverySegmentHasAContactEllipsoidOfBodySize) {
  const Checked c = CheckScene("  import std.humans.male50 as occupant");
  ASSERT_EQ(c.errors, 0) << Report(c);
  for (const Segment& s : c.scenario.segments) {
    ASSERT_FALSE(s.ellipsoids.empty()) << s.name << " has no contact ellipsoid";
    for (int e : s.ellipsoids) {
      const Ellipsoid& ellipsoid = c.scenario.ellipsoids[static_cast<std::size_t>(e)];
      for (double axis : ellipsoid.semi_axes) {
        // Between a finger's half-width and half a standing body's height.
        EXPECT_GT(axis, 0.02) << s.name;
        EXPECT_LT(axis, 0.5) << s.name;
      }
    }
  }
}

// A joint's range of motion as documented: the torque function is soft up to the limit (at most
// `soft` there) and has risen past 100 N*m ten degrees beyond it, on the side `direction` (+1 or
// -1) of the angle.
void ExpectStopAt(const Function& f, double limit_deg, double direction, double soft,
                  const std::string& what) {
  const double at = std::abs(Evaluate(f, limit_deg * kDeg));
  const double beyond = std::abs(Evaluate(f, (limit_deg + 10 * direction) * kDeg));
  EXPECT_LE(at, soft) << what << " is not soft at its limit " << limit_deg << " deg";
  EXPECT_GE(beyond, 100.0) << what << " has no stop past " << limit_deg << " deg";
}

TEST(StdlibMale50, RangesOfMotionAreTheDocumentedOnes) {
  const Checked c = CheckScene("  import std.humans.male50 as occupant");
  ASSERT_EQ(c.errors, 0) << Report(c);
  const CheckedScenario& s = c.scenario;
  auto function = [&](FunctionId id) -> const Function& {
    EXPECT_GE(id, 0);
    return s.functions.at(static_cast<std::size_t>(id));
  };
  // Ball joints: (stop, twist_stop) in degrees.
  const std::map<std::string, std::pair<double, double>> ball = {
      {"lumbar", {40, 20}},      {"thoracic", {30, 30}}, {"shoulder_l", {120, 80}},
      {"shoulder_r", {120, 80}}, {"hip_l", {110, 45}},   {"hip_r", {110, 45}},
      {"ankle_l", {35, 30}},     {"ankle_r", {35, 30}}};
  for (const auto& [name, limits] : ball) {
    const Joint& j = JointNamed(s, "occupant." + name);
    ASSERT_EQ(j.type, JointType::kBall) << name;
    ASSERT_TRUE(j.stop && j.twist_stop) << name;
    EXPECT_NEAR(*j.stop, limits.first * kDeg, 1e-12) << name;
    EXPECT_NEAR(*j.twist_stop, limits.second * kDeg, 1e-12) << name;
    ExpectStopAt(function(j.flexure), limits.first, 1, 150, name + " flexure");
    ExpectStopAt(function(j.twist), limits.second, 1, 150, name + " twist");
  }
  // Pin joints: flexion and extension limits, signed as the joint angle.
  // The knee flexes positive (0 to 135), the elbow negative (-145 to 5 of hyperextension).
  const std::map<std::string, std::pair<double, double>> pin = {
      {"knee_l", {135, 0}}, {"knee_r", {135, 0}}, {"elbow_l", {-145, 5}}, {"elbow_r", {-145, 5}}};
  for (const auto& [name, limits] : pin) {
    const Joint& j = JointNamed(s, "occupant." + name);
    ASSERT_EQ(j.type, JointType::kPin) << name;
    const double flexion_side = limits.first > 0 ? 1 : -1;
    ExpectStopAt(function(j.flexure), limits.first, flexion_side, 30, name + " flexion");
    ExpectStopAt(function(j.flexure), limits.second, -flexion_side, 30, name + " extension");
  }
  // The neck: flexion 30 and extension 35 degrees and lateral bending 20 at each joint; axial
  // rotation locked at T1 (precession, bit 0) and 70 degrees at the skull.
  for (const std::string name : {"neck_lower", "neck_upper"}) {
    const Joint& j = JointNamed(s, "occupant." + name);
    ASSERT_EQ(j.type, JointType::kEuler) << name;
    ExpectStopAt(function(j.nutation), 30, 1, 50, name + " flexion");
    ExpectStopAt(function(j.nutation), -35, -1, 50, name + " extension");
    ExpectStopAt(function(j.spin), 20, 1, 50, name + " lateral bending");
  }
  EXPECT_EQ(JointNamed(s, "occupant.neck_lower").locked_axes & 7u, 1u);
  ExpectStopAt(function(JointNamed(s, "occupant.neck_upper").precession), 70, 1, 50, "neck axial");
}

TEST(StdlibMale50, TheSeatedPoseIsInsideTheSoftRange) {
  // The flagship's seated knee (53.5 deg) and hip (80 deg) angles, and 90 deg of knee flexion,
  // cost less than 20 N*m each: the stops do not push a seated occupant.
  const Checked c = CheckScene("  import std.humans.male50 as occupant");
  const Joint& knee = JointNamed(c.scenario, "occupant.knee_l");
  const Joint& hip = JointNamed(c.scenario, "occupant.hip_l");
  const Function& knee_f = c.scenario.functions.at(static_cast<std::size_t>(knee.flexure));
  EXPECT_LT(Evaluate(knee_f, 90 * kDeg), 20.0);
  EXPECT_LT(Evaluate(knee_f, 53.5 * kDeg), 20.0);
  EXPECT_LT(Evaluate(c.scenario.functions.at(static_cast<std::size_t>(hip.flexure)), 80 * kDeg),
            20.0);
}

TEST(StdlibInterior, SurfacesAreFixedInTheFrameTheImportNames) {
  const Checked c = CheckScene(
      "  vehicle sled { velocity = (1 m/s, 0 m/s, 0 m/s) }\n"
      "  vehicle car { velocity = (2 m/s, 0 m/s, 0 m/s) }\n"
      "  import std.vehicles.midsize_driver as buck on sled\n"
      "  import std.vehicles.midsize_driver as other on car\n"
      "  import std.vehicles.midsize_driver as fixed\n"
      "  import std.humans.male50 as occupant\n"
      "  contact occupant.pelvis with buck.seat_pan { force = buck.seat_foam }\n"
      "  contact occupant.thorax with other.wheel_rim { force = other.steering_wheel }\n"
      "  contact occupant.head with fixed.windshield { force = fixed.windshield_glass }");
  ASSERT_EQ(c.errors, 0) << Report(c);
  // Three instances of seven planes and one ellipsoid (plus the occupant's ellipsoids).
  ASSERT_EQ(c.scenario.planes.size(), 21u);
  std::map<std::string, FrameRef> frames;
  for (const Plane& p : c.scenario.planes) frames[p.name] = p.frame;
  for (const Ellipsoid& e : c.scenario.ellipsoids) frames[e.name] = e.frame;
  for (const std::string surface : {"seat_pan", "seat_back", "floor", "toe_board", "knee_bolster",
                                    "instrument_panel", "windshield", "wheel_rim"}) {
    ASSERT_TRUE(frames.count("buck." + surface)) << surface;
    EXPECT_EQ(frames["buck." + surface].kind, FrameRef::Kind::kVehicle) << surface;
    EXPECT_EQ(frames["buck." + surface].index, 0) << surface;
    EXPECT_EQ(frames["other." + surface].index, 1) << surface;
    EXPECT_EQ(frames["fixed." + surface].kind, FrameRef::Kind::kGround) << surface;
  }
}

TEST(StdlibInterior, EveryPlaneFacesTheOccupant) {
  // The normal (P2 - P1) x (P3 - P1) points to the side contacts push towards: from each surface
  // towards the H-point region, the origin of the buck's frame.
  const Checked c = CheckScene("  import std.vehicles.midsize_driver as buck");
  ASSERT_EQ(c.errors, 0) << Report(c);
  ASSERT_EQ(c.scenario.planes.size(), 7u);
  for (const Plane& p : c.scenario.planes) {
    const Vec3 u{p.corners[1][0] - p.corners[0][0], p.corners[1][1] - p.corners[0][1],
                 p.corners[1][2] - p.corners[0][2]};
    const Vec3 v{p.corners[2][0] - p.corners[0][0], p.corners[2][1] - p.corners[0][1],
                 p.corners[2][2] - p.corners[0][2]};
    const Vec3 n{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    // The occupant's hip region, 100 mm above the H-point, lies on the normal's side.
    const double side = n[0] * (0 - p.corners[0][0]) + n[1] * (0 - p.corners[0][1]) +
                        n[2] * (0.1 - p.corners[0][2]);
    EXPECT_GT(side, 0) << p.name << " faces away from the occupant";
  }
}

TEST(StdlibInterior, AModuleSurfaceTakesNoFrameOfItsOwn) {
  const sled::testing::TempFolder temp;
  std::ofstream(temp.path() / "seat.sled")
      << "plane pan { corners = (0, 0, 0) mm, (1, 0, 0) m, (0, 1, 0) m }\n"
         "plane back on ground { corners = (0, 0, 0) mm, (0, 1, 0) m, (0, 0, 1) m }\n";
  const Checked c = CheckScene(
      "  vehicle car { velocity = (1 m/s, 0 m/s, 0 m/s) }\n"
      "  import seat as s on car",
      (temp.path() / "main.sled").string());
  EXPECT_THAT(Report(c), HasSubstr("error[E0212]: a plane of a module is fixed in the frame its "
                                   "import gives"));
  ASSERT_EQ(c.scenario.planes.size(), 1u);
  EXPECT_EQ(c.scenario.planes[0].name, "s.pan");
  EXPECT_EQ(c.scenario.planes[0].frame.kind, FrameRef::Kind::kVehicle);
}

// Exact delta-v and stopping distance of a piecewise-linear deceleration from v0.
std::pair<double, double> Integrate(const std::vector<std::array<double, 2>>& rows, double v0) {
  double v = v0, s = 0;
  for (std::size_t i = 1; i < rows.size(); ++i) {
    const double h = rows[i][0] - rows[i - 1][0];
    const double a0 = rows[i - 1][1], a1 = rows[i][1];
    s += v * h - a0 * h * h / 2 - (a1 - a0) * h * h / 6;
    v -= (a0 + a1) / 2 * h;
  }
  return {v0 - v, s};
}

TEST(StdlibPulses, NcapHalfSineValuesAndTableKeepTheDeltaV) {
  const Checked c = CheckScene(
      "  import std.pulses.ncap_56kmh as ncap\n"
      "  vehicle a { motion = half_sine(delta_v = ncap.delta_v, duration = ncap.duration) }\n"
      "  vehicle b { motion = table(ncap.tabulated, axis = -x) }\n"
      "  vehicle c { motion = trapezoid(peak = ncap.peak, rise = 1 ms, dwell = 1 ms, fall = 1 ms) "
      "}\n"
      "  vehicle d { motion = trapezoid(peak = 1 g, rise = ncap.stopping_distance / ncap.delta_v,"
      " dwell = 1 ms, fall = 1 ms) }");
  ASSERT_EQ(c.errors, 0) << Report(c);
  const double dv = 56 / 3.6;
  const auto& v = c.scenario.vehicles;
  EXPECT_NEAR(v[0].motion.delta_v, dv, 1e-12);
  EXPECT_NEAR(v[0].motion.duration, 0.1, 1e-12);
  EXPECT_NEAR(v[2].motion.peak / 9.80665, 24.9, 0.05);  // crash-conventions.md §3
  EXPECT_NEAR(v[3].motion.rise, 0.05, 1e-9);            // stopping distance dv T / 2 over dv
  ASSERT_EQ(v[1].motion.kind, Motion::Kind::kTable);
  EXPECT_EQ(v[1].motion.axis[0], -1);
  const auto [delta_v, distance] = Integrate(v[1].motion.table, dv);
  EXPECT_NEAR(delta_v, dv, dv * 2e-4);
  EXPECT_NEAR(distance, 0.778, 0.002);  // dv T / 2 = 0.78 m
}

TEST(StdlibPulses, R16TrapezoidStopsFrom50KmhIn400Mm) {
  const Checked c = CheckScene(
      "  import std.pulses.r16_50kmh as r16\n"
      "  vehicle a { motion = trapezoid(peak = r16.peak, rise = r16.ramp, dwell = r16.dwell,"
      " fall = r16.ramp) }");
  ASSERT_EQ(c.errors, 0) << Report(c);
  const Motion& m = c.scenario.vehicles.at(0).motion;
  const std::vector<std::array<double, 2>> rows = {
      {0, 0}, {m.rise, m.peak}, {m.rise + m.dwell, m.peak}, {m.rise + m.dwell + m.fall, 0}};
  const auto [delta_v, distance] = Integrate(rows, 50 / 3.6);
  EXPECT_NEAR(delta_v, 50 / 3.6, 1e-9);
  EXPECT_NEAR(distance, 0.40, 1e-9);
}

TEST(StdlibPulses, R44HalfSineStopsFrom50KmhIn650Mm) {
  const Checked c = CheckScene(
      "  import std.pulses.r44_50kmh as r44\n"
      "  vehicle a { motion = half_sine(delta_v = r44.delta_v, duration = r44.duration) }\n"
      "  vehicle b { motion = trapezoid(peak = r44.peak, rise = 1 ms, dwell = 1 ms, fall = 1 ms) "
      "}");
  ASSERT_EQ(c.errors, 0) << Report(c);
  const Motion& m = c.scenario.vehicles.at(0).motion;
  // Sample the half-sine finely and integrate.
  std::vector<std::array<double, 2>> rows;
  const double peak = 3.14159265358979 * m.delta_v / (2 * m.duration);
  for (int i = 0; i <= 2000; ++i) {
    const double t = m.duration * i / 2000;
    rows.push_back({t, peak * std::sin(3.14159265358979 * t / m.duration)});
  }
  const auto [delta_v, distance] = Integrate(rows, 50 / 3.6);
  EXPECT_NEAR(delta_v, 50 / 3.6, 1e-5);
  EXPECT_NEAR(distance, 0.65, 1e-5);
  EXPECT_NEAR(c.scenario.vehicles.at(1).motion.peak / 9.80665, 23.8, 0.05);
}

TEST(StdlibFlagship, EveryInteriorSurfaceIsInAContactAndTheBeltHasTwoParts) {
  const std::string path = std::string(SLED_SOURCE_ROOT) + "/examples/frontal_sled.sled";
  std::ifstream in(path);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ASSERT_FALSE(text.empty()) << path;
  const Checked c = CheckSource(text, path);
  ASSERT_EQ(c.errors + c.warnings, 0) << Report(c);
  const CheckedScenario& s = c.scenario;
  std::vector<std::string> touched;
  for (const Contact& contact : s.contacts) {
    touched.push_back(contact.second.kind == SurfaceRef::Kind::kPlane
                          ? s.planes[static_cast<std::size_t>(contact.second.index)].name
                          : s.ellipsoids[static_cast<std::size_t>(contact.second.index)].name);
  }
  for (const std::string surface : {"seat_pan", "seat_back", "floor", "toe_board", "knee_bolster",
                                    "instrument_panel", "windshield", "wheel_rim"}) {
    EXPECT_THAT(touched, Contains("buck." + surface));
  }
  ASSERT_EQ(s.belts.size(), 2u);
  for (const Belt& belt : s.belts) {
    EXPECT_EQ(belt.frame.kind, FrameRef::Kind::kVehicle) << belt.name;
    EXPECT_EQ(belt.path.size(), 3u) << belt.name;
  }
  ASSERT_EQ(s.vehicles.size(), 1u);
  EXPECT_NEAR(s.vehicles[0].motion.delta_v, 56 / 3.6, 1e-12);
  EXPECT_NEAR(s.run.end, 0.2, 1e-12);
}

}  // namespace
}  // namespace sled::compiler
