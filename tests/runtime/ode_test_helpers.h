// Small helpers the integrator tests share.
#pragma once

#include <algorithm>
#include <cmath>
#include <span>

#include "runtime/integrate/ode.h"

namespace sled::runtime::testing {

// Relative and absolute tolerance both `tol`.
inline IntegratorOptions Tolerance(double tol) {
  IntegratorOptions options;
  options.relative_tolerance = tol;
  options.absolute_tolerance = tol;
  return options;
}

inline double MaxAbsDifference(std::span<const double> a, std::span<const double> b) {
  double m = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) m = std::max(m, std::abs(a[i] - b[i]));
  return m;
}

}  // namespace sled::runtime::testing
