// compiler::Lower: the checked scenario to the runtime's Model. Expected values come from the
// rules in runtime/model.h, worked out by hand or by an independent computation (forward
// kinematics of the lowered model against the checker's initial poses), not from earlier output.
//
// The golden runner at the end lowers every tests/golden/model/*.sled and compares
// runtime::DumpModel with the .model file next to it; set SLED_UPDATE_GOLDEN=1 to write them.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include "compiler/check/initial_pose.h"
#include "runtime/model.h"
#include "sled/compile.h"
#include "tests/compiler/sled_process.h"

namespace sled::compiler {
namespace {

namespace fs = std::filesystem;
using runtime::JointKind;
using sled::testing::WorkingDirectory;
using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::IsEmpty;
using ::testing::Not;

const fs::path kRoot = SLED_SOURCE_ROOT;
constexpr double kDeg = std::numbers::pi / 180.0;

struct Result {
  Compilation compilation;
  std::string errors;  // compact diagnostics, when the scene does not compile

  const CheckedScenario& scenario() const { return compilation.scenario(); }
  const runtime::Model& model() const { return compilation.model(); }
  // The lowering's notes (N04xx), compact.
  std::vector<std::string> notes() const { return compilation.Notes(); }
  // The Model index of a segment by its qualified name; -1 when absent.
  int Segment(const std::string& name) const {
    for (std::size_t s = 0; s < model().nsegment(); ++s) {
      if (model().segment_name[s] == name) return static_cast<int>(s);
    }
    return -1;
  }
};

// Compiles text through sled::Compile; `path` names the buffer (relative to the working
// directory).
Result LowerText(const std::string& text, const std::string& path = "test.sled",
                 const std::string& stdlib = (kRoot / "stdlib").string()) {
  CompileOptions options;
  options.stdlib = stdlib;
  Result result{Compile(Source::Text(text, path), options), {}};
  if (!result.compilation.ok()) result.errors = result.compilation.Render();
  return result;
}

std::string Scene(const std::string& body) {
  return "scenario \"t\" {\n  time { end = 100 ms  output_every = 1 ms }\n" + body + "\n}\n";
}

#define ASSERT_CHECKED(result) ASSERT_EQ((result).errors, "") << "the scene does not check"

void ExpectNear(const runtime::Mat3& actual, const runtime::Mat3& expected, double tolerance) {
  EXPECT_LE((actual - expected).cwiseAbs().maxCoeff(), tolerance) << "actual:\n"
                                                                  << actual << "\nexpected:\n"
                                                                  << expected;
}

void ExpectNear(const runtime::Vec3& actual, const runtime::Vec3& expected, double tolerance) {
  EXPECT_LE((actual - expected).cwiseAbs().maxCoeff(), tolerance)
      << "actual " << actual.transpose() << ", expected " << expected.transpose();
}

const std::string kUnitInertia = "mass = 1 kg  inertia = (0.01, 0.01, 0.01) kg*m^2";

// --- Tree order -------------------------------------------------------------------------------

TEST(LowerTree, ParentsComeBeforeChildrenWhenJointsAreDeclaredOutOfOrder) {
  const Result r = LowerText(Scene(fmt::format(R"(
  body b {{
    reference = a
    segment d {{ {0} }}
    segment c {{ {0} }}
    segment e {{ {0} }}
    segment b {{ {0} }}
    segment a {{ {0} }}
    joint j3 : ball(c -> d) {{ at c = (0, 0, -1) m  at d = (0, 0, 1) m }}
    joint j2 : pin(b -> c) {{ at b = (0, 0, -1) m  at c = (0, 0, 1) m }}
    joint j1 : euler(a -> b) {{ at a = (0, 0, -1) m  at b = (0, 0, 1) m }}
    joint j4 : slip(a -> e) {{ at a = (0, 0, 1) m  at e = (0, 0, -1) m }}
  }})",
                                               kUnitInertia)));
  ASSERT_CHECKED(r);
  const runtime::Model& m = r.model();
  // Reference first, then depth first with children in the order of their joints.
  EXPECT_THAT(m.segment_name, ElementsAre("b.a", "b.b", "b.c", "b.d", "b.e"));
  EXPECT_THAT(m.segment_parent, ElementsAre(-1, 0, 1, 2, 0));
  EXPECT_THAT(m.joint_name, ElementsAre("", "b.j1", "b.j2", "b.j3", "b.j4"));
  EXPECT_THAT(m.joint_kind, ElementsAre(JointKind::kFree, JointKind::kEuler, JointKind::kPin,
                                        JointKind::kBall, JointKind::kSlip));
  // free 7/6, euler 3/3, pin 1/1, ball 4/3, slip 1/1.
  EXPECT_THAT(m.q_address, ElementsAre(0, 7, 10, 11, 15));
  EXPECT_THAT(m.v_address, ElementsAre(0, 6, 9, 10, 13));
  EXPECT_EQ(m.nq, 16);
  EXPECT_EQ(m.nv, 14);
  // Ball joints start at the identity quaternion; the rest at zero.
  EXPECT_EQ(m.q0.size(), 16u);
  EXPECT_EQ(m.q0[11], 1.0);
  EXPECT_EQ(m.q0[3], 1.0);  // the root's quaternion w
}

TEST(LowerTree, ANullJointStartsAFreeSegmentOfItsOwn) {
  const Result r = LowerText(Scene(fmt::format(R"(
  body b {{
    segment a {{ {0} }}
    segment loose {{ {0} }}
    segment hand {{ {0} }}
    joint wrist : pin(loose -> hand) {{ at loose = (0, 0, -1) m  at hand = (0, 0, 1) m }}
    joint spare : null(a -> loose)
  }}
  output {{
    joint_force b.spare
    joint_angle b.wrist
  }})",
                                               kUnitInertia)));
  ASSERT_CHECKED(r);
  const runtime::Model& m = r.model();
  EXPECT_THAT(m.segment_name, ElementsAre("b.a", "b.loose", "b.hand"));
  EXPECT_THAT(m.segment_parent, ElementsAre(-1, -1, 1));
  EXPECT_THAT(m.joint_kind, ElementsAre(JointKind::kFree, JointKind::kFree, JointKind::kPin));
  EXPECT_EQ(m.joint_name[1], "");
  EXPECT_EQ(m.nq, 15);
  EXPECT_EQ(m.nv, 13);
  // The null joint transmits nothing: its output is left out with a note; the pin's stays.
  ASSERT_EQ(m.output_kind.size(), 1u);
  EXPECT_EQ(m.output_index[0], 2);
  ASSERT_EQ(r.notes().size(), 1u);
  EXPECT_THAT(r.notes()[0], HasSubstr("null joint"));
}

