// The pedestrian and ejection-seat decks of examples/legacy end to end through the `sled`
// program: each converts with only the warnings the format reference calls for (fields it
// marks unverified, and fields sled's model approximates), the result checks with no diagnostic,
// `sled fmt --check` leaves it unchanged, and its run gives the same time histories, bit for bit,
// as the hand-written twin of the same scene. A realistic mistake in each deck gets the one located
// diagnostic it should.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "tests/compiler/legacy_twin.h"

namespace sled::testing {
namespace {

class LegacyCorpus : public LegacyTwinTest {
 protected:
  // Converts examples/legacy/NAME.ain, requires exactly the W0501 (unverified) and W0504
  // (approximated) warnings `expected` (each a "LINE:COLUMNS: warning[W05..]: card ..." prefix)
  // and nothing else, then checks, formats
  // and runs both the result and examples/legacy/NAME.sled and compares their values.
  void ExpectDeckMatchesTwin(const std::string& name, const std::vector<std::string>& expected,
                             int rows) {
    const std::string deck = "examples/legacy/" + name + ".ain";
    const fs::path converted = temp() / (name + ".sled");
    const SledResult convert =
        Sled({"convert", deck, "-o", converted.string(), "--diagnostics=compact"});
    ASSERT_EQ(convert.exit_code, 0) << convert.err;
    EXPECT_EQ(Count(convert.err, "error["), 0u) << convert.err;
    EXPECT_EQ(Count(convert.err, "warning["), expected.size()) << convert.err;
    EXPECT_EQ(Count(convert.err, "warning[W0501]") + Count(convert.err, "warning[W0504]"),
              expected.size())
        << convert.err;
    for (const std::string& warning : expected) {
      EXPECT_NE(convert.err.find(deck + ":" + warning), std::string::npos)
          << "missing: " << warning << "\n"
          << convert.err;
    }

    ExpectMatchesTwin(converted, "examples/legacy/" + name + ".sled", rows);
  }

  // Writes `deck` as NAME.ain, converts it and returns the scenario,
  // after requiring that it checks with no diagnostic.
  std::string ConvertCheckingClean(const std::string& name, const std::string& deck) {
    const fs::path path = temp() / (name + ".ain");
    WriteText(path, deck);
    const fs::path converted = temp() / (name + ".sled");
    const SledResult convert = Sled({"convert", path.string(), "-o", converted.string()});
    EXPECT_EQ(convert.exit_code, 0) << convert.err;
    if (convert.exit_code != 0) return {};
    const SledResult check = Sled({"check", converted.string()});
    EXPECT_EQ(check.exit_code, 0) << check.err;
    EXPECT_EQ(check.err, "");
    return ReadText(converted);
  }

