// What every deck of examples/legacy must satisfy once converted: the scenario checks with no
// diagnostic, `sled fmt --check` leaves it unchanged, and its run gives the same time histories,
// bit for bit, as the hand-written twin of the same scene (the column names differ with the
// names; the numbers may not). Shared by the round-trip and corpus tests.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "tests/compiler/sled_process.h"

namespace sled::testing {

class LegacyTwinTest : public SledProcessTest {
 protected:
  // `converted`: the scenario `sled convert` wrote; `twin`: its hand-written .sled (from the
  // repository root); `rows`: the output rows the deck's A.4 card asks for.
  void ExpectMatchesTwin(const fs::path& converted, const std::string& twin, int rows) {
    const SledResult check = Sled({"check", converted.string()});
    EXPECT_EQ(check.exit_code, 0) << check.err;
    EXPECT_EQ(check.err, "") << "the converted scenario has diagnostics";

    const SledResult format = Sled({"fmt", "--check", converted.string()});
    EXPECT_EQ(format.exit_code, 0) << format.out << format.err;

    const SledResult run_converted =
        Sled({"run", converted.string(), "-o", (temp() / "converted").string()});
    ASSERT_EQ(run_converted.exit_code, 0) << run_converted.err;
    const SledResult run_twin = Sled({"run", twin, "-o", (temp() / "twin").string()});
    ASSERT_EQ(run_twin.exit_code, 0) << run_twin.err;
    const std::string a = ReadText(temp() / "converted" / "timeseries.csv");
    const std::string b = ReadText(temp() / "twin" / "timeseries.csv");
    ASSERT_FALSE(ValuesOf(a).empty());
    EXPECT_TRUE(ValuesOf(a) == ValuesOf(b)) << "the converted deck and its twin differ";
    EXPECT_EQ(std::count(a.begin(), a.end(), '\n'), rows + 1);  // the header and the rows
  }

  // How often `what` occurs in `text`.
  static std::size_t Count(const std::string& text, const std::string& what) {
    std::size_t count = 0;
    for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) {
      ++count;
    }
    return count;
  }

 private:
  // The rows of a CSV file without its header line.
  static std::string ValuesOf(const std::string& csv) {
    const std::size_t end = csv.find('\n');
    return end == std::string::npos ? std::string() : csv.substr(end + 1);
  }
};

}  // namespace sled::testing
