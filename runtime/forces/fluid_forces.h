// Wind and water: forces of a moving or still fluid on the contact ellipsoids of the segments a
// `wind` or `water` block names (ATB's wind forces, F.7, and its water forces, F.9).
//
// Wind: the air moves at speed(t) along a direction fixed in its carrier (the ground, a vehicle or
// a segment: the air at rest in it but for the speed, at the carrier's velocity at each point);
// each ellipsoid feels the drag 0.5 rho Cd A |u| u of the air's velocity u relative to its
// centre, A the area the ellipsoid presents across u (its projection on the plane normal to u),
// applied at the centre. A blast given as a pressure p(t) instead pushes with Cd p A along the
// direction, A across it, whatever the body's motion (ATB's tabulated wind).
// Water: still, below a horizontal surface (normal against gravity, `level` above the ground
// origin along it). Each ellipsoid takes the buoyancy -rho g V_sub at the centroid of its
// submerged part (a plane cuts an ellipsoid as the affine image of a plane cutting the unit
// sphere, so V_sub and the centroid are the sphere's cap formulas mapped back) and the drag
// 0.5 rho Cd A f |v| v against its centre's velocity v, A as for wind and f the submerged share
// of the volume. The power of both into the segments is added to data.applied_power, so the
// energy balance counts their work with the applied loads'.
#pragma once

#include <cstdint>
#include <vector>

#include "runtime/model/model_types.h"

namespace sled::runtime {

struct Model;
struct Data;

// One row per ellipsoid in a fluid.
struct FluidTable {
  enum class Medium : std::uint8_t { kWind, kWater };
  std::vector<Medium> medium;
  std::vector<std::int32_t> segment;
  std::vector<Vec3> center;            // the ellipsoid's centre, segment frame
  std::vector<Mat3> axes;              // columns: its axes in the segment frame
  std::vector<Vec3> semi_axes;         // a, b, c
  std::vector<double> drag;            // drag coefficient Cd
  std::vector<double> density;         // of the fluid
  std::vector<std::int32_t> speed;     // wind: time -> speed, into Model::functions; else -1
  std::vector<std::int32_t> pressure;  // wind: time -> a blast's pressure; else -1
  std::vector<Vec3> direction;         // wind: unit, carrier's axes; water: up (against gravity)
  std::vector<FrameRef> carrier;       // wind: the frame the air is at rest in but for its speed
  std::vector<double> level;           // water: height of the surface along `direction`
  std::size_t size() const { return medium.size(); }
};

// The part of an ellipsoid below a plane: its share of the volume and its centroid.
struct SubmergedPart {
  double fraction = 0.0;  // 0 (dry) to 1 (under water)
  Vec3 centroid;          // world; the centre when dry
};

// `center` and `shape` (Q diag(a^2, b^2, c^2) Q^T of the ellipsoid's world axes Q) of an ellipsoid,
// the unit normal `up` of the surface and the surface's height `level` along it.
SubmergedPart SubmergedPartOf(const Vec3& center, const Mat3& shape, const Vec3& up, double level);

// The area an ellipsoid (semi-axes, in its own axes) presents across the unit direction `along`
// (in its own axes): pi sqrt((b c x)^2 + (a c y)^2 + (a b z)^2).
double ProjectedArea(const Vec3& semi_axes, const Vec3& along);

// Adds every row's force at data.time to data.external and its power to data.applied_power.
void AddFluidForces(const Model& model, Data& data);

}  // namespace sled::runtime
