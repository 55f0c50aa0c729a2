// The multibody equations as an OdeSystem for the integrators: state y = [q; v].
#pragma once

#include "runtime/data.h"
#include "runtime/integrate/ode.h"

namespace sled::runtime {

class MultibodySystem : public OdeSystem {
 public:
  MultibodySystem(const Model& model, Data& data);

  std::size_t size() const override;
  bool Derivative(double t, std::span<const double> y, std::span<double> dy) override;
  std::vector<std::size_t> VectorGroups() const override;
  void Project(double t, std::span<double> y) override;
  std::string FailureReason() const override;

  // Copies a state vector into data (q, v, time) and back.
  void Load(double t, std::span<const double> y);
  void Store(std::span<double> y) const;

  const Failure& failure() const { return failure_; }

 private:
  const Model& model_;
  Data& data_;
  Failure failure_;
};

}  // namespace sled::runtime
