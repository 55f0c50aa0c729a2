// The legacy corpus end to end through the `sled` program: each deck of examples/legacy converts
// with `sled convert`, the result checks with no error and no warning, `sled fmt --check` leaves
// it unchanged, and running it gives the same time histories, bit for bit, as the hand-written
// twin of the same scene (the column names differ with the names; the numbers may not).
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "tests/compiler/legacy_twin.h"

namespace sled::testing {
namespace {

class LegacyRoundTrip : public LegacyTwinTest {};

TEST_F(LegacyRoundTrip, SeatedOccupantDeckMatchesItsTwin) {
  const fs::path converted = temp() / "seated_occupant.sled";
  const SledResult convert =
      Sled({"convert", "examples/legacy/seated_occupant.ain", "-o", converted.string()});
  ASSERT_EQ(convert.exit_code, 0) << convert.err;
  EXPECT_NE(convert.err.find("warning[W0501]"), std::string::npos) << convert.err;
  // The free bag's differences from ATB's: the cylinder's table, the unfolding (measured), the
  // reaction panel and the bag's rotation.
  EXPECT_EQ(Count(convert.err, "warning[W0504]"), 4u) << convert.err;
  EXPECT_NE(convert.err.find("the reference temperature 432.252 K"), std::string::npos)
      << convert.err;
  EXPECT_NE(convert.err.find("85 rows every 0.0005 s up to 0.04164 s"), std::string::npos)
      << convert.err;

  // A.4: 300 output steps of 0.5 ms, so 301 rows.
  ExpectMatchesTwin(converted, "examples/legacy/seated_occupant.sled", 301);
}

TEST_F(LegacyRoundTrip, MangledDeckFailsWithALocatedDiagnostic) {
  std::string deck = ReadText(kSourceRoot / "examples/legacy/seated_occupant.ain");
  const std::size_t at = deck.find("LT      26.6");
  ASSERT_NE(at, std::string::npos);
  deck.replace(at + 8, 4, "26x6");
  const fs::path path = temp() / "deck.ain";
  WriteText(path, deck);
  const SledResult convert = Sled({"convert", path.string(), "--diagnostics=compact"});
  EXPECT_EQ(convert.exit_code, 1);
  EXPECT_NE(convert.err.find(":7-12: error[E0502]: card B.2.a (segment 1), columns 7-12"),
            std::string::npos)
      << convert.err;
  EXPECT_EQ(convert.out, "");
}

TEST_F(LegacyRoundTrip, TheDeprecatedAirbagOptionOnlyWarns) {
  const SledResult plain = Sled({"convert", "examples/legacy/seated_occupant.ain"});
  const SledResult with_option =
      Sled({"convert", "examples/legacy/seated_occupant.ain", "--approximate-airbags"});
  ASSERT_EQ(plain.exit_code, 0) << plain.err;
  EXPECT_EQ(with_option.exit_code, 0);
  EXPECT_EQ(with_option.out, plain.out);
  EXPECT_NE(plain.out.find("model = atb_free"), std::string::npos);
  EXPECT_NE(with_option.err.find("--approximate-airbags is deprecated and does nothing"),
            std::string::npos)
      << with_option.err;
}

TEST_F(LegacyRoundTrip, LinDeckConvertsByItsExtensionOrByDeckOption) {
  const SledResult from_ain = Sled({"convert", "examples/legacy/seated_occupant.ain"});
  const SledResult from_lin = Sled({"convert", "examples/legacy/seated_occupant.lin"});
  ASSERT_EQ(from_lin.exit_code, 0) << from_lin.err;
  EXPECT_EQ(from_lin.out, from_ain.out);
  // Another extension needs --deck; --blank-zero is for fixed columns only.
  const fs::path other = temp() / "seated_occupant.dat";
  WriteText(other, ReadText(kSourceRoot / "examples/legacy/seated_occupant.lin"));
  EXPECT_EQ(Sled({"convert", other.string()}).exit_code, 2);
  const SledResult forced = Sled({"convert", other.string(), "--deck=lin"});
  EXPECT_EQ(forced.exit_code, 0) << forced.err;
  EXPECT_EQ(forced.out, from_ain.out);
  EXPECT_EQ(Sled({"convert", other.string(), "--deck=lin", "--blank-zero"}).exit_code, 2);
}

}  // namespace
}  // namespace sled::testing
