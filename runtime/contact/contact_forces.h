// The contact force elements: each derivative evaluation places the contact surfaces, skips the
// pairs whose bounding spheres are apart, and applies the CVS force law (loading or unloading,
// damping, Coulomb friction, the finite plane's edge weight) to the segments as wrenches in
// data.external. The loading history changes only at events (where a deflection turns), so every
// evaluation is a function of the state and the events so far.
#pragma once

#include <span>

#include "runtime/contact/contact_geometry.h"
#include "runtime/dynamics/frame_motion.h"
#include "runtime/model/data.h"

namespace sled::runtime {

// Adds every contact pair's wrenches to data.external and records each pair's deflection, gap,
// force and point in data.contacts. Needs current kinematics (positions and velocities).
void AccumulateContactForces(const Model& model, Data& data);

// At the initial state (called by MakeData): pairs with the impulse option that start apart wait
// for their first touch; a hysteretic pair that starts deflected has loaded to that deflection.
void SetUpContacts(const Model& model, Data& data);

// The event where pair k's deflection turns while it loads: its largest deflection is the one
// at data's state (after Forward), which fixes its unloading curve.
void TurnContactHistory(const Model& model, Data& data, std::size_t k);

// With data's kinematics and surfaces current (after an accepted step or at an output row):
// records each tabulated contact's deflection past its table's rows (runtime/forces/table_range.h).
void WatchContactTables(const Model& model, Data& data);

// World poses of the contact surfaces from the current kinematics (into data.contacts).
void PlaceContactSurfaces(const Model& model, Data& data);

// The exact geometry of pair k (no bounding test), from the placed surfaces; updates the
// pair's warm start.
ContactGeometry PairGeometry(const Model& model, Data& data, std::size_t k);

// Ellipsoid e and plane p as data's last PlaceContactSurfaces placed them.
EllipsoidShape ShapeOf(const ContactTable& table, const ContactState& state, std::int32_t e);
PlaneShape PlaneOf(const ContactState& state, std::int32_t p);

// The frame carrying pair k's first (side 0: the ellipsoid) or second (side 1) surface.
FrameRef SurfaceFrame(const ContactTable& table, std::size_t k, int side);

// World velocity of the material point at `point` of the frame carrying pair k's first (side 0)
// or second (side 1) surface.
Vec3 SurfacePointVelocity(const Model& model, const Data& data, std::size_t k, int side,
                          const Vec3& point);

}  // namespace sled::runtime
