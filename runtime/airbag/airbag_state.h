// What changes during a run for the airbags of a Model (runtime/model/data.h holds one
// AirbagState): the results of the last evaluation, which outputs read, and the warm starts of the
// contact searches. The gas state itself (mass, internal energy) is integrated: it lives in
// Data::w. Sized once by SizeAirbagState (after Data::w is set); nothing in a step allocates.
#pragma once

#include <cstdint>
#include <vector>

#include "runtime/model/model_types.h"

namespace sled::runtime {

struct Model;
struct Data;

struct AirbagState {
  // --- Per bag, discrete modes switched only by events (MultibodySystem::HandleEvent), so the
  // gas equations stay smooth inside every step: whether the envelope is full, and the
  // inflator's phase (0 before deployment, 1 delivering, 2 spent: after a table's last row).
  std::vector<std::uint8_t> full;
  std::vector<std::uint8_t> inflow_phase;

  // --- Per bag, from the last evaluation.
  std::vector<double> pressure;     // absolute [Pa]
  std::vector<double> volume;       // of the gas [m^3]: the envelope less the segments inside
  std::vector<double> temperature;  // [K]
  std::vector<double> vent_flow;    // mass flow out of the vent [kg/s]
  std::vector<double> inflow;       // mass flow from the inflator [kg/s]
  std::vector<double> scale;        // envelope size over the fully deployed size, (0, 1]

  // --- Per contact, from the last evaluation (world frame).
  std::vector<Vec3> force;  // on the segment
  std::vector<Vec3> point;  // where it acts
  std::vector<double> area;
  std::vector<double> penetrated_volume;
  // Warm start of the common-normal search: the last normal, from the bag towards the segment.
  std::vector<Vec3> search_direction;

  // The bag whose gas the segments inside it left no volume at the last evaluation; -1: none.
  int failed_bag = -1;

  // Every field, for checkpoints (runtime/run/archive.h): the modes, and the last evaluation's
  // values (warm starts, the envelope scale that starts its Newton iteration, outputs).
  template <class Archive>
  void Serialize(Archive& a) {
    a.Field(full);
    a.Field(inflow_phase);
    a.Field(pressure);
    a.Field(volume);
    a.Field(temperature);
    a.Field(vent_flow);
    a.Field(inflow);
    a.Field(scale);
    a.Field(force);
    a.Field(point);
    a.Field(area);
    a.Field(penetrated_volume);
    a.Field(search_direction);
    a.Field(failed_bag);
  }
};

// Sizes data.airbags and sets the modes from data.w and data.time.
void SizeAirbagState(const Model& model, Data& data);

}  // namespace sled::runtime
