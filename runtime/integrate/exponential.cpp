#include "runtime/integrate/exponential.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "runtime/integrate/error_norm.h"
#include "runtime/run/archive.h"

namespace sled::runtime {
namespace {

constexpr std::size_t kGroupSize = 3;

// The restart probe sits this fraction of the first step along f0: far enough that the secant
// is not rounding noise, close enough to describe the Jacobian at y0.
constexpr double kProbeFraction = 1e-3;

// A group whose every component moved by less than this many ulps of itself gives no rate.
constexpr double kNoiseUlps = 64.0;

// How far the stage difference may stray from an eigendirection of the group's dynamics
// (tangent of the angle between dy and df) for its secant rate to be used.
constexpr double kMaxResidualRatio = 0.5;

// Highest factorial denominator of the phi series: z^22 / 25! < 1e-17 relative at |z| = 2.
constexpr int kSeriesTerms = 26;

bool AllFinite(std::span<const double> values) {
  for (const double value : values) {
    if (!std::isfinite(value)) return false;
  }
  return true;
}

}  // namespace

PhiValues ComputePhi(double z) {
  PhiValues phi;
  if (std::abs(z) < 2.0) {
    // phi3 = (1/3!) (1 + z/4 (1 + z/5 (1 + ...))), then phi_k = 1/k! + z phi_{k+1}.
    double nested = 1.0;
    for (int m = kSeriesTerms; m >= 4; --m) nested = 1.0 + z * nested / static_cast<double>(m);
    phi.phi3 = nested / 6.0;
    phi.phi2 = 0.5 + z * phi.phi3;
    phi.phi1 = 1.0 + z * phi.phi2;
  } else {
    phi.phi1 = std::expm1(z) / z;
    phi.phi2 = (phi.phi1 - 1.0) / z;
    phi.phi3 = (phi.phi2 - 0.5) / z;
  }
  return phi;
}

void ExponentialIntegrator::ResizeWorkspace(std::size_t size) {
  group_start_ = system().VectorGroups();
  const std::size_t groups = group_start_.size();
  group_of_.assign(size, groups);  // index `groups` is the shared "no group, rate 0" slot
  for (std::size_t g = 0; g < groups; ++g) {
    const std::size_t start = group_start_[g];
    for (std::size_t i = start; i < start + kGroupSize; ++i) {
      if (start + kGroupSize > size || group_of_[i] != groups) {
        throw std::invalid_argument("sled::runtime integrator exponential: vector group " +
                                    std::to_string(g) + " at " + std::to_string(start) +
                                    " leaves the state or overlaps another group");
      }
      group_of_[i] = g;
    }
  }
  lambda_place_.assign(groups + 1, 0.0);
  lambda_step_.assign(groups + 1, 0.0);
  phi_half_.assign(groups + 1, PhiValues{});
  phi_.assign(groups + 1, PhiValues{});
  for (auto* v : {&a_, &fa_, &na_, &b_, &fb_, &nb_, &error_, &dense_start_, &dense_n0_, &dense_na_,
                  &dense_nb_}) {
    v->assign(size, 0.0);
  }
  dense_lambda_.assign(groups + 1, 0.0);
  dense_phi_.assign(groups + 1, PhiValues{});
  rates_known_ = false;
  step_rates_valid_ = false;
}

void ExponentialIntegrator::EstimateRates(std::span<const double> y_base,
                                          std::span<const double> y_moved,
                                          std::span<const double> f_base,
                                          std::span<const double> f_moved,
                                          std::span<double> rates) const {
  const double eps = std::numeric_limits<double>::epsilon();
  const std::size_t groups = group_start_.size();
  for (std::size_t g = 0; g < groups; ++g) {
    const std::size_t s = group_start_[g];
    // Scale by the largest difference so |dy|^2 cannot underflow for tiny states.
    double scale = 0.0;
    bool moved = false;
    for (std::size_t i = s; i < s + kGroupSize; ++i) {
      const double dy = y_moved[i] - y_base[i];
      scale = std::max(scale, std::abs(dy));
      moved = moved || std::abs(dy) > kNoiseUlps * eps * std::abs(y_base[i]);
    }
    double rate = 0.0;
    bool trusted = false;
    if (scale > 0.0 && moved) {
      double dot = 0.0;
      double dy2 = 0.0;
      double df2 = 0.0;
      for (std::size_t i = s; i < s + kGroupSize; ++i) {
        const double dy = (y_moved[i] - y_base[i]) / scale;
        const double df = (f_moved[i] - f_base[i]) / scale;
        dot += dy * df;
        dy2 += dy * dy;
        df2 += df * df;
      }
      rate = dot / dy2;
      // Trust the secant only if the group moved along (nearly) an eigendirection of its own
      // dynamics: the residual df - rate dy, of size |df| sin(angle), must be small next to the
      // decay it claims, |rate dy| = |df| |cos(angle)|. A group driven by other groups or by
      // time-dependent loads, or with a stiff axis and slow ones, fails this.
      const double residual2 = std::max(df2 - dot * dot / dy2, 0.0);
      trusted = std::isfinite(rate) &&
                residual2 <= kMaxResidualRatio * kMaxResidualRatio * rate * rate * dy2;
    }
    // Only decay is integrated exponentially.
    rates[g] = trusted ? std::min(rate, 0.0) : 0.0;
  }
  rates[groups] = 0.0;
}

bool ExponentialIntegrator::TryStep(double h, double* error) {
  const std::size_t n = y_.size();
  const std::size_t slots = group_start_.size() + 1;
  step_rates_valid_ = false;

  if (!rates_known_) {
    // One probe gives the first rates, so that even the first step after a restart places its
    // half-step stage with the right decay (a and fa are scratch until the stage below).
    const double delta = kProbeFraction * h;
    for (std::size_t i = 0; i < n; ++i) a_[i] = y_[i] + delta * f0_[i];
    if (Evaluate(t_ + delta, a_, fa_) && AllFinite(fa_)) {
      EstimateRates(y_, a_, f0_, fa_, lambda_place_);
    } else {
      std::fill(lambda_place_.begin(), lambda_place_.end(), 0.0);
    }
    rates_known_ = true;
  }

  // Predictor, stage a at h/2: exponential Euler with the rate carried from the last step.
  for (std::size_t g = 0; g < slots; ++g) phi_half_[g] = ComputePhi(0.5 * h * lambda_place_[g]);
  for (std::size_t i = 0; i < n; ++i) {
    a_[i] = y_[i] + 0.5 * h * phi_half_[group_of_[i]].phi1 * f0_[i];
  }
  if (!Evaluate(t_ + 0.5 * h, a_, fa_)) return false;

  // This step's rates from the stage difference, then the samples of N and stage b at h.
  EstimateRates(y_, a_, f0_, fa_, lambda_step_);
  step_rates_valid_ = true;
  for (std::size_t g = 0; g < slots; ++g) phi_[g] = ComputePhi(h * lambda_step_[g]);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t g = group_of_[i];
    na_[i] = fa_[i] - lambda_step_[g] * (a_[i] - y_[i]);
    b_[i] = y_[i] + h * phi_[g].phi1 * (2.0 * na_[i] - f0_[i]);
  }
  if (!Evaluate(t_ + h, b_, fb_)) return false;

