// compiler::Lower for airbags: a bag becomes a Model airbag with its gas states (two auxiliary
// states, starting empty) and one contact per ellipsoid of each segment it may touch; what it
// cannot touch is dropped with a note that says why; the gas attributes carry their units.
#include <string>

#include <fmt/format.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "runtime/model/model.h"
#include "tests/verification/compile.h"

namespace sled::compiler {
namespace {

using ::testing::HasSubstr;
using ::testing::IsEmpty;
using ::testing::Not;

std::string Scene(const std::string& bag_frame, const std::string& contacts,
                  const std::string& extra = "") {
  return fmt::format(R"(scenario "bag" {{
  time {{ end = 50 ms  output_every = 1 ms }}
  vehicle car {{ }}
  body b {{
    segment trunk {{ mass = 30 kg  inertia = (1, 1, 1) kg*m^2
                    ellipsoid {{ semi_axes = (120, 150, 250) mm }}
                    ellipsoid {{ semi_axes = (100, 100, 100) mm  center = (0, 0, 300) mm }} }}
    segment bare {{ mass = 2 kg  inertia = (0.1, 0.1, 0.1) kg*m^2 }}
    joint j : ball(trunk -> bare) {{ at trunk = (0, 0, 0.4) m  at bare = (0, 0, -0.1) m }}
  }}
  airbag bag on {} {{
    position = (500, 0, 300) mm
    orientation = (180, 0, 0) deg
    semi_axes = (150, 300, 300) mm
    deploy_at = 15 ms
    inflow = table(time -> mass_flow) {{ 0 ms -> 0 kg/s  10 ms -> 2 kg/s  30 ms -> 0 kg/s }}
    vent_area = 20 cm^2
    contacts = {}
    {}
  }}
  output {{
    airbag_pressure bag
    airbag_force bag
    airbag_gas_mass bag
  }}
}}
)",
                     bag_frame, contacts, extra);
}

std::string Notes(const verification::Compiled& compiled) { return compiled.notes(); }

TEST(LowerAirbags, ABagIsSimulatedWithItsGasStatesAndContacts) {
  const verification::Compiled compiled = verification::CompileText(
      Scene("car", "b.trunk", "gas_temperature = 650 K  gamma = 1.3  gas_constant = 297 J/kg/K"));
  ASSERT_EQ(compiled.errors, "");
  EXPECT_THAT(Notes(compiled), Not(HasSubstr("not simulated yet")));
  EXPECT_EQ(compiled.notes(), "");
  const runtime::Model& m = compiled.model();
  ASSERT_EQ(m.airbags.size(), 1u);
  EXPECT_EQ(m.nw, 2);
  EXPECT_EQ(m.w0, std::vector<double>({0.0, 0.0}));
  EXPECT_EQ(m.airbags.state_address[0], 0);
  EXPECT_EQ(m.airbags.frame[0].kind, runtime::FrameRef::Kind::kVehicle);
  EXPECT_TRUE(m.airbags.deploy_point[0].isApprox(runtime::Vec3(0.5, 0, 0.3)));
  // Yaw 180 degrees: the bag deploys along -x.
  EXPECT_TRUE(m.airbags.axes[0].col(0).isApprox(runtime::Vec3(-1, 0, 0)));
  EXPECT_DOUBLE_EQ(m.airbags.deploy_time[0], 0.015);
  EXPECT_DOUBLE_EQ(m.airbags.vent_area[0], 20e-4);
  EXPECT_DOUBLE_EQ(m.airbags.inflow_temperature[0], 650.0);
  EXPECT_DOUBLE_EQ(m.airbags.gamma[0], 1.3);
  EXPECT_DOUBLE_EQ(m.airbags.gas_constant[0], 297.0);
  EXPECT_DOUBLE_EQ(m.airbags.discharge_coefficient[0], 0.6);  // the default
  EXPECT_DOUBLE_EQ(m.airbags.ambient_pressure[0], 101325.0);
  // The trunk's two ellipsoids: two contacts.
  ASSERT_EQ(m.airbags.contact_count[0], 2);
  EXPECT_TRUE(m.airbags.contact_center[1].isApprox(runtime::Vec3(0, 0, 0.3)));
  EXPECT_GE(m.airbags.inflow[0], 0);
  ASSERT_EQ(m.output_kind.size(), 3u);
  EXPECT_EQ(m.output_kind[0], runtime::Model::OutputKind::kAirbagPressure);
  EXPECT_EQ(m.output_kind[1], runtime::Model::OutputKind::kAirbagForce);
  EXPECT_EQ(m.output_kind[2], runtime::Model::OutputKind::kAirbagGasMass);
}

