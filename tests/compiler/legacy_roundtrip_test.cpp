// The legacy corpus end to end through the `sled` program: each deck of examples/legacy converts
// with `sled convert`, the result checks with no error and no warning, `sled fmt --check` leaves
// it unchanged, and running it gives the same time histories, bit for bit, as the hand-written
// twin of the same scene (the column names differ with the names; the numbers may not).
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "tests/compiler/sled_process.h"

namespace sled::testing {
namespace {

// The rows of a CSV file without its header line.
std::string ValuesOf(const std::string& csv) {
  const std::size_t end = csv.find('\n');
  return end == std::string::npos ? std::string() : csv.substr(end + 1);
}

class LegacyRoundTrip : public SledProcessTest {};

TEST_F(LegacyRoundTrip, SeatedOccupantDeckMatchesItsTwin) {
  const fs::path converted = temp() / "seated_occupant.sled";
  const SledResult convert = Sled({"convert", "examples/legacy/seated_occupant.ain", "-o",
                                   converted.string(), "--approximate-airbags"});
  ASSERT_EQ(convert.exit_code, 0) << convert.err;
  EXPECT_NE(convert.err.find("warning[W0501]"), std::string::npos) << convert.err;
  // The airbag's approximations: the cylinder's table, the gas law, the vent and the free bag
  // held fixed (with its reaction panel).
  std::size_t approximations = 0;
  for (std::size_t at = convert.err.find("warning[W0504]"); at != std::string::npos;
       at = convert.err.find("warning[W0504]", at + 1)) {
    ++approximations;
  }
  EXPECT_EQ(approximations, 5u) << convert.err;
  EXPECT_NE(convert.err.find("85 rows every 0.0005 s up to 0.04164 s"), std::string::npos)
      << convert.err;

  const SledResult check = Sled({"check", converted.string()});
  EXPECT_EQ(check.exit_code, 0) << check.err;
  EXPECT_EQ(check.err, "") << "the converted scenario has diagnostics";

  const SledResult format = Sled({"fmt", "--check", converted.string()});
  EXPECT_EQ(format.exit_code, 0) << format.out << format.err;

  const SledResult run_converted = Sled({"run", converted.string(), "-o", (temp() / "a").string()});
  ASSERT_EQ(run_converted.exit_code, 0) << run_converted.err;
  const SledResult run_twin =
      Sled({"run", "examples/legacy/seated_occupant.sled", "-o", (temp() / "b").string()});
  ASSERT_EQ(run_twin.exit_code, 0) << run_twin.err;
  const std::string a = ReadText(temp() / "a" / "timeseries.csv");
  const std::string b = ReadText(temp() / "b" / "timeseries.csv");
  ASSERT_FALSE(ValuesOf(a).empty());
  EXPECT_TRUE(ValuesOf(a) == ValuesOf(b)) << "the converted deck and its twin differ";
  // A.4: 300 output steps of 0.5 ms, so 301 rows after the header.
  EXPECT_EQ(std::count(a.begin(), a.end(), '\n'), 302);
}

TEST_F(LegacyRoundTrip, MangledDeckFailsWithALocatedDiagnostic) {
  std::string deck = ReadText(kSourceRoot / "examples/legacy/seated_occupant.ain");
  const std::size_t at = deck.find("LT      26.6");
  ASSERT_NE(at, std::string::npos);
  deck.replace(at + 8, 4, "26x6");
  const fs::path path = temp() / "deck.ain";
  WriteText(path, deck);
  const SledResult convert =
      Sled({"convert", path.string(), "--diagnostics=compact", "--approximate-airbags"});
  EXPECT_EQ(convert.exit_code, 1);
  EXPECT_NE(convert.err.find(":7-12: error[E0502]: card B.2.a (segment 1), columns 7-12"),
            std::string::npos)
      << convert.err;
  EXPECT_EQ(convert.out, "");
}

TEST_F(LegacyRoundTrip, WithoutTheOptionAnAirbagIsRefusedAtNbag) {
  const SledResult convert =
      Sled({"convert", "examples/legacy/seated_occupant.ain", "--diagnostics=compact"});
  EXPECT_EQ(convert.exit_code, 1);
  EXPECT_EQ(convert.out, "");
  EXPECT_NE(convert.err.find("seated_occupant.ain:103:13-18: error[E0507]: card D.1.a, columns "
                             "13-18: NBAG is 1: ATB's airbags are free rigid bodies"),
            std::string::npos)
      << convert.err;
  EXPECT_NE(convert.err.find("--approximate-airbags"), std::string::npos);
  EXPECT_EQ(convert.err.find("W0504"), std::string::npos) << convert.err;
}

TEST_F(LegacyRoundTrip, LinDeckConvertsByItsExtensionOrByDeckOption) {
  const SledResult from_ain =
      Sled({"convert", "examples/legacy/seated_occupant.ain", "--approximate-airbags"});
  const SledResult from_lin =
      Sled({"convert", "examples/legacy/seated_occupant.lin", "--approximate-airbags"});
  ASSERT_EQ(from_lin.exit_code, 0) << from_lin.err;
  EXPECT_EQ(from_lin.out, from_ain.out);
  // Another extension needs --deck; --blank-zero is for fixed columns only.
  const fs::path other = temp() / "seated_occupant.dat";
  WriteText(other, ReadText(kSourceRoot / "examples/legacy/seated_occupant.lin"));
  EXPECT_EQ(Sled({"convert", other.string()}).exit_code, 2);
  const SledResult forced =
      Sled({"convert", other.string(), "--deck=lin", "--approximate-airbags"});
  EXPECT_EQ(forced.exit_code, 0) << forced.err;
  EXPECT_EQ(forced.out, from_ain.out);
  EXPECT_EQ(Sled({"convert", other.string(), "--deck=lin", "--blank-zero", "--approximate-airbags"})
                .exit_code,
            2);
}

}  // namespace
}  // namespace sled::testing
