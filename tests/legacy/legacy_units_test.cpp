// The units of deck fields, checked against the V.3 input description: each converted deck is
// compiled and the Model's SI value compared with one derived by hand from the deck's number.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "legacy_test_deck.h"
#include "sled/compile.h"

namespace sled::lang::legacy {
namespace {

// Converts and compiles one of examples/legacy/ (with --approximate-airbags, as its tests do).
Compilation CompileDeck(const std::string& name) {
  ConvertOptions options;
  options.approximate_airbags = true;
  const Converted converted = ConvertText(ReadDeckFile(kLegacyDir + name), options, name);
  EXPECT_EQ(converted.errors, 0) << converted.All();
  return Compile(Source::Text(converted.text, kLegacyDir + "converted.sled"));
}

// C.2.a VIPS is in miles per hour: the seated occupant's sled, VIPS 30, starts at
// 30 * 0.44704 = 13.4112 m/s along x and its half-sine (VTIME 0.09, in UNITT = seconds)
// removes those 13.4112 m/s in 0.09 s. Read as in/s (the earlier reading) it was 0.762 m/s.
TEST(LegacyUnits, VipsIsInMilesPerHour) {
  const Compilation compiled = CompileDeck("seated_occupant.ain");
  ASSERT_TRUE(compiled.ok()) << compiled.Render();
  const runtime::Model& model = compiled.model();
  ASSERT_EQ(model.nvehicle(), 1u);
  EXPECT_NEAR(model.vehicle_velocity[0].x(), 13.4112, 1e-12);
  EXPECT_EQ(model.vehicle_velocity[0].y(), 0.0);
  EXPECT_EQ(model.vehicle_velocity[0].z(), 0.0);
  const runtime::VehicleMotion& motion = model.vehicle_motion[0];
  EXPECT_EQ(motion.kind, runtime::VehicleMotion::Kind::kHalfSine);
  EXPECT_NEAR(motion.delta_v, 13.4112, 1e-12);
  EXPECT_NEAR(motion.duration, 0.09, 1e-15);
}

// The pitched ejection seat: VIPS 44.69 mph = 19.9782176 m/s (44.69 * 0.44704), along the
// seat's x, which points down (-90 degrees of pitch turn x onto the ground's +z).
TEST(LegacyUnits, VipsOfAPitchedVehicleIsInMilesPerHour) {
  const Compilation compiled = CompileDeck("ejection_seat.ain");
  ASSERT_TRUE(compiled.ok()) << compiled.Render();
  const runtime::Model& model = compiled.model();
  EXPECT_NEAR(model.vehicle_velocity[0].x(), 0.0, 1e-12);
  EXPECT_NEAR(model.vehicle_velocity[0].z(), 19.9782176, 1e-9);
  EXPECT_NEAR(model.vehicle_motion[0].delta_v, 19.9782176, 1e-9);
}

// The W0501 of C.2.a names the units it assumed.
TEST(LegacyUnits, TheUnverifiedPulseNamesItsUnits) {
  ConvertOptions options;
  options.approximate_airbags = true;
  const Converted converted =
      ConvertText(ReadDeckFile(kLegacyDir + "seated_occupant.ain"), options);
  EXPECT_TRUE(
      converted.Has("VIPS is read in mph (the V.3 input description's unit, 1 mph = "
                    "0.44704 m/s) and VTIME in s (UNITT)"))
      << converted.All();
}

// A slip joint's coordinate is a length: its B.4 spring and stop and its B.5 damping read as a
// force against the displacement (lbf/in, in, lbf*s/in), which the checker takes for a slip joint
// (it refuses a torque law there). The seated occupant's left elbow made a slip joint (JTYPE 5,
// without its torsion spring):
// its spring of 20 is 20 lbf/in = 20 * 4.4482216152605 / 0.0254 = 3502.5367 N/m.
TEST(LegacyUnits, ASlipJointsSpringIsAForceAgainstItsDisplacement) {
  std::vector<std::string> lines =
      deck_testing::Lines(ReadDeckFile(kLegacyDir + "seated_occupant.ain"));
  const std::size_t elbow = deck_testing::LineStarting(lines, "LE      14   0");
  lines[elbow - 1].replace(10, 4, "   5");
  // Its B.4.a card (the 14th, after the last B.3.b) keeps the flexure spring, columns 1-36; a
  // slip joint has no torsion spring.
  lines[elbow + 14].resize(36);
  ConvertOptions options;
  options.approximate_airbags = true;
  const Converted converted = ConvertText(deck_testing::Join(lines), options);
  ASSERT_EQ(converted.errors, 0) << converted.All();
  EXPECT_TRUE(converted.Has("force against its displacement")) << converted.All();
  EXPECT_NE(converted.text.find("slip(lua -> lla)"), std::string::npos) << converted.text;
  EXPECT_NE(converted.text.find("flexure = polynomial(0, 20 lbf/in)"), std::string::npos)
      << converted.text;
  EXPECT_NE(converted.text.find("stop = 90 in"), std::string::npos) << converted.text;
  const Compilation compiled = Compile(Source::Text(converted.text, kLegacyDir + "converted.sled"));
  ASSERT_TRUE(compiled.ok()) << compiled.Render();
}

}  // namespace
}  // namespace sled::lang::legacy
