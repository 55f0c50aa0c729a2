#include "runtime/forces/fluid_forces.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "runtime/dynamics/frame_motion.h"
#include "runtime/forces/applied_loads.h"
#include "runtime/forces/functions.h"
#include "runtime/model/data.h"
#include "runtime/model/model.h"

namespace sled::runtime {
namespace {

constexpr double kPi = std::numbers::pi;

// 0.5 rho Cd A |u| u: the drag of a flow at velocity u (relative to the body) on an ellipsoid of
// the given semi-axes whose world axes are the columns of `axes`.
Vec3 Drag(double density, double drag, const Vec3& semi_axes, const Mat3& axes, const Vec3& u) {
  const double speed = u.norm();
  if (speed == 0.0 || drag == 0.0) return Vec3::Zero();
  const double area = ProjectedArea(semi_axes, axes.transpose() * (u / speed));
  return 0.5 * density * drag * area * speed * u;
}

}  // namespace

double ProjectedArea(const Vec3& semi_axes, const Vec3& along) {
  const double a = semi_axes.x(), b = semi_axes.y(), c = semi_axes.z();
  return kPi * std::sqrt(std::pow(b * c * along.x(), 2) + std::pow(a * c * along.y(), 2) +
                         std::pow(a * b * along.z(), 2));
}

SubmergedPart SubmergedPartOf(const Vec3& center, const Mat3& shape, const Vec3& up, double level) {
  // In the coordinates where the ellipsoid is the unit sphere, the water is the half-space below
  // the plane at height t (the surface's height above the centre over the ellipsoid's half
  // height h along `up`).
  const double h = std::sqrt(up.dot(shape * up));
  const double t = std::clamp((level - up.dot(center)) / h, -1.0, 1.0);
  SubmergedPart part;
  part.fraction = (t + 1) * (t + 1) * (2 - t) / 4;
  // The cap's centroid is at -3 (1 - t)^2 / (4 (2 - t)) along the sphere's normal; mapped back,
  // that normal's unit step is shape * up / h.
  const double depth = -3 * (1 - t) * (1 - t) / (4 * (2 - t));
  part.centroid = center + shape * up / h * depth;
  return part;
}

void AddFluidForces(const Model& model, Data& data) {
  const FluidTable& fluids = model.fluids;
  for (std::size_t k = 0; k < fluids.size(); ++k) {
    const auto s = static_cast<std::size_t>(fluids.segment[k]);
    const Mat3& R = data.rotation[s];
    const Vec3 arm = R * fluids.center[k];
    const Vec3 center = data.position[s] + arm;
    const Vec3 velocity =
        R * (data.velocity[s].tail<3>() + data.velocity[s].head<3>().cross(fluids.center[k]));
    const Mat3 axes = R * fluids.axes[k];
    const FrameMotion carrier = MotionOf(data, fluids.carrier[k]);
    const Vec3 along = carrier.rotation * fluids.direction[k];  // world
    if (fluids.pressure[k] >= 0) {
      const double area = ProjectedArea(fluids.semi_axes[k], axes.transpose() * along);
      const double pressure = EvaluateFunction(model.functions, fluids.pressure[k], data.time);
      AddAppliedForce(data, s, center, fluids.drag[k] * pressure * area * along, Vec3::Zero());
      continue;
    }
    if (fluids.medium[k] == FluidTable::Medium::kWind) {
      const double speed = EvaluateFunction(model.functions, fluids.speed[k], data.time);
      const Vec3 air = speed * along + VelocityAt(carrier, center) - velocity;
      AddAppliedForce(data, s, center,
                      Drag(fluids.density[k], fluids.drag[k], fluids.semi_axes[k], axes, air),
                      Vec3::Zero());
      continue;
    }
    const Vec3& a = fluids.semi_axes[k];
    const Mat3 shape =
        axes * Vec3(a.x() * a.x(), a.y() * a.y(), a.z() * a.z()).asDiagonal() * axes.transpose();
    const SubmergedPart part = SubmergedPartOf(center, shape, fluids.direction[k], fluids.level[k]);
    if (part.fraction == 0.0) continue;
    const double volume = 4.0 / 3.0 * kPi * a.x() * a.y() * a.z();
    const Vec3 buoyancy = -fluids.density[k] * part.fraction * volume * model.gravity;
    const Vec3 drag = part.fraction * Drag(fluids.density[k], fluids.drag[k], a, axes, -velocity);
    AddAppliedForce(data, s, part.centroid, buoyancy + drag, Vec3::Zero());
  }
}

}  // namespace sled::runtime
