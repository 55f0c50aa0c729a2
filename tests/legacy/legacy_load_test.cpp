// D.9, ATB's applied forces and torques, converted to `load` statements and run: a free
// segment pushed at its centre of mass by a constant force along its own x moves as
// x = F t^2 / 2m, a torque about its principal z axis spins it as w = tau t / Izz, and the
// loads' work is the kinetic energy; the card's direction is the x axis of its yaw and pitch in
// the segment's axes (INPUT_FORCE_TORQUE, FORCE_TORQUE). The reader's checks: a segment number
// outside the deck is E0512, a vehicle segment (which the load cannot move) and a torque's point
// W0503, more than MAX_FOR_TORQ cards E0505.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "legacy_test_deck.h"
#include "sled/compile.h"
#include "sled/simulate.h"

namespace sled::lang::legacy {
namespace {

constexpr double kPound = 4.4482216152605;  // N
constexpr double kInch = 0.0254;            // m
// BOXS: 10 lb over G = 386.088 in/s^2; its moment about z 4 lb*s^2*in.
constexpr double kMass = 10 / 386.088 * kPound / kInch;
constexpr double kIzz = 4 * kPound * kInch;

// One free segment BOXS, no gravity, 1 s of run (500 steps of 2 ms); `d9` its D.9 cards (NFORCE
// `count`), function 1 the constant `value` (lb or lb*in).
std::string Deck(const std::string& d9, int count, double value) {
  return fmt::format(R"(11/28/2026
ONE SEGMENT PUSHED
TEST
IN  LB  SEC           0.          0.          0.386.08800000
   0 5000.002000

     1     0        BOX                     0
BOXS   10.    3.    3.    4.    4.    4.    4.    0.    0.    0.   0

SLED
    0.    0.    0.    0.   0.1    0.    0.    0.     0    0.    0. 0 0 0
     0     0     0     0     0     0     0     0     0{:6d}     0     0

{}   1    LOAD
          0.          0.{:12.4f}          0.          0.
  99

                                 0   0           1
        0.        0.        0.        0.        0.        0.  0  0

     0

     0

     0

     0
     0
     0
     0
     0
     0
     0
)",
                     count, d9, value);
}

// The converted scenario with `output` requests added before its closing brace.
RunResult RunConverted(const Converted& converted, const std::string& outputs) {
  std::string text = converted.text;
  text.insert(text.rfind('}'), "  output { " + outputs + " }\n");
  Compilation compiled = Compile(Source::Text(text, "converted.sled"));
  EXPECT_TRUE(compiled.ok()) << compiled.Render() << text;
  if (!compiled.ok()) return {};
  return Simulate(compiled.model());
}

std::size_t Column(const runtime::TimeSeries& series, const std::string& name) {
  for (std::size_t c = 0; c < series.names.size(); ++c) {
    if (series.names[c].rfind(name + " [", 0) == 0) return c + 1;  // the name, then its unit
  }
  ADD_FAILURE() << "no channel " << name;
  return 0;
}

TEST(LegacyLoad, AConstantForceAtTheCentreMovesAFreeSegmentAsNewtonSays) {
  // 20 lb along BOXS's x (yaw 0, pitch 0; a roll of 30 deg turns x about itself).
  const std::string d9 =
      "     1     1        0.        0.        0.        0.        0.       30.\n";
  const Converted converted = ConvertText(Deck(d9, 1, 20));
  ASSERT_EQ(converted.errors, 0) << converted.All();
  EXPECT_NE(converted.text.find("frame = segment"), std::string::npos) << converted.text;
  const RunResult run = RunConverted(converted, "position box.boxs at (0, 0, 0) mm");
  ASSERT_FALSE(run.failed()) << run.summary.failure.cause;
  const double force = 20 * kPound;
  const std::size_t x = Column(run.series, "box.boxs.position.x");
  const std::size_t y = Column(run.series, "box.boxs.position.y");
  ASSERT_GT(run.series.rows(), 100u);
  for (std::size_t row = 0; row < run.series.rows(); row += 50) {
    const double t = run.series.values[row * run.series.columns];
    EXPECT_NEAR(run.series.values[row * run.series.columns + x], force * t * t / (2 * kMass), 1e-7)
        << t;
    EXPECT_NEAR(run.series.values[row * run.series.columns + y], 0.0, 1e-9) << t;
  }
  // At 1 s: the work is the kinetic energy (F t)^2 / 2m.
  EXPECT_NEAR(run.summary.energy.applied_work, force * force / (2 * kMass), 1e-6);
}

TEST(LegacyLoad, ATorqueCardSpinsTheSegmentAboutItsDirection) {
  // NFVSEG -1: 2 lb*in about the x axis turned by a pitch of -90 deg, BOXS's z.
  const std::string d9 =
      "    -1     1        0.        0.        0.        0.      -90.        0.\n";
  const Converted converted = ConvertText(Deck(d9, 1, 2));
  ASSERT_EQ(converted.errors, 0) << converted.All();
  EXPECT_NE(converted.text.find("axis = (0, 0, 1)"), std::string::npos) << converted.text;
  const RunResult run = RunConverted(converted, "angular_velocity box.boxs");
  ASSERT_FALSE(run.failed()) << run.summary.failure.cause;
  const double torque = 2 * kPound * kInch;
  const std::size_t wz = Column(run.series, "box.boxs.angular_velocity.z");
  for (std::size_t row = 0; row < run.series.rows(); row += 50) {
    const double t = run.series.values[row * run.series.columns];
    EXPECT_NEAR(run.series.values[row * run.series.columns + wz], torque * t / kIzz, 1e-7) << t;
  }
  EXPECT_NEAR(run.summary.energy.applied_work, torque * torque / (2 * kIzz), 1e-7);
}

TEST(LegacyLoad, TheDirectionIsTheXAxisOfTheYawAndPitch) {
  // Yaw 90, pitch 0: BOXS's y; yaw 0, pitch 90: its -z.
  const std::string d9 =
      "     1     1        0.        0.        1.       90.        0.        0.\n"
      "     1     1        0.        0.        0.        0.       90.        0.\n";
  const Converted converted = ConvertText(Deck(d9, 2, 20));
  ASSERT_EQ(converted.errors, 0) << converted.All();
  EXPECT_NE(converted.text.find("direction = (0, 1, 0)"), std::string::npos) << converted.text;
  EXPECT_NE(converted.text.find("point = (0, 0, 1) in"), std::string::npos) << converted.text;
  EXPECT_NE(converted.text.find("direction = (0, 0, -1)"), std::string::npos) << converted.text;
}

TEST(LegacyLoad, BadSegmentsAreReportedAtTheirColumns) {
  // Segment 0 and segment 3 (past the body and its one vehicle): E0512 at columns 1-6.
  const std::string bad = "     0     1\n     3     1\n";
  const Converted outside = ConvertText(Deck(bad, 2, 20));
  EXPECT_EQ(outside.errors, 2) << outside.All();
  EXPECT_TRUE(outside.Has(":14:1-6: error[E0512]")) << outside.All();
  EXPECT_TRUE(outside.Has(":15:1-6: error[E0512]")) << outside.All();
  // Segment 2 is the vehicle: left out with W0503; a torque's point likewise.
  const std::string ignored = "     2     1\n    -1     1        1.\n";
  const Converted left_out = ConvertText(Deck(ignored, 2, 20));
  EXPECT_EQ(left_out.errors, 0) << left_out.All();
  EXPECT_TRUE(left_out.Has(":14:1-6: warning[W0503]")) << left_out.All();
  EXPECT_TRUE(left_out.Has(":15:13-22: warning[W0503]")) << left_out.All();
  // NFORCE above MAX_FOR_TORQ (5).
  const Converted many = ConvertText(Deck("", 6, 20));
  EXPECT_TRUE(many.Has(":12:55-60: error[E0505]")) << many.All();
}

// F.10 actuators (corpus `actuators`: HIP driven from its proximal segment, KNEE from its
// distal one) convert with the signs of ATB's APPLY and JNTFNC: the proximal base keeps P and D
// and turns I's sign, the distal base turns P's and D's; a moving target with a derivative gain
// and an integral gain are W0504. ATB's stops are E0512 at their columns: a joint that is not a
// pin (STOP 111), a base segment that is neither of the joint's (STOP 112), an H.11 card without
// an actuator (STOP 741); an earlier actuator's integral term (ATB's shared sum) is E0507.
std::vector<std::string> ActuatorDeck() {
  return deck_testing::Lines(deck_testing::ReadDeckFile(std::string(SLED_SOURCE_ROOT) +
                                                        "/tests/legacy/corpus/actuators.ain"));
}

TEST(LegacyLoad, ActuatorsConvertWithTheSignsOfAtbsApply) {
  const std::vector<std::string> lines = ActuatorDeck();
  const Converted converted = ConvertText(deck_testing::Join(lines));
  ASSERT_EQ(converted.errors, 0) << converted.All();
  const std::size_t first = deck_testing::LineStarting(lines, "   1   1   1   2   3   4");
  EXPECT_TRUE(converted.text.find("actuator actuator_1 on leg.hip") != std::string::npos)
      << converted.text;
  EXPECT_TRUE(converted.text.find("actuator actuator_2 on leg.knee") != std::string::npos)
      << converted.text;
  // KNEE's gain -300 - 100 th0 becomes 300 + 100 th0; its rate gain -2 becomes 2.
  EXPECT_TRUE(
      converted.text.find("polynomial(angle -> rotational_stiffness, 300 lbf*in/deg, 100") !=
      std::string::npos)
      << converted.text;
  EXPECT_TRUE(converted.text.find("constant(2 lbf*in*s/deg)") != std::string::npos)
      << converted.text;
  EXPECT_TRUE(converted.text.find("constant(1000 lbf*in/deg/s)") != std::string::npos)
      << converted.text;
  // The moving target's derivative term (actuator 1) and the integral (actuator 2): W0504.
  EXPECT_TRUE(converted.Has(fmt::format(":{}:17-20: warning[W0504]", first))) << converted.All();
  EXPECT_TRUE(converted.Has(fmt::format(":{}:21-24: warning[W0504]", first + 1)))
      << converted.All();
  // H.11's request is read and left out (W0504).
  EXPECT_TRUE(converted.Has(fmt::format(":{}:1-12: warning[W0504]", lines.size())))
      << converted.All();
}

TEST(LegacyLoad, ActuatorChecksAreAtbsStops) {
  const std::vector<std::string> deck = ActuatorDeck();
  const std::size_t first = deck_testing::LineStarting(deck, "   1   1   1   2   3   4");
  auto with = [&](std::size_t line, const std::string& text) {
    std::vector<std::string> lines = deck;
    lines[line - 1] = text;
    return ConvertText(deck_testing::Join(lines));
  };
  // KNEE made a ball joint (JTYPE 0): STOP 111.
  const std::size_t knee = deck_testing::LineStarting(deck, "KNEE");
  std::string ball = deck[knee - 1];
  ball.replace(10, 4, "   0");
  const Converted not_pin = with(knee, ball);
  EXPECT_TRUE(not_pin.Has(fmt::format(":{}:1-4: error[E0512]", first + 1))) << not_pin.All();
  // Actuator 2's base segment 1 is not one of KNEE's (2 and 3): STOP 112.
  const Converted base = with(first + 1, "   2   1   5   6   8   7");
  EXPECT_TRUE(base.Has(fmt::format(":{}:5-8: error[E0512]", first + 1))) << base.All();
  // Actuator 1 with an integral gain: its term would be actuator 2's error in ATB.
  const Converted shared = with(first, "   1   1   1   2   3   7");
  EXPECT_TRUE(shared.Has(fmt::format(":{}:21-24: error[E0507]", first))) << shared.All();
  // H.11 with KSG 0.
  const Converted no_request = with(deck.size(), "     0");
  EXPECT_TRUE(no_request.Has(fmt::format(":{}:1-6: error[E0512]", deck.size())))
      << no_request.All();
}

}  // namespace
}  // namespace sled::lang::legacy