  // Corrector: the exact integral of the quadratic model, and the ETD2 difference.
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t g = group_of_[i];
    const PhiValues& p = phi_[g];
    const double n0 = f0_[i];
    nb_[i] = fb_[i] - lambda_step_[g] * (b_[i] - y_[i]);
    const double second_difference = n0 - 2.0 * na_[i] + nb_[i];
    y1_[i] = y_[i] + h * (p.phi1 * n0 + p.phi2 * (-3.0 * n0 + 4.0 * na_[i] - nb_[i]) +
                          4.0 * p.phi3 * second_difference);
    error_[i] = h * (4.0 * p.phi3 - 2.0 * p.phi2) * second_difference;
  }
  const double model_error = ErrorNorm(error_);
  if (!AllFinite(y1_)) {
    *error = std::numeric_limits<double>::quiet_NaN();  // reported as not finite
    return true;
  }

  // The derivative residual at the step end (ATB's consistency test): f(t + h, y1) against the
  // model's y'(h) = lambda (y1 - y0) + Nb. Both solutions above share the model, so their
  // difference cannot see a rate that is wrong for part of a group (a slow axis frozen by a
  // fast rate); the residual does. A residual that builds up over the step like tau^3 (smooth,
  // lambda = 0) costs about h/6 of it, Simpson's end weight; one that appears at once because
  // the model decayed within the step (h lambda << -1) costs all of h. The weight
  // h (1 - 5/6 phi1(z)) goes from the one to the other and is not damped by the model.
  if (!Evaluate(t_ + h, y1_, f1_)) return false;
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t g = group_of_[i];
    const double residual = f1_[i] - lambda_step_[g] * (y1_[i] - y_[i]) - nb_[i];
    error_[i] = h * (1.0 - 5.0 / 6.0 * phi_[g].phi1) * residual;
  }
  const double residual_error = ErrorNorm(error_);
  *error = std::max(model_error, residual_error);
  if (std::isnan(model_error) || std::isnan(residual_error)) {
    *error = std::numeric_limits<double>::quiet_NaN();
  }
  return true;
}

