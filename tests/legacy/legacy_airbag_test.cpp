// D.4 and F.6 airbags through `sled convert`, to ATB's free bag (`model = atb_free`): ATB's
// cylinder tabulated as sled's inflow (checked against the closed form evaluated independently,
// and against its analytic delivered mass), the reference temperature that gives the full bag
// ATB's gas law (against a hand evaluation of AIRBGG and AIRBG3), the bag's attributes from the
// deck, a W0504 for each difference, and a located diagnostic for each field sled cannot take.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "lang/legacy/airbag_inflow.h"
#include "tests/legacy/legacy_test_deck.h"

namespace sled::lang::legacy {
namespace {

using namespace deck_testing;  // NOLINT(google-build-using-namespace): the deck helpers

// The seated occupant's cylinder (D.4.d, D.4.e): 2000 psi over 14.7, 30 in^3 at 600 K, gamma 1.4,
// R 1152.2 in/K per weight, a 1.2 in^2 throat with a discharge coefficient of 0.8; G 386.088.
Cylinder CorpusCylinder() {
  return Cylinder{.gamma = 1.4,
                  .gas_constant = 1152.2,
                  .temperature = 600,
                  .supply_pressure = 2000,
                  .ambient_pressure = 14.7,
                  .volume = 30,
                  .throat_area = 1.2,
                  .discharge = 0.8,
                  .g = 386.088};
}

TEST(AirbagInflow, TheTableIsAtbsClosedForm) {
  const InflowTable table = TabulateCylinder(CorpusCylinder());
  // The end at 99.9 % of the gas, steps of 0.5 ms (the end over 50, rounded down to 1-2-5).
  EXPECT_NEAR(table.end, 0.04163796122570773, 1e-15);
  EXPECT_EQ(table.step, 0.0005);
  ASSERT_EQ(table.rows.size(), 85u);
  // Values of the closed form evaluated apart from sled (a Python transcription of AIRBGG and
  // INPUT_AIRBAGS), to 6 significant digits: W0 = 0.0874284 lb, C = 71.5950 /s.
  EXPECT_EQ(table.rows[0], std::make_pair(0.0, 0.0810623));
  EXPECT_EQ(table.rows[20], std::make_pair(0.01, 0.00317534));
  EXPECT_EQ(table.rows[80], std::make_pair(0.04, 2.4363e-05));
  EXPECT_EQ(table.rows.back(), std::make_pair(0.042, 1.95843e-05));
  // The delivered mass: the trapezoids of the table against the analytic integral, W0 / G
  // (1 - Q^(-5)) at the table's end (the table then stops).
  const double w0 = 0.08742839784759592, rate = 71.5950449488969;
  const double analytic = w0 / 386.088 * (1 - std::pow(1 + rate * 0.042, -5.0));
  double trapezoids = 0;
  for (std::size_t k = 1; k < table.rows.size(); ++k) {
    trapezoids += (table.rows[k].first - table.rows[k - 1].first) *
                  (table.rows[k].second + table.rows[k - 1].second) / 2;
  }
  // Linear interpolation of the convex flow A Q^-6 overshoots by the Euler-Maclaurin term
  // h^2 / 12 |f'(0)| = h^2 / 12 * 6 C A, against the mass A / (5 C): 2.5 (h C)^2 relative.
  const double overshoot = 2.5 * std::pow(0.0005 * rate, 2);
  EXPECT_NEAR(trapezoids / analytic - 1, overshoot, 0.1 * overshoot);
  EXPECT_NEAR(table.delivered, trapezoids / (w0 / 386.088), 1e-12);
}

// The seated-occupant deck, as text lines.
std::vector<std::string> Deck() { return Lines(ReadDeckFile(kLegacyDir + "seated_occupant.ain")); }

Converted Convert(const std::vector<std::string>& lines) { return ConvertText(Join(lines)); }

// The full volume of the seated occupant's bag, semi-axes (7, 10, 10) in.
const double kBagVolume = 4.0 / 3.0 * 3.14159265358979323846 * 7 * 10 * 10;

TEST(AirbagFill, TheReferenceTemperatureGivesAtbsSwitch) {
  const BagFill fill = FillFreeBag(CorpusCylinder(), kBagVolume);
  ASSERT_TRUE(fill.fills);
  // Evaluated apart from sled (Python, from AIRBGG and AIRBG3): CYVMAX 2936.8805 in^3, the fill
  // at Q = 2.5063327 with 0.08654438 lb delivered, SWITCH 33880.340 in^3/lb, so SWITCH CYPA / CYR.
  EXPECT_NEAR(fill.reference_temperature, 432.2522086136631, 1e-9);
  // ATB's unfolding volume against sled's proportional one: they meet at 0 and at the fill.
  EXPECT_GT(fill.largest_unfolding_difference, 0.0);
  EXPECT_LT(fill.largest_unfolding_difference, 0.5);
  // A bag larger than all the cylinder's gas at CYPA (CYVMAX) never fills: T0 / gamma.
  const BagFill never = FillFreeBag(CorpusCylinder(), 3000);
  EXPECT_FALSE(never.fills);
  EXPECT_NEAR(never.reference_temperature, 600 / 1.4, 1e-12);
}

class LegacyAirbag : public ::testing::Test {
 protected:
  void SetUp() override {
    lines_ = Deck();
    head_ = LineStarting(lines_, "DRIVER AIRBAG");
    contacts_ = LineStarting(lines_, "   1   2 3 3 5 5");
  }
  // Columns first.. of the D.4 card `offset` lines after D.4.a replaced by `text`.
  void Put(std::size_t line, int first, const std::string& text) {
    lines_[line - 1].replace(static_cast<std::size_t>(first - 1), text.size(), text);
  }
  std::vector<std::string> lines_;
  std::size_t head_ = 0, contacts_ = 0;
};

TEST_F(LegacyAirbag, TheDriverBagConverts) {
  const Converted converted = Convert(lines_);
  ASSERT_EQ(converted.errors, 0) << converted.All();
  const std::string& text = converted.text;
  EXPECT_NE(text.find("  airbag driver_airbag on sled {\n"
                      "    model = atb_free\n"
                      "    position = (24, 0, -24) in\n"
                      "    orientation = (180, 0, 0) deg\n"
                      "    semi_axes = (7, 10, 10) in\n"
                      "    deploy_at = 0.015 s\n"
                      "    inflow = driver_airbag_inflow\n"
                      "    gas_temperature = 432.2522086136631 K\n"
                      "    gamma = 1.4\n"
                      "    gas_constant = 1152.2 in/K * deck_g\n"
                      "    vent_area = 1 in^2\n"
                      "    discharge_coefficient = 0.5517042657971639\n"
                      "    ambient_pressure = 14.7 lbf/in^2\n"
                      "    bag_mass = 0.5 lbf / deck_g\n"
                      "    tether_stiffness = 1000 lbf/in\n"
                      "    contacts = occupant.ut, occupant.h\n  }"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("function driver_airbag_inflow = table(time -> mass_flow) {\n"
                      "    0 s -> 0.0810623 lbf*s/in\n"),
            std::string::npos);
  // One W0504 for each difference: the cylinder's table, the unfolding (measured), the bag's
  // rotation and the reaction panel.
  for (const auto& [line, columns] : std::vector<std::pair<std::size_t, std::string>>{
           {head_ + 3, "37-72"}, {head_ + 4, "13-36"}, {head_ + 5, "13-24"}, {head_ + 6, "1-72"}}) {
    EXPECT_TRUE(converted.Has(fmt::format("deck.ain:{}:{}: warning[W0504]", line, columns)))
        << line << ":" << columns << "\n"
        << converted.All();
  }
  EXPECT_EQ(std::count_if(
                converted.diagnostics.begin(), converted.diagnostics.end(),
                [](const std::string& d) { return d.find("warning[W0504]") != std::string::npos; }),
            4)
      << converted.All();
}

TEST_F(LegacyAirbag, TheFreeBagsBodyAndVentOpeningConvert) {
  Put(head_ + 3, 1, "         0.8");   // XBM
  Put(head_ + 4, 49, "          3.");  // CYPV
  Put(head_ + 5, 25, "          2.");  // VSCS
  Put(head_ + 5, 49, "         1.5");  // CMASS
  const Converted converted = Convert(lines_);
  ASSERT_EQ(converted.errors, 0) << converted.All();
  EXPECT_NE(converted.text.find("    vent_opening_pressure = 3 lbf/in^2\n"
                                "    bag_mass = 0.8 lbf / deck_g\n"
                                "    mass_factor = 1.5\n"),
            std::string::npos)
      << converted.text;
  EXPECT_TRUE(converted.Has(fmt::format("deck.ain:{}:25-48: warning[W0504]", head_ + 5)));
  SetUp();
  Put(head_ + 5, 49, "          0.");  // CMASS: ATB divides by the bag's mass
  EXPECT_TRUE(Convert(lines_).Has(fmt::format("deck.ain:{}:49-60: error[E0512]", head_ + 5)));
}

TEST_F(LegacyAirbag, ATurnedBagDeploysAlongItsOwnMinusX) {
  Put(head_ + 2, 1, "         30.         10.          5.");
  const Converted turned = Convert(lines_);
  ASSERT_EQ(turned.errors, 0) << turned.All();
  // ATB's axes turned half a turn about z: yaw + 180, pitch and roll negated.
  EXPECT_NE(turned.text.find("orientation = (-150, -10, -5) deg"), std::string::npos)
      << turned.text;
  EXPECT_TRUE(turned.Has(fmt::format("deck.ain:{}:1-72: warning[W0501]", head_ + 2)));
  // A deployment point on a turned panel: the panel's yaw of 90 degrees turns it.
  SetUp();
  Put(head_ + 7, 37, "         90.");
  const Converted panel = Convert(lines_);
  ASSERT_EQ(panel.errors, 0) << panel.All();
  EXPECT_NE(panel.text.find("position = (26"), std::string::npos) << panel.text;
}

TEST_F(LegacyAirbag, WhatSledCannotTakeIsLocated) {
  Put(head_ + 4, 13, "         1.8");  // gamma above 5/3
  EXPECT_TRUE(Convert(lines_).Has(fmt::format("deck.ain:{}:13-24: error[E0507]", head_ + 4)));
  SetUp();
  Put(head_ + 1, 13, "          0.");  // a flat bag
  EXPECT_TRUE(Convert(lines_).Has(fmt::format("deck.ain:{}:13-24: error[E0512]", head_ + 1)));
  SetUp();
  Put(head_, 21, "   0");  // no reaction panel for the deployment point
  EXPECT_TRUE(Convert(lines_).Has(fmt::format("deck.ain:{}:21-24: error[E0512]", head_)));
  SetUp();
  Put(contacts_, 9, " 3 4");  // the chest's contact with the neck's ellipsoid
  EXPECT_TRUE(Convert(lines_).Has(fmt::format("deck.ain:{}:11-12: error[E0507]", contacts_)));
  SetUp();
  Put(contacts_, 9, "99");  // no such segment
  EXPECT_TRUE(Convert(lines_).Has(fmt::format("deck.ain:{}:9-10: error[E0505]", contacts_)));
  SetUp();
  Put(contacts_, 1, "   2");  // the card of bag 1 numbered 2
  EXPECT_TRUE(Convert(lines_).Has(fmt::format("deck.ain:{}:1-4: error[E0512]", contacts_)));
  SetUp();
  Put(lines_.size() > 0 ? LineStarting(lines_, "     4     2     1") : 1, 13, "     6");
  EXPECT_TRUE(Convert(lines_).Has("error[E0505]: card D.1.a, columns 13-18"));
}

// Values that pass the field checks but leave the cylinder no finite time to empty (a throat
// of 1e-320 square inches: the throat's length overflows and the flow constant is 0; G = 0)
// give a located error, never a table of infinities or an undefined conversion.
TEST(AirbagInflow, ACylinderThatNeverEmptiesGivesNoTable) {
  Cylinder cylinder = CorpusCylinder();
  cylinder.throat_area = 1e-320;
  EXPECT_FALSE(TabulateCylinder(cylinder).valid);
  cylinder = CorpusCylinder();
  cylinder.g = 0;
  EXPECT_FALSE(TabulateCylinder(cylinder).valid);
  EXPECT_TRUE(TabulateCylinder(CorpusCylinder()).valid);
}

TEST_F(LegacyAirbag, ACylinderThatNeverEmptiesIsLocated) {
  Put(head_ + 4, 37, "     1.E-320");  // CYAT
  const Converted converted = Convert(lines_);
  EXPECT_TRUE(converted.Has(fmt::format("deck.ain:{}:37-72: error[E0512]", head_ + 3)))
      << converted.All();
}

TEST_F(LegacyAirbag, AClosedBagHasNoVent) {
  Put(head_ + 5, 1, "          0.");  // CYA0
  const Converted closed = Convert(lines_);
  ASSERT_EQ(closed.errors, 0) << closed.All();
  EXPECT_EQ(closed.text.find("vent_area"), std::string::npos);
  EXPECT_EQ(closed.text.find("discharge_coefficient"), std::string::npos);
}

TEST_F(LegacyAirbag, EveryTruncationInTheAirbagIsReported) {
  for (std::size_t keep = head_ - 1; keep < head_ + 8; ++keep) {
    EXPECT_GT(Convert({lines_.begin(), lines_.begin() + static_cast<std::ptrdiff_t>(keep)}).errors,
              0)
        << "cut after line " << keep;
  }
}

}  // namespace
}  // namespace sled::lang::legacy
