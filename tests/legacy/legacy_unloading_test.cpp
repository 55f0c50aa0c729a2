// ATB's R and G factors on an F.1.b contact become ATB's own law on the force function,
// `unloading = atb(energy_return = R, permanent_set = G)`: constants as numbers, R < 1 without
// G as G = 0, factors that change with the largest deflection as functions of it (the law
// itself is tested against hand computations in tests/runtime/atb_unloading_test.cpp and
// tests/verification/contact_test.cpp); R = 1 leaves G unused, as ATB does; values ATB's
// meaning does not allow are E0512 at their columns.
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

// The force function's R and G of ATB's law in the compiled Model, at deflection x [m].
double FactorAt(const runtime::Model& model, bool energy_return, double x) {
  const auto f = static_cast<std::size_t>(model.contacts.pair_function.at(0));
  const auto& ids = energy_return ? model.functions.atb_return : model.functions.atb_set;
  return runtime::EvaluateFunction(model.functions, ids.at(f), x);
}

TEST(LegacyUnloading, ConstantFactorsBecomeAtbsOwnLaw) {
  // R = 0.8, G = 0.25 become ATB's law itself: no approximation, no W0504.
  const Converted converted = WithFactors("   0", "   3", "   4", Constant(3, "R 0.8", "0.8"),
                                          Constant(4, "G 0.25", "0.25"));
  ASSERT_EQ(converted.errors, 0) << converted.All();
  EXPECT_NE(converted.text.find("    2 in -> 2000 lbf\n"
                                "    unloading = atb(energy_return = 0.8, permanent_set = 0.25)\n"
                                "  }"),
            std::string::npos)
      << converted.text;
  EXPECT_FALSE(converted.Has("W0504")) << converted.All();
  EXPECT_FALSE(converted.Has("W0502")) << converted.All();  // the factor functions are used
  Compilation compiled = Compile(Source::Text(converted.text, "factors.sled"));
  ASSERT_TRUE(compiled.ok()) << compiled.Render();
  EXPECT_EQ(FactorAt(compiled.model(), true, 0.03), 0.8);
  EXPECT_EQ(FactorAt(compiled.model(), false, 0.03), 0.25);
}

TEST(LegacyUnloading, AnRFactorWithoutGUnloadsToZeroDeflection) {
  // ATB's quadratic then ends at zero force at zero deflection: G = 0.
  const Converted converted = WithFactors("   0", "   3", "   0", Constant(3, "R 0.6", "0.6"),
                                          Constant(4, "G 0.25", "0.25"));
  ASSERT_EQ(converted.errors, 0) << converted.All();
  EXPECT_TRUE(converted.text.find("unloading = atb(energy_return = 0.6, permanent_set = 0)") !=
              std::string::npos)
      << converted.text;
  Compilation compiled = Compile(Source::Text(converted.text, "factors.sled"));
  ASSERT_TRUE(compiled.ok()) << compiled.Render();
  EXPECT_EQ(FactorAt(compiled.model(), false, 0.03), 0.0);
}

TEST(LegacyUnloading, FactorsThatChangeWithTheLargestDeflectionAreFunctionsOfIt) {
  // R from the table 0 in -> 0.5, 2 in -> 0.9: 0.7 at 1 in; G the polynomial 0.1 + 0.05 x
  // (x in inches): 0.15 at 1 in. Each is declared as a function deflection -> ratio.
  const std::string r_table =
      "   3    R TABLE\n          0.         -1.          0.          0.          0.\n"
      "     2\n          0.         0.5          2.         0.9\n";
  const std::string g_polynomial =
      "   4    G LINE\n          0.          1.          0.          0.          0.\n"
      "         0.1        0.05          0.          0.          0.          0.\n";
  const Converted converted = WithFactors("   0", "   3", "   4", r_table, g_polynomial);
  ASSERT_EQ(converted.errors, 0) << converted.All();
  EXPECT_TRUE(converted.text.find("table(deflection -> ratio)") != std::string::npos)
      << converted.text;
  EXPECT_TRUE(converted.text.find("polynomial(deflection -> ratio, 0.1, 0.05 in^-1)") !=
              std::string::npos)
      << converted.text;
  Compilation compiled = Compile(Source::Text(converted.text, "factors.sled"));
  ASSERT_TRUE(compiled.ok()) << compiled.Render() << converted.text;
  EXPECT_NEAR(FactorAt(compiled.model(), true, 0.0254), 0.7, 1e-12);
  EXPECT_NEAR(FactorAt(compiled.model(), false, 0.0254), 0.15, 1e-12);
}