TEST(LowerSymmetry, PlanarSymmetryKeepsOnlyTheDegreesOfFreedomOfTheXzPlane) {
  // A floating trunk with a ball joint (neck), an Euler joint (hip), a pin about y (knee), a pin
  // about x (would leave the plane) and a slip along y (likewise).
  const Result r = LowerText(Scene(fmt::format(R"(
  symmetry planar
  body b {{
    segment trunk {{ {0} }}
    segment head {{ {0} }}
    segment thigh {{ {0} }}
    segment shank {{ {0} }}
    segment flap {{ {0} }}
    segment slider {{ {0} }}
    joint neck : ball(trunk -> head) {{ at trunk = (0, 0, 0.3) m  at head = (0, 0, -0.1) m }}
    joint hip : euler(trunk -> thigh) {{ at trunk = (0, 0, -0.3) m  at thigh = (0, 0, 0.2) m }}
    joint knee : pin(thigh -> shank) {{ at thigh = (0, 0, -0.2) m  at shank = (0, 0, 0.2) m
                                        axis = (0, 1, 0) }}
    joint hinge : pin(trunk -> flap) {{ at trunk = (0.1, 0, 0) m  at flap = (0, 0, 0) m
                                        axis = (1, 0, 0) }}
    joint rail : slip(trunk -> slider) {{ at trunk = (0, 0, 0) m  at slider = (0, 0, 0) m
                                         axis = (0, 1, 0) }}
  }}
  initial b {{ position = (1, 0.5, 2) m  orientation = (0, 30, 0) deg
              velocity = (3, 0, -1) m/s  angular_velocity = (0, 2, 0) rad/s }}
  initial b.neck {{ angles = (0, 20, 0) deg }})",
                                               kUnitInertia)));
  ASSERT_CHECKED(r);
  const runtime::Model& m = r.model();
  EXPECT_THAT(m.joint_kind, ElementsAre(JointKind::kPlanar, JointKind::kPin, JointKind::kPin,
                                        JointKind::kPin, JointKind::kPin, JointKind::kSlip));
  // 3 + 1 + 1 + 1 + 1 + 1 coordinates, no quaternions.
  EXPECT_EQ(m.nq, 8);
  EXPECT_EQ(m.nv, 8);
  // The plane runs through the trunk's starting point; the state holds x, z and the pitch.
  ExpectNear(m.joint_point_in_parent[0], runtime::Vec3(0, 0.5, 0), 1e-15);
  EXPECT_NEAR(m.q0[0], 1.0, 1e-15);
  EXPECT_NEAR(m.q0[1], 2.0, 1e-15);
  EXPECT_NEAR(m.q0[2], 30.0 * std::numbers::pi / 180, 1e-12);
  EXPECT_NEAR(m.v0[0], 3.0, 1e-15);
  EXPECT_NEAR(m.v0[1], -1.0, 1e-15);
  EXPECT_NEAR(m.v0[2], 2.0, 1e-15);
  // The neck turns about y by its nutation; the pins that would leave the plane are locked.
  ExpectNear(m.joint_axis[1], runtime::Vec3(0, 1, 0), 1e-12);
  EXPECT_NEAR(m.q0[3], 20.0 * std::numbers::pi / 180, 1e-12);
  EXPECT_EQ(m.joint_locked[3], 0);
  EXPECT_EQ(m.joint_locked[4], 1);
  EXPECT_EQ(m.joint_locked[5], 1);
  const std::string notes = fmt::format("{}", fmt::join(r.notes(), "\n"));
  EXPECT_THAT(notes, HasSubstr("pin joint `b.hinge`"));
  EXPECT_THAT(notes, HasSubstr("slip joint `b.rail`"));
  EXPECT_THAT(notes, Not(HasSubstr("symmetry is not applied")));
}

