// ATB's R and G factors on an F.1.b contact: constant factors become the force function's
// `energy_loss = 1 - R` and `permanent_set = G`, and the W0504 warning's figures (how far ATB's
// quadratic unloading curve is from sled's power law, the energy each gives back) are checked
// against values derived by hand from DEF_NEW_QUADRATIC's quadratic; R = 1 leaves G unused, as
// ATB does; what sled cannot express (a factor that changes with the deflection, R < 1 without
// G, the inertial spike, ATB's rate-dependent force) is refused at its columns.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <string>

#include "tests/legacy/legacy_test_deck.h"

#include "runtime/forces/functions.h"
#include "sled/compile.h"

namespace sled::lang::legacy {
namespace {

using namespace deck_testing;  // NOLINT(google-build-using-namespace): the deck helpers

// The corpus deck two_segments.ain (a floor force table 0 -> 0, 1 -> 500, 2 -> 2000 lb against
// in) with E functions 3 and 4 (`f3`, `f4`: E.1 to E.4 cards) added and F.1.b's NF(2..4) set to
// `spike`, `r`, `g` (4 columns each).
Converted WithFactors(const std::string& spike, const std::string& r, const std::string& g,
                      const std::string& f3, const std::string& f4) {
  std::string deck =
      ReadDeckFile(std::string(SLED_SOURCE_ROOT) + "/tests/legacy/corpus/two_segments.ain");
  const std::string end_of_functions = "  99\n# ---- F cards";
  deck.replace(deck.find(end_of_functions), 4, f3 + f4 + "  99");
  const std::string f1b = "   1   2   0   0   1   0   0   0   2       0";
  deck.replace(deck.find(f1b), f1b.size(), "   1   2   0   0   1" + spike + r + g + "   2       0");
  return ConvertText(deck);
}

std::string Constant(int number, const std::string& title, const std::string& value) {
  return fmt::format("{:4}    {}\n          0.          0.{:>12}          0.          0.\n", number,
                     title, value);
}

TEST(LegacyUnloading, ConstantFactorsBecomeEnergyLossAndPermanentSet) {
  // R = 0.8, G = 0.25. At the table's last point x_max = 2 in: f = 2000 lb, the loading energy
  // E = 500 * 1 / 2 + (500 + 2000) / 2 * 1 = 1500 lb*in, the unloading range 0.75 * 2 = 1.5 in.
  // ATB's quadratic A1 u + A2 u^2 through (1.5, 2000) with area 0.8 * 1500 = 1200:
  // A1 = 2 / 1.5 * (3 * 1200 / 1.5 - 2000) = 533.33 >= 0, A2 = (2000 / 1.5 - A1) / 1.5 = 533.33
  // >= 0, so it gives back 80 %; in units of f and the range, 0.4 t + 0.6 t^2. sled's power law
  // t^n with n = 2000 * 1.5 / 1200 - 1 = 1.5 gives back 80 % too. 0.4 t + 0.6 t^2 - t^1.5 is
  // largest where 1.2 s^2 - 1.5 s + 0.4 = 0 (s = sqrt t): s = 0.38564, t = 0.14872, 0.0154 of f.
  const Converted converted = WithFactors("   0", "   3", "   4", Constant(3, "R 0.8", "0.8"),
                                          Constant(4, "G 0.25", "0.25"));
  ASSERT_EQ(converted.errors, 0) << converted.All();
  EXPECT_NE(converted.text.find("    2 in -> 2000 lbf\n    energy_loss = 0.2\n"
                                "    permanent_set = 0.25\n  }"),
            std::string::npos)
      << converted.text;
  EXPECT_TRUE(converted.Has("warning[W0504]")) << converted.All();
  EXPECT_TRUE(
      converted.Has("differ by up to 1.5 % of f(x_max), ATB's gives back 80.0 % of the "
                    "loading energy and sled's 80.0 %"))
      << converted.All();
  EXPECT_FALSE(converted.Has("W0502")) << converted.All();  // the factor functions are used
  Compilation compiled = Compile(Source::Text(converted.text, "factors.sled"));
  ASSERT_TRUE(compiled.ok()) << compiled.Render();
  const runtime::Model& model = compiled.model();
  const auto f = static_cast<std::size_t>(model.contacts.pair_function.at(0));
  EXPECT_NEAR(model.functions.energy_loss.at(f), 0.2, 1e-15);
  EXPECT_NEAR(model.functions.permanent_set.at(f), 0.25, 1e-15);
}

TEST(LegacyUnloading, WhereAtbClampsItsQuadraticTheWarningSaysHowMuchEnergyDiffers) {
  // R = 0.6, G = 0.25: 3 * 0.6 * 1500 / 1.5 = 1800 < 2000, so ATB's A1 is clamped to 0 and its
  // curve is the parabola 2000 t^2, which gives back 2000 * 1.5 / 3 = 1000 lb*in, 66.7 % of E;
  // sled's n = 2000 * 1.5 / 900 - 1 = 7/3 gives back 60 %. t^2 - t^(7/3) is largest at
  // t^(1/3) = 6/7: (6/7)^6 / 7 = 0.0567 of f.
  const Converted converted = WithFactors("   0", "   3", "   4", Constant(3, "R 0.6", "0.6"),
                                          Constant(4, "G 0.25", "0.25"));
  ASSERT_EQ(converted.errors, 0) << converted.All();
  EXPECT_TRUE(
      converted.Has("differ by up to 5.7 % of f(x_max), ATB's gives back 66.7 % of the "
                    "loading energy and sled's 60.0 %"))
      << converted.All();
}

TEST(LegacyUnloading, AnRFactorOfOneUnloadsAlongTheLoadingFunctionAndLeavesGUnused) {
  const Converted converted =
      WithFactors("   0", "   3", "   4", Constant(3, "R 1", "1."), Constant(4, "G 0.25", "0.25"));
  ASSERT_EQ(converted.errors, 0) << converted.All();
  EXPECT_EQ(converted.text.find("energy_loss"), std::string::npos) << converted.text;
  EXPECT_EQ(converted.text.find("permanent_set"), std::string::npos) << converted.text;
  EXPECT_TRUE(converted.Has(":29-32: warning[W0503]")) << converted.All();
}

TEST(LegacyUnloading, WhatSledCannotExpressIsRefusedAtItsColumns) {
  const std::string r = Constant(3, "R 0.8", "0.8"), g = Constant(4, "G 0.25", "0.25");
  const std::string table =
      "   3    R TABLE\n          0.         -1.          0.          0.  "
      "        0.\n     2\n          0.         0.5          2.         "
      "0.9\n";
  struct Case {
    const char *spike, *r, *g;
    std::string f3, f4;
    const char* expected;
  } cases[] = {
      {"   0", "   3", "   0", r, g, ":25-28: error[E0507]"},      // R < 1 without G
      {"   0", "   3", "   4", table, g, ":25-28: error[E0507]"},  // R changes with x_max
      {"   3", "   0", "   0", r, g, ":21-24: error[E0507]"},      // the inertial spike
      {"  -3", "   0", "   0", r, g, ":21-24: error[E0507]"},      // the rate-dependent force
      {"   0", "   3", "   4", Constant(3, "R 1.5", "1.5"), g, ":25-28: error[E0512]"},
      {"   0", "   3", "   4", r, Constant(4, "G 1", "1."), ":29-32: error[E0512]"},
  };
  for (const Case& c : cases) {
    const Converted converted = WithFactors(c.spike, c.r, c.g, c.f3, c.f4);
    EXPECT_TRUE(converted.Has(c.expected)) << c.expected << "\n" << converted.All();
  }
}

}  // namespace
}  // namespace sled::lang::legacy
