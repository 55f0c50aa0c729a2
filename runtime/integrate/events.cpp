#include "runtime/integrate/events.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sled::runtime {
namespace {

// A component crossed between two values when it left one strict side; reaching exactly zero
// counts as crossing, starting from zero does not (such components are settled by Start).
// `direction` as OdeSystem::EventDirection: the crossings that count.
bool Crossed(double from, double to, signed char direction) {
  return (direction >= 0 && from < 0.0 && to >= 0.0) || (direction <= 0 && from > 0.0 && to <= 0.0);
}

// Bounds the Illinois iteration; each pass at least moves a bracket end inward, and the bracket
// is valid whenever the loop stops.
constexpr int kMaxRootIterations = 200;

}  // namespace

void HermiteInterpolate(double theta, double h, std::span<const double> y0,
                        std::span<const double> f0, std::span<const double> y1,
                        std::span<const double> f1, std::span<double> y) {
  // The cubic Hermite basis on [0, 1].
  const double t2 = theta * theta;
  const double t3 = t2 * theta;
  const double h00 = 2.0 * t3 - 3.0 * t2 + 1.0;
  const double h10 = t3 - 2.0 * t2 + theta;
  const double h01 = -2.0 * t3 + 3.0 * t2;
  const double h11 = t3 - t2;
  for (std::size_t i = 0; i < y.size(); ++i) {
    y[i] = h00 * y0[i] + h * h10 * f0[i] + h01 * y1[i] + h * h11 * f1[i];
  }
}

void EventLocator::Reset(OdeSystem& system) {
  system_ = &system;
  count_ = system.EventCount();
  samples_ = count_ == 0 ? 0 : system.EventSamples();
  g_start_.assign(count_, 0.0);
  g_end_.assign(count_, 0.0);
  g_low_.assign(count_, 0.0);
  g_high_.assign(count_, 0.0);
  g_mid_.assign(count_, 0.0);
  crossing_.assign(count_, 0);
  direction_.assign(count_, 0);
  for (std::size_t k = 0; k < count_; ++k) {
    direction_[k] = static_cast<signed char>(system.EventDirection(k));
  }
  // The first Start settles every component that begins exactly on its surface.
  settle_.assign(count_, 0);
}

void EventLocator::Start(double t, std::span<const double> y, std::span<const double> dy,
                         double look_ahead, std::span<double> scratch) {
  if (count_ == 0) return;
  system_->Events(t, y, g_start_);
  bool any = false;
  for (std::size_t k = 0; k < count_; ++k) {
    if (g_start_[k] == 0.0) settle_[k] = 1;
    any = any || settle_[k] != 0;
  }
  if (any) {
    for (std::size_t i = 0; i < y.size(); ++i) scratch[i] = y[i] + look_ahead * dy[i];
    system_->Events(t + look_ahead, scratch, g_mid_);
    for (std::size_t k = 0; k < count_; ++k) {
      if (settle_[k] != 0) g_start_[k] = g_mid_[k];
    }
  }
  std::fill(settle_.begin(), settle_.end(), 0);
  std::fill(crossing_.begin(), crossing_.end(), 0);
}

bool EventLocator::Check(double t1, std::span<const double> y1) {
  if (count_ == 0) return false;
  system_->Events(t1, y1, g_end_);
  for (std::size_t k = 0; k < count_; ++k) {
    if (Crossed(g_start_[k], g_end_[k], direction_[k])) return true;
  }
  return false;
}

bool EventLocator::CheckInside(const StepInterpolant& interpolant, double t0, double t1,
                               std::span<double> y, double& t_found) {
  for (std::size_t i = 1; i <= samples_; ++i) {
    const double t = t0 + (t1 - t0) * static_cast<double>(i) / static_cast<double>(samples_ + 1);
    interpolant.Interpolate(t, y);
    system_->Events(t, y, g_mid_);
    for (std::size_t k = 0; k < count_; ++k) {
      if (Crossed(g_start_[k], g_mid_[k], direction_[k])) {
        std::copy(g_mid_.begin(), g_mid_.end(), g_end_.begin());
        t_found = t;
        return true;
      }
    }
  }
  return false;
}

