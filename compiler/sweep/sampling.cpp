#include "compiler/sweep/sampling.h"

#include <array>
#include <stdexcept>

namespace sled::compiler {
namespace {

// Joe and Kuo's direction numbers for dimensions 2 to 21: the degree s of the primitive
// polynomial, its coefficients a (the inner bits), and the initial odd numbers m_1..m_s.
// Dimension 1 is the van der Corput sequence (every m = 1).
struct SobolDirection {
  int degree;
  unsigned coefficients;
  std::array<unsigned, 7> initial;
};
constexpr std::array<SobolDirection, kMaxSobolDimensions - 1> kDirections = {{
    {1, 0, {1}},
    {2, 1, {1, 3}},
    {3, 1, {1, 3, 1}},
    {3, 2, {1, 1, 1}},
    {4, 1, {1, 1, 3, 3}},
    {4, 4, {1, 3, 5, 13}},
    {5, 2, {1, 1, 5, 5, 17}},
    {5, 4, {1, 1, 5, 5, 5}},
    {5, 7, {1, 1, 7, 11, 19}},
    {5, 11, {1, 1, 5, 1, 1}},
    {5, 13, {1, 1, 1, 3, 11}},
    {5, 14, {1, 3, 5, 5, 31}},
    {6, 1, {1, 3, 3, 9, 7, 49}},
    {6, 13, {1, 1, 1, 15, 21, 21}},
    {6, 16, {1, 3, 1, 13, 27, 49}},
    {6, 19, {1, 1, 1, 15, 7, 5}},
    {6, 22, {1, 3, 1, 15, 13, 25}},
    {6, 25, {1, 1, 5, 5, 19, 61}},
    {7, 1, {1, 3, 7, 11, 23, 15, 103}},
    {7, 4, {1, 3, 7, 13, 13, 15, 69}},
}};

constexpr int kBits = 32;

// The direction integers v_1..v_32 of one dimension (0-based), scaled to 32 bits.
std::array<std::uint32_t, kBits + 1> DirectionIntegers(int dimension) {
  std::array<std::uint32_t, kBits + 1> v{};
  if (dimension == 0) {
    for (int k = 1; k <= kBits; ++k) v[k] = std::uint32_t{1} << (kBits - k);
    return v;
  }
  const SobolDirection& d = kDirections.at(static_cast<std::size_t>(dimension - 1));
  const int s = d.degree;
  for (int k = 1; k <= s && k <= kBits; ++k) {
    v[k] = d.initial[static_cast<std::size_t>(k - 1)] << (kBits - k);
  }
  for (int k = s + 1; k <= kBits; ++k) {
    v[k] = v[k - s] ^ (v[k - s] >> s);
    for (int j = 1; j < s; ++j) {
      if ((d.coefficients >> (s - 1 - j)) & 1u) v[k] ^= v[k - j];
    }
  }
  return v;
}

}  // namespace

std::uint64_t SplitMix64::Next() {
  std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

double SplitMix64::Uniform() { return static_cast<double>(Next() >> 11) * 0x1.0p-53; }

std::uint64_t SplitMix64::Below(std::uint64_t bound) {
  // Rejection of the top partial block keeps every value equally likely.
  const std::uint64_t limit = ~std::uint64_t{0} - (~std::uint64_t{0} % bound);
  std::uint64_t x = Next();
  while (x >= limit) x = Next();
  return x % bound;
}

std::vector<std::vector<double>> LatinHypercube(int n, int d, std::uint64_t seed) {
  if (n < 1 || d < 1) throw std::invalid_argument("LatinHypercube: n and d must be positive");
  SplitMix64 random(seed);
  std::vector<std::vector<double>> points(static_cast<std::size_t>(n),
                                          std::vector<double>(static_cast<std::size_t>(d)));
  std::vector<int> strata(static_cast<std::size_t>(n));
  for (int j = 0; j < d; ++j) {
    for (int i = 0; i < n; ++i) strata[static_cast<std::size_t>(i)] = i;
    for (int i = n - 1; i > 0; --i) {  // Fisher–Yates
      const auto k = random.Below(static_cast<std::uint64_t>(i) + 1);
      std::swap(strata[static_cast<std::size_t>(i)], strata[k]);
    }
    for (int i = 0; i < n; ++i) {
      const double u = (strata[static_cast<std::size_t>(i)] + random.Uniform()) / n;
      points[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] =
          u < 1.0 ? u : 0x1.fffffffffffffp-1;
    }
  }
  return points;
}

std::vector<std::vector<double>> Sobol(int n, int d, std::uint64_t seed) {
  if (n < 1 || d < 1 || d > kMaxSobolDimensions) {
    throw std::invalid_argument("Sobol: n must be positive and d between 1 and 21");
  }
  std::vector<std::array<std::uint32_t, kBits + 1>> directions;
  std::vector<std::uint32_t> shift(static_cast<std::size_t>(d), 0);
  SplitMix64 random(seed);
  for (int j = 0; j < d; ++j) {
    directions.push_back(DirectionIntegers(j));
    if (seed != 0)
      shift[static_cast<std::size_t>(j)] = static_cast<std::uint32_t>(random.Next() >> 32);
  }
  std::vector<std::vector<double>> points(static_cast<std::size_t>(n),
                                          std::vector<double>(static_cast<std::size_t>(d)));
  std::vector<std::uint32_t> x(static_cast<std::size_t>(d), 0);
  for (int i = 0; i < n; ++i) {
    if (i > 0) {
      // Gray-code order: flip the direction of the lowest zero bit of i - 1.
      int c = 1;
      for (unsigned value = static_cast<unsigned>(i - 1); value & 1u; value >>= 1) ++c;
      for (int j = 0; j < d; ++j)
        x[static_cast<std::size_t>(j)] ^=
            directions[static_cast<std::size_t>(j)][static_cast<std::size_t>(c)];
    }
    for (int j = 0; j < d; ++j) {
      points[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] =
          static_cast<double>(x[static_cast<std::size_t>(j)] ^ shift[static_cast<std::size_t>(j)]) *
          0x1.0p-32;
    }
  }
  return points;
}

}  // namespace sled::compiler
