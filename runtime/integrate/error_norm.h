// The error measure and step-size controller shared by every integrator: one weighted RMS norm
// and one PI controller, so the methods differ only in how they estimate the local error.
#pragma once

#include <cstddef>
#include <span>

namespace sled::runtime {

// sqrt(mean_i (e_i / w_i)^2) with w_i = atol + rtol * max(|y0_i|, |y1_i|): the error of a step
// from y0 to y1 measured in units of the tolerance (1 = exactly the tolerance). Hairer's norm.
// NaN in the error or the states yields NaN, which every caller treats as a failed test.
// With `largest`, also the component whose weighted error |e_i / w_i| is largest (a NaN one
// counts as largest), so a failed step can say where it failed. Components from `scaled_from`
// on (quadratures, OdeSystem::QuadratureScale) are weighted with atol + rtol * max(|y0_i|,
// |y1_i|, scale).
struct LargestComponent {
  std::size_t index = 0;
  double weighted = -1.0;  // |e_i / w_i| (NaN when the component's error is NaN)
};
struct QuadratureWeight {
  std::size_t scaled_from = static_cast<std::size_t>(-1);  // none
  double scale = 0.0;
};
double WeightedRmsNorm(std::span<const double> error, std::span<const double> y0,
                       std::span<const double> y1, double relative_tolerance,
                       double absolute_tolerance, LargestComponent* largest = nullptr,
                       QuadratureWeight quadratures = {});

// The PI step-size controller of Hairer & Wanner (Solving ODEs I, §II.4, and dopri5.f): with
// err_n the weighted local error of the step just taken and k the power of h in that error
// (the lower of the two embedded orders plus one),
//   h_new = h * safety * err_n^(-alpha) * err_{n-1}^(beta),  alpha = 1/k - 0.75 beta,
// with beta = 0.2/k (0.04 for DOPRI5's k = 5, as in dopri5.f). The ratio h_new/h is kept in
// [kMinFactor, kMaxFactor], and never above 1 right after a rejection. A rejected step shrinks
// by safety * err_n^(-alpha), within [kMinFactor, 1] (dopri5.f).
class StepSizeController {
 public:
  static constexpr double kSafety = 0.9;
  static constexpr double kMinFactor = 0.2;
  static constexpr double kMaxFactor = 10.0;

  // `error_power` is k above; forgets the error history.
  void Configure(int error_power);
  // Forgets the error history (after an event or an external state change).
  void Restart();

  // Its memory of the last error, for checkpoints (runtime/run/archive.h).
  template <class Archive>
  void Serialize(Archive& archive) {
    archive.Field(previous_error_);
    archive.Field(last_rejected_);
  }

  // The next step after an accepted step of size h with weighted error `error` (<= 1).
  double Accepted(double h, double error);
  // A smaller step after a rejected step of size h with weighted error `error` (> 1, or NaN).
  double Rejected(double h, double error);

 private:
  double alpha_ = 0.17;
  double beta_ = 0.04;
  double previous_error_ = 1e-4;
  bool last_rejected_ = false;
};

}  // namespace sled::runtime
