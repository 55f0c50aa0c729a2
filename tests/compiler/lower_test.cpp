// compiler::Lower: the checked scenario to the runtime's Model: the joint tree, symmetry,
// geometry, functions and the initial state (scene elements, contacts, belts and the golden
// model dumps: lower_scene_test.cpp). Expected values come from the rules in runtime/model/model.h,
// worked out by hand or by an independent computation (forward kinematics of the lowered model
// against the checker's initial poses), not from earlier output.
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include "compiler/check/initial_pose.h"
#include "runtime/model/model.h"
#include "sled/compile.h"
#include "tests/compiler/lower_helpers.h"

namespace sled::compiler {
namespace {

using lower_test::ExpectNear;
using lower_test::kDeg;
using lower_test::kUnitInertia;
using lower_test::LowerText;
using lower_test::Result;
using lower_test::Scene;
using runtime::JointKind;
using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::Not;

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

TEST(LowerFunctions, AJointsEnergyLossUnloadsItsTorqueFunctions) {
  // `spring` serves two joints: the lossy one gets a copy with its energy loss, the other the
  // function as written; `own` keeps its own unloading; `slope` carries its unloading slope.
  const Result r = LowerText(Scene(fmt::format(R"(
  function spring = polynomial(0 N*m, 2 N*m/deg)
  function own = table(angle -> torque) {{ 0 deg -> 0 N*m  10 deg -> 5 N*m  energy_loss = 0.2 }}
  function slope = table(angle -> torque) {{ 0 deg -> 0 N*m  10 deg -> 5 N*m  unload_slope = 4 }}
  body b {{
    segment a {{ {0} }}
    segment c {{ {0} }}
    segment d {{ {0} }}
    segment e {{ {0} }}
    joint lossy : ball(a -> c) {{
      at a = (0, 0, -1) m  at c = (0, 0, 1) m  flexure = spring  twist = own  energy_loss = 0.6
    }}
    joint plain : pin(a -> d) {{ at a = (0, 0, 1) m  at d = (0, 0, -1) m  flexure = spring }}
    joint sloped : pin(a -> e) {{ at a = (1, 0, 0) m  at e = (0, 0, 0) m  flexure = slope }}
  }})",
                                               kUnitInertia)));
  ASSERT_CHECKED(r);
  const runtime::Model& m = r.model();
  ASSERT_EQ(m.nsegment(), 4u);
  const auto [flexure, twist, none] = m.joint_function[1];
  EXPECT_EQ(none, -1);
  EXPECT_DOUBLE_EQ(m.functions.energy_loss[static_cast<std::size_t>(flexure)], 0.6);
  EXPECT_DOUBLE_EQ(m.functions.energy_loss[static_cast<std::size_t>(twist)], 0.2);
  const auto plain = static_cast<std::size_t>(m.joint_function[2][0]);
  EXPECT_NE(plain, static_cast<std::size_t>(flexure));
  EXPECT_EQ(m.functions.energy_loss[plain], 0.0);
  EXPECT_EQ(m.functions.coefficients[static_cast<std::size_t>(m.functions.first[plain]) + 1],
            m.functions.coefficients[static_cast<std::size_t>(m.functions.first[flexure]) + 1]);
  const auto sloped = static_cast<std::size_t>(m.joint_function[3][0]);
  ASSERT_EQ(m.functions.unload_slope.size(), m.functions.size());
  EXPECT_EQ(m.functions.unload_slope[sloped], 4.0);
  EXPECT_EQ(m.functions.unload_slope[plain], 0.0);
  // No note: everything is simulated.
  EXPECT_TRUE(r.notes().empty());
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
  initial b.hand {{ angular_velocity = (1, 3, 1) rad/s }})",
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
  EXPECT_THAT(notes, ::testing::Not(HasSubstr("b.head")));
}

}  // namespace
}  // namespace sled::compiler
