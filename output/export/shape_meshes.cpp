#include "output/export/shape_meshes.h"

#include <cmath>
#include <numbers>

#include <Eigen/Geometry>

namespace sled::runtime {
namespace {

double SignedPower(double w, double e) { return std::copysign(std::pow(std::abs(w), e), w); }

void PutVertex(TriangleMesh& mesh, const Vec3& position, const Vec3& normal) {
  for (int i = 0; i < 3; ++i) mesh.positions.push_back(static_cast<float>(position[i]));
  for (int i = 0; i < 3; ++i) mesh.normals.push_back(static_cast<float>(normal[i]));
}

}  // namespace

TriangleMesh SuperellipsoidMesh(double degree, int rings, int sectors) {
  TriangleMesh mesh;
  const double e = 2.0 / degree;
  for (int i = 0; i <= rings; ++i) {
    const double phi = -std::numbers::pi / 2 + std::numbers::pi * i / rings;
    for (int j = 0; j <= sectors; ++j) {
      const double theta = 2 * std::numbers::pi * j / sectors;
      const Vec3 p(SignedPower(std::cos(phi), e) * SignedPower(std::cos(theta), e),
                   SignedPower(std::cos(phi), e) * SignedPower(std::sin(theta), e),
                   SignedPower(std::sin(phi), e));
      // Gradient of |x|^n + |y|^n + |z|^n; at the poles of the sphere, the position itself.
      Vec3 normal(SignedPower(p.x(), degree - 1), SignedPower(p.y(), degree - 1),
                  SignedPower(p.z(), degree - 1));
      normal = normal.norm() > 1e-12 ? normal.normalized() : p.normalized();
      PutVertex(mesh, p, normal);
    }
  }
  const auto row = static_cast<std::uint32_t>(sectors + 1);
  for (std::uint32_t i = 0; i < static_cast<std::uint32_t>(rings); ++i) {
    for (std::uint32_t j = 0; j < static_cast<std::uint32_t>(sectors); ++j) {
      const std::uint32_t a = i * row + j, b = a + 1, c = a + row, d = c + 1;
      // Counter-clockwise seen from outside.
      mesh.indices.insert(mesh.indices.end(), {a, b, d, a, d, c});
    }
  }
  return mesh;
}

TriangleMesh ParallelogramMesh(const Vec3& origin, const Vec3& u, const Vec3& v) {
  TriangleMesh mesh;
  const Vec3 cross = u.cross(v);
  const Vec3 normal = cross.norm() > 0 ? Vec3(cross.normalized()) : Vec3::UnitZ();
  for (const Vec3& corner : {origin, Vec3(origin + u), Vec3(origin + u + v), Vec3(origin + v)}) {
    PutVertex(mesh, corner, normal);
  }
  mesh.indices = {0, 1, 2, 0, 2, 3};
  return mesh;
}

}  // namespace sled::runtime
