// What changes during a run for the contacts of a Model: per pair, the result of the last force
// evaluation (outputs and events read it), the loading history committed after each accepted
// step, and the work arrays of the force pass. Sized once by SizeContactState; nothing in a step
// allocates.
#pragma once

#include <cstdint>
#include <vector>

#include "runtime/dynamics/vehicle.h"
#include "runtime/forces/force_deflection.h"
#include "runtime/model/model_types.h"

namespace sled::runtime {

struct Model;

// Where pair k went past what its force law describes (runtime/contact/contact_reach.h): a
// deflection beyond the ellipsoid's smallest semi-axis, or an ellipsoid that went from in front
// of a plane to wholly behind it (where the force is zero) over its parallelogram.
struct ContactLawOverrun {
  double deep_time = -1.0;    // when the deflection first passed the smallest semi-axis; -1: never
  double deepest = 0.0;       // the largest deflection past it
  double semi_axis = 0.0;     // the smallest semi-axis it passed
  double behind_time = -1.0;  // when it first ended wholly behind the plane; -1: never
};

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

  // --- Per pair, changed only at events (runtime/run/system.h): the largest deflection and its
  // unloading curve, set where the deflection turns (the event's function is `rate` while the
  // pair loads), so the integrators' error control sees every force between two turns.
  std::vector<LoadingHistory> history;
  std::vector<std::uint8_t> hysteresis;  // fixed: the pair's force law keeps a history
  // Per pair with the impulse option: 1 from the impulse at first touch (or from the start when
  // the surfaces start in contact) until the event of their separation. The force law waits for
  // it, so the step that reaches the surface is free flight and the impact is located exactly.
  std::vector<std::uint8_t> engaged;

  // --- Per pair, watched after each accepted step (WatchContactReach): whether the ellipsoid
  // was wholly behind its plane there, and where the force law was overrun.
  std::vector<std::uint8_t> behind;
  std::vector<ContactLawOverrun> overrun;

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

  // What carries from one evaluation to the next, for checkpoints (runtime/run/archive.h): the
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
    a.Field(behind);
    a.Field(overrun);
  }
};

void SizeContactState(const Model& model, ContactState& state);

}  // namespace sled::runtime
