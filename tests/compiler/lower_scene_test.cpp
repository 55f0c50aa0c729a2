// compiler::Lower: springs, outputs, contacts and belts of the scene, the model dump, and the
// golden runner, which lowers every tests/golden/model/*.sled and compares runtime::DumpModel with
// the .model file next to it (set SLED_UPDATE_GOLDEN=1 to write them). Expected values come from
// the rules in runtime/model/model.h, worked out by hand, not from earlier output.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include "runtime/model/model.h"
#include "sled/compile.h"
#include "tests/compiler/lower_helpers.h"
#include "tests/compiler/sled_process.h"

namespace sled::compiler {
namespace {

namespace fs = std::filesystem;
using lower_test::ExpectNear;
using lower_test::kDeg;
using lower_test::kRoot;
using lower_test::kUnitInertia;
using lower_test::LowerText;
using lower_test::Result;
using lower_test::Scene;
using sled::testing::WorkingDirectory;
using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::IsEmpty;

// --- Scene elements ----------------------------------------------------------------------------

TEST(LowerScene, SpringsWithoutAFreeLengthTakeTheInitialDistance) {
  const Result r = LowerText(Scene(R"(
  vehicle sled { position = (0, 0, 0) m }
  body b { segment s { mass = 1 kg  inertia = (0.01, 0.01, 0.01) kg*m^2 } }
  spring tether : b.s -> sled {
    at b.s = (0, 0, 1) m
    at sled = (3, 0, 0) m
    stiffness = 1 kN/m
  }
  tension strap : sled -> b.s {
    at sled = (0, 0, 0) m
    at b.s = (0, 0, 0) m
    stiffness = 1 kN/m
    free_length = 250 mm
  }
  initial b { position = (0, 0, 3) m }
  initial sled { position = (0, 0, 0) m  velocity = (2, 0, 0) m/s })"));
  ASSERT_CHECKED(r);
  const runtime::Model& m = r.model();
  ASSERT_EQ(m.nspring(), 2u);
  // (0, 0, 4) m to (3, 0, 0) m.
  EXPECT_DOUBLE_EQ(m.spring_free_length[0], 5.0);
  EXPECT_DOUBLE_EQ(m.spring_free_length[1], 0.25);
  EXPECT_EQ(m.spring_tension_only[1], 1);
  EXPECT_EQ(m.spring_first[0].kind, runtime::FrameRef::Kind::kSegment);
  EXPECT_EQ(m.spring_second[0].kind, runtime::FrameRef::Kind::kVehicle);
  EXPECT_EQ(m.spring_function[0], 0);
  EXPECT_EQ(m.spring_function[1], 1);
  ExpectNear(m.vehicle_velocity[0], runtime::Vec3(2, 0, 0), 0);
}

TEST(LowerScene, ActuatorsActOnThePinsChildAboutItsAxisInTheParent) {
  // The pin's axis (0, 3, 4) in the parent, made unit. Only the actuator with an integral gain
  // owns an auxiliary state, starting at zero.
  const Result r = LowerText(Scene(R"(
  body b {
    segment upper { mass = 1 kg  inertia = (0.01, 0.01, 0.01) kg*m^2 }
    segment lower { mass = 1 kg  inertia = (0.01, 0.01, 0.01) kg*m^2 }
    joint knee : pin(upper -> lower) {
      at upper = (0, 0, -0.2) m
      at lower = (0, 0, 0.2) m
      axis = (0, 3, 4)
    }
  }
  actuator hold on b.knee { target = 10 deg  proportional = 50 N*m/rad }
  actuator drive on b.knee {
    target = table(time -> angle) { 0 s -> 0 deg  1 s -> 90 deg }
    proportional = 50 N*m/rad
    derivative = 2 N*m*s/rad
    integral = 20 N*m/rad/s
  })"));
  ASSERT_CHECKED(r);
  const runtime::Model& m = r.model();
  const runtime::ActuatorTable& a = m.actuators;
  ASSERT_EQ(a.size(), 2u);
  EXPECT_EQ(m.segment_name[static_cast<std::size_t>(a.segment[0])], "b.lower");
  ExpectNear(a.axis[0], runtime::Vec3(0, 0.6, 0.8), 1e-12);
  EXPECT_EQ(a.derivative[0], -1);
  EXPECT_EQ(a.integral[0], -1);
  EXPECT_EQ(a.state_address[0], -1);
  EXPECT_GE(a.integral[1], 0);
  ASSERT_EQ(m.nw, 1);
  EXPECT_EQ(a.state_address[1], 0);
  EXPECT_EQ(m.w0[0], 0.0);
}

TEST(LowerScene, JointOutputsNameTheChildSegmentInTreeOrder) {
  const Result r = LowerText(Scene(fmt::format(R"(
  body b {{
    segment z {{ {0} }}
    segment y {{ {0} }}
    segment x {{ {0} }}
    joint second : pin(y -> z) {{ at y = (0, 0, -1) m  at z = (0, 0, 1) m }}
    joint first : pin(x -> y) {{ at x = (0, 0, -1) m  at y = (0, 0, 1) m }}
  }}
  output {{
    joint_torque b.second
    acceleration b.z at (0, 0, 10) mm as tip
  }})",
                                               kUnitInertia)));
  ASSERT_CHECKED(r);
  const runtime::Model& m = r.model();
  EXPECT_THAT(m.segment_name, ElementsAre("b.x", "b.y", "b.z"));
  ASSERT_EQ(m.output_kind.size(), 2u);
  EXPECT_EQ(m.output_kind[0], runtime::Model::OutputKind::kJointTorque);
  EXPECT_EQ(m.output_index[0], 2);
  EXPECT_EQ(m.output_label[1], "tip");
  EXPECT_EQ(m.output_index[1], 2);
  ExpectNear(m.output_point[1], runtime::Vec3(0, 0, 0.01), 1e-15);
}

TEST(LowerContacts, ContactsBecomePairsWithTheirOutputs) {
  const Result r = LowerText(Scene(R"(
  plane floor { corners = (0, 0, 0) m, (1, 0, 0) m, (0, 1, 0) m }
  body b {
    segment s {
      mass = 1 kg  inertia = (0.01, 0.01, 0.01) kg*m^2
      ellipsoid { semi_axes = (0.1, 0.1, 0.1) m }
      ellipsoid toe { semi_axes = (0.05, 0.1, 0.2) m  center = (0.1, 0, 0) m  degree = 4 }
    }
  }
  contact b.s with floor { force = 10 kN/m  damping = 5 N*s/m  friction = 0.3  impulse = true
                           restitution = 0.4 }
  initial b { position = (0, 0, 1) m }
  output { contact_force b.s with floor })"));
  ASSERT_CHECKED(r);
  EXPECT_THAT(r.notes(), IsEmpty());
  const runtime::ContactTable& c = r.model().contacts;
  ASSERT_EQ(c.npair(), 2u);  // one pair per ellipsoid of the segment
  EXPECT_EQ(c.nplane(), 1u);
  EXPECT_EQ(c.nellipsoid(), 2u);
  EXPECT_EQ(c.pair_kind[0], runtime::ContactTable::PairKind::kPlaneEllipsoid);
  EXPECT_EQ(c.pair_second[0], 0);
  EXPECT_EQ(c.pair_second[1], 0);
  EXPECT_EQ(c.pair_damping[1], 5.0);
  EXPECT_EQ(c.pair_friction[1], 0.3);
  EXPECT_EQ(c.pair_impulse[1], 1);
  EXPECT_EQ(c.pair_restitution[1], 0.4);
  EXPECT_EQ(c.ellipsoid_degree[1], 4.0);
  ExpectNear(c.plane_normal[0], runtime::Vec3::UnitZ(), 1e-15);
  ExpectNear(c.plane_edge_v[0], runtime::Vec3::UnitY(), 1e-15);
  ASSERT_EQ(r.model().functions.size(), 1u);
  EXPECT_EQ(c.pair_function[0], 0);
  // The request sums both pairs: force, point and deflection channels.
  EXPECT_THAT(c.group_pairs, ElementsAre(0, 1));
  EXPECT_THAT(r.model().output_kind, ElementsAre(runtime::Model::OutputKind::kContactForce,
                                                 runtime::Model::OutputKind::kContactPoint,
                                                 runtime::Model::OutputKind::kContactDeflection));
  EXPECT_THAT(r.model().output_label, ElementsAre("b.s.floor", "b.s.floor", "b.s.floor"));
}

TEST(LowerContacts, PairsThatCanNeverTouchAreLeftOut) {
  // A two-link arm hung from the ground at (0, 0, 2) m: the upper link reaches 0.3 + 0.1 m from
  // the pivot, the lower 0.6 + 0.1 m, both far above the floor at z = 0; the pin joint holds the
  // lower link's ellipsoid 0.2 m from the elbow and the upper's 0.1 m away, which their radii
  // (0.04, 0.05) cannot bridge; a third segment is locked to the second for good.
  const Result r = LowerText(Scene(R"(
  plane floor { corners = (-5, -5, 0) m, (5, -5, 0) m, (-5, 5, 0) m }
  plane wall { corners = (0.5, -5, 0) m, (0.5, 5, 0) m, (0.5, -5, 5) m }
  ellipsoid post on ground { semi_axes = (0.1, 0.1, 0.1) m  center = (0, 0, 2.9) m }
  body arm {
    segment upper {
      mass = 1 kg  inertia = (0.01, 0.01, 0.01) kg*m^2
      ellipsoid { semi_axes = (0.05, 0.05, 0.05) m  center = (0, 0, 0.1) m }
    }
    segment lower {
      mass = 1 kg  inertia = (0.01, 0.01, 0.01) kg*m^2
      ellipsoid { semi_axes = (0.04, 0.04, 0.04) m  center = (0, 0, -0.2) m }
    }
    segment hand {
      mass = 1 kg  inertia = (0.01, 0.01, 0.01) kg*m^2
      ellipsoid { semi_axes = (0.03, 0.03, 0.03) m }
    }
    joint elbow : pin(upper -> lower) { at upper = (0, 0, -0.2) m  at lower = (0, 0, 0.2) m }
    joint wrist : pin(lower -> hand) {
      at lower = (0, 0, -0.2) m  at hand = (0, 0, 0.1) m  locked = true
    }
  }
  constraint shoulder : fixed_point(ground -> arm.upper) {
    at ground = (0, 0, 2) m  at arm.upper = (0, 0, 0.2) m
  }
  contact arm.upper with floor { force = 10 kN/m }
  contact arm.lower with floor { force = 10 kN/m }
  contact arm.lower with wall { force = 10 kN/m }
  contact arm.upper with arm.lower { force = 10 kN/m }
  contact arm.lower with arm.hand { force = 10 kN/m }
  contact arm.hand with arm.upper { force = 10 kN/m }
  contact arm.lower with post { force = 10 kN/m }
  initial arm { position = (0, 0, 1.8) m })"));
  ASSERT_CHECKED(r);
  EXPECT_THAT(
      r.notes(),
      ElementsAre("test.sled:28:3: note[N0401]: contact between `arm.upper` and `floor` is left "
                  "out: they can "
                  "never touch (`arm.upper` is held 2 m from it and reaches 0.15 m)",
                  "test.sled:29:3: note[N0401]: contact between `arm.lower` and `floor` is left "
                  "out: they can "
                  "never touch (`arm.lower` is held 2 m from it and reaches 0.84 m)",
                  "test.sled:31:3: note[N0401]: contact between `arm.upper` and `arm.lower` is "
                  "left out: they "
                  "can never touch (joint `arm.elbow` keeps them apart)",
                  "test.sled:32:3: note[N0401]: contact between `arm.lower` and `arm.hand` is left "
                  "out: they "
                  "can never touch (their segments are joined rigidly by joints locked for good)"));
  // Left: the wall (0.5 m from the pivot, within reach), the hand against the upper link, and
  // the post (0.9 m above the pivot, its surface 0.8 m: within the 0.84 m reach).
  EXPECT_EQ(r.model().contacts.npair(), 3u);
}

TEST(LowerBelts, PathsFunctionsHarnessesAndTiePoints) {
  const Result r = LowerText(Scene(R"(
  vehicle sled { motion = half_sine(delta_v = 10 km/h, duration = 50 ms, axis = -x) }
  function webbing = table(strain -> force) { 0 -> 0 N  0.1 -> 8 kN  0.2 -> 8 kN }
  body b {
    segment s {
      mass = 1 kg  inertia = (0.01, 0.01, 0.01) kg*m^2
      ellipsoid { semi_axes = (0.1, 0.2, 0.3) m  center = (10, 0, 0) mm  orientation = (90, 0, 0) deg }
    }
  }
  body c { segment s { mass = 1 kg  inertia = (0.01, 0.01, 0.01) kg*m^2 } }
  belt lap on sled {
    path = (0, -200, 0) mm -> b.s -> (0, 200, 0) mm
    force = webbing
    slack = 5 mm
    pretension = 10 kN
    friction = 0.2
  }
  harness h on sled {
    friction = 0.3
    belt one { path = (0, 0, 0) m -> b.s -> (0.1, 0, 0) m  force = webbing }
    belt two { path = (0.1, 0, 0) m -> c.s -> (0.2, 0, 0) m  force = webbing }
  }
  initial b { position = (0.3, 0, 0) m }
  initial c { position = (0.3, 0, 0.5) m }
  output { belt_force h.two })"));
  ASSERT_CHECKED(r);
  const runtime::BeltTable& belts = r.model().belts;
  EXPECT_THAT(belts.name, ElementsAre("lap", "h.one", "h.two"));
  EXPECT_THAT(belts.harness, ElementsAre(-1, 0, 0));
  EXPECT_THAT(belts.first_point, ElementsAre(0, 3, 6));
  EXPECT_THAT(belts.point_count, ElementsAre(3, 3, 3));
  EXPECT_THAT(belts.slack, ElementsAre(0.005, 0.0, 0.0));
  EXPECT_THAT(belts.pretension, ElementsAre(10000.0, 0.0, 0.0));
  EXPECT_THAT(belts.friction, ElementsAre(0.2, 0.0, 0.0));
  EXPECT_THAT(belts.function, ElementsAre(0, 0, 0));  // one webbing function, copied once
  EXPECT_THAT(belts.point_wraps, ElementsAre(0, 1, 0, 0, 1, 0, 0, 1, 0));
  EXPECT_EQ(belts.point_frame[0].kind, runtime::FrameRef::Kind::kVehicle);
  EXPECT_EQ(belts.point_frame[1].kind, runtime::FrameRef::Kind::kSegment);
  EXPECT_EQ(belts.point_frame[1].index, r.Segment("b.s"));
  EXPECT_EQ(belts.point_frame[7].index, r.Segment("c.s"));
  ExpectNear(belts.point_position[2], runtime::Vec3(0, 0.2, 0), 1e-15);
  ExpectNear(belts.point_position[1], runtime::Vec3(0.01, 0, 0), 1e-15);
  ExpectNear(belts.point_semi_axes[1], runtime::Vec3(0.1, 0.2, 0.3), 1e-15);
  ExpectNear(belts.point_axes[1],
             Eigen::AngleAxisd(90 * kDeg, runtime::Vec3::UnitZ()).toRotationMatrix(), 1e-15);
  ExpectNear(belts.point_semi_axes[7], runtime::Vec3::Zero(), 0.0);  // no ellipsoid: a point
  EXPECT_THAT(belts.harness_name, ElementsAre("h"));
  EXPECT_THAT(belts.harness_friction, ElementsAre(0.3));
  // h.one ends where h.two starts: one tie point between path points 5 and 6.
  ASSERT_EQ(belts.tie_points.size(), 1u);
  EXPECT_EQ(belts.tie_points[0], (std::array<std::int32_t, 2>{5, 6}));
  EXPECT_THAT(belts.tie_harness, ElementsAre(0));
  ASSERT_EQ(r.model().output_kind.size(), 1u);
  EXPECT_EQ(r.model().output_kind[0], runtime::Model::OutputKind::kBeltForce);
  EXPECT_EQ(r.model().output_index[0], 2);
  std::string notes;
  for (const std::string& note : r.notes()) notes += note + "\n";
  EXPECT_THAT(notes, HasSubstr("segment `c.s` has no ellipsoid: belt `h.two` passes through its "
                               "centre of mass"));
  EXPECT_THAT(notes, HasSubstr("the force of belt `lap` does not reach its pretension of 10000 N"));
  EXPECT_THAT(notes, ::testing::Not(HasSubstr("not simulated")));
}

// --- `sled check --dump-model` -----------------------------------------------------------------

TEST(LowerDriver, CheckDumpModelPrintsTheModel) {
  const fs::path sled = testing::SledBinary();
  const fs::path scene = kRoot / "tests" / "golden" / "model" / "pendulum.sled";
  const std::string command =
      fmt::format("'{}' check '{}' --dump-model 2>/dev/null", sled.string(), scene.string());
  FILE* pipe = popen(command.c_str(), "r");
  ASSERT_NE(pipe, nullptr);
  std::string out;
  char buffer[4096];
  std::size_t n = 0;
  while ((n = fread(buffer, 1, sizeof buffer, pipe)) > 0) out.append(buffer, n);
  const int status = pclose(pipe);
  EXPECT_EQ(status, 0);
  // The pivot (a fixed-point constraint to the ground) is the upper bar's ball joint to its base.
  EXPECT_THAT(out, HasSubstr("sizes segment 2 joint 2 position 5 velocity 4"));
  EXPECT_THAT(out, HasSubstr("joint 1 joint_kind pin joint_name \"pendulum.hinge\" q_address 4 "
                             "q_count 1 v_address 3 v_count 1"));
}

// --- Golden files: tests/golden/model/*.sled -> *.model ------------------------------------------

std::string ReadText(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(LowerGolden, DumpModelMatchesTheExpectedFiles) {
  // Paths relative to the repository root, so the side table's file names are stable.
  WorkingDirectory root(kRoot);
  const fs::path folder = fs::path("tests") / "golden" / "model";
  std::vector<fs::path> inputs;
  for (const auto& entry : fs::directory_iterator(folder)) {
    if (entry.path().extension() == ".sled") inputs.push_back(entry.path());
  }
  std::sort(inputs.begin(), inputs.end());
  ASSERT_GE(inputs.size(), 3u);
  const char* update = std::getenv("SLED_UPDATE_GOLDEN");
  const bool updating = update != nullptr && std::string(update) == "1";
  for (const fs::path& input : inputs) {
    SCOPED_TRACE(input.string());
    const Result r = LowerText(ReadText(input), input.generic_string(), "stdlib");
    ASSERT_CHECKED(r);
    const std::string actual = runtime::DumpModel(r.model());
    fs::path expected_path = input;
    expected_path.replace_extension(".model");
    if (updating) {
      std::ofstream(expected_path, std::ios::binary | std::ios::trunc) << actual;
      continue;
    }
    ASSERT_TRUE(fs::exists(expected_path)) << "run with SLED_UPDATE_GOLDEN=1 to write it";
    const std::string expected = ReadText(expected_path);
    if (actual == expected) continue;
    // Name the first differing line.
    std::istringstream a(actual), e(expected);
    std::string line_a, line_e;
    int line = 1;
    while (true) {
      const bool more_a = static_cast<bool>(std::getline(a, line_a));
      const bool more_e = static_cast<bool>(std::getline(e, line_e));
      if (!more_a || !more_e || line_a != line_e) {
        ADD_FAILURE() << "first difference at line " << line
                      << ":\n  actual:   " << (more_a ? line_a : "<end>")
                      << "\n  expected: " << (more_e ? line_e : "<end>");
        break;
      }
      ++line;
    }
  }
}

// NIC and TTI read accelerometers fixed to their segments (an acceleration request's own axes):
// the head's and T1's, at the neck_lower joint's point on the thorax, and the thorax's and the
// abdomen's; the Tibia Index reads the knee's force and torque.
TEST(LowerCriteria, NicTtiAndTibiaIndexReadTheirTwoGroups) {
  const Result r = LowerText(Scene(R"(
  import std.humans.male50 as occupant
  output {
    criteria = nic(occupant.head, t1 = occupant.neck_lower),
      tti(occupant.thorax, spine = occupant.abdomen), tibia_index(occupant.knee_l)
  })"));
  ASSERT_EQ(r.errors, "");
  const runtime::Model& m = r.model();
  ASSERT_EQ(m.ncriterion(), 3u);
  const auto group = [&](std::size_t c, bool second) {
    return static_cast<std::size_t>(second ? m.criterion_second_output[c] : m.criterion_output[c]);
  };
  const auto in_own_axes = [&](std::size_t g, const char* segment) {
    EXPECT_EQ(m.output_kind[g], runtime::Model::OutputKind::kAcceleration);
    EXPECT_EQ(m.output_index[g], r.Segment(segment));
    EXPECT_TRUE(m.output_relative.empty() || m.output_relative[g] == 0);
  };
  in_own_axes(group(0, false), "occupant.head");
  in_own_axes(group(0, true), "occupant.thorax");
  // male50: `joint neck_lower ... at thorax = (-40, 0, 73) mm`.
  ExpectNear(m.output_point[group(0, true)], runtime::Vec3(-0.040, 0, 0.073), 1e-12);
  EXPECT_TRUE(m.output_point[group(0, false)].isZero());
  in_own_axes(group(1, false), "occupant.thorax");
  in_own_axes(group(1, true), "occupant.abdomen");
  EXPECT_EQ(m.output_kind[group(2, false)], runtime::Model::OutputKind::kJointForce);
  EXPECT_EQ(m.output_kind[group(2, true)], runtime::Model::OutputKind::kJointTorque);
  EXPECT_EQ(m.output_index[group(2, true)], r.Segment("occupant.lower_leg_l"));
}

}  // namespace
}  // namespace sled::compiler