// A trunk with two arms, paired for mirror symmetry.
const std::string kTwoArms = fmt::format(R"(
  symmetry mirror {{ pair = b.arm_l, b.arm_r }}
  body b {{
    segment trunk {{ {0} }}
    segment arm_l {{ {0} }}
    segment arm_r {{ {0} }}
    joint shoulder_l : ball(trunk -> arm_l) {{ at trunk = (0, 0.2, 0) m  at arm_l = (0, 0, 0.1) m }}
    joint shoulder_r : ball(trunk -> arm_r) {{ at trunk = (0, -0.2, 0) m  at arm_r = (0, 0, 0.1) m }}
  }}
)",
                                         kUnitInertia);

TEST(LowerSymmetry, MirrorSymmetryIsRefusedWithAReasonWhenASpringActsOnARightSegment) {
  const Result r = LowerText(Scene(kTwoArms + R"(
  spring tether : b.arm_r -> ground { at b.arm_r = (0, 0, 0) m  at ground = (0, -1, 0) m
                                      stiffness = 100 N/m })"));
  ASSERT_CHECKED(r);
  const runtime::Model& m = r.model();
  EXPECT_EQ(m.nsegment(), 3u);
  EXPECT_TRUE(m.segment_mirror_twin.empty());
  EXPECT_THAT(fmt::format("{}", fmt::join(r.notes(), "\n")),
              HasSubstr("mirror symmetry is not applied: spring `tether` acts on a right segment"));
}

TEST(LowerSymmetry, MirrorSymmetryIsRefusedWhenALeftSegmentHasAnUnpairedChild) {
  const Result r = LowerText(Scene(fmt::format(R"(
  symmetry mirror {{ pair = b.arm_l, b.arm_r }}
  body b {{
    segment trunk {{ {0} }}
    segment arm_l {{ {0} }}
    segment arm_r {{ {0} }}
    segment hand {{ {0} }}
    joint shoulder_l : ball(trunk -> arm_l) {{ at trunk = (0, 0.2, 0) m  at arm_l = (0, 0, 0.1) m }}
    joint shoulder_r : ball(trunk -> arm_r) {{ at trunk = (0, -0.2, 0) m  at arm_r = (0, 0, 0.1) m }}
    joint wrist : ball(arm_l -> hand) {{ at arm_l = (0, 0, -0.1) m  at hand = (0, 0, 0.05) m }}
  }})",
                                               kUnitInertia)));
  ASSERT_CHECKED(r);
  EXPECT_TRUE(r.model().segment_mirror_twin.empty());
  EXPECT_THAT(fmt::format("{}", fmt::join(r.notes(), "\n")),
              HasSubstr("mirror symmetry is not applied: `b.hand` hangs from the left "
                        "segment `b.arm_l` but is not the left one of a pair"));
}