long EventLocator::EarliestCrossing(std::span<const double> g_low,
                                    std::span<const double> g_high) const {
  // The secant root of component k sits at the fraction |g_hi| / |g_hi - g_lo| back from the
  // high end; the largest fraction is the earliest root (as in SUNDIALS' rootfinding).
  long best = -1;
  double best_fraction = -1.0;
  for (std::size_t k = 0; k < count_; ++k) {
    if (!Crossed(g_low[k], g_high[k], direction_[k])) continue;
    const double fraction = std::abs(g_high[k] / (g_high[k] - g_low[k]));
    if (fraction > best_fraction) {
      best_fraction = fraction;
      best = static_cast<long>(k);
    }
  }
  return best;
}

double EventLocator::Locate(const StepInterpolant& interpolant, double t0, double t1,
                            double tolerance, std::span<double> y, double t_probe) {
  // Never ask for a bracket narrower than the time's own rounding.
  const double eps = std::numeric_limits<double>::epsilon();
  tolerance = std::max(tolerance, 4.0 * eps * std::max(std::abs(t0), std::abs(t1)));
  std::copy(g_start_.begin(), g_start_.end(), g_low_.begin());
  std::copy(g_end_.begin(), g_end_.end(), g_high_.begin());
  double t_low = t0;
  double t_high = t1;
  long tracked = EarliestCrossing(g_low_, g_high_);

  // Illinois: when the same end of the bracket moves twice in a row, the other end's value is
  // weighted so the next secant lands closer to it, which restores superlinear convergence.
  int side = 0;
  int previous_side = -1;
  double weight = 1.0;
  bool probe = t_probe > t0 && t_probe < t1;
  double nudge = 1.0;  // how far the safeguard moves a trial point, in half tolerances
  for (int iteration = 0; iteration < kMaxRootIterations && tracked >= 0; ++iteration) {
    const double width = t_high - t_low;
    if (width <= tolerance) break;
    if (side == previous_side) {
      weight = side == 2 ? weight * 2.0 : weight * 0.5;
    } else {
      weight = 1.0;
    }
    const auto k = static_cast<std::size_t>(tracked);
    double t_mid = t_high - width * g_high_[k] / (g_high_[k] - weight * g_low_[k]);
    if (probe) t_mid = t_probe;  // (the caller's guess first)
    probe = false;
    // Safeguard: a trial point within half a tolerance of an end moves inside, by half a
    // tolerance the first time (the secant has found the root: the bracket closes on it in one
    // pass), ten times as far each time after in a row (it has not), and at most half the
    // bracket. So each pass shrinks the bracket, and a secant trusted elsewhere converges
    // superlinearly. (A tenth of the bracket at every pass took 12 passes per located event on
    // the flagship; a tenth of it near an end only, as CVODE's cvRootfind, 7; this, 5.)
    if (!(t_mid - t_low >= 0.5 * tolerance) || !(t_high - t_mid >= 0.5 * tolerance)) {
      const double inside = std::min(0.5 * tolerance * nudge, 0.5 * width);
      t_mid = t_mid - t_low < t_high - t_mid ? t_low + inside : t_high - inside;
      nudge *= 10.0;
    } else {
      nudge = 1.0;
    }

    interpolant.Interpolate(t_mid, y);
    system_->Events(t_mid, y, g_mid_);
    previous_side = side;
    const long in_low_half = EarliestCrossing(g_low_, g_mid_);
    if (in_low_half >= 0) {
      t_high = t_mid;
      std::copy(g_mid_.begin(), g_mid_.end(), g_high_.begin());
      tracked = in_low_half;
      side = 1;
    } else {
      t_low = t_mid;
      std::copy(g_mid_.begin(), g_mid_.end(), g_low_.begin());
      tracked = EarliestCrossing(g_low_, g_high_);
      side = 2;
    }
  }

  interpolant.Interpolate(t_high, y);
  for (std::size_t k = 0; k < count_; ++k) {
    crossing_[k] = 0;
    if (Crossed(g_start_[k], g_high_[k], direction_[k])) {
      crossing_[k] = g_start_[k] < 0.0 ? 1 : -1;
      settle_[k] = 1;
    }
  }
  return t_high;
}

void EventLocator::Advance() { std::copy(g_end_.begin(), g_end_.end(), g_start_.begin()); }

}  // namespace sled::runtime
