// Space-filling samples of the unit hypercube [0, 1)^d for sweep designs. Both are reproducible
// from their seed on every platform: the random numbers come from SplitMix64, whose output the
// algorithm fixes (the standard library's distributions are implementation-defined).
#pragma once

#include <cstdint>
#include <vector>

namespace sled::compiler {

// SplitMix64 (Steele, Lea and Flood 2014): a 64-bit state advanced by a constant, mixed.
class SplitMix64 {
 public:
  explicit SplitMix64(std::uint64_t seed) : state_(seed) {}
  std::uint64_t Next();
  double Uniform();                          // [0, 1), 53 random bits
  std::uint64_t Below(std::uint64_t bound);  // [0, bound), unbiased; bound > 0

 private:
  std::uint64_t state_;
};

// A Latin hypercube of n points in d dimensions: in each dimension the n points fall one in each
// of the n equal strata, at a uniform random place in it; the strata are paired across
// dimensions by independent random permutations. points[i][j].
std::vector<std::vector<double>> LatinHypercube(int n, int d, std::uint64_t seed);

// The most dimensions Sobol supports (the direction numbers sled carries).
inline constexpr int kMaxSobolDimensions = 21;

// The first n points of the Sobol sequence in d <= kMaxSobolDimensions dimensions, with the
// direction numbers of Joe and Kuo (2008, new-joe-kuo-6.21201), in Gray-code order (the first
// point is the origin). A seed other than 0 applies a random digital shift (each coordinate's
// bits XORed with random bits drawn from the seed), which keeps the net's stratification;
// seed 0 gives the plain sequence.
std::vector<std::vector<double>> Sobol(int n, int d, std::uint64_t seed);

}  // namespace sled::compiler