TEST(LowerSymmetry, MirrorSymmetryLeavesTheRightTwinOutAndReadsItsOutputsFromTheLeft) {
  const Result r = LowerText(Scene(kTwoArms + R"(
  initial b { position = (0, 0.5, 1) m }
  output { position b.arm_r at (0, -0.1, 0) m })"));
  ASSERT_CHECKED(r);
  const runtime::Model& m = r.model();
  EXPECT_THAT(m.segment_name, ElementsAre("b.trunk", "b.arm_l"));
  EXPECT_THAT(m.joint_kind, ElementsAre(JointKind::kPlanar, JointKind::kBall));
  EXPECT_THAT(m.segment_mirror_twin, ElementsAre(0, 1));
  EXPECT_THAT(m.segment_mirror_count, ElementsAre(1, 2));
  ExpectNear(m.mirror_normal[1], runtime::Vec3(0, 1, 0), 1e-15);
  EXPECT_EQ(m.mirror_plane_y, 0.5);
  ASSERT_EQ(m.output_index.size(), 1u);
  EXPECT_EQ(m.output_index[0], 1);
  EXPECT_THAT(m.output_mirrored, ElementsAre(1));
  ExpectNear(m.output_point[0], runtime::Vec3(0, 0.1, 0), 0);
}

TEST(LowerTree, Male50HasOneCoordinateBlockPerJoint) {
  const Result r = LowerText(Scene("  import std.humans.male50 as occupant"));
  ASSERT_CHECKED(r);
  const runtime::Model& m = r.model();
  ASSERT_EQ(m.nsegment(), 15u);
  // Expected sizes from the checked joint types: a free root, then one block per joint.
  int nq = 7;
  int nv = 6;
  for (const Joint& joint : r.scenario().joints) {
    switch (joint.type) {
      case JointType::kBall:
        nq += 4;
        nv += 3;
        break;
      case JointType::kEuler:
        nq += 3;
        nv += 3;
        break;
      case JointType::kPin:
      case JointType::kSlip:
        nq += 1;
        nv += 1;
        break;
      case JointType::kNull:
        nq += 7;
        nv += 6;
        break;
    }
  }
  EXPECT_EQ(m.nq, nq);
  EXPECT_EQ(m.nv, nv);
  EXPECT_EQ(m.nq, 49);  // 8 ball, 2 Euler and 4 pin joints
  EXPECT_EQ(m.nv, 40);
  EXPECT_EQ(m.segment_name[0], "occupant.pelvis");
  for (std::size_t s = 0; s < m.nsegment(); ++s) {
    EXPECT_LT(m.segment_parent[s], static_cast<int>(s)) << m.segment_name[s];
    const int next_q = s + 1 < m.nsegment() ? m.q_address[s + 1] : m.nq;
    const int next_v = s + 1 < m.nsegment() ? m.v_address[s + 1] : m.nv;
    EXPECT_EQ(m.q_address[s] + m.q_count[s], next_q) << m.segment_name[s];
    EXPECT_EQ(m.v_address[s] + m.v_count[s], next_v) << m.segment_name[s];
  }
  EXPECT_EQ(m.q0.size(), 49u);
  EXPECT_EQ(m.v0.size(), 40u);
  // neck_lower locks its precession, the neck's axial rotation (bit 0).
  const int neck = r.Segment("occupant.neck");
  ASSERT_GE(neck, 0);
  EXPECT_EQ(m.joint_kind[static_cast<std::size_t>(neck)], JointKind::kEuler);
  EXPECT_EQ(m.joint_locked[static_cast<std::size_t>(neck)], 1);
  // The side table names the stdlib file.
  EXPECT_THAT(m.segment_source[0].file, HasSubstr("male50.sled"));
  EXPECT_GT(m.segment_source[0].line, 0u);
  EXPECT_THAT(m.joint_source[static_cast<std::size_t>(neck)].file, HasSubstr("male50.sled"));
}

TEST(LowerTree, AnEmptyBodyGivesAnEmptyModel) {
  const Result r = LowerText(Scene("  body nothing {}"));
  ASSERT_CHECKED(r);
  EXPECT_EQ(r.model().nsegment(), 0u);
  EXPECT_EQ(r.model().nq, 0);
  EXPECT_TRUE(r.model().q0.empty());
  EXPECT_FALSE(runtime::DumpModel(r.model()).empty());
}

// --- Segment and joint geometry ---------------------------------------------------------------

TEST(LowerGeometry, PrincipalAxesTurnTheInertia) {
  const Result r = LowerText(Scene(R"(
  body b {
    segment s { mass = 1 kg  inertia = (1, 2, 3) kg*m^2  principal_axes = (90, 0, 0) deg }
  })"));
  ASSERT_CHECKED(r);
  // Yaw 90: the principal x axis lies along the segment's y, so Ixx and Iyy swap.
  runtime::Mat3 expected = runtime::Mat3::Zero();
  expected.diagonal() << 2, 1, 3;
  ExpectNear(r.model().segment_inertia[0], expected, 1e-12);
}

TEST(LowerGeometry, APinAxisGivenInTheParentIsTurnedIntoTheJointFrame) {
  const Result r = LowerText(Scene(fmt::format(R"(
  body b {{
    segment a {{ {0} }}
    segment c {{ {0} }}
    joint hinge : pin(a -> c) {{
      at a = (0, 0, -100) mm
      at c = (0, 0, 100) mm
      axes a = (90, 0, 0) deg
      axes c = (0, 90, 0) deg
      axis = (0, 1, 0)
    }}
  }})",
                                               kUnitInertia)));
  ASSERT_CHECKED(r);
  const runtime::Model& m = r.model();
  // The joint frame's x axis is the parent's y (yaw 90), so the parent's y axis is the joint's x.
  ExpectNear(m.joint_axis[1], runtime::Vec3(1, 0, 0), 1e-12);
  ExpectNear(m.joint_frame_in_parent[1] * m.joint_axis[1], runtime::Vec3(0, 1, 0), 1e-12);
  const runtime::Mat3 yaw90 =
      Eigen::AngleAxisd(std::numbers::pi / 2, runtime::Vec3::UnitZ()).toRotationMatrix();
  const runtime::Mat3 pitch90 =
      Eigen::AngleAxisd(std::numbers::pi / 2, runtime::Vec3::UnitY()).toRotationMatrix();
  ExpectNear(m.joint_frame_in_parent[1], yaw90, 1e-12);
  ExpectNear(m.joint_frame_in_child[1], pitch90, 1e-12);
  ExpectNear(m.joint_point_in_parent[1], runtime::Vec3(0, 0, -0.1), 1e-15);
  ExpectNear(m.joint_point_in_child[1], runtime::Vec3(0, 0, 0.1), 1e-15);
}

TEST(LowerGeometry, JointCharacteristicsAreCopied) {
  const Result r = LowerText(Scene(fmt::format(R"(
  body b {{
    segment a {{ {0} }}
    segment c {{ {0} }}
    segment d {{ {0} }}
    joint shoulder : ball(a -> c) {{
      at a = (0, 0, -100) mm  at c = (0, 0, 100) mm
      flexure = 2 N*m/deg  twist = 1 N*m/deg
      viscous = 0.5 N*m*s/rad  coulomb = 0.25 N*m
      stop = 90 deg  stop_impulse = true  restitution = 0.3
      lock_below = 5 N*m  unlock_above = 60 N*m
    }}
    joint neck : euler(a -> d) {{
      at a = (0, 0, 100) mm  at d = (0, 0, -100) mm
      nutation = 1 N*m/deg  spin = 2 N*m/deg
      locked = precession, spin
    }}
  }})",
                                               kUnitInertia)));
  ASSERT_CHECKED(r);
  const runtime::Model& m = r.model();
  // Functions are numbered as the joints use them, in tree order.
  EXPECT_THAT(m.joint_function[1], ElementsAre(0, 1, -1));
  EXPECT_THAT(m.joint_function[2], ElementsAre(-1, 2, 3));
  ASSERT_EQ(m.functions.size(), 4u);
  EXPECT_EQ(m.functions.kind[0], runtime::FunctionTable::Kind::kPolynomial);
  EXPECT_NEAR(m.functions.coefficients[static_cast<std::size_t>(m.functions.first[0]) + 1],
              2 / kDeg, 1e-9);
  EXPECT_DOUBLE_EQ(m.joint_viscous[1], 0.5);
  EXPECT_DOUBLE_EQ(m.joint_coulomb[1], 0.25);
  EXPECT_NEAR(m.joint_stop[1], 90 * kDeg, 1e-15);
  EXPECT_EQ(m.joint_twist_stop[1], 0.0);  // none
  EXPECT_EQ(m.joint_stop_impulse[1], 1);
  EXPECT_DOUBLE_EQ(m.joint_restitution[1], 0.3);
  EXPECT_DOUBLE_EQ(m.joint_lock_below[1], 5);
  EXPECT_DOUBLE_EQ(m.joint_unlock_above[1], 60);
  EXPECT_EQ(m.joint_lock_below[2], -1.0);
  EXPECT_EQ(m.joint_locked[1], 0);
  EXPECT_EQ(m.joint_locked[2], 5);  // precession (bit 0) and spin (bit 2)
}

