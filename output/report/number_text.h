// Numbers as the report shows them: a few significant digits, times in milliseconds.
#pragma once

#include <optional>
#include <string>

namespace sled::report {

// `value` with `digits` significant digits ("1.234e-05", "56.7"); "–" for a non-finite value.
std::string Significant(double value, int digits = 4);
// A time in seconds shown in ms with up to 2 decimals ("62.15 ms" as "62.15").
std::string Milliseconds(double seconds);
// An optional value, or "–".
std::string Significant(const std::optional<double>& value, int digits = 4);

}  // namespace sled::report
