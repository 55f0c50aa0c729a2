// What changes during a run for the contacts of a Model: per pair, the result of the last force
// evaluation (outputs and events read it), the loading history committed after each accepted
// step, and the work arrays of the force pass. Sized once by SizeContactState; nothing in a step
// allocates.
#pragma once

#include <cstdint>
#include <vector>

#include "runtime/force_deflection.h"
#include "runtime/model_types.h"
#include "runtime/vehicle.h"

namespace sled::runtime {

struct Model;

struct ContactState {
  // --- Per pair, from the last force evaluation (world frame).
  std::vector<double> deflection;    // > 0 in contact, 0 apart
  std::vector<double> gap;           // signed distance, > 0 apart (a lower bound when far apart)
  std::vector<double> normal_force;  // >= 0, including damping and the edge weight
  std::vector<Vec3> force;           // on the first surface: normal force plus friction
  std::vector<Vec3> point;           // where the force acts
  std::vector<Vec3> normal;          // unit, the direction the first surface is pushed
  // Warm start of the common-normal search of ellipsoid pairs: the last normal found (from the
  // first ellipsoid towards the second).
  std::vector<Vec3> search_direction;

  // Per pair with a hysteretic force law, from the last force evaluation: the deflection's time
  // derivative while the pair is loading (beyond its largest deflection so far), else 0.
  std::vector<double> rate;

  // --- Per pair, changed only at events (runtime/system.h): the largest deflection and its
  // unloading curve, set where the deflection turns (the event's function is `rate` while the
  // pair loads), so the integrators' error control sees every force between two turns.
  std::vector<LoadingHistory> history;
  std::vector<std::uint8_t> hysteresis;  // fixed: the pair's force law keeps a history
  // Per pair with the impulse option: 1 from the impulse at first touch (or from the start when
  // the surfaces start in contact) until the event of their separation. The force law waits for
  // it, so the step that reaches the surface is free flight and the impact is located exactly.
  std::vector<std::uint8_t> engaged;

  // --- Per surface, recomputed each evaluation: world pose and motion of its frame.
  std::vector<Vec3> ellipsoid_center;    // world
  std::vector<Mat3> ellipsoid_rotation;  // ellipsoid axes to world
  std::vector<Vec3> plane_origin;        // world
  std::vector<Vec3> plane_edge_u;
  std::vector<Vec3> plane_edge_v;
  std::vector<Vec3> plane_normal;

  // --- Impulse workspace: the velocity response to a unit contact impulse and a saved velocity.
  std::vector<double> response;
  std::vector<double> saved_v;

  // What carries from one evaluation to the next, for checkpoints (runtime/archive.h): the
  // committed histories, and the last evaluation's values (warm starts, outputs).
  template <class Archive>
  void Serialize(Archive& a) {
    a.Field(deflection);
    a.Field(gap);
    a.Field(normal_force);
    a.Field(force);
    a.Field(point);
    a.Field(normal);
    a.Field(search_direction);
    a.Field(rate);
    a.Field(history);
    a.Field(engaged);
  }
};

void SizeContactState(const Model& model, ContactState& state);

}  // namespace sled::runtime