// --- Functions ---------------------------------------------------------------------------------

TEST(LowerFunctions, OnlyFunctionsTheModelUsesAreKept) {
  const Result r = LowerText(Scene(fmt::format(R"(
  function unused = polynomial(0 N*m, 9 N*m/deg)
  function foam = table(deflection -> force) {{ 0 mm -> 0 N  10 mm -> 1 kN }}
  function knee = table(angle -> torque) {{
    -10 deg -> -5 N*m
    0 deg -> 0 N*m
    10 deg -> 5 N*m
    energy_loss = 0.5
    permanent_set = 0.1
  }}
  plane floor {{ corners = (0, 0, 0) m, (1, 0, 0) m, (0, 1, 0) m }}
  body b {{
    segment a {{ {0}  ellipsoid {{ semi_axes = (0.1, 0.1, 0.1) m }} }}
    segment c {{ {0} }}
    joint j : pin(a -> c) {{ at a = (0, 0, -1) m  at c = (0, 0, 1) m  flexure = knee }}
  }}
  contact b.a with floor {{ force = foam }}
  initial b {{ position = (0, 0, 1) m }})",
                                               kUnitInertia)));
  ASSERT_CHECKED(r);
  const runtime::Model& m = r.model();
  // `unused` is never referred to; the joint's `knee` comes first, then the contact's `foam`.
  ASSERT_EQ(m.functions.size(), 2u);
  EXPECT_EQ(m.contacts.pair_function[0], 1);
  EXPECT_EQ(m.functions.count[1], 2);
  EXPECT_THAT(m.joint_function[1], ElementsAre(0, -1, -1));
  EXPECT_EQ(m.functions.kind[0], runtime::FunctionTable::Kind::kTable);
  EXPECT_EQ(m.functions.first[0], 0);
  EXPECT_EQ(m.functions.count[0], 3);
  ASSERT_EQ(m.functions.points_x.size(), 5u);  // knee's three rows, then foam's two
  EXPECT_EQ(m.functions.first[1], 3);
  EXPECT_DOUBLE_EQ(m.functions.points_y[4], 1000);
  EXPECT_NEAR(m.functions.points_x[0], -10 * kDeg, 1e-15);
  EXPECT_DOUBLE_EQ(m.functions.points_y[2], 5);
  EXPECT_DOUBLE_EQ(m.functions.energy_loss[0], 0.5);
  EXPECT_DOUBLE_EQ(m.functions.permanent_set[0], 0.1);
}

