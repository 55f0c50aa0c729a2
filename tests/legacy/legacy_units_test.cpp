// The units of deck fields, checked against the V.3 input description: each converted deck is
// compiled and the Model's SI value compared with one derived by hand from the deck's number.
#include <gtest/gtest.h>

#include <string>

#include "legacy_test_deck.h"
#include "sled/compile.h"

namespace sled::lang::legacy {
namespace {

using deck_testing::Converted;
using deck_testing::ConvertText;
using deck_testing::kLegacyDir;
using deck_testing::ReadDeckFile;

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

}  // namespace
}  // namespace sled::lang::legacy
