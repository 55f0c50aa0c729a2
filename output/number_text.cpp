#include "output/number_text.h"

#include <algorithm>
#include <array>
#include <charconv>

namespace sled::runtime {

char* WriteShortest(char* out, double value) {
  // The shortest digits in scientific notation, "-1.2345e-05": a sign, a digit, a point and the
  // other digits (up to 16), then the exponent, two or three digits. 24 characters at most.
  std::array<char, 32> text{};
  const char* const first = text.data();
  const char* const end =
      std::to_chars(text.data(), text.data() + text.size(), value, std::chars_format::scientific)
          .ptr;
  const char* e = std::find(std::max(first, end - 5), end, 'e');
  int exponent = 0;
  if (e != end) {
    for (const char* c = e + 2; c < end; ++c) exponent = 10 * exponent + (*c - '0');
    if (e[1] == '-') exponent = -exponent;
  }
  // Not finite ("nan", "-inf": no exponent), or outside fmt's fixed range: as it is.
  if (e == end || exponent < -4 || exponent >= 16) return std::copy(first, end, out);
  // Fixed notation from the same digits, the decimal point moved by the exponent.
  const char* lead = first;
  if (*lead == '-') *out++ = *lead++;
  const char* rest = lead + 1 < e ? lead + 2 : e;  // the digits after the point
  const auto after = static_cast<int>(e - rest);
  if (exponent < 0) {  // 0.000ddd
    *out++ = '0';
    *out++ = '.';
    out = std::fill_n(out, -exponent - 1, '0');
    *out++ = *lead;
    return std::copy(rest, e, out);
  }
  *out++ = *lead;
  if (after <= exponent) {  // ddd000: a whole number
    out = std::copy(rest, e, out);
    return std::fill_n(out, exponent - after, '0');
  }
  out = std::copy(rest, rest + exponent, out);  // ddd.ddd
  *out++ = '.';
  return std::copy(rest + exponent, e, out);
}

void AppendShortest(std::string& out, double value) {
  std::array<char, kShortestMaxChars> text{};
  out.append(text.data(), WriteShortest(text.data(), value));
}

}  // namespace sled::runtime