// --- Initial state -----------------------------------------------------------------------------

TEST(LowerInitialState, RollOf90DegreesIsAQuaternionAboutX) {
  const Result r = LowerText(Scene(R"(
  body b { segment s { mass = 1 kg  inertia = (0.01, 0.01, 0.01) kg*m^2 } }
  initial b { position = (1, 2, 3) m  orientation = (0, 0, 90) deg })"));
  ASSERT_CHECKED(r);
  const std::vector<double>& q = r.model().q0;
  ASSERT_EQ(q.size(), 7u);
  EXPECT_DOUBLE_EQ(q[0], 1);
  EXPECT_DOUBLE_EQ(q[1], 2);
  EXPECT_DOUBLE_EQ(q[2], 3);
  EXPECT_NEAR(q[3], std::sqrt(0.5), 1e-15);  // w
  EXPECT_NEAR(q[4], std::sqrt(0.5), 1e-15);  // x
  EXPECT_NEAR(q[5], 0, 1e-15);
  EXPECT_NEAR(q[6], 0, 1e-15);
}

TEST(LowerInitialState, VelocitiesGivenInTheWorldAreHeldInTheSegmentFrame) {
  const Result r = LowerText(Scene(R"(
  body b { segment s { mass = 1 kg  inertia = (0.01, 0.01, 0.01) kg*m^2 } }
  initial b.s {
    orientation = (90, 0, 0) deg
    velocity = (3, 0, 0) m/s
    angular_velocity = (0, 0, 2) rad/s
  })"));
  ASSERT_CHECKED(r);
  const std::vector<double>& v = r.model().v0;
  ASSERT_EQ(v.size(), 6u);
  // Yaw 90: the world x axis is the segment's -y; z is shared.
  EXPECT_NEAR(v[0], 0, 1e-15);
  EXPECT_NEAR(v[1], 0, 1e-15);
  EXPECT_NEAR(v[2], 2, 1e-15);
  EXPECT_NEAR(v[3], 0, 1e-15);
  EXPECT_NEAR(v[4], -3, 1e-15);
  EXPECT_NEAR(v[5], 0, 1e-15);
}

// Rotation of each segment from the lowered model alone (R_WC = R_WP A_P R_J A_C^T), and the
// centre of mass from the joint points, as the runtime's kinematics would compute them.
struct Pose {
  runtime::Mat3 rotation;
  runtime::Vec3 position;
};

std::vector<Pose> ForwardKinematics(const runtime::Model& m) {
  std::vector<Pose> poses(m.nsegment());
  for (std::size_t s = 0; s < m.nsegment(); ++s) {
    const auto qa = static_cast<std::size_t>(m.q_address[s]);
    const std::vector<double>& q = m.q0;
    if (m.joint_kind[s] == JointKind::kFree) {
      poses[s].position = runtime::Vec3(q[qa], q[qa + 1], q[qa + 2]);
      poses[s].rotation =
          Eigen::Quaterniond(q[qa + 3], q[qa + 4], q[qa + 5], q[qa + 6]).toRotationMatrix();
      continue;
    }
    runtime::Mat3 joint = runtime::Mat3::Identity();
    runtime::Vec3 slide = runtime::Vec3::Zero();
    switch (m.joint_kind[s]) {
      case JointKind::kBall:
        joint = Eigen::Quaterniond(q[qa], q[qa + 1], q[qa + 2], q[qa + 3]).toRotationMatrix();
        break;
      case JointKind::kEuler:
        joint = (Eigen::AngleAxisd(q[qa], runtime::Vec3::UnitZ()) *
                 Eigen::AngleAxisd(q[qa + 1], runtime::Vec3::UnitY()) *
                 Eigen::AngleAxisd(q[qa + 2], runtime::Vec3::UnitX()))
                    .toRotationMatrix();
        break;
      case JointKind::kPin:
        joint = Eigen::AngleAxisd(q[qa], m.joint_axis[s]).toRotationMatrix();
        break;
      case JointKind::kSlip:
        slide = m.joint_axis[s] * q[qa];
        break;
      case JointKind::kFree:
      case JointKind::kPlanar:
        break;
    }
    const Pose& parent = poses[static_cast<std::size_t>(m.segment_parent[s])];
    poses[s].rotation = parent.rotation * m.joint_frame_in_parent[s] * joint *
                        m.joint_frame_in_child[s].transpose();
    poses[s].position =
        parent.position +
        parent.rotation * (m.joint_point_in_parent[s] + m.joint_frame_in_parent[s] * slide) -
        poses[s].rotation * m.joint_point_in_child[s];
  }
  return poses;
}

TEST(LowerInitialState, JointAnglesAgreeWithTheCheckersInitialPoses) {
  // Ball, Euler and pin joints with turned joint axes and angles on all three axes: the lowered
  // coordinates must place every segment where compiler::ComputeInitialPoses does.
  const Result r = LowerText(Scene(fmt::format(R"(
  body b {{
    segment a {{ {0} }}
    segment c {{ {0} }}
    segment d {{ {0} }}
    segment e {{ {0} }}
    joint ball_joint : ball(a -> c) {{
      at a = (0, 10, -100) mm  at c = (5, 0, 100) mm
      axes a = (10, 20, 30) deg  axes c = (-15, 5, 40) deg
    }}
    joint euler_joint : euler(c -> d) {{
      at c = (0, 0, -100) mm  at d = (0, 20, 100) mm
      axes c = (0, 30, 0) deg  axes d = (45, 0, 0) deg
    }}
    joint pin_joint : pin(d -> e) {{
      at d = (30, 0, -100) mm  at e = (0, 0, 100) mm
      axes d = (90, 0, 20) deg
      axis = (0.6, 0, 0.8)
    }}
  }}
  initial b {{ position = (1, 2, 3) m  orientation = (30, -20, 10) deg }}
  initial b.ball_joint {{ angles = (20, -35, 50) deg }}
  initial b.euler_joint {{ angles = (-40, 25, 70) deg }}
  initial b.pin_joint {{ angles = (60, 0, 0) deg }})",
                                               kUnitInertia)));
  ASSERT_CHECKED(r);
  const std::vector<Pose> model_poses = ForwardKinematics(r.model());
  const InitialPoses checker_poses = ComputeInitialPoses(r.scenario());
  for (std::size_t old = 0; old < r.scenario().segments.size(); ++old) {
    const std::string& name = r.scenario().segments[old].name;
    const int s = r.Segment(name);
    ASSERT_GE(s, 0) << name;
    SCOPED_TRACE(name);
    Mat3 rows = checker_poses.segments[old].rotation;
    runtime::Mat3 expected;
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) expected(i, j) = rows[i][j];
    }
    ExpectNear(model_poses[static_cast<std::size_t>(s)].rotation, expected, 1e-12);
    const Vec3& p = checker_poses.segments[old].position;
    ExpectNear(model_poses[static_cast<std::size_t>(s)].position, runtime::Vec3(p[0], p[1], p[2]),
               1e-12);
  }
  // The ball joint's quaternion is Rz(20) Ry(-35) Rx(50).
  const runtime::Model& m = r.model();
  const std::size_t ball = static_cast<std::size_t>(r.Segment("b.c"));
  const auto qa = static_cast<std::size_t>(m.q_address[ball]);
  const Eigen::Quaterniond expected = Eigen::AngleAxisd(20 * kDeg, runtime::Vec3::UnitZ()) *
                                      Eigen::AngleAxisd(-35 * kDeg, runtime::Vec3::UnitY()) *
                                      Eigen::AngleAxisd(50 * kDeg, runtime::Vec3::UnitX());
  EXPECT_NEAR(m.q0[qa], expected.w(), 1e-15);
  EXPECT_NEAR(m.q0[qa + 1], expected.x(), 1e-15);
  EXPECT_NEAR(m.q0[qa + 2], expected.y(), 1e-15);
  EXPECT_NEAR(m.q0[qa + 3], expected.z(), 1e-15);
}

