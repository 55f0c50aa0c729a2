#include "compiler/check/displacement_history.h"

namespace sled::compiler {

AccelerationHistory AccelerationFromDisplacement(
    const std::vector<std::array<double, 2>>& samples) {
  AccelerationHistory history;
  const std::size_t n = samples.size();
  if (n < 2) return history;
  // Second derivatives m_i at the samples, m_0 = m_{n-1} = 0 (natural ends), from the
  // continuity of the first derivative: h_{i-1} m_{i-1} + 2 (h_{i-1} + h_i) m_i + h_i m_{i+1}
  // = 6 (slope_i - slope_{i-1}); a tridiagonal system, solved by the Thomas algorithm (it is
  // diagonally dominant, so no pivoting is needed).
  std::vector<double> m(n, 0.0);
  if (n > 2) {
    std::vector<double> diagonal(n, 0.0), upper(n, 0.0), rhs(n, 0.0);
    auto h = [&](std::size_t i) { return samples[i + 1][0] - samples[i][0]; };
    auto slope = [&](std::size_t i) { return (samples[i + 1][1] - samples[i][1]) / h(i); };
    for (std::size_t i = 1; i + 1 < n; ++i) {
      const double lower = h(i - 1);
      diagonal[i] = 2.0 * (h(i - 1) + h(i));
      upper[i] = h(i);
      rhs[i] = 6.0 * (slope(i) - slope(i - 1));
      if (i > 1) {
        const double factor = lower / diagonal[i - 1];
        diagonal[i] -= factor * upper[i - 1];
        rhs[i] -= factor * rhs[i - 1];
      }
    }
    for (std::size_t i = n - 2; i >= 1; --i) {
      m[i] = (rhs[i] - (i + 2 < n ? upper[i] * m[i + 1] : 0.0)) / diagonal[i];
    }
  }
  for (std::size_t i = 0; i < n; ++i) history.table.push_back({samples[i][0], m[i]});
  const double h0 = samples[1][0] - samples[0][0];
  history.position = samples[0][1];
  history.velocity = (samples[1][1] - samples[0][1]) / h0 - h0 * (2.0 * m[0] + m[1]) / 6.0;
  return history;
}

}  // namespace sled::compiler