TEST(LegacyUnloading, AnRFactorOfOneUnloadsAlongTheLoadingFunctionAndLeavesGUnused) {
  const Converted converted =
      WithFactors("   0", "   3", "   4", Constant(3, "R 1", "1."), Constant(4, "G 0.25", "0.25"));
  ASSERT_EQ(converted.errors, 0) << converted.All();
  EXPECT_EQ(converted.text.find("unloading"), std::string::npos) << converted.text;
  EXPECT_TRUE(converted.Has(":29-32: warning[W0503]")) << converted.All();
}

TEST(LegacyUnloading, NegativeFunctionNumbersBecomeTheRateDependentForce) {
  // NF(2) = -3, NF(3) = -4: ATB's F2(D) F3(D') (FUNC_RATE_DEP) with F2 the constant 100 lb and
  // F3 the table 0 in/s -> 0, 10 in/s -> 1 (0.5 at 0.127 m/s); NF(4) = 0: no F4.
  const std::string rate_table =
      "   4    F3 TABLE\n          0.         -1.          0.          0.          0.\n"
      "     2\n          0.          0.         10.          1.\n";
  const Converted converted =
      WithFactors("  -3", "  -4", "   0", Constant(3, "F2 100", "100."), rate_table);
  ASSERT_EQ(converted.errors, 0) << converted.All();
  EXPECT_TRUE(converted.text.find("table(velocity -> ratio)") != std::string::npos)
      << converted.text;
  EXPECT_TRUE(converted.text.find("0 in/s -> 0") != std::string::npos) << converted.text;
  Compilation compiled = Compile(Source::Text(converted.text, "rate.sled"));
  ASSERT_TRUE(compiled.ok()) << compiled.Render() << converted.text;
  const runtime::Model& model = compiled.model();
  const runtime::FunctionTable& f = model.functions;
  EXPECT_NEAR(runtime::EvaluateFunction(f, model.contacts.pair_rate_scaled_force.at(0), 0.01),
              100 * 4.4482216152605, 1e-9);
  EXPECT_NEAR(runtime::EvaluateFunction(f, model.contacts.pair_rate_scale.at(0), 0.127), 0.5,
              1e-12);
  EXPECT_EQ(model.contacts.pair_rate_force.at(0), -1);
  // NF(2) alone: ATB multiplies it by a missing F3, so the term is nothing (W0503).
  const Converted alone = WithFactors("  -3", "   0", "   0", Constant(3, "F2 100", "100."), "");
  ASSERT_EQ(alone.errors, 0) << alone.All();
  EXPECT_TRUE(alone.Has(":21-24: warning[W0503]")) << alone.All();
  EXPECT_EQ(alone.text.find("rate_scaled_force"), std::string::npos) << alone.text;
}

TEST(LegacyUnloading, WhatSledCannotExpressIsRefusedAtItsColumns) {
  const std::string r = Constant(3, "R 0.8", "0.8"), g = Constant(4, "G 0.25", "0.25");
  struct Case {
    const char *spike, *r, *g;
    std::string f3, f4;
    const char* expected;
  } cases[] = {
      {"   3", "   0", "   0", r, g, ":37-48: error[E0507]"},  // a spike without its end D3
      {"  -3", "   4", "   0", r, g, ":21-32: error[E0512]"},  // rate terms beside R
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
