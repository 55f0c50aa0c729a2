#include "runtime/system.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "runtime/dynamics.h"
#include "runtime/joint.h"

namespace sled::runtime {

MultibodySystem::MultibodySystem(const Model& model, Data& data) : model_(model), data_(data) {}

std::size_t MultibodySystem::size() const {
  return static_cast<std::size_t>(model_.nq + model_.nv);
}

void MultibodySystem::Load(double t, std::span<const double> y) {
  const auto nq = static_cast<std::size_t>(model_.nq);
  data_.time = t;
  std::copy(y.begin(), y.begin() + static_cast<std::ptrdiff_t>(nq), data_.q.begin());
  std::copy(y.begin() + static_cast<std::ptrdiff_t>(nq), y.end(), data_.v.begin());
}

void MultibodySystem::Store(std::span<double> y) const {
  std::copy(data_.q.begin(), data_.q.end(), y.begin());
  std::copy(data_.v.begin(), data_.v.end(), y.begin() + model_.nq);
}

bool MultibodySystem::Derivative(double t, std::span<const double> y, std::span<double> dy) {
  Load(t, y);
  failure_ = Failure{};
  if (!Forward(model_, data_, &failure_)) {
    failure_.time = t;
    return false;
  }
  const auto nq = static_cast<std::size_t>(model_.nq);
  PositionDerivative(model_, data_.q, data_.v, data_.locked, dy.first(nq));
  std::copy(data_.vdot.begin(), data_.vdot.end(), dy.begin() + static_cast<std::ptrdiff_t>(nq));
  for (double value : dy) {
    if (!std::isfinite(value)) {
      failure_.time = t;
      failure_.cause = "the state derivative is not finite";
      return false;
    }
  }
  return true;
}

std::vector<std::size_t> MultibodySystem::VectorGroups() const {
  // Angular and linear velocities are physical 3-vectors: one decay rate each.
  std::vector<std::size_t> groups;
  const auto nq = static_cast<std::size_t>(model_.nq);
  for (std::size_t s = 0; s < model_.nsegment(); ++s) {
    const auto va = nq + static_cast<std::size_t>(model_.v_address[s]);
    if (model_.joint_kind[s] == JointKind::kFree) {
      groups.push_back(va);
      groups.push_back(va + 3);
    } else if (model_.joint_kind[s] == JointKind::kBall) {
      groups.push_back(va);
    }
  }
  return groups;
}

void MultibodySystem::Project(double t, std::span<double> y) {
  (void)t;
  // Unit quaternions: the integrators move them off the unit sphere by the local error.
  for (std::size_t s = 0; s < model_.nsegment(); ++s) {
    std::size_t address = static_cast<std::size_t>(model_.q_address[s]);
    if (model_.joint_kind[s] == JointKind::kFree) address += 3;
    if (model_.joint_kind[s] != JointKind::kFree && model_.joint_kind[s] != JointKind::kBall) {
      continue;
    }
    double norm = 0.0;
    for (std::size_t k = 0; k < 4; ++k) norm += y[address + k] * y[address + k];
    norm = std::sqrt(norm);
    if (norm > 0) {
      for (std::size_t k = 0; k < 4; ++k) y[address + k] /= norm;
    }
  }
}

std::string MultibodySystem::FailureReason() const {
  if (failure_.where.empty()) return failure_.cause;
  return fmt::format("{}: {}", failure_.where, failure_.cause);
}

}  // namespace sled::runtime
