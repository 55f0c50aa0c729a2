// Numbers as text for the files a run writes: the shortest text that reads back to the same
// double, spelled exactly as fmt's "{}" spells it (fixed notation for decimal exponents -4 to 15,
// otherwise scientific, "1e-05", "1.5e+16"; "nan", "inf"), from one std::to_chars call and a
// move of the decimal point: no allocation and no format string per value, which the CSV writer
// needs hundreds of thousands of times.
#pragma once

#include <cstddef>
#include <string>

namespace sled::runtime {

// The most characters WriteShortest writes ("-0.00012345678901234567", "-1.2345678901234567e-308").
inline constexpr std::size_t kShortestMaxChars = 32;

// Writes the text at `out` (room for kShortestMaxChars) and returns its end.
char* WriteShortest(char* out, double value);

void AppendShortest(std::string& out, double value);

}  // namespace sled::runtime
