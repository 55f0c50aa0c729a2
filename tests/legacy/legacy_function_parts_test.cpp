// E.2's D0, D2, D3 and D4 and F.1.b's inertial spike (NF(2)), on the floor contact of the corpus
// deck two_segments.ain: a spike with its end D3 becomes `spike = NAME  spike_end = D3` of ATB's
// law (tested against hand computations in tests/runtime/atb_unloading_test.cpp and
// tests/verification/contact_test.cpp), a two-part function of two tables that meet at |D1|
// one table, D0 under an R factor the law's `origin`; what ATB's reference leaves unknown is
// refused at its columns. The corpus deck spike_parts_origin checks the SI values.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <string>

#include "tests/legacy/legacy_test_deck.h"

#include "runtime/forces/functions.h"
#include "sled/compile.h"

namespace sled::lang::legacy {
namespace {

using namespace deck_testing;  // NOLINT(google-build-using-namespace): the deck helpers

constexpr double kInch = 0.0254;
constexpr double kPound = 4.4482216152605;

// two_segments.ain with its floor function 1 replaced by `floor`, functions `extra` added, and
// F.1.b's force, NF(2..4) set to `force`, `spike`, `r`, `g` (4 columns each).
Converted Deck(const std::string& floor, const std::string& extra, const std::string& force,
               const std::string& spike, const std::string& r, const std::string& g) {
  std::string deck =
      ReadDeckFile(std::string(SLED_SOURCE_ROOT) + "/tests/legacy/corpus/two_segments.ain");
  const std::string table = "   1    FLOOR FORCE\n";
  const std::size_t at = deck.find(table);
  const std::size_t end = deck.find("   2    FRICTION");
  if (!floor.empty()) deck.replace(at, end - at, floor);
  const std::string end_of_functions = "  99\n# ---- F cards";
  deck.replace(deck.find(end_of_functions), 4, extra + "  99");
  const std::string f1b = "   1   2   0   0   1   0   0   0   2       0";
  deck.replace(deck.find(f1b), f1b.size(),
               "   1   2   0   0" + force + spike + r + g + "   2       0");
  return ConvertText(deck);
}

// An E.1 and E.2 card of a constant function with D0, D3 and D4.
std::string Constant(int number, const std::string& title, double value, double d0 = 0,
                     double d3 = 0, double d4 = 0) {
  return fmt::format("{:4}    {}\n{:12.4f}          0.{:12.4f}{:12.4f}{:12.4f}\n", number, title,
                     d0, value, d3, d4);
}

TEST(LegacyFunctionParts, TheInertialSpikeBecomesThatOfAtbsLaw) {
  // Spike function 3 (50 lb, ending at D3 = 0.5 in) with R = 0.8 (function 4), and with R = 1:
  // ATB's law then carries the spike on its elastic loading curve.
  for (const char* r : {"   4", "   0"}) {
    const Converted converted =
        Deck("", Constant(3, "SPIKE", 50, 0, 0.5) + Constant(4, "R 0.8", 0.8), "   1", "   3", r,
             "   0");
    ASSERT_EQ(converted.errors, 0) << converted.All();
    EXPECT_NE(converted.text.find(
                  fmt::format("unloading = atb(energy_return = {}, permanent_set = 0, spike = "
                              "spike, spike_end = 0.5 in)",
                              r[3] == '4' ? "0.8" : "1")),
              std::string::npos)
        << converted.text;
    Compilation compiled = Compile(Source::Text(converted.text, "spike.sled"));
    ASSERT_TRUE(compiled.ok()) << compiled.Render() << converted.text;
    const runtime::FunctionTable& f = compiled.model().functions;
    const auto floor = static_cast<std::size_t>(compiled.model().contacts.pair_function.at(0));
    ASSERT_GE(f.atb_spike.at(floor), 0);
    EXPECT_NEAR(runtime::EvaluateFunction(f, f.atb_spike[floor], 0.001), 50 * kPound, 1e-9);
    EXPECT_NEAR(f.atb_spike_end.at(floor), 0.5 * kInch, 1e-15);
  }
}

TEST(LegacyFunctionParts, TwoTablesThatMeetAtD1AreOneTable) {
  // D1 = -1, D2 = -3: 0 -> 0, 2 in -> 1000 lb up to 1 in, then 0.5 -> 0, 1 -> 500, 3 -> 4500
  // up to 3 in: 0, 500 lb at 1 in, 4500 lb at 3 in (2500 lb at 2 in, not the first's 1000).
  const std::string two_parts =
      "   1    TWO PARTS\n          0.         -1.         -3.          0.          0.\n"
      "     2\n          0.          0.          2.       1000.\n"
      "     3\n         0.5          0.          1.        500.          3.       4500.\n";
  const Converted converted = Deck(two_parts, "", "   1", "   0", "   0", "   0");
  ASSERT_EQ(converted.errors, 0) << converted.All();
  EXPECT_NE(converted.text.find("    0 in -> 0 lbf\n    1 in -> 500 lbf\n    3 in -> 4500 lbf\n"),
            std::string::npos)
      << converted.text;
  // No warning about where the parts end (E.2 columns 13-36).
  EXPECT_FALSE(converted.Has("13-24: warning[W0501]")) << converted.All();
  EXPECT_FALSE(converted.Has("25-36: warning[W0501]")) << converted.All();
  Compilation compiled = Compile(Source::Text(converted.text, "parts.sled"));
  ASSERT_TRUE(compiled.ok()) << compiled.Render();
  const runtime::Model& model = compiled.model();
  EXPECT_NEAR(
      runtime::EvaluateFunction(model.functions, model.contacts.pair_function.at(0), 2 * kInch),
      2500 * kPound, 1e-9);
}

TEST(LegacyFunctionParts, D0UnderAnRFactorIsTheOriginOfAtbsLaw) {
  // The polynomial 400 lb/in D from D0 = -0.25 in, R = 0.6: `origin = -0.25 in`. Without an R
  // factor nothing integrates it and the deflection never falls below D0: left out (W0503).
  const std::string from =
      "   3    FROM -0.25\n       -0.25          1.          0.          0."
      "          0.\n          0.        400.          0.          0.     "
      "     0.          0.\n";
  const Converted converted =
      Deck("", from + Constant(4, "R 0.6", 0.6), "   3", "   0", "   4", "   0");
  ASSERT_EQ(converted.errors, 0) << converted.All();
  EXPECT_NE(converted.text.find("permanent_set = 0, origin = -0.25 in)"), std::string::npos)
      << converted.text;
  Compilation compiled = Compile(Source::Text(converted.text, "origin.sled"));
  ASSERT_TRUE(compiled.ok()) << compiled.Render();
  const runtime::FunctionTable& f = compiled.model().functions;
  EXPECT_NEAR(
      f.atb_origin.at(static_cast<std::size_t>(compiled.model().contacts.pair_function.at(0))),
      -0.25 * kInch, 1e-15);
  const Converted elastic = Deck("", from, "   3", "   0", "   0", "   0");
  ASSERT_EQ(elastic.errors, 0) << elastic.All();
  EXPECT_TRUE(elastic.Has(":1-12: warning[W0503]")) << elastic.All();
  EXPECT_EQ(elastic.text.find("origin"), std::string::npos) << elastic.text;
}

TEST(LegacyFunctionParts, WhatTheReferenceLeavesUnknownIsRefusedAtItsColumns) {
  const std::string r = Constant(4, "R 0.8", 0.8);
  const std::string polynomial_part =
      "   1    POLY PART\n          0.         -1.          2.          0.          0.\n"
      "     2\n          0.          0.          2.       1000.\n"
      "          0.        500.          0.          0.          0.          0.\n";
  const std::string jump =
      "   1    JUMP\n          0.         -1.         -3.          0.          0.\n"
      "     2\n          0.          0.          2.       1000.\n"
      "     2\n          1.        600.          3.       4500.\n";
  struct Case {
    std::string floor, extra;
    const char *force, *spike, *r;
    const char* expected;
  } cases[] = {
      // a spike whose D3 is 0: where ATB drops it is in FRCDFL
      {"", Constant(3, "SPIKE", 50) + r, "   1", "   3", "   4", ":37-48: error[E0507]"},
      // D3 of the force function itself, D4 of any
      {"", Constant(3, "F", 100, 0, 1) + r, "   3", "   0", "   4", ":37-48: error[E0507]"},
      {"", Constant(3, "F", 100, 0, 0, 1) + r, "   3", "   0", "   4", ":49-60: error[E0507]"},
      // D0 above 0 under an R factor: the value below D0 is in EVALFD
      {"", Constant(3, "F", 100, 0.5) + r, "   3", "   0", "   4", ":1-12: error[E0507]"},
      // a polynomial part, and two tables with a jump at |D1|
      {polynomial_part, "", "   1", "   0", "   0", ":25-36: error[E0507]"},
      {jump, "", "   1", "   0", "   0", ":25-36: error[E0507]"},
  };
  for (const Case& c : cases) {
    const Converted converted = Deck(c.floor, c.extra, c.force, c.spike, c.r, "   0");
    EXPECT_TRUE(converted.Has(c.expected)) << c.expected << "\n" << converted.All();
  }
}

}  // namespace
}  // namespace sled::lang::legacy
