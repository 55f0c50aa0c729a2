// The small ODE systems the integrator tests solve (exact solutions, stiff, events, failures,
// projections) and the fixture that runs a test with every method.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <memory>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "runtime/integrate/adaptive_integrator.h"
#include "runtime/integrate/make_integrator.h"
#include "runtime/integrate/ode.h"

namespace sled::runtime::testing {

// y' = A y, A row-major n x n.
class LinearSystem : public OdeSystem {
 public:
  LinearSystem(std::size_t n, std::vector<double> a, std::vector<std::size_t> groups = {},
               bool analytic_jacobian = true)
      : n_(n), a_(std::move(a)), groups_(std::move(groups)), analytic_(analytic_jacobian) {}
  std::size_t size() const override { return n_; }
  bool Derivative(double, std::span<const double> y, std::span<double> dy) override {
    for (std::size_t i = 0; i < n_; ++i) {
      double sum = 0.0;
      for (std::size_t j = 0; j < n_; ++j) sum += a_[i * n_ + j] * y[j];
      dy[i] = sum;
    }
    return true;
  }
  bool Jacobian(double, std::span<const double>, std::span<double> jacobian) override {
    if (!analytic_) return false;
    std::copy(a_.begin(), a_.end(), jacobian.begin());
    return true;
  }
  std::vector<std::size_t> VectorGroups() const override { return groups_; }

 private:
  std::size_t n_;
  std::vector<double> a_;
  std::vector<std::size_t> groups_;
  bool analytic_;
};

// The Kepler problem in 3-D with position and velocity as two vector groups. Eccentricity e,
// period 2 pi; after one period the exact state is the initial one.
class Kepler : public OdeSystem {
 public:
  // `jacobian_scale` multiplies the analytic Jacobian (0: none, so finite differences; a value
  // other than 1 gives a wrong W, to test the W-method property).
  explicit Kepler(double jacobian_scale = 1.0) : jacobian_scale_(jacobian_scale) {}
  static std::vector<double> Initial(double e) {
    return {1.0 - e, 0.0, 0.0, 0.0, std::sqrt((1.0 + e) / (1.0 - e)), 0.0};
  }
  std::size_t size() const override { return 6; }
  bool Derivative(double, std::span<const double> y, std::span<double> dy) override {
    const double r2 = y[0] * y[0] + y[1] * y[1] + y[2] * y[2];
    const double r3 = r2 * std::sqrt(r2);
    for (int i = 0; i < 3; ++i) {
      dy[i] = y[i + 3];
      dy[i + 3] = -y[i] / r3;
    }
    return true;
  }
  bool Jacobian(double, std::span<const double> y, std::span<double> jacobian) override {
    if (jacobian_scale_ == 0.0) return false;
    std::fill(jacobian.begin(), jacobian.end(), 0.0);
    const double r2 = y[0] * y[0] + y[1] * y[1] + y[2] * y[2];
    const double r = std::sqrt(r2);
    const double r3 = r2 * r;
    const double r5 = r3 * r2;
    for (std::size_t i = 0; i < 3; ++i) {
      jacobian[i * 6 + i + 3] = jacobian_scale_;
      for (std::size_t j = 0; j < 3; ++j) {
        const double value = (i == j ? -1.0 / r3 : 0.0) + 3.0 * y[i] * y[j] / r5;
        jacobian[(i + 3) * 6 + j] = jacobian_scale_ * value;
      }
    }
    return true;
  }
  std::vector<std::size_t> VectorGroups() const override { return {0, 3}; }

 private:
  double jacobian_scale_;
};

// Van der Pol in Lienard time, y1' = y2, y2' = mu^2 ((1 - y1^2) y2 - y1), no analytic
// Jacobian.
class VanDerPol : public OdeSystem {
 public:
  explicit VanDerPol(double mu) : mu2_(mu * mu) {}
  std::size_t size() const override { return 2; }
  bool Derivative(double, std::span<const double> y, std::span<double> dy) override {
    dy[0] = y[1];
    dy[1] = mu2_ * ((1.0 - y[0] * y[0]) * y[1] - y[0]);
    return true;
  }

 private:
  double mu2_;
};

// A ball dropped from 1 m, restitution 0.8. Event 0 is the height (impact: reverse and scale the
// velocity), event 1 the velocity (apex: record the height).
class BouncingBall : public OdeSystem {
 public:
  static constexpr double kG = 9.81;
  static constexpr double kRestitution = 0.8;
  std::size_t size() const override { return 2; }
  bool Derivative(double, std::span<const double> y, std::span<double> dy) override {
    dy[0] = y[1];
    dy[1] = -kG;
    return true;
  }
  std::size_t EventCount() const override { return 2; }
  void Events(double, std::span<const double> y, std::span<double> g) override {
    g[0] = y[0];
    g[1] = y[1];
  }
  EventEffect HandleEvent(std::size_t k, int direction, double t, std::span<double> y) override {
    if (k == 0 && direction < 0) {
      impacts.push_back(t);
      y[1] = -kRestitution * y[1];
      return EventEffect::kStateChanged;
    }
    if (k == 1 && direction < 0) apexes.push_back(y[0]);
    return EventEffect::kModeChanged;
  }
  void Reserve() {
    impacts.reserve(64);
    apexes.reserve(64);
  }
  std::vector<double> impacts;
  std::vector<double> apexes;
};

// y' = 1 from 0; Derivative fails once y > 1.
class FailsAboveOne : public OdeSystem {
 public:
  std::size_t size() const override { return 1; }
  bool Derivative(double, std::span<const double> y, std::span<double> dy) override {
    if (y[0] > 1.0) return false;
    dy[0] = 1.0;
    return true;
  }
  std::string FailureReason() const override { return "y exceeds 1"; }
};

// y' = 1000 y from 1e290: grows past the largest double near t = 0.04.
class BlowsUp : public OdeSystem {
 public:
  std::size_t size() const override { return 1; }
  bool Derivative(double, std::span<const double> y, std::span<double> dy) override {
    dy[0] = 1e3 * y[0];
    return true;
  }
};

// A unit circle, x' = -y, y' = x, whose Project renormalises the radius and counts its calls.
class ProjectedCircle : public OdeSystem {
 public:
  std::size_t size() const override { return 2; }
  bool Derivative(double, std::span<const double> y, std::span<double> dy) override {
    dy[0] = -y[1];
    dy[1] = y[0];
    return true;
  }
  void Project(double, std::span<double> y) override {
    ++projections;
    const double r = std::hypot(y[0], y[1]);
    y[0] /= r;
    y[1] /= r;
  }
  long projections = 0;
};

inline std::unique_ptr<Integrator> Make(const std::string& method) {
  auto integrator = MakeIntegrator(method);
  EXPECT_NE(integrator, nullptr) << method;
  return integrator;
}

inline AdaptiveIntegrator& Fixed(Integrator& integrator) {
  return dynamic_cast<AdaptiveIntegrator&>(integrator);
}

inline constexpr const char* kMethods[] = {"dopri5", "rosenbrock", "exponential", "cvs", "auto"};

// TEST_P(EveryMethod, ...) runs with each of kMethods (instantiated in integrator_test.cpp).
class EveryMethod : public ::testing::TestWithParam<const char*> {};

}  // namespace sled::runtime::testing