void ExponentialIntegrator::SerializeHistory(Archive& archive) {
  archive.Field(lambda_place_);
  archive.Field(lambda_step_);
  archive.Field(phi_half_);
  archive.Field(phi_);
  archive.Field(rates_known_);
  archive.Field(step_rates_valid_);
  for (auto* v : {&dense_start_, &dense_n0_, &dense_na_, &dense_nb_, &dense_lambda_}) {
    archive.Field(*v);
  }
}

void ExponentialIntegrator::PrepareDenseOutput() {
  std::copy(y_.begin(), y_.end(), dense_start_.begin());
  std::copy(f0_.begin(), f0_.end(), dense_n0_.begin());
  std::copy(na_.begin(), na_.end(), dense_na_.begin());
  std::copy(nb_.begin(), nb_.end(), dense_nb_.begin());
  std::copy(lambda_step_.begin(), lambda_step_.end(), dense_lambda_.begin());
}

void ExponentialIntegrator::DenseOutput(double theta, std::span<double> y) const {
  const double h = dense_step();
  for (std::size_t g = 0; g < dense_phi_.size(); ++g) {
    dense_phi_[g] = ComputePhi(theta * h * dense_lambda_[g]);
  }
  for (std::size_t i = 0; i < y.size(); ++i) {
    const PhiValues& p = dense_phi_[group_of_[i]];
    const double n0 = dense_n0_[i], na = dense_na_[i], nb = dense_nb_[i];
    y[i] = dense_start_[i] + theta * h *
                                 (p.phi1 * n0 + theta * p.phi2 * (-3.0 * n0 + 4.0 * na - nb) +
                                  4.0 * theta * theta * p.phi3 * (n0 - 2.0 * na + nb));
  }
}

void ExponentialIntegrator::StepAccepted() {
  if (std::any_of(lambda_step_.begin(), lambda_step_.end(),
                  [](double rate) { return rate < 0.0; })) {
    ++mutable_stats().decaying_steps;
  }
  std::copy(lambda_step_.begin(), lambda_step_.end(), lambda_place_.begin());
}

void ExponentialIntegrator::StepRejected() {
  // The retry starts from the same point: its best rate guess is the one just measured.
  if (step_rates_valid_) {
    std::copy(lambda_step_.begin(), lambda_step_.end(), lambda_place_.begin());
  }
}

}  // namespace sled::runtime
