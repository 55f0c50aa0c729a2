// Contact geometry of CVS surfaces in world coordinates: the support point of an ellipsoid or
// hyper-ellipsoid, the plane–ellipsoid deflection on a finite plane, and the ellipsoid–ellipsoid
// deflection along the common normal. Pure functions of the poses; docs/runtime.md, "Contacts",
// gives the definitions.
#pragma once

#include <utility>

#include "runtime/model/model_types.h"

namespace sled::runtime {

// An ellipsoid |x/a|^n + |y/b|^n + |z/c|^n <= 1 in its own axes (n = degree >= 2), placed in the
// world.
struct EllipsoidShape {
  Vec3 center = Vec3::Zero();
  Mat3 rotation = Mat3::Identity();  // ellipsoid axes to world
  Vec3 semi_axes = Vec3::Ones();
  double degree = 2.0;
  double radius = 1.0;  // bounding sphere about the centre (BoundingRadius)
};

// A finite plane: the parallelogram origin + s edge_u + t edge_v for s, t in [0, 1], with the
// unit normal its contacts push towards.
struct PlaneShape {
  Vec3 origin = Vec3::Zero();
  Vec3 edge_u = Vec3::UnitX();
  Vec3 edge_v = Vec3::UnitY();
  Vec3 normal = Vec3::UnitZ();
};

// The smallest sphere about the centre that holds the (hyper-)ellipsoid, or a tight bound on it.
double BoundingRadius(const Vec3& semi_axes, double degree);

// The point of the surface farthest along the unit `direction`; `extent` = direction . (point -
// center), the support function.
Vec3 SupportPoint(const EllipsoidShape& shape, const Vec3& direction, double* extent);

struct ContactGeometry {
  // Overlap along the normal: > 0 in contact; < 0 the separation (for ellipsoid pairs the
  // distance between the surfaces; for a plane the height of the ellipsoid above it).
  double deflection = 0.0;
  bool touching = false;        // the force law applies (deflection > 0, and on the plane's side)
  Vec3 normal = Vec3::UnitZ();  // unit: the direction the first surface (the ellipsoid) is pushed
  Vec3 point = Vec3::Zero();    // where the force acts
  double weight = 1.0;          // share of the contact footprint that lies on a finite plane
  // The deepest point of each surface along the normal (for a plane, where its material point
  // under the ellipsoid's deepest point is): the deflection's time derivative is the closing
  // speed of the surfaces' material points there, -normal . (v_first - v_second) (the envelope
  // theorem: the support points' own motion along the surfaces does not change the extents).
  Vec3 deepest_first = Vec3::Zero();
  Vec3 deepest_second = Vec3::Zero();
};

// The coordinates (s, t) of `point` (on the plane) in its parallelogram: point = origin +
// s edge_u + t edge_v; both in [0, 1] over the parallelogram.
std::pair<double, double> ParallelogramCoordinates(const PlaneShape& plane, const Vec3& point);

// An ellipsoid against a finite plane. Deflection: how far the ellipsoid's deepest point lies
// behind the plane. Point: where the line from the centre to the deepest point crosses the
// plane (for an ellipsoid, the centre of the ellipse the plane cuts), moved onto the
// parallelogram. Weight: the fraction of that cut ellipse inside the parallelogram (each edge
// cuts it as a half-plane), so the force fades smoothly over an edge.
ContactGeometry PlaneEllipsoid(const PlaneShape& plane, const EllipsoidShape& ellipsoid);

// Two ellipsoids: the deflection is the least overlap over all directions n of the two solids'
// extents, h_first(n) + h_second(-n) - n . (c_second - c_first); at the minimum, n is the common
// normal (the deepest points of both surfaces lie on one line along n) and the point is midway
// between the deepest points. Negative when apart (minus the distance between the surfaces).
// `direction` is the warm start (first towards second) and receives the normal found.
ContactGeometry EllipsoidEllipsoid(const EllipsoidShape& first, const EllipsoidShape& second,
                                   Vec3& direction);

}  // namespace sled::runtime
