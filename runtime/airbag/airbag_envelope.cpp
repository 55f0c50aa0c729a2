#include "runtime/airbag/airbag_envelope.h"

#include <cmath>
#include <numbers>

#include "runtime/airbag/gas.h"
#include "runtime/contact/contact_geometry.h"

namespace sled::runtime {
namespace {

// The envelope's scale of an unfolding bag that segments push into is solved to this relative
// accuracy (far below the integrators' tolerances, so the rates stay smooth in the state).
constexpr double kScaleTolerance = 1e-13;
constexpr int kScaleIterations = 60;

// Support extent of an ellipsoid (semi-axes along the columns of `rotation`) along unit n.
double Extent(const Vec3& semi_axes, const Mat3& rotation, const Vec3& n) {
  return (rotation.transpose() * n).cwiseProduct(semi_axes).norm();
}

}  // namespace

double FullAirbagVolume(const AirbagTable& table, std::size_t b) {
  return 4.0 / 3.0 * std::numbers::pi * table.semi_axes[b].prod();
}

Penetration Penetrate(const Model& model, Data& data, std::size_t b, const FrameMotion& carrier,
                      double scale) {
  const AirbagTable& table = model.airbags;
  AirbagState& state = data.airbags;
  const Vec3& semi_axes = table.semi_axes[b];
  EllipsoidShape bag;
  bag.rotation = carrier.rotation * table.axes[b];
  bag.semi_axes = scale * semi_axes;
  bag.center = carrier.origin + carrier.rotation * table.deploy_point[b] +
               scale * semi_axes.x() * bag.rotation.col(0);
  bag.radius = scale * semi_axes.maxCoeff();
  Penetration out;
  const auto first = static_cast<std::size_t>(table.first_contact[b]);
  const auto last = first + static_cast<std::size_t>(table.contact_count[b]);
  for (std::size_t c = first; c < last; ++c) {
    state.area[c] = 0.0;
    state.penetrated_volume[c] = 0.0;
    state.force[c].setZero();
    if (scale <= 0) continue;
    const auto s = static_cast<std::size_t>(table.contact_segment[c]);
    EllipsoidShape segment;
    segment.center = data.position[s] + data.rotation[s] * table.contact_center[c];
    segment.rotation = data.rotation[s] * table.contact_axes[c];
    segment.semi_axes = table.contact_semi_axes[c];
    segment.radius = table.contact_radius[c];
    if ((segment.center - bag.center).norm() > segment.radius + bag.radius) continue;
    const ContactGeometry g = EllipsoidEllipsoid(bag, segment, state.search_direction[c]);
    if (g.deflection <= 0) continue;
    const Vec3 normal = -g.normal;  // from the bag towards the segment
    // The volume lost is the smaller of the two caps the deflection cuts: a head pushed into a
    // large bag takes its own cap, a large body flattening a small bag the bag's.
    const EllipsoidCap bag_cap = CutEllipsoidCap(bag.semi_axes, bag.rotation, normal, g.deflection);
    const EllipsoidCap segment_cap =
        CutEllipsoidCap(segment.semi_axes, segment.rotation, normal, g.deflection);
    const EllipsoidCap& cap = bag_cap.volume < segment_cap.volume ? bag_cap : segment_cap;
    state.area[c] = cap.area;
    state.penetrated_volume[c] = cap.volume;
    state.point[c] = g.point;
    state.force[c] = normal;
    out.volume += cap.volume;
    // The deflection grows as the segment closes on the bag along the normal, and as the
    // envelope grows: its surface point along the normal moves out by its full-size extent plus
    // the centre's move along x, per unit of scale.
    const Vec3 closing =
        VelocityAt(carrier, g.point) -
        VelocityAt(MotionOf(data, {FrameRef::Kind::kSegment, table.contact_segment[c]}), g.point);
    out.motion_rate += cap.area * normal.dot(closing);
    out.per_scale += cap.area * (Extent(semi_axes, bag.rotation, normal) +
                                 semi_axes.x() * normal.dot(bag.rotation.col(0)));
  }
  return out;
}

// Safeguarded Newton on a bracket that doubles until it holds the root.
double UnfoldedScale(const Model& model, Data& data, std::size_t b, const FrameMotion& carrier,
                     double gas_volume, Penetration& penetration) {
  const double full = FullAirbagVolume(model.airbags, b);
  auto excess = [&](double s) {
    penetration = Penetrate(model, data, b, carrier, s);
    return s * s * s * full - penetration.volume - gas_volume;
  };
  double low = std::cbrt(gas_volume / full);
  if (excess(low) >= 0) return low;  // nothing in the way
  double high = 2 * low;
  for (int k = 0; k < kScaleIterations && excess(high) < 0; ++k) high *= 2;
  double s = high;
  for (int k = 0; k < kScaleIterations && high - low > kScaleTolerance * high; ++k) {
    const double f = excess(s);
    if (f == 0) break;
    (f < 0 ? low : high) = s;
    const double slope = 3 * s * s * full - penetration.per_scale;
    const double newton = slope > 0 ? s - f / slope : -1.0;
    s = newton > low && newton < high ? newton : 0.5 * (low + high);
  }
  excess(s);  // leave the contacts recorded at the scale returned
  return s;
}

}  // namespace sled::runtime
