// Numbers as the CSV writer spells them (output/number_text.h): the text fmt's "{}" gives, which
// the files had before, and the same double when read back, for edge values and for random bit
// patterns and magnitudes.
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "output/number_text.h"

namespace sled::runtime {
namespace {

std::string Shortest(double value) {
  std::string text;
  AppendShortest(text, value);
  return text;
}

void ExpectAsFmtAndExact(double value) {
  const std::string text = Shortest(value);
  EXPECT_EQ(text, fmt::format("{}", value));
  if (!std::isfinite(value)) return;
  double back = 0.0;
  std::from_chars(text.data(), text.data() + text.size(), back);
  EXPECT_EQ(std::bit_cast<std::uint64_t>(back), std::bit_cast<std::uint64_t>(value)) << text;
}

TEST(NumberText, EdgeValues) {
  const double max = std::numeric_limits<double>::max();
  for (const double value : {0.0,
                             -0.0,
                             1.0,
                             -1.0,
                             0.1,
                             1e-4,
                             1.2345e-4,
                             9.9999e-5,
                             1e-5,
                             100.0,
                             1e15,
                             1e16,
                             9999999999999998.0,
                             1.2345678901234567e16,
                             123456789012345.6,
                             5e-324,
                             max,
                             -max,
                             std::numeric_limits<double>::infinity(),
                             -std::numeric_limits<double>::infinity(),
                             std::numeric_limits<double>::quiet_NaN()}) {
    ExpectAsFmtAndExact(value);
  }
  EXPECT_EQ(Shortest(0.00012), "0.00012");
  EXPECT_EQ(Shortest(1.5e-5), "1.5e-05");
  EXPECT_EQ(Shortest(250.0), "250");
  EXPECT_EQ(Shortest(-3.25), "-3.25");
}

TEST(NumberText, RandomValues) {
  std::mt19937_64 random(14);
  std::uniform_real_distribution<double> decades(-8.0, 18.0);
  for (int k = 0; k < 100000; ++k) {
    const auto value = std::bit_cast<double>(static_cast<std::uint64_t>(random()));
    ExpectAsFmtAndExact(value);
    const double magnitude = std::pow(10.0, decades(random));
    ExpectAsFmtAndExact(magnitude);
    ExpectAsFmtAndExact(-std::round(magnitude));
  }
}

}  // namespace
}  // namespace sled::runtime