  // Converts the deck with `edit` applied and returns the compact diagnostics.
  std::string ConvertMangled(const std::string& name, const std::string& from,
                             const std::string& to) {
    std::string deck = ReadText(kSourceRoot / "examples/legacy" / (name + ".ain"));
    const std::size_t at = deck.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at == std::string::npos) return {};
    deck.replace(at, from.size(), to);
    const fs::path path = temp() / "deck.ain";
    WriteText(path, deck);
    const SledResult convert = Sled({"convert", path.string(), "--diagnostics=compact"});
    EXPECT_EQ(convert.exit_code, 1);
    EXPECT_EQ(convert.out, "");
    return convert.err;
  }
};

TEST_F(LegacyCorpus, PedestrianDeckMatchesItsTwin) {
  // The vehicle's half-sine (VINO12), the frame of the planes and the F.1 layout are unverified.
  ExpectDeckMatchesTwin("pedestrian",
                        {"107:19-30: warning[W0501]: card C.2.a (vehicle 1), columns 19-30",
                         "110:1-12: warning[W0501]: card D.2 (plane 1), columns 1-28",
                         "173:1-44: warning[W0501]: card F.1.b (plane 1, contact 1), columns 1-44"},
                        2001);  // A.4: 2000 output steps of 0.1 ms
}

TEST_F(LegacyCorpus, EjectionSeatDeckMatchesItsTwin) {
  // Also W0504 where the harness's webbing wraps a segment: sled lays it over the ellipsoid
  // rather than through ATB's point fixed on it.
  ExpectDeckMatchesTwin("ejection_seat",
                        {"106:19-30: warning[W0501]: card C.2.a (vehicle 1), columns 19-30",
                         "109:1-16: warning[W0501]: card D.2 (plane 1), columns 1-28",
                         "154:1-44: warning[W0501]: card F.1.b (plane 1, contact 1), columns 1-44",
                         "174:37-72: warning[W0504]: card F.8.d.1 (harness 1, belt 1, point 2)",
                         "182:37-72: warning[W0504]: card F.8.d.1 (harness 1, belt 2, point 2)",
                         "190:37-72: warning[W0504]: card F.8.d.1 (harness 1, belt 3, point 2)"},
                        2501);  // A.4: 2500 output steps of 0.1 ms
}

TEST_F(LegacyCorpus, ALetterOForAZeroInAWeightIsLocated) {
  const std::string err = ConvertMangled("pedestrian", "RUL     20.3", "RUL     2O.3");
  EXPECT_NE(err.find("deck.ain:21:7-12: error[E0502]: card B.2.a (segment 6), columns 7-12 "
                     "(WEIGHT, the segment's weight): `2O.3` is not a number"),
            std::string::npos)
      << err;
  EXPECT_EQ(Count(err, "error["), 1u) << err;
}

TEST_F(LegacyCorpus, AContactCardShiftedOneColumnIsLocated) {
  // The first contact of plane 2 pushed one column right: J leaves columns 1-4.
  const std::string err = ConvertMangled("pedestrian", "\n   2   7   0   0   2   0   0   0   7",
                                         "\n    2   7   0   0   2   0   0   0   7");
  EXPECT_NE(err.find("deck.ain:175:1-4: error[E0512]: card F.1.b (plane 2, contact 1), columns "
                     "1-4: J is 0 on a card for plane 2"),
            std::string::npos)
      << err;
}

TEST_F(LegacyCorpus, AMissingJointSpringCardIsFoundWhereTheDeckRunsOutOfStep) {
  // Without the last B.4.a card every later card is read one early, and the first field that
  // cannot hold what is read there is the vehicle's title on C.1, taken as segment 15's B.6.
  const std::string err =
      ConvertMangled("ejection_seat",
                     "   15.    0.    0.   0.5         90.    8.    0.    0.   0.5         90.\n"
                     "    1.    0.    1.",
                     "    1.    0.    1.");
  EXPECT_NE(err.find("deck.ain:104:1-6: error[E0502]: card B.6 (segment 15), columns 1-6 (an "
                     "integrator convergence test): `SEAT C` is not a number"),
            std::string::npos)
      << err;
}

TEST_F(LegacyCorpus, ConvertedConstraintsCheckClean) {
  // The seated occupant's hands held to the sled: one at its point (KQTYPE 1), one at its initial
  // distance (KQTYPE 2), two D.6 cards before D.7.
  std::string deck = ReadText(kSourceRoot / "examples/legacy/seated_occupant.ain");
  const std::string counts = "     4     2     1     0     0";
  const std::size_t at = deck.find(counts);
  ASSERT_NE(at, std::string::npos);
  deck.replace(at, counts.size(), "     4     2     1     0     2");
  const std::size_t d7 = deck.find("# D.7");
  ASSERT_NE(d7, std::string::npos);
  deck.insert(d7,
              "     1    13    16    0.    0.   -6.   20.    8.  -10.\n"
              "     2    15    16    0.    0.   -6.   20.   -8.  -10.\n");
  const std::string text = ConvertCheckingClean("constrained", deck);
  EXPECT_NE(text.find("constraint constraint_1 : fixed_point(occupant.rla -> sled)"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("constraint constraint_2 : fixed_distance(occupant.lla -> sled)"),
            std::string::npos);
}

TEST_F(LegacyCorpus, NamesThatCollideTakeTheirKindAndCheckClean) {
  // The seated occupant's deck already names a plane and a function KNEE BOLSTER (and FLOOR);
  // here the floor is titled like the sled, and the lumbar joint's twist is the seat foam
  // (function 1), which the contacts also use, in other units.
  std::string deck = ReadText(kSourceRoot / "examples/legacy/seated_occupant.ain");
  const std::string floor = "   3    FLOOR";
  deck.replace(deck.find(floor), floor.size(), "   3    SLED");
  const std::string lumbar = "   60.    0.    0.   0.5         45.   40.";
  deck.replace(deck.find(lumbar), lumbar.size(), "   60.    0.    0.   0.5         45.   -1.");
  const std::string text = ConvertCheckingClean("names", deck);
  // The first use of a function takes its plain name (here the joint's, in torque units), a
  // later use in other units its kind.
  for (const char* name :
       {"  vehicle sled {", "  plane sled_plane on sled {", "  plane knee_bolster on sled {",
        "  function knee_bolster_force = table(deflection -> force)",
        "  function floor = polynomial(deflection -> force",
        "  function seat_foam = table(angle -> torque)", "twist = seat_foam\n",
        "  function seat_foam_force = table(deflection -> force)",
        "contact occupant.rf with sled_plane {\n    force = floor\n"}) {
    EXPECT_NE(text.find(name), std::string::npos) << name << "\n" << text;
  }
}

}  // namespace
}  // namespace sled::testing
