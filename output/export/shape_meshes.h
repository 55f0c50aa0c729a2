// Triangle meshes of the contact surfaces for the animation: the unit (hyper-)ellipsoid
// |x|^n + |y|^n + |z|^n = 1 (n = 2: the sphere, scaled to the semi-axes by its node) and the
// parallelogram of a finite plane.
#pragma once

#include <cstdint>
#include <vector>

#include "runtime/model/model_types.h"

namespace sled::runtime {

struct TriangleMesh {
  std::vector<float> positions;  // x, y, z per vertex
  std::vector<float> normals;    // unit, per vertex
  std::vector<std::uint32_t> indices;
};

// The unit superellipsoid of `degree` (2 or more) by latitude rings and longitude sectors:
// x = c(phi) c(theta), y = c(phi) s(theta), z = s(phi) with c(w) = sign(w) |w|^(2/n), so each
// vertex lies exactly on the surface; normals from the gradient of the surface function.
TriangleMesh SuperellipsoidMesh(double degree, int rings, int sectors);

// The parallelogram origin + s u + t v (s, t in [0, 1]), normal along u x v.
TriangleMesh ParallelogramMesh(const Vec3& origin, const Vec3& u, const Vec3& v);

}  // namespace sled::runtime