TEST(LowerInitialState, AnAngularVelocityOfAHangingSegmentSetsItsJointRates) {
  const Result r = LowerText(Scene(fmt::format(R"(
  body b {{
    segment a {{ {0} }}
    segment head {{ {0} }}
    segment hand {{ {0} }}
    joint neck : ball(a -> head) {{
      at a = (0, 0, 100) mm  at head = (0, 0, -100) mm
      axes a = (90, 0, 0) deg  axes head = (90, 0, 0) deg
    }}
    joint wrist : pin(a -> hand) {{
      at a = (0, 0, -100) mm  at hand = (0, 0, 100) mm
      axis = y
    }}
  }}
  initial b {{ angular_velocity = (0, 0, 1) rad/s  velocity = (1, 0, 0) m/s }}
  initial b.head {{ angular_velocity = (0, 2, 1) rad/s }}
  initial b.hand {{ angular_velocity = (1, 3, 1) rad/s  position = (0, 0, 0) m }})",
                                               kUnitInertia)));
  ASSERT_CHECKED(r);
  const runtime::Model& m = r.model();
  // The head turns at (0, 2, 0) rad/s relative to `a`, and its frame is aligned with the world
  // (the joint's axes are turned alike on both sides), so the ball's rate is (0, 2, 0).
  const auto head_v =
      static_cast<std::size_t>(m.v_address[static_cast<std::size_t>(r.Segment("b.head"))]);
  EXPECT_NEAR(m.v0[head_v], 0, 1e-15);
  EXPECT_NEAR(m.v0[head_v + 1], 2, 1e-15);
  EXPECT_NEAR(m.v0[head_v + 2], 0, 1e-15);
  // The pin turns about y only: its rate is 3 rad/s, and the rest is noted.
  const auto hand_v =
      static_cast<std::size_t>(m.v_address[static_cast<std::size_t>(r.Segment("b.hand"))]);
  EXPECT_NEAR(m.v0[hand_v], 3, 1e-15);
  std::string notes;
  for (const std::string& note : r.notes()) notes += note + "\n";
  EXPECT_THAT(notes, HasSubstr("angular velocity of `b.hand` is matched only in part"));
  EXPECT_THAT(notes, HasSubstr("initial position of `b.hand` is left out"));
  EXPECT_THAT(notes, ::testing::Not(HasSubstr("b.head")));
}

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
  EXPECT_THAT(out, HasSubstr("sizes segments 2 nq 5 nv 4"));
  EXPECT_THAT(out, HasSubstr("joint 1 pendulum.hinge pin q 4+1 v 3+1"));
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

}  // namespace
}  // namespace sled::compiler
