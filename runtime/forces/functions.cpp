#include "runtime/forces/functions.h"

#include <algorithm>
#include <cmath>

namespace sled::runtime {

namespace {

// The first point of the table segment that holds x (the end segments reach past the table).
std::size_t SegmentOf(const double* xs, std::size_t count, double x) {
  const double* upper = std::upper_bound(xs + 1, xs + count - 1, x);
  return static_cast<std::size_t>(upper - xs) - 1;
}

}  // namespace

double EvaluateFunction(const FunctionTable& functions, std::int32_t id, double x) {
  if (id < 0) return 0.0;
  const auto f = static_cast<std::size_t>(id);
  const auto first = static_cast<std::size_t>(functions.first[f]);
  const auto count = static_cast<std::size_t>(functions.count[f]);
  switch (functions.kind[f]) {
    case FunctionTable::Kind::kConstant:
      return functions.constant[f];
    case FunctionTable::Kind::kPolynomial: {
      double value = 0.0;
      for (std::size_t k = count; k-- > 0;) value = value * x + functions.coefficients[first + k];
      return value;
    }
    case FunctionTable::Kind::kTable: {
      const double* xs = functions.points_x.data() + first;
      const double* ys = functions.points_y.data() + first;
      if (count == 1) return ys[0];
      const std::size_t i = SegmentOf(xs, count, x);
      const double slope = (ys[i + 1] - ys[i]) / (xs[i + 1] - xs[i]);
      return ys[i] + slope * (x - xs[i]);
    }
  }
  return 0.0;
}

double FunctionSlope(const FunctionTable& functions, std::int32_t id, double x) {
  if (id < 0) return 0.0;
  const auto f = static_cast<std::size_t>(id);
  const auto first = static_cast<std::size_t>(functions.first[f]);
  const auto count = static_cast<std::size_t>(functions.count[f]);
  switch (functions.kind[f]) {
    case FunctionTable::Kind::kConstant:
      return 0.0;
    case FunctionTable::Kind::kPolynomial: {
      double value = 0.0;
      for (std::size_t k = count; k-- > 1;) {
        value = value * x + static_cast<double>(k) * functions.coefficients[first + k];
      }
      return value;
    }
    case FunctionTable::Kind::kTable: {
      const double* xs = functions.points_x.data() + first;
      const double* ys = functions.points_y.data() + first;
      if (count == 1) return 0.0;
      const std::size_t i = SegmentOf(xs, count, x);
      return (ys[i + 1] - ys[i]) / (xs[i + 1] - xs[i]);
    }
  }
  return 0.0;
}

double IntegrateFunction(const FunctionTable& functions, std::int32_t id, double x) {
  if (id < 0) return 0.0;
  const auto f = static_cast<std::size_t>(id);
  const auto first = static_cast<std::size_t>(functions.first[f]);
  const auto count = static_cast<std::size_t>(functions.count[f]);
  switch (functions.kind[f]) {
    case FunctionTable::Kind::kConstant:
      return functions.constant[f] * x;
    case FunctionTable::Kind::kPolynomial: {
      double value = 0.0;
      for (std::size_t k = count; k-- > 0;) {
        value = value * x + functions.coefficients[first + k] / static_cast<double>(k + 1);
      }
      return value * x;
    }
    case FunctionTable::Kind::kTable: {
      // Linear between the rows (and beyond the ends): the trapezoid rule on each piece between
      // the rows that lie between 0 and x is exact.
      const double low = std::min(0.0, x), high = std::max(0.0, x);
      double sum = 0.0, left = low;
      const double* xs = functions.points_x.data() + first;
      for (std::size_t k = 0; k <= count; ++k) {
        const double right = k < count ? std::min(std::max(xs[k], low), high) : high;
        if (right > left) {
          sum += 0.5 *
                 (EvaluateFunction(functions, id, left) + EvaluateFunction(functions, id, right)) *
                 (right - left);
          left = right;
        }
      }
      return x >= 0 ? sum : -sum;
    }
  }
  return 0.0;
}

bool CoversNegative(const FunctionTable& functions, std::int32_t id) {
  if (id < 0) return false;
  const auto f = static_cast<std::size_t>(id);
  return functions.kind[f] == FunctionTable::Kind::kTable &&
         functions.points_x[static_cast<std::size_t>(functions.first[f])] < 0;
}

double RestoringTorque(const FunctionTable& functions, std::int32_t id, double x) {
  if (id < 0) return 0.0;
  if (CoversNegative(functions, id)) return -EvaluateFunction(functions, id, x);
  const double magnitude = EvaluateFunction(functions, id, std::abs(x));
  return x >= 0 ? -magnitude : magnitude;
}

}  // namespace sled::runtime