TEST(LowerAirbags, SegmentsTheBagCannotTouchAreDroppedWithANote) {
  // Fixed in the trunk, the bag cannot touch the trunk; `bare` has no ellipsoid.
  const verification::Compiled compiled =
      verification::CompileText(Scene("b.trunk", "b.trunk, b.bare"));
  ASSERT_EQ(compiled.errors, "");
  const std::string notes = Notes(compiled);
  EXPECT_THAT(notes, HasSubstr("airbag `bag` cannot touch `b.trunk`: the bag is fixed in it"));
  EXPECT_THAT(notes, HasSubstr("airbag `bag` cannot touch `b.bare`: it has no contact ellipsoid"));
  EXPECT_THAT(notes, HasSubstr("airbag `bag` touches no segment"));
  const runtime::Model& m = compiled.model();
  ASSERT_EQ(m.airbags.size(), 1u);
  EXPECT_EQ(m.airbags.contact_count[0], 0);
  EXPECT_EQ(m.airbags.frame[0].kind, runtime::FrameRef::Kind::kSegment);
}

TEST(LowerAirbags, GasAttributesAreCheckedForUnitsAndRange) {
  EXPECT_THAT(verification::CompileText(Scene("car", "b.trunk", "gas_temperature = 600")).errors,
              HasSubstr("gas_temperature"));
  EXPECT_THAT(verification::CompileText(Scene("car", "b.trunk", "gas_temperature = 600 Pa")).errors,
              HasSubstr("temperature [K]"));
  EXPECT_THAT(verification::CompileText(Scene("car", "b.trunk", "gamma = 1")).errors,
              HasSubstr("gamma"));
  EXPECT_THAT(verification::CompileText(Scene("car", "b.trunk", "gas_constant = 287 J/kg")).errors,
              HasSubstr("specific gas constant [J/kg/K]"));
  EXPECT_THAT(
      verification::CompileText(Scene("car", "b.trunk", "discharge_coefficient = 1.5")).errors,
      HasSubstr("discharge_coefficient"));
}

TEST(LowerAirbags, ABagDeployingAfterTheEndIsNoted) {
  const verification::Compiled compiled = verification::CompileText(
      Scene("car", "b.trunk", "")
          .replace(Scene("car", "b.trunk", "").find("deploy_at = 15 ms"), 17, "deploy_at = 80 ms"));
  ASSERT_EQ(compiled.errors, "");
  EXPECT_THAT(Notes(compiled), HasSubstr("deploys at 0.08 s, when the run has ended"));
}

TEST(LowerAirbags, AtbsFreeBagHasItsBodyAndEightStates) {
  const verification::Compiled compiled = verification::CompileText(
      Scene("car", "b.trunk",
            "model = atb_free  bag_mass = 0.2 kg  mass_factor = 1.5  tether_stiffness = 3 kN/m  "
            "vent_opening_pressure = 10 kPa"));
  ASSERT_EQ(compiled.errors, "");
  const runtime::Model& m = compiled.model();
  ASSERT_EQ(m.airbags.size(), 1u);
  EXPECT_EQ(m.airbags.free_bag[0], 1);
  // The gas mass, the mass vented, the centre and its velocity, all starting at zero.
  EXPECT_EQ(m.nw, 8);
  EXPECT_EQ(m.w0, std::vector<double>(8, 0.0));
  EXPECT_DOUBLE_EQ(m.airbags.bag_mass[0], 0.2);
  EXPECT_DOUBLE_EQ(m.airbags.mass_factor[0], 1.5);
  EXPECT_DOUBLE_EQ(m.airbags.tether_stiffness[0], 3000.0);
  EXPECT_DOUBLE_EQ(m.airbags.vent_opening_pressure[0], 10e3);
  // The energy bag is the default, with its two states.
  const verification::Compiled energy = verification::CompileText(Scene("car", "b.trunk"));
  ASSERT_EQ(energy.errors, "");
  EXPECT_EQ(energy.model().airbags.free_bag[0], 0);
  EXPECT_EQ(energy.model().nw, 2);
}

TEST(LowerAirbags, TheFreeBagsAttributesOnAnEnergyBagAreRefused) {
  EXPECT_THAT(
      verification::CompileText(Scene("car", "b.trunk", "tether_stiffness = 3 kN/m")).errors,
      HasSubstr("error[E0440]: airbag `bag` has `tether_stiffness`"));
  EXPECT_THAT(
      verification::CompileText(Scene("car", "b.trunk", "model = energy  bag_mass = 1 kg")).errors,
      HasSubstr("error[E0440]: airbag `bag` has `bag_mass`"));
  EXPECT_THAT(verification::CompileText(Scene("car", "b.trunk", "model = atb")).errors,
              HasSubstr("E0308"));
  EXPECT_THAT(
      verification::CompileText(Scene("car", "b.trunk", "model = atb_free  mass_factor = 0"))
          .errors,
      HasSubstr("mass_factor"));
}

}  // namespace
}  // namespace sled::compiler
