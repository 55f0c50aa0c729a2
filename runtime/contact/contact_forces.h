// The contact force elements: each derivative evaluation places the contact surfaces, skips the
// pairs whose bounding spheres are apart, and applies the CVS force law (loading or unloading,
// damping, Coulomb friction, the finite plane's edge weight) to the segments as wrenches in
// data.external. The loading history is committed after accepted steps only.
#pragma once

#include <span>

#include "runtime/contact/contact_geometry.h"
#include "runtime/data.h"
#include "runtime/frame_motion.h"

namespace sled::runtime {

// Adds every contact pair's wrenches to data.external and records each pair's deflection, gap,
// force and point in data.contacts. Needs current kinematics (positions and velocities).
void AccumulateContactForces(const Model& model, Data& data);

// After an accepted step, with data's time and state at its end: records each contact's largest
// deflection, which fixes its unloading curve, and whether pairs with the impulse option touch.
// Nothing to do (and no work) when no contact function loses energy or sets and no pair has
// the impulse.
void CommitContactHistory(const Model& model, Data& data);

// With data's kinematics and surfaces current (after an accepted step or at an output row):
// records each tabulated contact's deflection past its table's rows (runtime/table_range.h).
void WatchContactTables(const Model& model, Data& data);

// World poses of the contact surfaces from the current kinematics (into data.contacts).
void PlaceContactSurfaces(const Model& model, Data& data);

// The exact geometry of pair k (no bounding test), from the placed surfaces; updates the
// pair's warm start.
ContactGeometry PairGeometry(const Model& model, Data& data, std::size_t k);

// World velocity of the material point at `point` of the frame carrying pair k's first (side 0)
// or second (side 1) surface.
Vec3 SurfacePointVelocity(const Model& model, const Data& data, std::size_t k, int side,
                          const Vec3& point);

}  // namespace sled::runtime
