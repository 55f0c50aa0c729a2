#include "runtime/integrate/dormand_prince.h"

#include <algorithm>
#include <cmath>

#include "runtime/integrate/error_norm.h"
#include "runtime/run/archive.h"

namespace sled::runtime {
namespace {

// Dormand & Prince, "A family of embedded Runge-Kutta formulae", J. Comput. Appl. Math. 6
// (1980) 19-26; coefficients, error weights and dense output as in Hairer's dopri5.f.
constexpr double kC2 = 1.0 / 5.0, kC3 = 3.0 / 10.0, kC4 = 4.0 / 5.0, kC5 = 8.0 / 9.0;
constexpr double kA21 = 1.0 / 5.0;
constexpr double kA31 = 3.0 / 40.0, kA32 = 9.0 / 40.0;
constexpr double kA41 = 44.0 / 45.0, kA42 = -56.0 / 15.0, kA43 = 32.0 / 9.0;
constexpr double kA51 = 19372.0 / 6561.0, kA52 = -25360.0 / 2187.0, kA53 = 64448.0 / 6561.0,
                 kA54 = -212.0 / 729.0;
constexpr double kA61 = 9017.0 / 3168.0, kA62 = -355.0 / 33.0, kA63 = 46732.0 / 5247.0,
                 kA64 = 49.0 / 176.0, kA65 = -5103.0 / 18656.0;
// Fifth-order weights (also row 7 of A: the FSAL stage).
constexpr double kB1 = 35.0 / 384.0, kB3 = 500.0 / 1113.0, kB4 = 125.0 / 192.0,
                 kB5 = -2187.0 / 6784.0, kB6 = 11.0 / 84.0;
// Fifth- minus fourth-order weights: the local error estimate.
constexpr double kE1 = 71.0 / 57600.0, kE3 = -71.0 / 16695.0, kE4 = 71.0 / 1920.0,
                 kE5 = -17253.0 / 339200.0, kE6 = 22.0 / 525.0, kE7 = -1.0 / 40.0;
// Dense output (Shampine's fourth-order continuous extension, as in dopri5.f CONTD5).
constexpr double kD1 = -12715105075.0 / 11282082432.0, kD3 = 87487479700.0 / 32700410799.0,
                 kD4 = -10690763975.0 / 1880347072.0, kD5 = 701980252875.0 / 199316789632.0,
                 kD6 = -1453857185.0 / 822651844.0, kD7 = 69997945.0 / 29380423.0;

}  // namespace

void DormandPrince::ResizeWorkspace(std::size_t size) {
  for (auto* v : {&k2_, &k3_, &k4_, &k5_, &k6_, &stage_, &error_, &r1_, &r2_, &r3_, &r4_, &r5_}) {
    v->assign(size, 0.0);
  }
  controlled_ = std::min(system().ControlledSize(), size);
  RestartHistory();
}

void DormandPrince::RestartHistory() {
  stiffness_ratio_ = 0.0;
  stiff_steps_ = 0;
  nonstiff_steps_ = 0;
}

void DormandPrince::StepAccepted() {
  if (stiffness_ratio_ > kStiffRatio) {
    nonstiff_steps_ = 0;
    ++stiff_steps_;
  } else if (++nonstiff_steps_ >= kNonStiffSteps) {
    stiff_steps_ = 0;
  }
}

bool DormandPrince::TryStep(double h, double* error) {
  const std::size_t n = y_.size();
  const std::vector<double>& k1 = f0_;
  std::vector<double>& k7 = f1_;

  for (std::size_t i = 0; i < n; ++i) stage_[i] = y_[i] + h * kA21 * k1[i];
  if (!Evaluate(t_ + kC2 * h, stage_, k2_)) return false;
  for (std::size_t i = 0; i < n; ++i) stage_[i] = y_[i] + h * (kA31 * k1[i] + kA32 * k2_[i]);
  if (!Evaluate(t_ + kC3 * h, stage_, k3_)) return false;
  for (std::size_t i = 0; i < n; ++i) {
    stage_[i] = y_[i] + h * (kA41 * k1[i] + kA42 * k2_[i] + kA43 * k3_[i]);
  }
  if (!Evaluate(t_ + kC4 * h, stage_, k4_)) return false;
  for (std::size_t i = 0; i < n; ++i) {
    stage_[i] = y_[i] + h * (kA51 * k1[i] + kA52 * k2_[i] + kA53 * k3_[i] + kA54 * k4_[i]);
  }
  if (!Evaluate(t_ + kC5 * h, stage_, k5_)) return false;
  for (std::size_t i = 0; i < n; ++i) {
    stage_[i] =
        y_[i] + h * (kA61 * k1[i] + kA62 * k2_[i] + kA63 * k3_[i] + kA64 * k4_[i] + kA65 * k5_[i]);
  }
  if (!Evaluate(t_ + h, stage_, k6_)) return false;
  for (std::size_t i = 0; i < n; ++i) {
    y1_[i] = y_[i] + h * (kB1 * k1[i] + kB3 * k3_[i] + kB4 * k4_[i] + kB5 * k5_[i] + kB6 * k6_[i]);
  }
  if (!Evaluate(t_ + h, y1_, k7)) return false;
  // Stage 6 (still in stage_) and y1 share the time t + h: their derivatives' difference over
  // their distance estimates |lambda| along it.
  double numerator = 0.0, denominator = 0.0;
  for (std::size_t i = 0; i < controlled_; ++i) {
    numerator += (k7[i] - k6_[i]) * (k7[i] - k6_[i]);
    denominator += (y1_[i] - stage_[i]) * (y1_[i] - stage_[i]);
  }
  stiffness_ratio_ = denominator > 0.0 ? h * std::sqrt(numerator / denominator) : 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    error_[i] =
        h * (kE1 * k1[i] + kE3 * k3_[i] + kE4 * k4_[i] + kE5 * k5_[i] + kE6 * k6_[i] + kE7 * k7[i]);
  }
  *error = ErrorNorm(error_);
  return true;
}

void DormandPrince::PrepareDenseOutput() {
  // dopri5.f's CONTD5 form, stored once per accepted step: the rows between step ends and the
  // event location read it.
  const double h = step_;
  for (std::size_t i = 0; i < y_.size(); ++i) {
    const double r2 = y1_[i] - y_[i];
    const double r3 = h * f0_[i] - r2;
    r1_[i] = y_[i];
    r2_[i] = r2;
    r3_[i] = r3;
    r4_[i] = r2 - h * f1_[i] - r3;
    r5_[i] = h * (kD1 * f0_[i] + kD3 * k3_[i] + kD4 * k4_[i] + kD5 * k5_[i] + kD6 * k6_[i] +
                  kD7 * f1_[i]);
  }
}

void DormandPrince::SerializeHistory(Archive& archive) {
  for (auto* r : {&r1_, &r2_, &r3_, &r4_, &r5_}) archive.Field(*r);
}

void DormandPrince::DenseOutput(double theta, std::span<double> y) const {
  const double s = theta;
  const double s1 = 1.0 - s;
  for (std::size_t i = 0; i < y.size(); ++i) {
    y[i] = r1_[i] + s * (r2_[i] + s1 * (r3_[i] + s * (r4_[i] + s1 * r5_[i])));
  }
}

}  // namespace sled::runtime
